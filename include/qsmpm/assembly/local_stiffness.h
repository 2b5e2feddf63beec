#ifndef qsmpm_assembly_local_stiffness_h
#define qsmpm_assembly_local_stiffness_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * A stiffness G that is a sum of small dense matrices, each on a few
   * degrees of freedom, linear in the step's increment: the residual of a
   * step becomes R(du) - G du and the preconditioner's matrix K + G. The
   * stabilizations of the step are such terms (GhostPenalty on the faces
   * of cut cells, NullModeHold on the stiffness-free modes of pairs of
   * dofs); this class holds their matrices and applies them.
   */
  class LocalStiffness
  {
  public:
    /// Whether G has any entry (on any rank).
    bool
    active() const
    {
      return n_global > 0;
    }

    /// The number of local matrices (all ranks).
    unsigned int
    n_terms() const
    {
      return n_global;
    }

    /// R -= G du.
    void
    subtract_forces(const TrilinosWrappers::MPI::Vector &du,
                    TrilinosWrappers::MPI::Vector       &R) const;

    /// diagonal += the diagonal of G (a vector of the locally owned dofs).
    void
    add_diagonal_to(TrilinosWrappers::MPI::Vector &diagonal) const;

    /// Add the couplings of G to @p pattern (with @p periodicity, as the
    /// tangent's pattern).
    void
    add_couplings(const AffineConstraints<double>   &periodicity,
                  TrilinosWrappers::SparsityPattern &pattern) const;

    /// K += G, with the step's @p constraints (as the tangent's cells).
    void
    add_to(const AffineConstraints<double> &constraints,
           TrilinosWrappers::SparseMatrix  &K) const;

  protected:
    /// Forget all matrices (no entry until the next build()).
    void
    clear();

    /// Add the matrix @p matrix on the degrees of freedom @p dofs (of this
    /// rank, or its ghosts).
    void
    add(const std::vector<types::global_dof_index> &dofs,
        const FullMatrix<double>                   &matrix);

    /// Assemble G from the matrices added since clear(), with rows
    /// @p owned and the ghosts @p relevant (collective).
    void
    build(const IndexSet &owned,
          const IndexSet &relevant,
          const MPI_Comm  communicator);

  private:
    TrilinosWrappers::SparseMatrix                    G;
    std::vector<std::vector<types::global_dof_index>> term_dofs;
    std::vector<FullMatrix<double>>                   term_matrices;
    mutable TrilinosWrappers::MPI::Vector             scratch;
    unsigned int                                      n_global = 0;
  };
} // namespace qsmpm

#endif
