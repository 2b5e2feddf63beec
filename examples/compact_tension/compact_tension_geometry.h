/* ---------------------------------------------------------------------
 *
 * qsmpm example: compact_tension -- the specimen
 *
 * The compact-tension specimen of the example compact_tension (paper
 * Section 3): grid, body, crack band and load pins. It is not part of the
 * library: it belongs to this one example, and it is header-only so that
 * the example builds from its own directory (also when installed, see
 * share/qsmpm/examples/compact_tension/CMakeLists.txt). The tests
 * cts_coarse and checkpoint_restart include it from here
 * (tests/CMakeLists.txt puts examples/compact_tension/ on their include
 * path).
 *
 * ---------------------------------------------------------------------
 */
#ifndef qsmpm_examples_compact_tension_geometry_h
#define qsmpm_examples_compact_tension_geometry_h

#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <limits>
#include <memory>
#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/loading/boundary_descriptor.h>
#include <qsmpm/materials/decohesion.h>
#include <qsmpm/materials/smeared_cracks.h>
#include <string>
#include <utility>
#include <vector>

namespace CompactTension
{
  using namespace dealii;
  using namespace qsmpm;

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
    struct Parameters : ParameterStruct<Parameters>
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
      /**
       * Where cracks may start: "centre line", the cells that contain the
       * centre line below the notch (the paper), or "everywhere", the whole
       * specimen but the cells at the pins (see in_cracking_region()).
       */
      std::string cracking_region = "centre line";

      /// Declare the entries of the subsection, bound to the members
      /// (ParameterHandler::add_parameter(); the initializers above are
      /// the defaults). ParameterStruct adds declare_parameters() and
      /// parse_parameters().
      void
      add_parameters(ParameterHandler &prm);
    };

    explicit CompactTensionGeometry(const Parameters &parameters);

    /**
     * Set up @p problem for this specimen: the grid, the model (Decohesion
     * or SmearedCracks, cracks only in the cracking region, see
     * in_cracking_region(); the model's "Crack band width" must equal h,
     * the smearing length of a crack along a cell edge), material points
     * in the body with
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
          std::unique_ptr<ConstitutiveModel<dim>>         model,
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

    /**
     * Whether a crack may start at @p x: with `Cracking region = centre
     * line` in the crack band (in_crack_band()); with `everywhere` in the
     * whole specimen but within two cells of a pin's nodes. The pins hold
     * single grid nodes, whose corners concentrate stress as no real
     * loading pin (a bolt through a hole) does; a crack that started there
     * would not be part of the test.
     */
    bool
    in_cracking_region(const Point<dim> &x) const;

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

    /**
     * The number of crack-band points of @p problem and of those that have
     * failed completely (Decohesion: [[u_n]] >= u0; SmearedCracks: a crack
     * that has dissipated G_f), summed over @p communicator; the
     * lowest band point, the hinge (see setup()), is counted in neither.
     * The band is broken once both numbers are equal (and not zero).
     *
     * By then the points have moved by millimetres (the centre line by
     * half the load-point displacement), so the band points are those that
     * started in the band, x - u, and the hinge is the one that was lowest
     * at the start.
     */
    std::pair<unsigned int, unsigned int>
    count_failed_band_points(const QuasiStaticProblem<dim> &problem,
                             const MPI_Comm                 communicator) const;

    /**
     * With the SmearedCracks model: the energy (J, for the depth d) the
     * points' cracks have dissipated, on the centre line (the points that
     * started in the crack band: the main crack) and elsewhere, summed
     * over @p communicator. A crack dissipates D per unit crack area (see
     * SmearedCracks::crack_summaries()) over the crack area V / L of its
     * point (V its volume, L the smearing length); in 2D the volumes are
     * areas and the depth d makes the energy. {0, 0} with Decohesion.
     */
    std::pair<double, double>
    crack_dissipation(const QuasiStaticProblem<dim> &problem,
                      const MPI_Comm                 communicator) const;

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



  namespace internal
  {
    /// u_x = t (the load factor), the other components zero.
    template <int dim>
    class LoadPointDisplacement : public Function<dim>
    {
    public:
      LoadPointDisplacement()
        : Function<dim>(dim)
      {
      }
      double
      value(const Point<dim> &, const unsigned int component) const override
      {
        return component == 0 ? this->get_time() : 0.;
      }
    };
  } // namespace internal



  template <int dim>
  void
  CompactTensionGeometry<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Compact tension");
    {
      prm.add_parameter("Ligament length",
                        ligament,
                        "b (m): the uncracked length below the notch tip. "
                        "Rounded to a whole number of cells.",
                        Patterns::Double(0.));
      prm.add_parameter("Depth",
                        depth,
                        "d (m): specimen thickness. In 2D it only scales the "
                        "load P.",
                        Patterns::Double(0.));
      prm.add_parameter("Cell size",
                        cell_size,
                        "h (m): size of the square grid cells; also the notch "
                        "width and the width of the crack band.",
                        Patterns::Double(0.));
      prm.add_parameter("Width over ligament",
                        width_ratio,
                        "W / b: specimen width (in x, across the notch) over "
                        "the ligament. The original dimensions are unknown; "
                        "2.4 is the ASTM E399 ratio 1.2 W_astm / (W_astm - a) "
                        "with a = W_astm / 2.",
                        Patterns::Double(0.));
      prm.add_parameter("Load plate width",
                        plate_cells,
                        "Width, in cells, of the rigid pin at the top centre "
                        "of each appendage: the top nodes within half of it "
                        "from the load point are displaced together. At least "
                        "1 (two nodes) with one point per cell, see "
                        "CompactTensionGeometry::add_supports().",
                        Patterns::Integer(1));
      prm.add_parameter(
        "Back-face point refinement",
        back_face_refinement,
        "k: the crack-band cell at the back face (the end of the ligament) "
        "gets k times as many material points along the ligament (y) as "
        "the other cells, e.g. 1 x k with one point per cell. Its lowest "
        "point is the hinge about which the broken specimen rotates and "
        "which never breaks (a zero-strain mode at that point), so the "
        "crack area that is never dissipated shrinks from h d to h d / k "
        "(with one point per cell). 1: the paper's one point per cell.",
        Patterns::Integer(1, 64));
      prm.add_parameter(
        "Grid margin",
        grid_margin,
        "Number of empty grid cells added around the specimen on all four "
        "sides, so that points may leave the specimen's rectangle: needed "
        "when the broken halves rotate apart by degrees (Run to complete "
        "failure). 0: the grid is the specimen.",
        Patterns::Integer(0, 100));
      prm.add_parameter(
        "Cracking region",
        cracking_region,
        "Where cracks may start. centre line: the cells that contain the "
        "centre line below the notch (the paper, Section 3.3). everywhere: "
        "the whole specimen but two cells around each pin's nodes (the "
        "smeared cracks model, which finds the cracks' normals itself).",
        Patterns::Selection("centre line|everywhere"));
      prm.add_parameter("Notch depth over ligament",
                        notch_ratio,
                        "a / b: depth of the notch from the top edge over the "
                        "ligament; the specimen height is a + b.",
                        Patterns::Double(0.));
    }
    prm.leave_subsection();
  }



  template <int dim>
  CompactTensionGeometry<dim>::CompactTensionGeometry(
    const Parameters &parameters)
    : parameters(parameters)
  {
    const double h = parameters.cell_size;
    AssertThrow(h > 0,
                ExcMessage("Compact tension: <Cell size> must be positive."));
    AssertThrow(parameters.ligament >= 2 * h,
                ExcMessage("Compact tension: <Ligament length> = " +
                           std::to_string(parameters.ligament) +
                           " m must span at least two cells of <Cell size> "
                           "= " +
                           std::to_string(h) + " m."));
    n_ligament = static_cast<unsigned int>(std::round(parameters.ligament / h));
    n_notch    = static_cast<unsigned int>(
      std::round(parameters.notch_ratio * parameters.ligament / h));
    // An odd number of columns, so that one is centred on x = 0.
    n_x =
      2 * static_cast<unsigned int>(std::round(
            0.5 * (parameters.width_ratio * parameters.ligament / h - 1.))) +
      1;
    // Each check names the entry to change; the patterns of the entries
    // only exclude negative numbers.
    AssertThrow(parameters.depth > 0,
                ExcMessage("Compact tension: <Depth> must be positive, got " +
                           std::to_string(parameters.depth) +
                           " (the load is the reaction per unit depth times "
                           "the depth)."));
    AssertThrow(n_notch >= 1,
                ExcMessage("Compact tension: <Notch depth over ligament> = " +
                           std::to_string(parameters.notch_ratio) +
                           " gives a notch less than one cell (<Cell size>) "
                           "deep."));
    AssertThrow(n_x >= 5,
                ExcMessage("Compact tension: <Width over ligament> = " +
                           std::to_string(parameters.width_ratio) +
                           " gives a specimen less than five cells wide."));
    // The pins must lie on the top of their appendage: a plate wider than
    // an appendage would reach across the notch (tying both appendages
    // together) or beyond the specimen. The appendage on the right spans
    // [h/2, W/2], the plate half its width on either side of the load
    // point.
    const double half_plate = 0.5 * parameters.plate_cells * h;
    AssertThrow(load_point_x() - half_plate > 0.5 * h - 1e-6 * h &&
                  load_point_x() + half_plate < 0.5 * width() + 1e-6 * h,
                ExcMessage(
                  "Compact tension: <Load plate width> = " +
                  std::to_string(parameters.plate_cells) +
                  " cells is wider than an appendage allows (" +
                  std::to_string(static_cast<unsigned int>(
                    std::round(2 *
                               std::min(load_point_x() - 0.5 * h,
                                        0.5 * width() - load_point_x()) /
                               h))) +
                  " cells at most for this <Width over ligament> and <Cell "
                  "size>): the pin would reach across the notch or beyond "
                  "the specimen."));
  }



  template <int dim>
  void
  CompactTensionGeometry<dim>::make_grid(BackgroundGrid<dim> &grid) const
  {
    const double                  h = parameters.cell_size;
    const unsigned int            m = parameters.grid_margin;
    Point<dim>                    lower, upper;
    std::array<unsigned int, dim> subdivisions;
    lower[0]        = -0.5 * width() - m * h;
    upper[0]        = 0.5 * width() + m * h;
    subdivisions[0] = n_x + 2 * m;
    lower[1]        = -(m * h);
    upper[1]        = height() + m * h;
    subdivisions[1] = n_ligament + n_notch + 2 * m;
    if (dim == 3)
      {
        subdivisions[dim - 1] =
          std::max(1u,
                   static_cast<unsigned int>(std::round(parameters.depth / h)));
        upper[dim - 1] = parameters.depth;
      }
    grid.make_box(lower, upper, subdivisions);
  }



  template <int dim>
  unsigned int
  CompactTensionGeometry<dim>::setup(
    QuasiStaticProblem<dim>                        &problem,
    std::unique_ptr<ConstitutiveModel<dim>>         model,
    const unsigned int                              points_per_direction,
    const typename MaterialPointSet<dim>::Placement placement) const
  {
    Tensor<1, dim> x_normal;
    x_normal[0]       = 1.;
    const auto region = [this](const Point<dim> &x) {
      return in_cracking_region(x);
    };
    double smearing = 0.;
    if (auto *decohesion = dynamic_cast<Decohesion<dim> *>(model.get()))
      {
        smearing = decohesion->smearing_length(x_normal);
        decohesion->set_crack_region(region);
      }
    else if (auto *cracks = dynamic_cast<SmearedCracks<dim> *>(model.get()))
      {
        smearing = cracks->smearing_length(x_normal);
        cracks->set_crack_region(region);
      }
    else
      AssertThrow(false,
                  ExcMessage("Compact tension: the material model must be "
                             "<decohesion> or <smeared cracks>, not <" +
                             model->name() + ">."));
    AssertThrow(std::abs(smearing - cell_size()) <= 1e-12 * cell_size(),
                ExcMessage("Compact tension: the model's 'Crack band width' "
                           "must equal the cell size h."));
    make_grid(problem.grid());
    problem.set_model(std::move(model));
    // The body, and the back-face band cell with k times as many points
    // along y (see the class documentation on the hinge); with k = 1 the
    // second call fills that cell like the others.
    problem.points().fill(
      [this](const Point<dim> &x) {
        return in_body(x) && !in_back_face_cell(x);
      },
      points_per_direction,
      placement);
    std::array<unsigned int, dim> n_back_face;
    n_back_face.fill(points_per_direction);
    n_back_face[1] *= parameters.back_face_refinement;
    problem.points().fill(
      [this](const Point<dim> &x) { return in_back_face_cell(x); },
      MaterialPointSet<dim>::reference_rule(placement, n_back_face));
    return add_supports(problem.boundary_conditions());
  }



  template <int dim>
  bool
  CompactTensionGeometry<dim>::in_body(const Point<dim> &x) const
  {
    const bool in_rectangle =
      std::abs(x[0]) < 0.5 * width() && x[1] > 0. && x[1] < height();
    return in_rectangle && !(in_crack_band(x) && x[1] > ligament());
  }



  template <int dim>
  bool
  CompactTensionGeometry<dim>::in_crack_band(const Point<dim> &x) const
  {
    return std::abs(x[0]) < 0.5 * parameters.cell_size;
  }



  template <int dim>
  bool
  CompactTensionGeometry<dim>::in_cracking_region(const Point<dim> &x) const
  {
    if (parameters.cracking_region == "centre line")
      return in_crack_band(x);
    const double h       = parameters.cell_size;
    const double reach_x = (0.5 * parameters.plate_cells + 2.) * h;
    return !(std::abs(std::abs(x[0]) - load_point_x()) < reach_x &&
             x[1] > height() - 2. * h);
  }



  template <int dim>
  bool
  CompactTensionGeometry<dim>::in_back_face_cell(const Point<dim> &x) const
  {
    return in_crack_band(x) && x[1] > 0. && x[1] < parameters.cell_size;
  }



  template <int dim>
  unsigned int
  CompactTensionGeometry<dim>::add_supports(BoundaryDescriptor<dim> &bcs) const
  {
    const double tolerance = 1e-6 * parameters.cell_size;
    const double x_load = load_point_x(), y_top = height();
    // Each pin moves the top nodes within half the plate width of the load
    // point (2 cells: 3 nodes by default) together in x, and holds only the
    // node at the load point in y. It thus transmits no moment: the
    // appendages may rotate about their pins, which they must do once the
    // ligament has broken (a pin fixed in y at all its nodes would clamp
    // them and the load would rise again). A single node in x does not work
    // with one point per cell: both pins would sit on nodes of opposite
    // parity, and a translation in x plus the zero-energy checkerboard
    // (hourglass) mode of one-point quadrature would satisfy both without
    // any strain -- the specimen would carry no load.
    const double half_plate =
      (0.5 * parameters.plate_cells + 1e-6) * parameters.cell_size;
    std::array<bool, dim> x_only{}, y_only{};
    x_only[0]         = true;
    y_only[1]         = true;
    const auto zero   = std::make_shared<Functions::ZeroFunction<dim>>(dim);
    const auto on_pin = [=](const double x_centre, const double half_width) {
      return [=](const Point<dim> &p) {
        return std::abs(p[0] - x_centre) < half_width &&
               std::abs(p[1] - y_top) < tolerance;
      };
    };
    // Left pin: fixed.
    bcs.add_dirichlet_nodes("left load point",
                            on_pin(-x_load, half_plate),
                            x_only,
                            zero);
    bcs.add_dirichlet_nodes("left load point y",
                            on_pin(-x_load, tolerance),
                            y_only,
                            zero);
    // Right pin: u_x = t, u_y = 0.
    const unsigned int right = bcs.dirichlet_conditions().size();
    bcs.add_dirichlet_nodes(
      "right load point",
      on_pin(x_load, half_plate),
      x_only,
      std::make_shared<internal::LoadPointDisplacement<dim>>());
    bcs.add_dirichlet_nodes("right load point y",
                            on_pin(x_load, tolerance),
                            y_only,
                            zero);
    return right;
  }



  template <int dim>
  double
  CompactTensionGeometry<dim>::load(
    const std::vector<Tensor<1, dim>> &reactions,
    const unsigned int                 right_condition) const
  {
    AssertThrow(right_condition < reactions.size(),
                ExcMessage("Compact tension: no reaction of the load point."));
    // In 2D the point volumes are areas: forces per unit depth.
    return reactions[right_condition][0] * (dim == 2 ? parameters.depth : 1.);
  }



  template <int dim>
  std::pair<unsigned int, unsigned int>
  CompactTensionGeometry<dim>::count_failed_band_points(
    const QuasiStaticProblem<dim> &problem,
    const MPI_Comm                 communicator) const
  {
    const auto       &points  = problem.points();
    const auto       &offsets = points.get_offsets();
    const auto *const decohesion =
      dynamic_cast<const Decohesion<dim> *>(&points.get_model());
    const auto *const cracks_model =
      dynamic_cast<const SmearedCracks<dim> *>(&points.get_model());
    AssertThrow(decohesion != nullptr || cracks_model != nullptr,
                ExcMessage("Compact tension: the material model must be "
                           "<decohesion> or <smeared cracks>."));
    const unsigned int opening =
      decohesion != nullptr ?
        points.get_layout().offset(Decohesion<dim>::crack_opening_name) :
        0;
    std::array<typename SmearedCracks<dim>::CrackSummary, dim> cracks;
    const auto failed = [&](const auto &particle) {
      const auto data = particle.get_properties();
      if (decohesion != nullptr)
        return data[opening] / decohesion->critical_opening() >= 1.;
      const unsigned int n =
        cracks_model->crack_summaries({data.data() + offsets.state,
                                       cracks_model->n_state_components()},
                                      cracks);
      for (unsigned int k = 0; k < n; ++k)
        if (cracks[k].dissipated >=
            (1. - 1e-9) * cracks_model->fracture_energy())
          return true;
      return false;
    };
    double lowest = std::numeric_limits<double>::max();
    for (const auto &particle : points.get_particle_handler())
      {
        const Point<dim> x0 = points.initial_location(particle);
        if (in_crack_band(x0))
          lowest = std::min(lowest, x0[1]);
      }
    lowest              = Utilities::MPI::min(lowest, communicator);
    unsigned int n_band = 0, n_failed = 0;
    for (const auto &particle : points.get_particle_handler())
      {
        const Point<dim> x0 = points.initial_location(particle);
        if (in_crack_band(x0) && x0[1] > lowest + 1e-6 * cell_size())
          {
            ++n_band;
            if (failed(particle))
              ++n_failed;
          }
      }
    return {Utilities::MPI::sum(n_band, communicator),
            Utilities::MPI::sum(n_failed, communicator)};
  }



  template <int dim>
  std::pair<double, double>
  CompactTensionGeometry<dim>::crack_dissipation(
    const QuasiStaticProblem<dim> &problem,
    const MPI_Comm                 communicator) const
  {
    const auto *model =
      dynamic_cast<const SmearedCracks<dim> *>(&problem.points().get_model());
    if (model == nullptr)
      return {0., 0.};
    const auto &offsets = problem.points().get_offsets();
    std::array<typename SmearedCracks<dim>::CrackSummary, dim> cracks;
    double main = 0., beside = 0.;
    for (const auto &particle : problem.points().get_particle_handler())
      {
        const auto         data  = particle.get_properties();
        const unsigned int count = model->crack_summaries(
          {data.data() + offsets.state, model->n_state_components()}, cracks);
        const bool main_crack =
          in_crack_band(problem.points().initial_location(particle));
        for (unsigned int k = 0; k < count; ++k)
          (main_crack ? main : beside) += cracks[k].dissipated /
                                          cracks[k].length *
                                          data[offsets.initial_volume];
      }
    const double depth = dim == 2 ? parameters.depth : 1.;
    return {Utilities::MPI::sum(main, communicator) * depth,
            Utilities::MPI::sum(beside, communicator) * depth};
  }



  template <int dim>
  double
  CompactTensionGeometry<dim>::cell_size() const
  {
    return parameters.cell_size;
  }



  template <int dim>
  double
  CompactTensionGeometry<dim>::ligament() const
  {
    return n_ligament * parameters.cell_size;
  }



  template <int dim>
  double
  CompactTensionGeometry<dim>::depth() const
  {
    return parameters.depth;
  }



  template <int dim>
  double
  CompactTensionGeometry<dim>::width() const
  {
    return n_x * parameters.cell_size;
  }



  template <int dim>
  double
  CompactTensionGeometry<dim>::height() const
  {
    return (n_ligament + n_notch) * parameters.cell_size;
  }



  template <int dim>
  double
  CompactTensionGeometry<dim>::load_point_x() const
  {
    // The middle of an appendage, [h/2, W/2], snapped to a grid node (nodes
    // lie at x = (k + 1/2) h).
    const double h = parameters.cell_size;
    const double x = 0.25 * (width() + h);
    return (std::round(x / h - 0.5) + 0.5) * h;
  }



} // namespace CompactTension

#endif
