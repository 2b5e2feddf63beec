#ifndef qsmpm_loading_step_constraints_h
#define qsmpm_loading_step_constraints_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <utility>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * The linear constraints of one load step, du_i = sum_j c_ij du_j + b_i,
   * and what the Jacobian-free Newton-Krylov solver needs to do with them
   * on distributed vectors.
   *
   * Two kinds of constrained degrees of freedom occur:
   * - prescribed ones (displacement conditions, nodes without points):
   *   no c_ij, only b_i. Their residual rows hold minus the reaction
   *   forces (R = f_ext - f_int) and are kept; they have no equation;
   * - coupled ones (periodic boundary conditions: du_slave = du_master +
   *   jump). Their residual is the force on the same physical node as the
   *   master's, so condense() adds it to the master's row (R <- C^T R).
   *
   * Corrections of Newton's method live in the space of the homogeneous
   * constraints (b = 0), make_admissible(); residuals live in the condensed
   * space, condense() and set_constrained_to_zero(). Without coupled
   * degrees of freedom both reduce to zeroing the constrained components.
   */
  class StepConstraints
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    /**
     * Take over the closed constraints of a step; @p owned are the locally
     * owned degrees of freedom of the grid.
     */
    void
    reinit(AffineConstraints<double> &&constraints,
           const IndexSet             &owned,
           const MPI_Comm              communicator);

    /// The constraints themselves (with their inhomogeneities b).
    const AffineConstraints<double> &
    get() const;

    /// The communicator of the step's vectors.
    MPI_Comm
    get_communicator() const;

    /// du_i = sum_j c_ij du_j + b_i on the constrained components.
    void
    distribute(VectorType &du) const;

    /// v_i = sum_j c_ij v_j on the constrained components (zero if none).
    void
    make_admissible(VectorType &v) const;

    /// R_j += c_ij R_i for the coupled i, then R_i = 0 there.
    void
    condense(VectorType &R) const;

    /// v_i = 0 on every constrained component.
    void
    set_constrained_to_zero(VectorType &v) const;

  private:
    AffineConstraints<double> constraints;
    /// Locally owned coupled dofs with their entries (j, c_ij).
    std::vector<
      std::pair<types::global_dof_index,
                std::vector<std::pair<types::global_dof_index, double>>>>
      coupled;
    /// Scratch vector that may be written at every master dof.
    mutable VectorType master_forces;
    /// Scratch vector with the values of every master dof (ghosted).
    mutable VectorType master_values;
    bool               any_coupling     = false;
    MPI_Comm           mpi_communicator = MPI_COMM_SELF;
  };
} // namespace qsmpm

#endif
