#ifndef qsmpm_particles_shape_cache_h
#define qsmpm_particles_shape_cache_h

#include <Epetra_BlockMap.h>
#include <array>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/particles/affine_q1_cell.h>
#include <qsmpm/particles/material_point_set.h>
#include <vector>

namespace qsmpm
{
  /**
   * Shape-function values N_i(x_p) and gradients grad N_i(x_p) at all
   * locally owned material points, together with the degrees of freedom
   * they connect.
   *
   * Because the grid moves with the body during a load step, N_i(x_p^k) and
   * grad N_i(x_p^k) are the same for every residual evaluation of the step
   * (paper Section 2.3). They are computed once, by reinit(), at the start of
   * each step, and every residual evaluation, Jacobian-vector product,
   * tangent assembly and point update reads them from here.
   *
   * Points are grouped by the cell that holds them. Each group has a list of
   * nodes: with linear shape functions the cell's 2^dim vertices in
   * deal.II's order; with GIMP the nodes of the 3^dim cells around the cell
   * that some point of the group reaches (see
   * BackgroundGrid::node_block_dofs()). The degrees of freedom of a group
   * are numbered node by node: local dof i = node * dim + component. Each
   * point has a stencil of stencil_size(p) nodes (2^dim linear, up to 3^dim
   * GIMP: the nodes where its weight or gradient is non-zero), given as
   * indices into its group's node list, with the value and gradient of the
   * shape function of each.
   *
   * A GIMP domain that reaches across the grid's edge (a face of the box
   * that is not periodic) is cut there: the weights are the averages of the
   * shape functions over the part of the domain inside the grid. They stay
   * a partition of unity and their gradients sum to zero, so no load and no
   * internal force leaves through the edge; the point's volume is
   * unchanged, its material is taken to lie inside the grid.
   */
  template <int dim>
  class ShapeCache
  {
  public:
    static constexpr unsigned int n_vertices =
      GeometryInfo<dim>::vertices_per_cell;
    /// The largest stencil: 3^dim nodes (GIMP).
    static constexpr unsigned int max_stencil_size = dim == 2 ? 9 : 27;
    /// The largest number of dofs of a group: the 4^dim nodes of the block.
    static constexpr unsigned int max_dofs_per_group =
      BackgroundGrid<dim>::n_block_nodes * dim;
    /// The largest number of bodies of a multi-field grid.
    static constexpr unsigned int max_bodies = 8;

    /**
     * A group of points: the points [first_point, end_point) of @p body
     * in @p cell. With one body (the default) a group is a cell with
     * points; on a multi-field grid (BackgroundGrid::set_n_bodies()) each
     * body in a cell is a group of its own, whose dofs are that body's
     * field at the cell's nodes.
     */
    struct CellRange
    {
      typename Triangulation<dim>::active_cell_iterator cell;
      unsigned int                                      first_point;
      unsigned int                                      end_point;
      unsigned int                                      body = 0;
    };

    /**
     * On a multi-field grid: the body of each material id
     * (@p body_of_material[id]; numbers::invalid_unsigned_int for an id of
     * no body, which reinit() rejects). Empty (the default): one body.
     */
    void
    set_bodies(const std::vector<unsigned int> &body_of_material);

    /**
     * Recompute everything for the current point positions (and, with
     * cpGIMP, the points' current domains). @p ghosted is a vector with the
     * locally relevant layout of the grid; local_dofs() index its local
     * storage directly.
     */
    void
    reinit(const BackgroundGrid<dim>           &grid,
           MaterialPointSet<dim>               &points,
           const TrilinosWrappers::MPI::Vector &ghosted);

    /**
     * Release all memory. Once the points have moved (MaterialPointSet::
     * advect()), the values describe positions they no longer have, and
     * sorting them into their new cells moves their properties in memory,
     * so the property pointers would dangle: the cache is of no further use
     * until the next reinit(). Releasing its memory (about 40 bytes per
     * point in 2D and 60 in 3D on affine cells, more with GIMP) before the
     * points are sorted lowers the peak memory of a run, since deal.II's
     * sorting makes a copy of all particle data for a moment.
     */
    void
    clear();

    /**
     * A number that changes with every reinit() and clear(): who keeps
     * data derived from the cache (the residual's packed copy of the
     * committed point state) can tell whether it is still current.
     */
    unsigned long
    generation() const
    {
      return generation_count;
    }

    unsigned int
    n_cells() const
    {
      return cells.size();
    }

    unsigned int
    n_points() const
    {
      return point_properties.size();
    }

    /// The largest number of nodes of a point: 2^dim (linear) or 3^dim
    /// (GIMP).
    unsigned int
    stencil_size() const
    {
      return stencil;
    }

    /**
     * The number of nodes of point @p p: 2^dim (linear); with GIMP the
     * nodes with a non-zero weight or gradient, from 2^dim (a domain inside
     * its cell) to 3^dim.
     */
    unsigned int
    stencil_size(const unsigned int p) const
    {
      return point_stencil_sizes[p];
    }

    const CellRange &
    cell(const unsigned int c) const
    {
      return cells[c];
    }

    /**
     * With linear shape functions, the map of cell @p c if it is affine
     * (AffineQ1Cell: gradients and forces without the points' shape
     * gradients); nullptr on other cells and with GIMP.
     */
    const AffineQ1Cell<dim> *
    affine_cell(const unsigned int c) const
    {
      return cell_is_affine[c] ? &affine_cells[c] : nullptr;
    }

    /// The number of cells for which affine_cell() is not null.
    unsigned int
    n_affine_cells() const
    {
      return affine_cell_count;
    }

    /// Number of degrees of freedom of group @p c (nodes times dim).
    unsigned int
    n_dofs(const unsigned int c) const
    {
      return dof_offsets[c + 1] - dof_offsets[c];
    }

    /// Local indices (into the ghosted vector's storage) of group @p c.
    const int *
    local_dofs(const unsigned int c) const
    {
      return &cell_local_dofs[dof_offsets[c]];
    }

    /// Global indices of the degrees of freedom of group @p c.
    const types::global_dof_index *
    global_dofs(const unsigned int c) const
    {
      return &cell_global_dofs[dof_offsets[c]];
    }

    /**
     * The stencil of point @p p: indices into its group's node list (with
     * linear shape functions the cell's vertices 0..2^dim-1).
     */
    const unsigned short *
    nodes(const unsigned int p) const
    {
      return stencil == n_vertices ? vertex_nodes.data() :
                                     &stencil_nodes[p * stencil];
    }

    /// Room for the values of one point's stencil (see values()).
    using ValueBuffer = std::array<double, max_stencil_size>;
    /// Room for the gradients of one point's stencil (see gradients()).
    using GradientBuffer = std::array<Tensor<1, dim>, max_stencil_size>;

    /**
     * N_k(x_p) for the stencil nodes k = 0..stencil_size(p)-1 of point @p p
     * of cell @p c. They are stored for GIMP and for cells that are not
     * affine. On an affine cell with linear shape functions (every cell of
     * a box grid) nothing is stored per point, which halves the cache's
     * memory in 2D and takes two thirds off it in 3D: the values are
     * computed from the point's reference location into @p buffer
     * (AffineQ1Cell::shape_functions(), a few dozen flops), and the pointer
     * returned points there.
     */
    const double *
    values(const unsigned int c,
           const unsigned int p,
           ValueBuffer       &buffer) const
    {
      if (shape_offsets[c] == numbers::invalid_unsigned_int)
        {
          affine_cells[c].shape_functions(point_reference_locations[p],
                                          buffer.data(),
                                          nullptr);
          return buffer.data();
        }
      return &shape_values[stored_index(c, p) * stencil];
    }

    /// grad N_k(x_p), as values().
    const Tensor<1, dim> *
    gradients(const unsigned int c,
              const unsigned int p,
              GradientBuffer    &buffer) const
    {
      if (shape_offsets[c] == numbers::invalid_unsigned_int)
        {
          affine_cells[c].shape_functions(point_reference_locations[p],
                                          nullptr,
                                          buffer.data());
          return buffer.data();
        }
      return &shape_gradients[stored_index(c, p) * stencil];
    }

    /// Position x_p of point @p p at the start of the step.
    const Point<dim> &
    position(const unsigned int p) const
    {
      return point_positions[p];
    }

    /**
     * With linear shape functions, the reference location xi_p of point
     * @p p in its cell (for AffineQ1Cell); not kept with GIMP.
     */
    const Point<dim> &
    reference_location(const unsigned int p) const
    {
      return point_reference_locations[p];
    }

    /// The point's property array (see MaterialPointSet::Offsets), to read.
    const double *
    properties(const unsigned int p) const
    {
      return point_properties[p];
    }

    /**
     * The property arrays of points @p p, p + 1, ...: those of a cell's
     * points are consecutive (see PointStateBatch).
     */
    const double *const *
    property_arrays(const unsigned int p) const
    {
      return point_properties.data() + p;
    }

    /**
     * The same array, to write: the point state belongs to the point set,
     * so only who holds @p points, the writable set that reinit() read the
     * points from, may change it (QuasiStaticResidual::commit()). Evaluating
     * a residual, which must not change any point, has no such access.
     */
    double *
    properties(const unsigned int p, MaterialPointSet<dim> &points) const
    {
      Assert(&points == point_set,
             ExcMessage("The points are not those of the ShapeCache."));
      (void)points;
      return point_properties[p];
    }

    /**
     * The locally relevant degrees of freedom whose nodes have no material
     * point in their support on any rank. They have no equation and must be
     * constrained (paper Section 2.2).
     *
     * With @p min_nodal_volume > 0 also the nodes whose support holds less
     * material than that, measured as sum_p Omega_p N_i(x_p) with the point
     * volumes at offset @p volume_offset of the point properties. A node that
     * a GIMP domain only just reaches has a stiffness of the order of the
     * square of the overlap; such rows make Newton's linear systems nearly
     * singular (most of all with F-bar, which leaves one volumetric
     * constraint per cell). Holding them fixed for one step is the
     * inactive-node treatment of the paper applied to nearly empty nodes.
     * With @p per_radian (axisymmetry, volumes r dA per radian) the
     * measure is the area sum_p Omega_p / r_p N_i(x_p), so that the same
     * threshold means the same at every radius.
     */
    IndexSet
    dofs_without_points(const BackgroundGrid<dim> &grid,
                        const unsigned int         volume_offset    = 0,
                        const double               min_nodal_volume = 0.,
                        const bool                 per_radian = false) const;

    /**
     * The material in the support of each degree of freedom, sum_p Omega_p
     * N_i(x_p) over the points of the dof's body (the same for each
     * direction of a node), with the point volumes at offset
     * @p volume_offset of the point properties (per radian divided by r_p
     * with @p per_radian, as above); summed over the ranks, on the locally
     * owned dofs.
     */
    TrilinosWrappers::MPI::Vector
    nodal_volumes(const BackgroundGrid<dim> &grid,
                  const unsigned int         volume_offset,
                  const bool                 per_radian = false) const;

    /**
     * Interpolate a nodal vector (ghosted storage @p local_values) at point
     * @p p of group @p c: sum_k v_k N_k(x_p).
     */
    Tensor<1, dim>
    interpolate(const unsigned int c,
                const unsigned int p,
                const double      *local_values) const;

  private:
    /// The place of point @p p of cell @p c in the stored values.
    unsigned int
    stored_index(const unsigned int c, const unsigned int p) const
    {
      return shape_offsets[c] + (p - cells[c].first_point);
    }

    /// Linear shape functions of the point's cell.
    void
    add_linear_cell(const typename DoFHandler<dim>::active_cell_iterator &cell,
                    const BackgroundGrid<dim>                            &grid,
                    const Epetra_BlockMap                                &map,
                    unsigned int                                         &p,
                    Particles::ParticleHandler<dim> &particle_handler,
                    const unsigned int               body,
                    const unsigned int               n_points);

    /// The body of a point with properties @p data (0 with one body).
    unsigned int
    body_of(const double *data) const;

    /// See set_bodies().
    std::vector<unsigned int> body_of_material;
    /// Offset of the material id in the point properties (reinit()).
    unsigned int material_id_offset = 0;

    /// GIMP weights over the 3^dim cells around the point's cell, for the
    /// points of @p body in it (all points with one body); domains cut at
    /// the grid's edge.
    void
    add_gimp_cell(const typename DoFHandler<dim>::active_cell_iterator &cell,
                  const BackgroundGrid<dim>                            &grid,
                  const MaterialPointSet<dim>                          &points,
                  const Epetra_BlockMap                                &map,
                  unsigned int                                         &p,
                  Particles::ParticleHandler<dim> &particle_handler,
                  const unsigned int               body);

    unsigned long                        generation_count  = 0;
    unsigned int                         affine_cell_count = 0;
    unsigned int                         stencil           = n_vertices;
    std::vector<CellRange>               cells;
    std::vector<AffineQ1Cell<dim>>       affine_cells;
    std::vector<unsigned char>           cell_is_affine;
    std::vector<unsigned int>            dof_offsets;
    std::vector<int>                     cell_local_dofs;
    std::vector<types::global_dof_index> cell_global_dofs;
    /// Per cell: the stored index of its first point (stored_index()),
    /// or invalid if its points' shape functions are not stored.
    std::vector<unsigned int>   shape_offsets;
    std::vector<unsigned short> stencil_nodes;
    /// 0, 1, ..., 2^dim - 1: the stencil of every point with linear shape
    /// functions.
    static constexpr std::array<unsigned short, n_vertices> vertex_nodes = [] {
      std::array<unsigned short, n_vertices> v{};
      for (unsigned int i = 0; i < n_vertices; ++i)
        v[i] = i;
      return v;
    }();
    std::vector<unsigned char>  point_stencil_sizes;
    std::vector<double>         shape_values;
    std::vector<Tensor<1, dim>> shape_gradients;
    std::vector<double *>       point_properties;
    /// The point set of the last reinit(), whose properties these are.
    const MaterialPointSet<dim> *point_set = nullptr;
    std::vector<Point<dim>>      point_positions;
    std::vector<Point<dim>>      point_reference_locations;
    /// Scratch of add_gimp_cell().
    std::vector<types::global_dof_index> block_dofs;
    /// Scratch of add_linear_cell(): the values and reference gradients of
    /// all Q1 shape functions at one point (one call of the FE's
    /// polynomial space instead of one per shape function), and the unused
    /// higher derivatives.
    std::vector<double>         q1_values;
    std::vector<Tensor<1, dim>> q1_gradients;
    std::vector<Tensor<2, dim>> q1_unused_2;
    std::vector<Tensor<3, dim>> q1_unused_3;
    std::vector<Tensor<4, dim>> q1_unused_4;
  };
} // namespace qsmpm

#endif
