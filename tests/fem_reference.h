// An independent reference for the tests: the standard finite-element
// stiffness and body-force vector of linear elasticity, assembled with
// deal.II's FEValues on a serial DoFHandler, sharing no code with qsmpm.
#ifndef qsmpm_tests_fem_reference_h
#define qsmpm_tests_fem_reference_h

#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <functional>
#include <vector>

namespace FEM
{
  using namespace dealii;

  /**
   * K = sum_cells int eps(N_i) : C : eps(N_j), f = int N_i . b, condensed
   * with @p constraints, quadrature @p quadrature. @p add_cell_loads, if
   * given, adds further loads of a cell (e.g. tractions on its faces) to
   * the cell vector before it is distributed.
   */
  template <int dim>
  void
  assemble_elasticity(const DoFHandler<dim>           &dof_handler,
                      const Quadrature<dim>           &quadrature,
                      const SymmetricTensor<4, dim>   &C,
                      const Tensor<1, dim>            &body_force,
                      const AffineConstraints<double> &constraints,
                      SparseMatrix<double>            &K,
                      Vector<double>                  &f,
                      const std::function<void(
                        const typename DoFHandler<dim>::active_cell_iterator &,
                        Vector<double> &)>            &add_cell_loads = {})
  {
    const auto   &fe = dof_handler.get_fe();
    FEValues<dim> fe_values(
      fe, quadrature, update_values | update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     u(0);
    const unsigned int                   n = fe.dofs_per_cell;
    FullMatrix<double>                   K_cell(n, n);
    Vector<double>                       f_cell(n);
    std::vector<types::global_dof_index> dofs(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        K_cell = 0;
        f_cell = 0;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          for (unsigned int i = 0; i < n; ++i)
            {
              const auto eps_i = fe_values[u].symmetric_gradient(i, q);
              for (unsigned int j = 0; j < n; ++j)
                K_cell(i, j) += eps_i * C *
                                fe_values[u].symmetric_gradient(j, q) *
                                fe_values.JxW(q);
              f_cell(i) +=
                fe_values[u].value(i, q) * body_force * fe_values.JxW(q);
            }
        if (add_cell_loads)
          add_cell_loads(cell, f_cell);
        cell->get_dof_indices(dofs);
        constraints.distribute_local_to_global(K_cell, f_cell, dofs, K, f);
      }
  }
} // namespace FEM

#endif
