#ifndef qsmpm_materials_hencky_h
#define qsmpm_materials_hencky_h

#include <qsmpm/materials/isotropic_hyperelastic.h>

namespace qsmpm
{
  /**
   * Isotropic Hencky hyperelasticity: Hooke's law between the Kirchhoff
   * stress and the logarithmic (Hencky) strain,
   *
   *   tau = lambda tr(eps) I + 2 mu eps = D : eps,   eps = 1/2 ln b,
   *
   * with the left Cauchy-Green tensor b = F F^T, the Lame constants lambda,
   * mu of E, nu and D the isotropic elasticity tensor. The stored energy is
   * W = lambda/2 tr(eps)^2 + mu eps : eps; the model is exact for large
   * rotations and reduces to linear elasticity for small strains.
   *
   * Consistent tangent (see ConstitutiveModel::kirchhoff_tangent()): with a
   * variation d l = d(Delta F) Delta F^{-1}, d F = d l F and
   * d b = d l b + b d l^T, so
   *
   *   d tau = D : 1/2 L : (d l b + b d l^T),
   *   c_ijkl = sum_q (D : L)_ijkq b_ql,
   *
   * where L = d(ln b)/d b is the derivative of the tensor logarithm by the
   * Daleckii-Krein formula in the eigenbasis of b (see TensorFunctions; it
   * is accurate also for equal or nearly equal principal stretches).
   *
   * In 2D the model is plane strain: F_zz = 1, so b_zz = 1, ln b_zz = 0 and
   * the 2x2 in-plane formulas are exact (tau_zz = lambda tr(eps) is not
   * represented). Plane stress is not supported.
   *
   * For a deformation gradient with J = det F <= 0 (or not finite) the
   * stress is NaN, which the Newton line search treats as a failed trial;
   * the tangent depends on b only.
   *
   * The small-strain interface (update_stress(), tangent()) is linear
   * elasticity with the same E, nu: sigma = sigma_old + C : d eps.
   *
   * Selected in a .prm file with `set Model = hencky`.
   */
  template <int dim>
  class Hencky : public IsotropicHyperelastic<dim>
  {
  public:
    std::string
    name() const override
    {
      return "hencky";
    }

    Hencky(const double young_modulus, const double poisson_ratio);

    /// Construct from the subsection "hencky".
    explicit Hencky(ParameterHandler &prm);



    /// tau = D : 1/2 ln(F F^T) at F = kinematics.F.
    void
    update_kirchhoff_stress(const PointState<dim>             &old,
                            const FiniteStrainKinematics<dim> &kinematics,
                            SymmetricTensor<2, dim>           &tau,
                            ArrayView<double> new_state) const override;

    /// c_ijkl = sum_q (D : d(ln b)/d b)_ijkq b_ql at b = F F^T.
    Tensor<4, dim>
    kirchhoff_tangent(
      const PointState<dim>             &old,
      const FiniteStrainKinematics<dim> &kinematics) const override;
  };
} // namespace qsmpm

#endif
