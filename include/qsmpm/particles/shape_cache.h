#ifndef qsmpm_particles_shape_cache_h
#define qsmpm_particles_shape_cache_h

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/particles/material_point_set.h>
#include <vector>

namespace qsmpm
{
  /**
   * Shape-function values N_i(x_p) and gradients grad N_i(x_p) at all
   * locally owned material points, together with the cells' degrees of
   * freedom.
   *
   * Because the grid moves with the body during a load step, N_i(x_p^k) and
   * grad N_i(x_p^k) are the same for every residual evaluation of the step
   * (paper Section 2.3). They are computed once, by reinit(), at the start of
   * each step, and every residual evaluation, Jacobian-vector product,
   * tangent assembly and point update reads them from here.
   *
   * Data are stored in flat arrays, cell by cell; inside a cell the local
   * degree of freedom i = v * dim + c belongs to vertex v and component c.
   */
  template <int dim>
  class ShapeCache
  {
  public:
    static constexpr unsigned int n_vertices =
      GeometryInfo<dim>::vertices_per_cell;
    static constexpr unsigned int dofs_per_cell = dim * n_vertices;

    /// A cell holding points: its points are [first_point, end_point).
    struct CellRange
    {
      typename Triangulation<dim>::active_cell_iterator cell;
      unsigned int                                      first_point;
      unsigned int                                      end_point;
    };

    /**
     * Recompute everything for the current point positions. @p ghosted is a
     * vector with the locally relevant layout of the grid; local_dofs()
     * index its local storage directly.
     */
    void
    reinit(const BackgroundGrid<dim>           &grid,
           MaterialPointSet<dim>               &points,
           const TrilinosWrappers::MPI::Vector &ghosted);

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

    const CellRange &
    cell(const unsigned int c) const
    {
      return cells[c];
    }

    /// Local indices (into the ghosted vector's storage) of cell @p c.
    const int *
    local_dofs(const unsigned int c) const
    {
      return &cell_local_dofs[c * dofs_per_cell];
    }

    /// Global indices of the degrees of freedom of cell @p c.
    const types::global_dof_index *
    global_dofs(const unsigned int c) const
    {
      return &cell_global_dofs[c * dofs_per_cell];
    }

    /// N_v(x_p), v = 0..n_vertices-1.
    const double *
    values(const unsigned int p) const
    {
      return &shape_values[p * n_vertices];
    }

    /// grad N_v(x_p), v = 0..n_vertices-1.
    const Tensor<1, dim> *
    gradients(const unsigned int p) const
    {
      return &shape_gradients[p * n_vertices];
    }

    /// Position x_p of point @p p at the start of the step.
    const Point<dim> &
    position(const unsigned int p) const
    {
      return point_positions[p];
    }

    /// The point's property array (see MaterialPointSet::Offsets).
    double *
    properties(const unsigned int p) const
    {
      return point_properties[p];
    }

    /**
     * The locally relevant degrees of freedom whose nodes have no material
     * point in their support on any rank. They have no equation and must be
     * constrained (paper Section 2.2).
     */
    IndexSet
    dofs_without_points(const BackgroundGrid<dim> &grid) const;

    /**
     * Interpolate a nodal vector (ghosted storage @p local_values) at point
     * @p p of cell @p c: sum_i v_i N_i(x_p).
     */
    Tensor<1, dim>
    interpolate(const unsigned int c,
                const unsigned int p,
                const double      *local_values) const;

  private:
    std::vector<CellRange>               cells;
    std::vector<int>                     cell_local_dofs;
    std::vector<types::global_dof_index> cell_global_dofs;
    std::vector<double>                  shape_values;
    std::vector<Tensor<1, dim>>          shape_gradients;
    std::vector<double *>                point_properties;
    std::vector<Point<dim>>              point_positions;
  };
} // namespace qsmpm

#endif
