#ifndef qsmpm_solvers_path_following_newton_h
#define qsmpm_solvers_path_following_newton_h

#include <algorithm>
#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <iomanip>
#include <qsmpm/solvers/jacobian_free_operator.h>
#include <qsmpm/solvers/newton_krylov.h>
#include <qsmpm/solvers/newton_parameters.h>

namespace qsmpm
{
  /**
   * Newton's method for one load step whose load factor is an unknown
   * (path following, indirect displacement control): the prescribed
   * displacement increments are Delta lambda g, with g the increments for a
   * unit change of the load factor, and one more equation, the path
   * constraint
   *
   *   phi(du, Delta lambda) = a Delta lambda + b F(du) + c D(du)
   *                           + e w . du - d = 0,
   *
   * fixes Delta lambda. F(du) = -g . R(du) is the generalized force, the
   * work-conjugate of the load factor (the reaction on the constrained
   * rows of the residual, weighted with g), D(du) the energy the points
   * dissipate in the step (Operator::dissipation() after a residual
   * evaluation; ConstitutiveModel::dissipation()), w . du a linear
   * function of the increment, e.g. the opening of a gauge across a crack
   * (crack-mouth opening displacement control: c = 0, e = 1, d = the
   * opening increment; de Borst 1987). The dissipation-based
   * constraint of Gutierrez (2004) for a prescribed displacement is of this
   * form: the energy dissipated in a step, for a material that unloads
   * secantly, is
   *
   *   Delta D = (F_0 Delta lambda - (F - F_0) lambda_0) / 2,
   *
   * i.e. a = F_0 / 2, b = -lambda_0 / 2, d = Delta tau - lambda_0 F_0 / 2.
   * That formula, however, counts elastic unloading of a model that unloads
   * with its elastic stiffness (plasticity, Schreyer's decohesion) as
   * dissipation, and Newton's method then finds unloading instead of the
   * softening path. QuasiStaticProblem therefore prescribes the dissipation
   * that the points compute themselves, D(du) = Delta tau (c = 1, d =
   * Delta tau). Either grows monotonically along a softening path, also
   * where the load factor decreases (a snap-back), so prescribing it traces
   * the path.
   *
   * Each Newton iteration solves the bordered system
   *
   *   [ J_ff    J_fc g  ] [delta u     ]   [ -R_f ]
   *   [ b dF/du  dphi/dl] [delta lambda] = [ -phi ]
   *
   * by bordering: J_ff x = -R_f and J_ff y = -J_fc g (two GMRES solves
   * with the operator's preconditioner and the finite-difference products
   * of JacobianFreeOperator), then delta lambda from the linearized
   * constraint and delta u = x + delta lambda (y + g). The derivatives of F
   * and D along x, y and g are directional differences (one residual
   * evaluation each). The first iteration from du = 0 is the
   * tangent predictor.
   *
   * Where the constraint cannot be met with -@p back_limit <= Delta lambda
   * <= @p limit
   * (an elastic step dissipates nothing; at lambda = 0 the constraint does
   * not even depend on Delta lambda), Delta lambda is set to +limit and the
   * step is one of displacement control; it is accepted once the
   * dissipation at that increment does not exceed the target (phi <= 0).
   * Setting Delta lambda = +limit rather than clipping keeps the direction
   * of loading where the linearized constraint is singular (its sign is
   * then round-off).
   *
   * Operator as for NewtonKrylov.
   */
  template <typename Operator, typename VectorType>
  class PathFollowingNewton
  {
  public:
    /**
     * phi = load_factor_weight Delta lambda + force_weight F(du) +
     * dissipation_weight D(du) - value.
     */
    struct Constraint
    {
      double load_factor_weight;
      double force_weight;
      double dissipation_weight;
      double value;
      /**
       * Optional linear term gauge_weight (w . du): the opening of a gauge
       * between two material points (crack-mouth opening control), w the
       * vector that maps the grid increment to it (OpeningGauge). Its
       * derivatives are exact (w . v), without residual evaluations.
       */
      const VectorType *gauge        = nullptr;
      double            gauge_weight = 0.;
    };

    /**
     * Which equilibria of the constraint are admissible: the generalized
     * force must keep the sign of the loading, sign F >= -tolerance (sign
     * 0: no condition). A softening specimen loaded through pins can also
     * dissipate Delta tau when it is pushed back (closing a compact-tension
     * specimen puts its back face in tension); that equilibrium satisfies
     * the constraint but is not the loading path.
     */
    struct ForceGuard
    {
      double sign      = 0.;
      double tolerance = 0.;
    };

    explicit PathFollowingNewton(const NewtonParameters   &parameters,
                                 const ConditionalOStream *log = nullptr)
      : parameters(parameters)
      , log(parameters.verbose ? log : nullptr)
    {
    }

    /**
     * Solve from du = 0, Delta lambda = 0. A snap-back may need steps back
     * larger than the forward @p limit; only where the linearized
     * constraint is (nearly) singular does its solution reach far beyond,
     * with either sign, hence a bound @p back_limit on those. If not
     * @p allow_limit, a
     * solution at the limit (see the class documentation) counts as a
     * failure. @p g: the increments of the
     * constrained components for a unit load-factor increment (zero on
     * every free component). On return @p du is the increment (its
     * constrained components Delta lambda g), @p delta_lambda the
     * load-factor increment, @p R the residual of du with the constrained
     * rows, and @p force F(du). A solution that violates @p guard is a
     * failure ("the load reversed its sign").
     */
    NewtonReport
    solve(const Operator   &op,
          const VectorType &g,
          const Constraint &constraint,
          const double      limit,
          const double      back_limit,
          const bool        allow_limit,
          VectorType       &du,
          double           &delta_lambda,
          VectorType       &R,
          double           &force,
          const ForceGuard &guard = ForceGuard()) const
    {
      NewtonReport report;
      VectorType   x(du), y(du), rhs(du), trial(du), dR(du), step(du);
      R.reinit(du);
      du           = 0.;
      delta_lambda = 0.;

      op.residual(du, R);
      force       = -(g * R);
      double norm = internal::free_norm(op, R, rhs);
      double phi  = constraint_value(constraint, delta_lambda, du, force, op);
      report.initial_residual = norm;
      report.residual_history.push_back(norm);
      // The stopping test of NewtonKrylov relative to the residual of the
      // paper's first guess (prescribed increments, zero elsewhere); that
      // guess is known once the predictor has fixed Delta lambda.
      double       target = parameters.tolerance * parameters.residual_floor;
      const double phi_tolerance =
        parameters.tolerance * std::max(std::abs(constraint.value), 1e-300);
      bool at_limit = false;

      for (unsigned int n = 0;; ++n)
        {
          report.final_residual = norm;
          if (!std::isfinite(norm) || !std::isfinite(phi))
            {
              report.failure = "the residual is not a finite number";
              return report;
            }
          if (n > 0 && norm <= target && at_limit && !allow_limit)
            {
              report.failure = "the path constraint cannot be met with "
                               "the largest increment";
              return report;
            }
          if (n > 0 && norm <= target &&
              (at_limit ? phi <= phi_tolerance :
                          std::abs(phi) <= phi_tolerance))
            {
              if (guard.sign * force < -guard.tolerance)
                {
                  report.failure = "the load reversed its sign";
                  return report;
                }
              report.converged = true;
              return report;
            }
          if (n >= parameters.max_iterations)
            {
              report.failure =
                "no convergence in " + std::to_string(n) + " Newton iterations";
              return report;
            }

          const double scale =
            du.l2_norm() > 0. ? du.l2_norm() : std::abs(limit) * g.l2_norm();
          const JacobianFreeOperator<Operator, VectorType> J(
            op, du, R, parameters.sqrt_eps_prec, scale);

          // dR/dlambda: the response of the full residual to the prescribed
          // increments, and the generalized force's share of it.
          const double psi = measure(constraint, g, du, R, op);
          J.vmult(rhs, g);
          rhs *= -1.;
          unsigned int iterations = solve_linear(op, J, rhs, y, report);

          // The equilibrium correction; none is needed if R_f is already
          // small (the first iteration of a step).
          double dpsi_x = 0.;
          if (norm > target)
            {
              rhs = R;
              rhs *= -1.;
              iterations += solve_linear(op, J, rhs, x, report);
              dpsi_x = derivative(op, constraint, g, du, R, psi, x, scale, dR);
            }
          else
            x = 0.;
          // The one-sided derivatives of psi along +-(y + g), the change
          // of the state per unit increase and decrease of lambda.
          step = y;
          step += g;
          const double forward =
            constraint.load_factor_weight +
            derivative(op, constraint, g, du, R, psi, step, scale, dR);
          step *= -1.;
          const double backward =
            -constraint.load_factor_weight +
            derivative(op, constraint, g, du, R, psi, step, scale, dR);

          // delta lambda from phi + dphi = 0, with dphi = dpsi_x + forward
          // delta lambda for delta lambda >= 0 and dpsi_x + backward
          // |delta lambda| for delta lambda <= 0. The dissipation is not
          // differentiable where a point starts or stops cracking: at the
          // peak of a snap-back, an increase of lambda unloads the crack
          // elastically (no dissipation) while a decrease opens it, and a
          // two-sided linearization sees no dependence at all. Of the
          // solutions on the two sides, the nearer one; none: the limit.
          const double needed   = -(phi + dpsi_x);
          double       d_lambda = std::numeric_limits<double>::infinity();
          if (forward != 0. && needed / forward >= 0.)
            d_lambda = needed / forward;
          if (backward != 0. && needed / backward >= 0. &&
              needed / backward < std::abs(d_lambda))
            d_lambda = -needed / backward;
          at_limit = false;
          if (!(delta_lambda + d_lambda <= limit &&
                delta_lambda + d_lambda >= -back_limit))
            {
              d_lambda = limit - delta_lambda;
              at_limit = true;
            }

          // delta u = x + delta lambda (y + g).
          step = y;
          step += g;
          step *= d_lambda;
          step += x;

          double alpha = 1.;
          for (unsigned int k = 0;; ++k)
            {
              trial = du;
              trial.add(alpha, step);
              op.residual(trial, R);
              const double trial_norm = internal::free_norm(op, R, rhs);
              if (k == parameters.max_line_search_steps || n == 0 ||
                  (std::isfinite(trial_norm) &&
                   trial_norm <= (1. - 1e-4 * alpha) * std::max(norm, target)))
                {
                  norm = trial_norm;
                  break;
                }
              alpha *= 0.5;
              ++report.line_search_steps;
            }
          du = trial;
          delta_lambda += alpha * d_lambda;
          force = -(g * R);
          phi   = constraint_value(constraint, delta_lambda, du, force, op);
          report.newton_iterations = n + 1;
          report.residual_history.push_back(norm);

          if (n == 0)
            {
              // The paper's first guess for this Delta lambda.
              trial = g;
              trial *= delta_lambda;
              op.residual(trial, rhs);
              const double force_level = rhs.l2_norm();
              const double reference   = internal::free_norm(op, rhs, rhs);
              report.initial_residual  = reference;
              target =
                internal::stopping_target(parameters, reference, force_level);
            }
          if (log != nullptr)
            *log << "    newton " << std::setw(2) << report.newton_iterations
                 << "  |R| " << std::scientific << std::setprecision(3) << norm
                 << "  phi " << phi << "  gmres " << std::setw(4) << iterations
                 << "  d lambda " << delta_lambda
                 << (at_limit ? " (limit)" : "") << "  step "
                 << std::defaultfloat << alpha << std::endl;
        }
    }

  private:
    /// phi at @p du, the state of the last op.residual(), with force
    /// @p force.
    static double
    constraint_value(const Constraint &c,
                     const double      delta_lambda,
                     const VectorType &du,
                     const double      force,
                     const Operator   &op)
    {
      return c.load_factor_weight * delta_lambda + c.force_weight * force +
             (c.dissipation_weight != 0. ?
                c.dissipation_weight * op.dissipation() :
                0.) +
             gauge_term(c, du) - c.value;
    }

    /// e w . du.
    static double
    gauge_term(const Constraint &c, const VectorType &du)
    {
      return c.gauge != nullptr ? c.gauge_weight * (*c.gauge * du) : 0.;
    }

    /// psi = b F + c D + e w . du at @p du, the state of the last
    /// op.residual(), which gave @p R.
    static double
    measure(const Constraint &c,
            const VectorType &g,
            const VectorType &du,
            const VectorType &R,
            const Operator   &op)
    {
      return (c.force_weight != 0. ? -c.force_weight * (g * R) : 0.) +
             (c.dissipation_weight != 0. ?
                c.dissipation_weight * op.dissipation() :
                0.) +
             gauge_term(c, du);
    }

    /**
     * The directional derivative of psi (at @p du, where psi = @p psi and
     * the residual is @p R) along @p v, by the difference quotient with the
     * step of JacobianFreeOperator. The residual must be evaluated on all
     * rows, constrained ones included (which JacobianFreeOperator zeroes):
     * those hold the generalized force. @p scratch: a vector like du.
     */
    double
    derivative(const Operator   &op,
               const Constraint &constraint,
               const VectorType &g,
               const VectorType &du,
               const VectorType &R,
               const double      psi,
               const VectorType &v,
               const double      scale,
               VectorType       &scratch) const
    {
      (void)R;
      // A constraint linear in du needs no residual evaluation.
      if (constraint.force_weight == 0. && constraint.dissipation_weight == 0.)
        return gauge_term(constraint, v);
      const double v_norm = v.l2_norm();
      if (v_norm == 0.)
        return 0.;
      const double h = parameters.sqrt_eps_prec *
                       (scale > 0. ? scale : op.typical_increment_norm()) /
                       v_norm;
      VectorType perturbed(du);
      perturbed.add(h, v);
      op.residual(perturbed, scratch);
      return (measure(constraint, g, perturbed, scratch, op) - psi) / h;
    }

    /// GMRES as in NewtonKrylov (right preconditioning); returns its
    /// iterations.
    unsigned int
    solve_linear(const Operator                                   &op,
                 const JacobianFreeOperator<Operator, VectorType> &J,
                 VectorType                                       &rhs,
                 VectorType                                       &s,
                 NewtonReport                                     &report) const
    {
      op.set_constrained_to_zero(rhs);
      s                     = 0.;
      const double rhs_norm = rhs.l2_norm();
      if (rhs_norm == 0.)
        return 0;
      SolverControl control(parameters.max_linear_iterations,
                            parameters.linear_tolerance * rhs_norm,
                            /*log_history=*/false,
                            /*log_result=*/false);
      typename SolverGMRES<VectorType>::AdditionalData data(
        parameters.gmres_restart + 2, /*right_preconditioning=*/true);
      SolverGMRES<VectorType> gmres(control, data);
      try
        {
          gmres.solve(J,
                      s,
                      rhs,
                      internal::AdmissiblePreconditioner<Operator>{op});
        }
      catch (const SolverControl::NoConvergence &)
        {
          ++report.inexact_linear_solves;
        }
      op.make_admissible(s);
      report.linear_iterations += control.last_step();
      return control.last_step();
    }

    const NewtonParameters    parameters;
    const ConditionalOStream *log;
  };
} // namespace qsmpm

#endif
