#ifndef qsmpm_fracture_compact_tension_geometry_h
#define qsmpm_fracture_compact_tension_geometry_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <memory>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/loading/boundary_descriptor.h>
#include <qsmpm/materials/decohesion.h>
#include <vector>

namespace qsmpm
{
  /**
   * The compact-tension specimen (CTS) of paper Section 3.3 (Fig. 2) on a
   * uniform grid of square cells of size h: a rectangle of width W (in x)
   * and height H = a + b (in y) with a notch of width h and depth a from the
   * top edge along the centre line x = 0, which leaves the ligament b below
   * the notch. The two halves beside the notch are the appendages. The grid
   * is the rectangle itself (optionally with a margin of empty cells, see
   * Parameters::grid_margin), with one column of cells centred on x = 0: the
   * notch is the upper part of that column (cells without points), the
   * ligament its lower part, which is where cracks may form (the cells that
   * contain the centre line).
   *
   * Loads (displacement control, load factor t = load-point displacement in
   * metres): a pin at the top centre of each appendage that moves the top
   * grid nodes within half the "Load plate width" (2 cells by default) of
   * the load point together in x and holds the node at the load point in y,
   * so that it transmits no moment. The left pin is fixed, the right one
   * moves by t in +x. See add_supports() for why a pin of one node does not
   * work with one point per cell.
   *
   * The outer dimensions of the specimens of Wittmann et al. are not given
   * in the paper; the defaults follow ASTM E399-like proportions with a notch
   * as deep as the ligament: W = 2.4 b, a = b. W is rounded to an odd
   * number of cells (so that a column is centred on x = 0), and the load
   * points to the nearest grid node. In 3D the specimen is extruded through
   * the depth d in z (the loads act on lines of nodes); in 2D the depth only
   * scales the forces.
   */
  template <int dim>
  class CompactTensionGeometry
  {
  public:
    /**
     * The subsection "Compact tension" of a .prm file.
     */
    struct Parameters
    {
      /// Ligament length b (m).
      double ligament = 0.15;
      /// Specimen depth d (m).
      double depth = 0.12;
      /// Grid cell size h (m).
      double cell_size = 0.01;
      /// W / b.
      double width_ratio = 2.4;
      /// a / b: notch depth from the top edge over the ligament.
      double notch_ratio = 1.0;
      /// Width of the load pins in cells (plate_cells + 1 nodes each).
      unsigned int plate_cells = 2;
      /**
       * k: the crack-band cell at the back face (the bottom end of the
       * ligament) gets k times as many points along the ligament (y) as the
       * other cells; 1 fills it like every other cell. See setup().
       */
      unsigned int back_face_refinement = 1;
      /**
       * Empty grid cells around the specimen on all sides, so that points
       * may move out of the specimen's rectangle: the broken halves rotate
       * apart by several degrees when a run goes on to complete failure.
       * 0: the grid is the specimen.
       */
      unsigned int grid_margin = 0;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    explicit CompactTensionGeometry(const Parameters &parameters);

    /**
     * Set up @p problem for this specimen: the grid, the model (cracks only
     * in the cells on the centre line, smearing length from h; the model's
     * "Crack band width" must equal h), material points in the body with
     * @p points_per_direction^dim per cell, and the pins. Returns the index
     * of the pulled pin among the displacement conditions (see load()).
     *
     * <h4>The hinge at the back face</h4>
     * Once the crack has run through the ligament, the two halves rotate
     * apart about the lowest point of the crack band: with no load left, a
     * single point carries no stress, so it has zero strain. A relative
     * (opening) rotation theta about height y0 gives eps_xx = theta (y -
     * y0) / h at a band point at height y, zero only at y = y0; with one
     * point per cell the hinge is the point of the last (back-face) cell,
     * and the rotation is the hourglass mode of one-point quadrature in
     * that cell: the point never breaks, and its share of the
     * crack area, h d, is never dissipated (the work of the load at
     * complete failure is G_f (b - h) d instead of G_f b d). Only one point
     * can act as the hinge, so the missing share is that of the lowest
     * point. With back_face_refinement = k, the back-face band cell holds
     * n x (k n) points (n = @p points_per_direction; n x k n x n in 3D),
     * each of volume V_cell / (k n^dim): the missing share becomes at
     * most h / (k n) of b (with k > 1 the lowest point may fail as well in
     * the end; see the example compact_tension's documentation). The smearing
     * length of Decohesion is the band width h for every point, so each point
     * still dissipates G_f times its crack area (V_p / h) and the band as a
     * whole G_f b d less the hinge's share. There are only k - 1
     * extra points, but the small ones make the AMG-preconditioned GMRES
     * work harder (about 1.7 times the wall time for b = 15 cm, k = 8).
     */
    unsigned int
    setup(QuasiStaticProblem<dim>                        &problem,
          std::unique_ptr<Decohesion<dim>>                model,
          const unsigned int                              points_per_direction,
          const typename MaterialPointSet<dim>::Placement placement) const;

    /// The box grid: [-W/2, W/2] x [0, H] (x [0, d] in 3D), enlarged by
    /// grid_margin cells on the four sides in x and y.
    void
    make_grid(BackgroundGrid<dim> &grid) const;

    /// Whether @p x lies in the specimen (in the rectangle, not in the
    /// notch).
    bool
    in_body(const Point<dim> &x) const;

    /// Whether @p x lies in the cells that contain the centre line, where
    /// cracks are allowed.
    bool
    in_crack_band(const Point<dim> &x) const;

    /// Whether @p x lies in the crack-band cell(s) at the back face (the
    /// bottom row of the band, 0 < y < h), see setup().
    bool
    in_back_face_cell(const Point<dim> &x) const;

    /**
     * Add the two load pins to @p bcs, in this order: "left load point"
     * (u_x = 0 on the pin's nodes), "left load point y" (u_y = 0 at the load
     * point), "right load point" (u_x = t), "right load point y" (u_y = 0),
     * and return the index of "right load point" among
     * bcs.dirichlet_conditions().
     *
     * Each pin moves plate_cells + 1 top nodes in x. With one point per cell
     * (at the cell centre) and a single node per pin, the pins would sit on
     * nodes of opposite parity (a column is centred on x = 0), and a
     * translation by t/2 plus the checkerboard hourglass mode of one-point
     * quadrature with amplitude t/2 would satisfy both without any strain:
     * the specimen would carry no load. Only one node per pin is held in y,
     * so that the appendages can rotate about the pins.
     */
    unsigned int
    add_supports(BoundaryDescriptor<dim> &bcs) const;

    /**
     * The load P (N) for the full depth d from the reactions of the last
     * step: the x force the right load point exerts on the specimen.
     */
    double
    load(const std::vector<Tensor<1, dim>> &reactions,
         const unsigned int                 right_condition) const;

    /// Cell size h.
    double
    cell_size() const;
    /// Ligament b as discretized (a whole number of cells).
    double
    ligament() const;
    /// Depth d.
    double
    depth() const;
    /// Width W and height H of the grid.
    double
    width() const;
    double
    height() const;
    /// x coordinate of the right load point (the left one is at -x).
    double
    load_point_x() const;

  private:
    const Parameters parameters;
    unsigned int     n_x, n_ligament, n_notch;
  };
} // namespace qsmpm

#endif
