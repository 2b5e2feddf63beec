#ifndef qsmpm_solvers_preconditioner_reuse_h
#define qsmpm_solvers_preconditioner_reuse_h

#include <array>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>
#include <qsmpm/solvers/newton_krylov.h>
#include <qsmpm/solvers/newton_parameters.h>

namespace qsmpm
{
  /**
   * When a load step builds a new stiffness and preconditioner, and when it
   * reuses the one of an earlier step (Nonlinear solver/Preconditioner
   * reuse steps and Preconditioner reuse growth).
   *
   * A preconditioner stays an approximate inverse of the tangent as long as
   * the points and their state change little, and GMRES, which works with
   * the exact Jacobian-vector products, then only needs a few more
   * iterations. It serves at most <Preconditioner reuse steps> steps; a
   * step that fails, or in which GMRES needed more than <Preconditioner
   * reuse growth> times the iterations per Newton iteration of the
   * preconditioner's first step, gets a new one next time. So does a step
   * whose constrained degrees of freedom (prescribed, held or without
   * material) are not those of the step that built the preconditioner: a
   * node that the body reaches at large deformation, held when the
   * preconditioner was built, is free now, and the old preconditioner acts
   * on it as on a fixed one (measured in the cantilever at finite strain
   * with GIMP: 317 GMRES iterations per Newton iteration with reuse
   * across such changes, 8 without).
   */
  class PreconditionerReuse
  {
  public:
    /// Build a new preconditioner before the next step.
    void
    reset();

    /**
     * Whether the next step builds a new preconditioner (counted as a
     * build), given whether the preconditioner needs a matrix at all
     * (@p needs_matrix) and the parameters.
     */
    bool
    build_for_step(const bool needs_matrix, const NewtonParameters &parameters);

    /**
     * The same, and a new preconditioner as well if the step's constrained
     * degrees of freedom @p constraints (locally owned and relevant lines)
     * differ from those of the step that built the current one (compared
     * by their number and a checksum of their indices over all ranks of
     * @p communicator).
     */
    bool
    build_for_step(const bool                       needs_matrix,
                   const NewtonParameters          &parameters,
                   const AffineConstraints<double> &constraints,
                   const IndexSet                  &owned,
                   const MPI_Comm                   communicator);

    /**
     * The number and the checksum of the constrained degrees of freedom
     * the current preconditioner was built for (the last build_for_step()
     * with constraints that asked for a build; {-1, -1} before).
     */
    const std::array<double, 2> &
    constrained_signature() const;

    /**
     * The preconditioner the last build_for_step() asked for was not built
     * but taken over from another problem (QuasiStaticProblem::
     * take_over_preconditioner()): not counted as a build.
     */
    void
    count_as_taken_over();

    /// Count a step of the current preconditioner, with its @p report.
    void
    count_use(const NewtonReport &report, const NewtonParameters &parameters);

    /// Whether the last build_for_step() kept an earlier preconditioner.
    bool
    reused() const;

    /// How many times a preconditioner has been built.
    unsigned int
    n_builds() const;

  private:
    /// Load steps the preconditioner has served (0: build one before the
    /// next step).
    unsigned int age = 0;
    /// GMRES iterations per Newton iteration in the first of them.
    double       rate        = 0.;
    unsigned int builds      = 0;
    bool         last_reused = false;
    /// The number of constrained dofs and a checksum of their indices at
    /// the last build.
    std::array<double, 2> constrained{{-1., -1.}};
  };
} // namespace qsmpm

#endif
