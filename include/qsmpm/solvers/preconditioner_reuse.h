#ifndef qsmpm_solvers_preconditioner_reuse_h
#define qsmpm_solvers_preconditioner_reuse_h

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
   * preconditioner's first step, gets a new one next time.
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
  };
} // namespace qsmpm

#endif
