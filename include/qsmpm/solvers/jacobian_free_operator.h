#ifndef qsmpm_solvers_jacobian_free_operator_h
#define qsmpm_solvers_jacobian_free_operator_h

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

namespace qsmpm
{
  namespace internal
  {
    /// Whether Operator has increment_scale_floor().
    template <typename Operator, typename = void>
    struct has_increment_scale_floor : std::false_type
    {
    };

    template <typename Operator>
    struct has_increment_scale_floor<
      Operator,
      std::void_t<
        decltype(std::declval<const Operator &>().increment_scale_floor())>>
      : std::true_type
    {
    };

    /// The operator's smallest scale of the increments of interest, or 0.
    template <typename Operator>
    double
    increment_scale_floor(const Operator &op)
    {
      if constexpr (has_increment_scale_floor<Operator>::value)
        return op.increment_scale_floor();
      else
        return 0.;
    }
  } // namespace internal

  /**
   * The Jacobian-vector product of paper eqs. (A.3)-(A.4) as a matrix-free
   * operator for deal.II's Krylov solvers:
   *
   *   J(du) s ~ (R(du + h s) - R(du)) / h,   h = sqrt(eps_prec) d / ||s||,
   *
   * so that the perturbation h s has the norm sqrt(eps_prec) d, where d is
   * the size of the increments of interest: ||du||, or, where du = 0 (a
   * linearization at the start of a step without prescribed increments),
   * the operator's typical_increment_norm(); also where ||du|| is below
   * 1e-8 of it, a round-off increment. (h = 0, Js = 0, if s = 0.)
   *
   * The perturbation must be relative to a displacement scale, not to
   * ||s||: with a preconditioner, the Krylov directions s are corrections
   * of the size of residual / stiffness, which in physical units can be
   * 1e-6 and less. The earlier choice h = sqrt(eps_prec) ||s|| for du = 0
   * then perturbed the strains by less than the round-off of the stresses
   * already on the points; the difference quotient was exactly zero and
   * GMRES divided by zero (issue 10: the self-weight column with AMG
   * stopped with a NaN residual at its second load step).
   *
   * An operator may also provide increment_scale_floor(), a size below
   * which ||du|| is not taken (0: none): a rigid body that slides past a
   * body in steady sliding changes the residual while du, the body's own
   * deformation, is almost zero, and a perturbation relative to that
   * ||du|| made the products round-off (StepOperator: the bodies'
   * motion in the step).
   *
   * Constrained components of the product are zero, so the Krylov vectors
   * never leave the space of admissible corrections.
   *
   * Operator must provide residual(du, R), set_constrained_to_zero(v) and
   * typical_increment_norm().
   */
  template <typename Operator, typename VectorType>
  class JacobianFreeOperator
  {
  public:
    /**
     * The product at @p du, where R(du) = @p R_du. The norm of du in h may
     * be replaced by @p scale (> 0), the size of the increments of interest,
     * for linearizations at du = 0 (see NewtonKrylov's predictor); if both
     * are zero (or ||du|| below 1e-8 of it), the operator's
     * typical_increment_norm() is used.
     */
    JacobianFreeOperator(const Operator   &op,
                         const VectorType &du,
                         const VectorType &R_du,
                         const double      sqrt_eps_prec,
                         const double      scale = 0.)
      : op(op)
      , du(du)
      , R_du(R_du)
      , sqrt_eps_prec(sqrt_eps_prec)
      , increment_scale([&]() {
        const double d =
          scale > 0. ?
            scale :
            std::max(du.l2_norm(), internal::increment_scale_floor(op));
        // An increment of round-off size (a step that starts in
        // equilibrium, whose predictor moved nothing) sets no scale either:
        // a perturbation relative to it would be round-off itself.
        const double typical = op.typical_increment_norm();
        return d > 1e-8 * typical ? d : typical;
      }())
    {
      Assert(increment_scale > 0., ExcInternalError());
    }

    void
    vmult(VectorType &dst, const VectorType &s) const
    {
      const double s_norm = s.l2_norm();
      if (s_norm == 0.)
        {
          dst = 0.;
          return;
        }
      const double h = sqrt_eps_prec * increment_scale / s_norm;
      perturbed.reinit(du, /*omit_zeroing_entries=*/true);
      perturbed = du;
      perturbed.add(h, s);
      op.residual(perturbed, dst);
      dst.add(-1., R_du);
      dst *= 1. / h;
      op.set_constrained_to_zero(dst);
    }

  private:
    const Operator    &op;
    const VectorType  &du;
    const VectorType  &R_du;
    const double       sqrt_eps_prec;
    const double       increment_scale;
    mutable VectorType perturbed;
  };
} // namespace qsmpm

#endif
