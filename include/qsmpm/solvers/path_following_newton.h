#ifndef qsmpm_solvers_path_following_newton_h
#define qsmpm_solvers_path_following_newton_h

#include <algorithm>
#include <cmath>
#include <deal.II/base/conditional_ostream.h>
#include <iomanip>
#include <limits>
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
   * dissipate in the step (Operator::dissipation() of a residual
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
   * Operator as for NewtonKrylov, and with
   *   - double dissipation(const Evaluation &e) const;
   *     (the energy all points dissipate in the state of the evaluation
   *     that returned e).
   */
  template <typename Operator, typename VectorType>
  class PathFollowingNewton
  {
  public:
    /// What Operator::residual() returns besides the residual.
    using Evaluation = typename internal::EvaluationOf<Operator, VectorType>;

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
     * rows, @p force F(du), and @p evaluation what the
     * evaluation of that residual found (see Operator::residual()). A
     * solution that violates @p guard is a failure ("the load reversed its
     * sign").
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
          Evaluation       &evaluation,
          const ForceGuard &guard = ForceGuard()) const
    {
      NewtonReport report;
      Iterate      it{du, R, delta_lambda, force, du, du, du, du, du, du};
      R.reinit(du);
      du           = 0.;
      delta_lambda = 0.;

      it.last = op.residual(du, R);
      force   = -(g * R);
      it.norm = internal::free_norm(op, R, it.rhs);
      it.phi =
        constraint_value(constraint, delta_lambda, du, force, op, it.last);
      report.initial_residual = it.norm;
      report.residual_history.push_back(it.norm);
      // The stopping test of NewtonKrylov relative to the residual of the
      // paper's first guess (prescribed increments, zero elsewhere); that
      // guess is known once the predictor has fixed Delta lambda.
      it.target = parameters.tolerance * parameters.residual_floor;
      const double phi_tolerance =
        parameters.tolerance * std::max(std::abs(constraint.value), 1e-300);

      for (unsigned int n = 0;; ++n)
        {
          report.final_residual = it.norm;
          if (finished(it, n, phi_tolerance, allow_limit, guard, report))
            {
              evaluation = it.accepted;
              return report;
            }
          const Correction correction =
            solve_bordered(op, g, constraint, limit, back_limit, it, report);
          const double alpha =
            n == 0 ? predictor(op, g, constraint, correction, it, report) :
                     corrector(op, g, constraint, correction, it, report);
          report.newton_iterations = n + 1;
          if (log != nullptr)
            *log << "    newton " << std::setw(2) << report.newton_iterations
                 << "  |R| " << std::scientific << std::setprecision(3)
                 << it.norm << "  phi " << it.phi << "  gmres " << std::setw(4)
                 << correction.iterations << "  d lambda " << delta_lambda
                 << (it.at_limit ? " (limit)" : "") << "  step "
                 << std::defaultfloat << alpha << std::endl;
        }
    }

  private:
    /**
     * The iterate of solve() (the caller's du, R, Delta lambda and F), the
     * free norm of its residual, its constraint value, the stopping
     * target, whether Delta lambda is at the limit, and work vectors.
     */
    struct Iterate
    {
      VectorType &du;
      VectorType &R;
      double     &delta_lambda;
      double     &force;
      /// x, y: the two solutions of the bordered system; step: the
      /// Newton step; rhs, trial, dR: scratch.
      VectorType x, y, rhs, trial, dR, step;
      double     norm     = 0.;
      double     phi      = 0.;
      double     target   = 0.;
      bool       at_limit = false;
      /// What the last residual evaluation found (whose dissipation psi
      /// reads), and the evaluation of du.
      Evaluation last{}, accepted{};
    };

    /// The Newton step of one iteration (in Iterate::step) and its
    /// load-factor part.
    struct Correction
    {
      double       d_lambda;
      unsigned int iterations;
    };

    /**
     * Acceptance: whether the solve ends at the iterate @p it of iteration
     * @p n, converged (the residual below the target and the constraint
     * met, or, at the limit, not exceeded, with the force of the sign of
     * @p guard) or failed (report.failure says why).
     */
    bool
    finished(const Iterate     &it,
             const unsigned int n,
             const double       phi_tolerance,
             const bool         allow_limit,
             const ForceGuard  &guard,
             NewtonReport      &report) const
    {
      if (!std::isfinite(it.norm) || !std::isfinite(it.phi))
        {
          internal::record_failure(report,
                                   "the residual is not a finite number");
          return true;
        }
      const bool equilibrium = n > 0 && it.norm <= it.target;
      if (equilibrium && it.at_limit && !allow_limit)
        {
          report.failure = "the path constraint cannot be met with "
                           "the largest increment";
          return true;
        }
      if (equilibrium && (it.at_limit ? it.phi <= phi_tolerance :
                                        std::abs(it.phi) <= phi_tolerance))
        {
          if (guard.sign * it.force < -guard.tolerance)
            report.failure = "the load reversed its sign";
          else
            report.converged = true;
          return true;
        }
      if (n >= parameters.max_iterations)
        {
          report.failure =
            "no convergence in " + std::to_string(n) + " Newton iterations";
          return true;
        }
      return false;
    }

    /**
     * The bordered system of one iteration at @p it (see the class
     * documentation): x and y by GMRES, delta lambda from the linearized
     * constraint on the nearer side, or the limit (Iterate::at_limit),
     * and the step delta u = x + delta lambda (y + g) in Iterate::step.
     */
    Correction
    solve_bordered(const Operator   &op,
                   const VectorType &g,
                   const Constraint &constraint,
                   const double      limit,
                   const double      back_limit,
                   Iterate          &it,
                   NewtonReport     &report) const
    {
      const double scale =
        it.du.l2_norm() > 0. ? it.du.l2_norm() : std::abs(limit) * g.l2_norm();
      const JacobianFreeOperator<Operator, VectorType> J(
        op, it.du, it.R, parameters.sqrt_eps_prec, scale);

      // dR/dlambda: the response of the full residual to the prescribed
      // increments, and the generalized force's share of it.
      const double psi = measure(constraint, g, it.du, it.R, op, it.last);
      J.vmult(it.rhs, g);
      it.rhs *= -1.;
      unsigned int iterations =
        internal::solve_correction(
          op, J, parameters, parameters.linear_tolerance, it.rhs, it.y, report)
          .iterations;

      // The equilibrium correction; none is needed if R_f is already
      // small (the first iteration of a step).
      double dpsi_x = 0.;
      if (it.norm > it.target)
        {
          it.rhs = it.R;
          it.rhs *= -1.;
          iterations += internal::solve_correction(op,
                                                   J,
                                                   parameters,
                                                   parameters.linear_tolerance,
                                                   it.rhs,
                                                   it.x,
                                                   report)
                          .iterations;
          dpsi_x =
            derivative(op, constraint, g, it.du, it.R, psi, it.x, scale, it.dR);
        }
      else
        it.x = 0.;
      // The one-sided derivatives of psi along +-(y + g), the change
      // of the state per unit increase and decrease of lambda.
      it.step = it.y;
      it.step += g;
      const double forward =
        constraint.load_factor_weight +
        derivative(op, constraint, g, it.du, it.R, psi, it.step, scale, it.dR);
      it.step *= -1.;
      const double backward =
        -constraint.load_factor_weight +
        derivative(op, constraint, g, it.du, it.R, psi, it.step, scale, it.dR);

      // delta lambda from phi + dphi = 0, with dphi = dpsi_x + forward
      // delta lambda for delta lambda >= 0 and dpsi_x + backward
      // |delta lambda| for delta lambda <= 0. The dissipation is not
      // differentiable where a point starts or stops cracking: at the
      // peak of a snap-back, an increase of lambda unloads the crack
      // elastically (no dissipation) while a decrease opens it, and a
      // two-sided linearization sees no dependence at all. Of the
      // solutions on the two sides, the nearer one; none: the limit.
      const double needed   = -(it.phi + dpsi_x);
      double       d_lambda = std::numeric_limits<double>::infinity();
      if (forward != 0. && needed / forward >= 0.)
        d_lambda = needed / forward;
      if (backward != 0. && needed / backward >= 0. &&
          needed / backward < std::abs(d_lambda))
        d_lambda = -needed / backward;
      it.at_limit = false;
      if (!(it.delta_lambda + d_lambda <= limit &&
            it.delta_lambda + d_lambda >= -back_limit))
        {
          d_lambda    = limit - it.delta_lambda;
          it.at_limit = true;
        }

      // delta u = x + delta lambda (y + g).
      it.step = it.y;
      it.step += g;
      it.step *= d_lambda;
      it.step += it.x;
      return {d_lambda, iterations};
    }

    /**
     * The predictor, the first iteration from du = 0: the whole step of
     * @p correction (the tangent predictor), after which the paper's first
     * guess for this Delta lambda (its prescribed increments, zero
     * elsewhere) is known and sets the stopping target. Returns the step
     * length, 1.
     */
    double
    predictor(const Operator   &op,
              const VectorType &g,
              const Constraint &constraint,
              const Correction &correction,
              Iterate          &it,
              NewtonReport     &report) const
    {
      const double alpha = line_search(op, false, it, report);
      update(op, g, constraint, correction, alpha, it, report);
      it.trial = g;
      it.trial *= it.delta_lambda;
      // The constraint measure psi of the next iteration reads the
      // dissipation of this evaluation, the last one (as the solver always
      // has).
      it.last                  = op.residual(it.trial, it.rhs);
      const double force_level = it.rhs.l2_norm();
      const double reference   = internal::free_norm(op, it.rhs, it.rhs);
      report.initial_residual  = reference;
      it.target = internal::stopping_target(parameters, reference, force_level);
      return alpha;
    }

    /**
     * A corrector: the step of @p correction with a backtracking line
     * search on the free residual norm. Returns the step length.
     */
    double
    corrector(const Operator   &op,
              const VectorType &g,
              const Constraint &constraint,
              const Correction &correction,
              Iterate          &it,
              NewtonReport     &report) const
    {
      const double alpha = line_search(op, true, it, report);
      update(op, g, constraint, correction, alpha, it, report);
      return alpha;
    }

    /**
     * The trial point du + alpha step in Iterate::trial, its residual in
     * Iterate::R and the free norm in Iterate::norm: alpha = 1, halved
     * (if @p backtrack) until the norm decreases enough or the line
     * search's halvings are used up. Returns alpha.
     */
    double
    line_search(const Operator &op,
                const bool      backtrack,
                Iterate        &it,
                NewtonReport   &report) const
    {
      double alpha = 1.;
      for (unsigned int k = 0;; ++k)
        {
          it.trial = it.du;
          it.trial.add(alpha, it.step);
          it.last                 = op.residual(it.trial, it.R);
          const double trial_norm = internal::free_norm(op, it.R, it.rhs);
          if (k == parameters.max_line_search_steps || !backtrack ||
              (std::isfinite(trial_norm) &&
               trial_norm <=
                 (1. - 1e-4 * alpha) * std::max(it.norm, it.target)))
            {
              it.norm = trial_norm;
              return alpha;
            }
          alpha *= 0.5;
          ++report.line_search_steps;
        }
    }

    /// Accept the trial point of line_search() with the load-factor
    /// increment alpha d_lambda: the new force and phi.
    void
    update(const Operator   &op,
           const VectorType &g,
           const Constraint &constraint,
           const Correction &correction,
           const double      alpha,
           Iterate          &it,
           NewtonReport     &report) const
    {
      it.du = it.trial;
      it.delta_lambda += alpha * correction.d_lambda;
      it.force = -(g * it.R);
      it.phi   = constraint_value(
        constraint, it.delta_lambda, it.du, it.force, op, it.last);
      it.accepted = it.last;
      report.residual_history.push_back(it.norm);
    }

    /// phi at @p du, whose residual evaluation gave @p evaluation and
    /// the force
    /// @p force.
    static double
    constraint_value(const Constraint &c,
                     const double      delta_lambda,
                     const VectorType &du,
                     const double      force,
                     const Operator   &op,
                     const Evaluation &evaluation)
    {
      return c.load_factor_weight * delta_lambda + c.force_weight * force +
             (c.dissipation_weight != 0. ?
                c.dissipation_weight * op.dissipation(evaluation) :
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
    /// op.residual(), which gave @p R and @p evaluation.
    static double
    measure(const Constraint &c,
            const VectorType &g,
            const VectorType &du,
            const VectorType &R,
            const Operator   &op,
            const Evaluation &evaluation)
    {
      return (c.force_weight != 0. ? -c.force_weight * (g * R) : 0.) +
             (c.dissipation_weight != 0. ?
                c.dissipation_weight * op.dissipation(evaluation) :
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
      const Evaluation evaluation = op.residual(perturbed, scratch);
      return (measure(constraint, g, perturbed, scratch, op, evaluation) -
              psi) /
             h;
    }

    const NewtonParameters    parameters;
    const ConditionalOStream *log;
  };
} // namespace qsmpm

#endif
