#ifndef qsmpm_grid_field_shape_values_h
#define qsmpm_grid_field_shape_values_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/fe/fe.h>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * The number of dofs of one body's field in a cell of the grid's finite
   * element @p fe (BackgroundGrid: dim components per body).
   */
  template <int dim>
  inline unsigned int
  field_dofs_per_cell(const FiniteElement<dim> &fe)
  {
    return fe.n_dofs_per_cell() / (fe.n_components() / dim);
  }

  /**
   * The Q1 functions of the field of body @p body at the reference point
   * @p xi of a cell with the dofs @p cell_dofs: appends, for each of the
   * field_dofs_per_cell() dofs of that field, its global index to @p dofs,
   * its direction (0 to dim - 1) to @p directions and N_i(xi) to
   * @p values. A load that acts through a material point (a rigid body's
   * contact, a surface traction) acts on the field of the point's body
   * only; with one body that is every dof of the cell.
   */
  template <int dim>
  inline void
  append_field_shape_values(
    const FiniteElement<dim>                   &fe,
    const std::vector<types::global_dof_index> &cell_dofs,
    const Point<dim>                           &xi,
    const unsigned int                          body,
    std::vector<types::global_dof_index>       &dofs,
    std::vector<unsigned int>                  &directions,
    std::vector<double>                        &values)
  {
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const unsigned int component = fe.system_to_component_index(i).first;
        if (component / dim != body)
          continue;
        dofs.push_back(cell_dofs[i]);
        directions.push_back(component % dim);
        values.push_back(fe.shape_value_component(i, xi, component));
      }
  }
} // namespace qsmpm

#endif
