#include <qsmpm/assembly/local_stiffness.h>

namespace qsmpm
{
  void
  LocalStiffness::clear()
  {
    term_dofs.clear();
    term_matrices.clear();
    n_global = 0;
  }



  void
  LocalStiffness::add(const std::vector<types::global_dof_index> &dofs,
                      const FullMatrix<double>                   &matrix)
  {
    AssertDimension(dofs.size(), matrix.m());
    term_dofs.push_back(dofs);
    term_matrices.push_back(matrix);
  }



  void
  LocalStiffness::build(const IndexSet &owned,
                        const IndexSet &relevant,
                        const MPI_Comm  communicator)
  {
    n_global =
      dealii::Utilities::MPI::sum(static_cast<unsigned int>(term_dofs.size()),
                                  communicator);
    if (n_global == 0)
      return;
    TrilinosWrappers::SparsityPattern pattern(owned,
                                              owned,
                                              relevant,
                                              communicator);
    for (const auto &dofs : term_dofs)
      for (const auto row : dofs)
        for (const auto column : dofs)
          pattern.add(row, column);
    pattern.compress();
    G.reinit(pattern);
    for (unsigned int t = 0; t < term_dofs.size(); ++t)
      G.add(term_dofs[t], term_matrices[t]);
    G.compress(VectorOperation::add);
  }



  void
  LocalStiffness::subtract_forces(const TrilinosWrappers::MPI::Vector &du,
                                  TrilinosWrappers::MPI::Vector       &R) const
  {
    if (!active())
      return;
    scratch.reinit(R, /*omit_zeroing_entries=*/true);
    G.vmult(scratch, du);
    R -= scratch;
  }



  void
  LocalStiffness::add_diagonal_to(TrilinosWrappers::MPI::Vector &diagonal) const
  {
    if (!active())
      return;
    for (const auto row : diagonal.locally_owned_elements())
      diagonal(row) += G.diag_element(row);
    diagonal.compress(VectorOperation::add);
  }



  void
  LocalStiffness::add_couplings(
    const AffineConstraints<double>   &periodicity,
    TrilinosWrappers::SparsityPattern &pattern) const
  {
    for (const auto &dofs : term_dofs)
      periodicity.add_entries_local_to_global(dofs,
                                              pattern,
                                              /*keep_constrained=*/true);
  }



  void
  LocalStiffness::add_to(const AffineConstraints<double> &constraints,
                         TrilinosWrappers::SparseMatrix  &K) const
  {
    for (unsigned int t = 0; t < term_dofs.size(); ++t)
      constraints.distribute_local_to_global(term_matrices[t], term_dofs[t], K);
  }
} // namespace qsmpm
