#ifndef qsmpm_solvers_jacobian_free_operator_h
#define qsmpm_solvers_jacobian_free_operator_h

#include <cmath>

namespace qsmpm
{
  /**
   * The Jacobian-vector product of paper eqs. (A.3)-(A.4) as a matrix-free
   * operator for deal.II's Krylov solvers:
   *
   *   J(du) s ~ (R(du + h s) - R(du)) / h,
   *   h = sqrt(eps_prec) ||du|| / ||s||   if du != 0,
   *   h = sqrt(eps_prec) ||s||            if du  = 0,   (h = 0, Js = 0, if s =
   * 0).
   *
   * Constrained components of the product are zero, so the Krylov vectors
   * never leave the space of admissible corrections.
   *
   * Operator must provide residual(du, R) and set_constrained_to_zero(v).
   */
  template <typename Operator, typename VectorType>
  class JacobianFreeOperator
  {
  public:
    /**
     * The product at @p du, where R(du) = @p R_du. The norm of du in h may
     * be replaced by @p scale (> 0), the size of the increments of interest,
     * for linearizations at du = 0 (see NewtonKrylov's predictor).
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
      , du_norm(scale > 0. ? scale : du.l2_norm())
    {
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
      const double h = du_norm > 0. ? sqrt_eps_prec * du_norm / s_norm :
                                      sqrt_eps_prec * s_norm;
      perturbed.reinit(du, /*omit_zeroing_entries=*/true);
      perturbed = du;
      perturbed.add(h, s);
      op.residual(perturbed, dst);
      dst.add(-1., R_du);
      dst *= 1. / h;
      op.set_constrained_to_zero(dst);
      ++n_products;
    }

    /// Number of products (residual evaluations) so far.
    unsigned int
    n_vmults() const
    {
      return n_products;
    }

  private:
    const Operator      &op;
    const VectorType    &du;
    const VectorType    &R_du;
    const double         sqrt_eps_prec;
    const double         du_norm;
    mutable VectorType   perturbed;
    mutable unsigned int n_products = 0;
  };
} // namespace qsmpm

#endif
