#ifndef qsmpm_solvers_newton_krylov_h
#define qsmpm_solvers_newton_krylov_h

#include <algorithm>
#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <iomanip>
#include <qsmpm/solvers/jacobian_free_operator.h>
#include <qsmpm/solvers/newton_parameters.h>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

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
    /// ||R|| (free rows) of the first iterate (du_0, or the caller's guess)
    /// and after every Newton iteration.
    std::vector<double> residual_history;
    /// Why the solve failed (empty if it converged).
    std::string failure;
    /// The failure is GMRES's breakdown on a singular Jacobian (a caller
    /// that knows the discretization may say what makes it singular).
    bool singular_jacobian = false;
    /// The force level of the stopping test (internal::stopping_target())
    /// at the first iterate: ||R|| there.
    double force_level = 0.;
    /// Converged because a Newton iteration did not halve a residual
    /// already below 1e-6 of the force level (internal::force_noise()),
    /// above the stopping target.
    bool stagnated = false;
  };



  namespace internal
  {
    /// What Operator::residual() returns besides the residual.
    template <typename Operator, typename VectorType>
    using EvaluationOf =
      std::decay_t<decltype(std::declval<const Operator &>().residual(
        std::declval<const VectorType &>(),
        std::declval<VectorType &>()))>;

    /// Whether the operator has update_preconditioner(du) (see
    /// NewtonKrylov).
    template <typename Operator, typename VectorType, typename = void>
    struct UpdatesPreconditioner : std::false_type
    {
    };

    template <typename Operator, typename VectorType>
    struct UpdatesPreconditioner<
      Operator,
      VectorType,
      std::void_t<
        decltype(std::declval<const Operator &>().update_preconditioner(
          std::declval<const VectorType &>()))>> : std::true_type
    {
    };

    /**
     * An operator's preconditioner as deal.II's solvers want it (a vmult()),
     * mapping residual-like Krylov vectors to admissible corrections; shared
     * by the Newton solvers.
     */
    template <typename Operator>
    struct AdmissiblePreconditioner
    {
      const Operator &op;
      template <typename VectorType>
      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        op.precondition(dst, src);
        op.make_admissible(dst);
      }
    };

    /**
     * What went wrong first in a GMRES solve whose correction is not a
     * finite number (see solve_correction()). The wrappers below watch
     * the products and the preconditioner; a result that is not finite
     * counts only where its input was finite, so that what GMRES makes
     * of its own division by zero is not taken for the cause.
     */
    struct BreakdownWatch
    {
      std::string first_cause;
      bool        zero_product = false;
      void
      note(const std::string &cause)
      {
        if (first_cause.empty())
          first_cause = cause;
      }
    };

    /// An operator's vmult() watched by a BreakdownWatch: a result that is
    /// not finite is noted as @p cause.
    template <typename Wrapped>
    struct Watched
    {
      const Wrapped  &wrapped;
      BreakdownWatch &watch;
      const char     *cause;
      template <typename VectorType>
      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        wrapped.vmult(dst, src);
        const double norm = dst.l2_norm();
        if (!std::isfinite(norm) && std::isfinite(src.l2_norm()))
          watch.note(cause);
        else if (norm == 0. && src.l2_norm() > 0.)
          watch.zero_product = true;
      }
    };

    /// ||R|| over the unconstrained components (the rows with an equation).
    template <typename Operator, typename VectorType>
    double
    free_norm(const Operator &op, const VectorType &R, VectorType &scratch)
    {
      scratch = R;
      op.set_constrained_to_zero(scratch);
      return scratch.l2_norm();
    }

    /**
     * The size of a residual that is noise against the forces in the body,
     * @p force_level (||R|| on all degrees of freedom, the supports'
     * reactions included): 1e-6 of them. It bounds Newton's target from
     * below (stopping_target()), and a Newton iteration that cannot lower a
     * residual of that size ends the solve as converged
     * (NewtonReport::stagnated): a step whose load does not change (a load
     * held constant) starts in equilibrium up to the points' motion in the
     * last step, and its target, relative to that tiny first residual,
     * then lies below what the kinks of contact and plasticity let Newton
     * reach (a footing held at a constant force on von Mises soil stalled
     * at 6e-7 of the forces with a target of 3e-12 of them).
     */
    inline double
    force_noise(const double force_level)
    {
      return 1e-6 * force_level;
    }

    /// @p target, at most NewtonParameters::residual_ceiling where that is
    /// set.
    inline double
    below_ceiling(const NewtonParameters &parameters, const double target)
    {
      return parameters.residual_ceiling > 0. ?
               std::min(target, parameters.residual_ceiling) :
               target;
    }

    /**
     * The target of Newton's stopping test for a step whose first guess
     * du_0 has the residual norm @p reference on the free degrees of
     * freedom and @p force_level on all of them (the rows of the supports
     * hold their reactions, so this is the size of the forces in the
     * body): gamma max(floor, ||R(du_0)||, 1e-6 force_level). The last
     * term keeps a step whose load hardly changes from asking for a
     * residual below round-off; like the first two it is measured in the
     * units of the forces, so the test gives the same iterates whatever
     * the units (with the floor 0, the default).
     *
     * Without NewtonParameters::relative_to_load, @p reference is the
     * residual norm of the solve's first iterate and the target is
     * gamma max(floor, reference): the caller's floor is then the guard
     * against round-off (the fixed-stress iterations of a pore fluid).
     *
     * Either target is at most NewtonParameters::residual_ceiling, where
     * the caller knows the forces in the body better than the first
     * residual does.
     */
    inline double
    stopping_target(const NewtonParameters &parameters,
                    const double            reference,
                    const double            force_level)
    {
      if (!parameters.relative_to_load)
        return below_ceiling(parameters,
                             parameters.tolerance *
                               std::max(parameters.residual_floor, reference));
      return below_ceiling(parameters,
                           parameters.tolerance *
                             std::max({parameters.residual_floor,
                                       reference,
                                       force_noise(force_level)}));
    }

    /// Records @p why in @p report unless an earlier failure is recorded:
    /// the first cause found is the one the user needs.
    inline void
    record_failure(NewtonReport &report, const std::string &why)
    {
      if (report.failure.empty())
        report.failure = why;
    }

    /// What one GMRES solve did.
    struct LinearSolve
    {
      unsigned int iterations;
      /// Reduction of the linear residual that was reached.
      double reduction;
    };

    /**
     * The linear solve of both Newton solvers: GMRES on J s = rhs to the
     * relative tolerance @p tolerance, with the operator's preconditioner
     * on the right, so that GMRES measures the true residual. The
     * constrained components of @p rhs are zeroed first, and @p s satisfies
     * the homogeneous constraints on return (zero if @p rhs is). A
     * correction that GMRES does not solve to the tolerance is returned
     * all the same (an inexact correction is still a descent direction in
     * most cases; Newton's test decides) and counted in
     * report.inexact_linear_solves; the iterations are added to
     * report.linear_iterations. A correction that is not a finite number
     * (GMRES broke down) records the cause in report.failure: a perturbed
     * residual or a preconditioned vector that is not a finite number, or
     * else a Jacobian that is singular on the Krylov space.
     */
    template <typename Operator, typename VectorType>
    LinearSolve
    solve_correction(const Operator                                   &op,
                     const JacobianFreeOperator<Operator, VectorType> &J,
                     const NewtonParameters &parameters,
                     const double            tolerance,
                     VectorType             &rhs,
                     VectorType             &s,
                     NewtonReport           &report)
    {
      op.set_constrained_to_zero(rhs);
      s                     = 0.;
      const double rhs_norm = rhs.l2_norm();
      if (rhs_norm == 0.)
        return {0, 0.};
      SolverControl control(parameters.max_linear_iterations,
                            tolerance * rhs_norm,
                            /*log_history=*/false,
                            /*log_result=*/false);
      typename SolverGMRES<VectorType>::AdditionalData data(
        parameters.gmres_restart + 2, /*right_preconditioning=*/true);
      SolverGMRES<VectorType>                  gmres(control, data);
      BreakdownWatch                           watch;
      const AdmissiblePreconditioner<Operator> preconditioner{op};
      try
        {
          gmres.solve(
            Watched<JacobianFreeOperator<Operator, VectorType>>{
              J,
              watch,
              "the residual of a perturbed iterate (a Jacobian-free "
              "product) is not a finite number"},
            s,
            rhs,
            Watched<AdmissiblePreconditioner<Operator>>{
              preconditioner,
              watch,
              "the preconditioner returned a vector that is not a finite "
              "number (its matrix is singular)"});
        }
      catch (const SolverControl::NoConvergence &)
        {
          ++report.inexact_linear_solves;
        }
      op.make_admissible(s);
      report.linear_iterations += control.last_step();
      // GMRES divides by zero where its Hessenberg matrix is singular, i.e.
      // where the preconditioned Jacobian is singular on the Krylov space:
      // the cause where the products and the preconditioner gave finite
      // numbers.
      if (!std::isfinite(s.l2_norm()) && report.failure.empty())
        {
          report.singular_jacobian = watch.first_cause.empty();
          report.failure =
            "GMRES broke down: " +
            (report.singular_jacobian ?
               std::string("the Jacobian is singular") +
                 (watch.zero_product ?
                    " (the residual does not change along a correction)" :
                    "") :
               watch.first_cause);
        }
      return {control.last_step(), control.last_value() / rhs_norm};
    }
  } // namespace internal



  /**
   * The Jacobian-free Newton-Krylov method of paper Appendix A: Newton's
   * method (A.1) whose linear systems J(du_n) s = -R(du_n) are solved by
   * deal.II's GMRES with the finite-difference product of
   * JacobianFreeOperator.
   *
   * Operator is the nonlinear problem of one load step and must provide
   *   - Evaluation residual(const VectorType &du, VectorType &R) const;
   *     (R(du), and what else the evaluation found, e.g. the smallest
   *     volume ratio of the points: a copyable type, returned by solve()
   *     for the solution);
   *   - void set_constrained_to_zero(VectorType &v) const;
   *     (residual space: zero the rows without an equation);
   *   - void make_admissible(VectorType &v) const;
   *     (correction space: constrained components from the homogeneous
   *     constraints, i.e. zero where prescribed and equal to the master's
   *     where periodic);
   *   - void precondition(VectorType &dst, const VectorType &src) const;
   *     (an approximation of J^{-1}, or a copy for none);
   *   - optionally void update_preconditioner(const VectorType &du) const;
   *     (called before the linear solve of every Newton iteration with
   *     the iterate, for a preconditioner of the Jacobian there);
   *   - double typical_increment_norm() const;
   *     (the size of increments where du = 0 gives none, for the
   *     finite-difference step of JacobianFreeOperator).
   *
   * The initial guess du_0 handed to solve() must satisfy the displacement
   * boundary conditions (paper A.1 step 1); every correction satisfies the
   * homogeneous constraints, so every iterate satisfies the constraints
   * too. GMRES works with right preconditioning: its Krylov vectors are
   * residuals, the preconditioner maps them to admissible corrections.
   */
  template <typename Operator, typename VectorType>
  class NewtonKrylov
  {
  public:
    /// What Operator::residual() returns besides the residual.
    using Evaluation = typename internal::EvaluationOf<Operator, VectorType>;

    /**
     * With NewtonParameters::verbose, one line per iteration goes to
     * @p log (a ConditionalOStream that is active on one rank only).
     */
    explicit NewtonKrylov(const NewtonParameters   &parameters,
                          const ConditionalOStream *log = nullptr)
      : parameters(parameters)
      , log(parameters.verbose ? log : nullptr)
    {
    }

    /**
     * Solve R(du) = 0 from the initial guess @p du. On return @p R holds the
     * residual of the returned @p du, including the constrained rows.
     *
     * With InitialGuess::linear_predictor, the first iterate is not the
     * paper's du_0 (the prescribed increments on constrained components,
     * zero elsewhere) but the solution of the problem linearized about the
     * free part of du_0, with the prescribed increments as data:
     *
     *   J(b) s = -(R(b) + J(b) g),   du_1 = b + g + s,
     *
     * where g is the constrained part of du_0 and b the rest. The paper's
     * du_0 concentrates the whole prescribed increment in the first layer
     * of cells at the boundary, with strains of order (increment / cell
     * size) that grow as the grid is refined; linearizing there makes the
     * first Newton steps poor. The predictor is the usual first iterate of
     * finite-element codes and solves a linear problem in one iteration. It
     * counts as a Newton iteration; the stopping test still uses the
     * paper's ||R(du_0)||.
     *
     * With InitialGuess::extrapolation, @p du is the first iterate (the
     * caller's guess, whose constrained components are the prescribed
     * increments); the stopping test uses ||R(du_0)|| with du_0 = g, its
     * constrained part, as above, at the cost of one more residual.
     * (InitialGuess::boundary_values: @p du is du_0.)
     *
     * On return, @p R is R(@p du), and @p evaluation what the evaluation
     * of that residual found (Operator::residual()'s return value, e.g.
     * the smallest volume ratio of the points).
     */
    NewtonReport
    solve(const Operator &op, VectorType &du, VectorType &R) const
    {
      Evaluation evaluation;
      return solve(op, du, R, evaluation);
    }

    /// As above, with what the evaluation of the returned residual found.
    NewtonReport
    solve(const Operator &op,
          VectorType     &du,
          VectorType     &R,
          Evaluation     &evaluation) const
    {
      NewtonReport report;
      VectorType   s, rhs, trial;
      R.reinit(du);
      s.reinit(du);
      rhs.reinit(du);
      trial.reinit(du);

      using InitialGuess = NewtonParameters::InitialGuess;
      double reference = 0., force_level = 0.;
      if (parameters.initial_guess == InitialGuess::extrapolation)
        {
          // The stopping test stays relative to the residual of the paper's
          // du_0 = g, the constrained part of the guess: relative to that of
          // a guess close to the solution it would ask for far more.
          trial = du;
          op.set_constrained_to_zero(trial);
          s = du;
          s -= trial;
          op.residual(s, R);
          reference   = internal::free_norm(op, R, rhs);
          force_level = R.l2_norm();
        }
      evaluation  = op.residual(du, R);
      double norm = internal::free_norm(op, R, rhs);
      if (parameters.initial_guess != InitialGuess::extrapolation)
        {
          reference   = norm;
          force_level = R.l2_norm();
        }
      report.initial_residual = reference;
      report.force_level      = force_level;
      report.residual_history.push_back(norm);
      const double target =
        internal::stopping_target(parameters,
                                  parameters.relative_to_load ? reference :
                                                                norm,
                                  force_level);

      double forcing = parameters.linear_tolerance, previous_norm = reference;
      // GMRES solves in a row that stalled (stalled()).
      unsigned int stalls = 0;
      // auto that no caller resolved (QuasiStaticProblem does, by the
      // kinematics): the linear predictor.
      if ((parameters.initial_guess == InitialGuess::linear_predictor ||
           parameters.initial_guess == InitialGuess::automatic) &&
          norm > target && std::isfinite(norm))
        {
          // The predictor's solve, too, goes no further than the Newton
          // target asks with Eisenstat-Walker (its right-hand side is about
          // R(du_0)): the polycrystal's six tests needed 20 % fewer GMRES
          // iterations, the same stiffness.
          const double tolerance =
            parameters.forcing == NewtonParameters::Forcing::eisenstat_walker ?
              no_further_than(parameters.linear_tolerance, target, norm) :
              parameters.linear_tolerance;
          norm = predict(op, du, R, evaluation, report, tolerance);
        }

      for (unsigned int n = report.newton_iterations;; ++n)
        {
          report.final_residual = norm;
          if (!std::isfinite(norm))
            {
              internal::record_failure(report,
                                       "the residual is not a finite number");
              return report;
            }
          if (norm <= target)
            {
              report.converged = true;
              return report;
            }
          if (n >= parameters.max_iterations)
            {
              report.failure =
                "no convergence in " + std::to_string(n) + " Newton iterations";
              return report;
            }

          // Eisenstat-Walker once there is a reduction to adapt to: after
          // the predictor, or from an extrapolated guess that improved on
          // du_0 (previous_norm is ||R(du_0)|| in the first iteration). A
          // first solve from du_0 keeps the linear tolerance but does not
          // solve further than the Newton target asks either.
          if (parameters.forcing == NewtonParameters::Forcing::eisenstat_walker)
            forcing = (n > 0 || norm < previous_norm) ?
                        eisenstat_walker(forcing, norm, previous_norm, target) :
                        no_further_than(forcing, target, norm);
          previous_norm = norm;

          if constexpr (internal::UpdatesPreconditioner<Operator,
                                                        VectorType>::value)
            op.update_preconditioner(du);

          // A.1 step 4: J s = -R with constrained components of s zero.
          rhs = R;
          rhs *= -1.;
          const JacobianFreeOperator<Operator, VectorType> J(
            op, du, R, parameters.sqrt_eps_prec);
          const internal::LinearSolve linear = internal::solve_correction(
            op, J, parameters, forcing, rhs, s, report);
          if (!std::isfinite(s.l2_norm()))
            return report; // solve_correction() recorded why
          stalls = stalled(linear) ? stalls + 1 : 0;
          if (stalls == 2)
            {
              report.failure =
                "GMRES stalled: " +
                std::to_string(parameters.max_linear_iterations) +
                " iterations reduced its residual by less than a factor 10 "
                "in two Newton iterations in a row";
              return report;
            }

          // A.1 step 5, with an optional backtracking line search.
          double alpha     = 1.;
          bool   stagnated = false;
          for (unsigned int k = 0;; ++k)
            {
              trial = du;
              trial.add(alpha, s);
              const Evaluation trial_evaluation = op.residual(trial, R);
              const double     trial_norm = internal::free_norm(op, R, rhs);
              const bool       decrease   = std::isfinite(trial_norm) &&
                                    trial_norm <= (1. - 1e-4 * alpha) * norm;
              if (decrease || k == parameters.max_line_search_steps)
                {
                  // Below the forces' noise, an iteration that does not
                  // halve the residual is no longer Newton's convergence
                  // but the kinks of contact and plasticity (or the
                  // finite differences) at that scale: the solve stops,
                  // at the trial if it lowered the residual.
                  stagnated =
                    norm <= internal::below_ceiling(
                              parameters, internal::force_noise(force_level)) &&
                    !(decrease && trial_norm <= 0.5 * norm);
                  if (stagnated && !decrease)
                    {
                      // R holds the trial's residual: the one of du again.
                      evaluation = op.residual(du, R);
                      trial      = du;
                      alpha      = 0.;
                    }
                  else
                    {
                      norm       = trial_norm;
                      evaluation = trial_evaluation;
                    }
                  break;
                }
              alpha *= 0.5;
              ++report.line_search_steps;
            }
          du                       = trial;
          report.newton_iterations = n + 1;
          report.residual_history.push_back(norm);
          print_iteration(report, norm, linear, alpha);
          if (stagnated)
            {
              report.final_residual = norm;
              report.converged      = true;
              report.stagnated      = true;
              return report;
            }
        }
    }

  private:
    /**
     * Whether GMRES reached its iteration limit with less than a tenth of
     * its residual removed. Its correction then hardly lowers the
     * linearized residual, and Newton no longer converges: at the knee of
     * a rigid footing's load curve on von Mises soil (13,122 dofs, AMG),
     * a step whose GMRES stalled at 1000 iterations with reductions of
     * 0.4-0.7 went on doing so for the remaining 11 of its 20 Newton
     * iterations, 5 s each, and failed. Two stalls in a row end the solve
     * as failed (the step is then tried again with another preconditioner
     * or cut back); a single one, after which Newton may still recover,
     * does not.
     */
    bool
    stalled(const internal::LinearSolve &linear) const
    {
      return linear.iterations >= parameters.max_linear_iterations &&
             linear.reduction > 0.1;
    }

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
      return no_further_than(eta, target, norm);
    }

    /**
     * The relative GMRES tolerance @p tolerance, raised where it would
     * solve further than the Newton target asks: to half of @p target
     * relative to the current residual @p norm.
     */
    static double
    no_further_than(const double tolerance,
                    const double target,
                    const double norm)
    {
      return std::max(tolerance, 0.5 * target / norm);
    }

    /**
     * The linear predictor (see solve()), solved by GMRES to the relative
     * @p tolerance: replaces @p du by b + g + s,
     * @p R by its residual and @p evaluation by what its evaluation found;
     * returns the norm of the free part of R.
     */
    double
    predict(const Operator &op,
            VectorType     &du,
            VectorType     &R,
            Evaluation     &evaluation,
            NewtonReport   &report,
            const double    tolerance) const
    {
      VectorType base(du), rhs(du), s(du);
      op.set_constrained_to_zero(base);
      const double scale = du.l2_norm();
      // rhs = -(R(b) + J(b) g), with g = du - b.
      s = du;
      s -= base;
      op.residual(base, R);
      const JacobianFreeOperator<Operator, VectorType> J(
        op, base, R, parameters.sqrt_eps_prec, scale);
      J.vmult(rhs, s);
      rhs += R;
      rhs *= -1.;
      const internal::LinearSolve linear = internal::solve_correction(
        op, J, parameters, tolerance, rhs, s, report);
      du += s;
      evaluation               = op.residual(du, R);
      const double norm        = internal::free_norm(op, R, rhs);
      report.newton_iterations = 1;
      report.residual_history.push_back(norm);
      print_iteration(report, norm, linear, 1.);
      return norm;
    }

    /// One line per Newton iteration if verbose.
    void
    print_iteration(const NewtonReport          &report,
                    const double                 norm,
                    const internal::LinearSolve &linear,
                    const double                 alpha) const
    {
      if (log != nullptr)
        *log << "    newton " << std::setw(2) << report.newton_iterations
             << "  |R| " << std::scientific << std::setprecision(3) << norm
             << "  gmres " << std::setw(4) << linear.iterations
             << "  reduction " << linear.reduction << "  step "
             << std::defaultfloat << alpha << std::endl;
    }

    const NewtonParameters    parameters;
    const ConditionalOStream *log;
  };
} // namespace qsmpm

#endif
