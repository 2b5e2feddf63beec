#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <qsmpm/assembly/tangent_assembler.h>
#include <qsmpm/base/utilities.h>

namespace qsmpm
{
  template <int dim>
  void
  TangentAssembler<dim>::reinit(const BackgroundGrid<dim> &grid)
  {
    // Displacement conditions only fix values, but periodicity constraints
    // couple the nodes of opposite faces: condensing them adds the slave's
    // couplings to its master's row. Those are the only couplings that do
    // not change from step to step, so this pattern serves every step.
    AffineConstraints<double> periodicity(grid.locally_relevant_dofs());
    grid.make_periodicity_constraints(periodicity);
    periodicity.close();
    IndexSet writable_rows = grid.locally_relevant_dofs();
    for (const auto &line : periodicity.get_lines())
      for (const auto &entry : line.entries)
        writable_rows.add_index(entry.first);
    writable_rows.compress();
    TrilinosWrappers::SparsityPattern pattern(grid.locally_owned_dofs(),
                                              grid.locally_owned_dofs(),
                                              writable_rows,
                                              grid.get_communicator());
    DoFTools::make_sparsity_pattern(grid.get_dof_handler(),
                                    pattern,
                                    periodicity,
                                    /*keep_constrained_dofs=*/true,
                                    dealii::Utilities::MPI::this_mpi_process(
                                      grid.get_communicator()));
    pattern.compress();
    K.reinit(pattern);
  }



  template <int dim>
  void
  TangentAssembler<dim>::assemble(const BackgroundGrid<dim>       &grid,
                                  const MaterialPointSet<dim>     &points,
                                  const ShapeCache<dim>           &cache,
                                  const AffineConstraints<double> &constraints)
  {
    constexpr unsigned int n_vertices    = ShapeCache<dim>::n_vertices;
    constexpr unsigned int dofs_per_cell = ShapeCache<dim>::dofs_per_cell;
    const auto            &offsets       = points.get_offsets();
    const auto            &model         = points.get_model();
    const unsigned int     n_state       = model.n_state_components();

    K = 0;
    FullMatrix<double>                   K_cell(dofs_per_cell, dofs_per_cell);
    std::vector<types::global_dof_index> dofs(dofs_per_cell);
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        K_cell            = 0;
        const auto &range = cache.cell(c);
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const double         *data   = cache.properties(p);
            const Tensor<1, dim> *grad_N = cache.gradients(p);
            const PointState<dim> state{
              Utils::read_symmetric<dim>(data + offsets.strain),
              Utils::read_symmetric<dim>(data + offsets.stress),
              ArrayView<const double>(data + offsets.state, n_state),
              data[offsets.volume]};
            const Tensor<4, dim> C      = Tensor<4, dim>(model.tangent(state));
            const double         volume = data[offsets.volume];
            // K_(v,a),(w,b) = Omega sum_kl dN_v/dx_k C_akbl dN_w/dx_l
            for (unsigned int v = 0; v < n_vertices; ++v)
              for (unsigned int w = 0; w < n_vertices; ++w)
                for (unsigned int a = 0; a < dim; ++a)
                  for (unsigned int b = 0; b < dim; ++b)
                    {
                      double sum = 0;
                      for (unsigned int k = 0; k < dim; ++k)
                        for (unsigned int l = 0; l < dim; ++l)
                          sum += grad_N[v][k] * C[a][k][b][l] * grad_N[w][l];
                      K_cell(v * dim + a, w * dim + b) += volume * sum;
                    }
          }
        dofs.assign(cache.global_dofs(c), cache.global_dofs(c) + dofs_per_cell);
        constraints.distribute_local_to_global(K_cell, dofs, K);
      }
    K.compress(VectorOperation::add);

    // Constrained dofs outside every cell with points (nodes without points)
    // got no entry at all: give them a diagonal of the matrix's scale.
    double diagonal_sum = 0, n_diagonal = 0;
    for (const auto dof : grid.locally_owned_dofs())
      if (!constraints.is_constrained(dof))
        {
          diagonal_sum += K.diag_element(dof);
          n_diagonal += 1;
        }
    diagonal_sum =
      dealii::Utilities::MPI::sum(diagonal_sum, grid.get_communicator());
    n_diagonal =
      dealii::Utilities::MPI::sum(n_diagonal, grid.get_communicator());
    const double scale = n_diagonal > 0 ? diagonal_sum / n_diagonal : 1.;
    for (const auto dof : grid.locally_owned_dofs())
      if (constraints.is_constrained(dof) && K.diag_element(dof) == 0.)
        K.set(dof, dof, scale);
    K.compress(VectorOperation::insert);
  }



  template <int dim>
  const TrilinosWrappers::SparseMatrix &
  TangentAssembler<dim>::matrix() const
  {
    return K;
  }



  template class TangentAssembler<2>;
  template class TangentAssembler<3>;
} // namespace qsmpm
