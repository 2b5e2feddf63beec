#ifndef qsmpm_solvers_newton_krylov_h
#define qsmpm_solvers_newton_krylov_h

#include <cmath>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <qsmpm/solvers/jacobian_free_operator.h>
#include <qsmpm/solvers/newton_parameters.h>
#include <string>

namespace qsmpm
{
  /**
   * What happened in one Newton solve.
   */
  struct NewtonReport
  {
    bool         converged         = false;
    unsigned int newton_iterations = 0;
    /// GMRES iterations summed over the Newton iterations.
    unsigned int linear_iterations = 0;
    /// Newton corrections GMRES did not solve to its tolerance.
    unsigned int inexact_linear_solves = 0;
    /// Line-search halvings summed over the Newton iterations.
    unsigned int line_search_steps = 0;
    double       initial_residual  = 0.;
    double       final_residual    = 0.;
    /// Why the solve failed (empty if it converged).
    std::string failure;
  };



  /**
   * The Jacobian-free Newton-Krylov method of paper Appendix A: Newton's
   * method (A.1) whose linear systems J(du_n) s = -R(du_n) are solved by
   * deal.II's GMRES with the finite-difference product of
   * JacobianFreeOperator.
   *
   * Operator is the nonlinear problem of one load step and must provide
   *   - void residual(const VectorType &du, VectorType &R) const;
   *   - void set_constrained_to_zero(VectorType &v) const;
   *   - void precondition(VectorType &dst, const VectorType &src) const;
   *     (an approximation of J^{-1}, or a copy for none).
   *
   * The initial guess du_0 handed to solve() must satisfy the displacement
   * boundary conditions (paper A.1 step 1); every correction vanishes on
   * constrained components, so every iterate does too.
   */
  template <typename Operator, typename VectorType>
  class NewtonKrylov
  {
  public:
    explicit NewtonKrylov(const NewtonParameters &parameters)
      : parameters(parameters)
    {
    }

    /**
     * Solve R(du) = 0 from the initial guess @p du. On return @p R holds the
     * residual of the returned @p du, including the constrained rows.
     */
    NewtonReport
    solve(const Operator &op, VectorType &du, VectorType &R) const
    {
      NewtonReport report;
      VectorType   s, rhs, trial;
      R.reinit(du);
      s.reinit(du);
      rhs.reinit(du);
      trial.reinit(du);

      op.residual(du, R);
      double norm             = free_norm(op, R, rhs);
      report.initial_residual = norm;
      const double target =
        parameters.tolerance * std::max(parameters.residual_floor, norm);

      double forcing = parameters.linear_tolerance, previous_norm = norm;
      for (unsigned int n = 0;; ++n)
        {
          report.final_residual = norm;
          if (!std::isfinite(norm))
            {
              report.failure = "the residual is not a finite number";
              return report;
            }
          if (norm <= target)
            {
              report.converged = true;
              return report;
            }
          if (n == parameters.max_iterations)
            {
              report.failure =
                "no convergence in " + std::to_string(n) + " Newton iterations";
              return report;
            }

          if (parameters.eisenstat_walker && n > 0)
            forcing = eisenstat_walker(forcing, norm, previous_norm, target);
          previous_norm = norm;

          // A.1 step 4: J s = -R with constrained components of s zero.
          rhs = R;
          rhs *= -1.;
          op.set_constrained_to_zero(rhs);
          s = 0.;
          const JacobianFreeOperator<Operator, VectorType> J(
            op, du, R, parameters.sqrt_eps_prec);
          SolverControl control(parameters.max_linear_iterations,
                                parameters.linear_tolerance * rhs.l2_norm(),
                                /*log_history=*/false,
                                /*log_result=*/false);
          // Right preconditioning: GMRES then measures the true residual.
          typename SolverGMRES<VectorType>::AdditionalData data(
            parameters.gmres_restart + 2, /*right_preconditioning=*/true);
          SolverGMRES<VectorType> gmres(control, data);
          try
            {
              gmres.solve(J, s, rhs, Preconditioner{op});
            }
          catch (const SolverControl::NoConvergence &)
            {
              // An inexact correction is still a descent direction in
              // most cases; Newton's test decides.
              ++report.inexact_linear_solves;
            }
          report.linear_iterations += control.last_step();
          op.set_constrained_to_zero(s);

          // A.1 step 5, with an optional backtracking line search.
          double alpha = 1.;
          for (unsigned int k = 0;; ++k)
            {
              trial = du;
              trial.add(alpha, s);
              op.residual(trial, R);
              const double trial_norm = free_norm(op, R, rhs);
              if (k == parameters.max_line_search_steps ||
                  (std::isfinite(trial_norm) &&
                   trial_norm <= (1. - 1e-4 * alpha) * norm))
                {
                  norm = trial_norm;
                  break;
                }
              alpha *= 0.5;
              ++report.line_search_steps;
            }
          du                       = trial;
          report.newton_iterations = n + 1;
        }
    }

  private:
    /**
     * Eisenstat and Walker's forcing term, choice 2 (gamma = 0.9,
     * alpha = 2), with their safeguard against too small forcing terms and
     * a floor that avoids solving more accurately than the Newton target.
     */
    static double
    eisenstat_walker(const double previous_forcing,
                     const double norm,
                     const double previous_norm,
                     const double target)
    {
      const double gamma = 0.9, eta_max = 0.9;
      double       eta       = gamma * std::pow(norm / previous_norm, 2);
      const double safeguard = gamma * previous_forcing * previous_forcing;
      if (safeguard > 0.1)
        eta = std::max(eta, safeguard);
      eta = std::min(eta, eta_max);
      return std::max(eta, 0.5 * target / norm);
    }

    /// The preconditioner as deal.II's solvers want it: a vmult().
    struct Preconditioner
    {
      const Operator &op;
      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        op.precondition(dst, src);
        op.set_constrained_to_zero(dst);
      }
    };

    /// ||R|| over the unconstrained components (the rows with an equation).
    static double
    free_norm(const Operator &op, const VectorType &R, VectorType &scratch)
    {
      scratch = R;
      op.set_constrained_to_zero(scratch);
      return scratch.l2_norm();
    }

    const NewtonParameters parameters;
  };
} // namespace qsmpm

#endif
