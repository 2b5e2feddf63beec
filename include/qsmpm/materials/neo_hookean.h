#ifndef qsmpm_materials_neo_hookean_h
#define qsmpm_materials_neo_hookean_h

#include <qsmpm/materials/isotropic_hyperelastic.h>

namespace qsmpm
{
  /**
   * Compressible neo-Hookean hyperelasticity with the stored energy
   *
   *   W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2,
   *
   * C = F^T F, J = det F, whose Kirchhoff stress is
   *
   *   tau = mu (b - I) + lambda ln J I,   b = F F^T,
   *
   * with the Lame constants lambda, mu of E, nu (so that the model reduces
   * to linear elasticity with E, nu for small strains).
   *
   * Consistent tangent (see ConstitutiveModel::kirchhoff_tangent()): with a
   * variation d l = d(Delta F) Delta F^{-1}, d b = d l b + b d l^T and
   * d(ln J) = tr(d l), so
   *
   *   c_ijkl = mu (delta_ik b_lj + b_il delta_jk) + lambda delta_ij delta_kl.
   *
   * In 2D the model is plane strain: F_zz = 1, so b_zz = 1, J = det of the
   * 2x2 F, and the in-plane formulas are exact (tau_zz = lambda ln J is not
   * represented). Plane stress is not supported.
   *
   * For J <= 0 (or not finite) the stress is NaN, which the Newton line
   * search treats as a failed trial.
   *
   * The small-strain interface (update_stress(), tangent()) is linear
   * elasticity with the same E, nu: sigma = sigma_old + C : d eps.
   *
   * Selected in a .prm file with `set Model = neo-Hookean`.
   */
  template <int dim>
  class NeoHookean : public IsotropicHyperelastic<dim>
  {
  public:
    std::string
    name() const override
    {
      return "neo-Hookean";
    }

    NeoHookean(const double young_modulus, const double poisson_ratio);

    /// Construct from the subsection "neo-Hookean".
    explicit NeoHookean(ParameterHandler &prm);



    /// tau = mu (b - I) + lambda ln J I at F = kinematics.F.
    void
    update_kirchhoff_stress(const PointState<dim>             &old,
                            const FiniteStrainKinematics<dim> &kinematics,
                            SymmetricTensor<2, dim>           &tau,
                            ArrayView<double> new_state) const override;

    /// c_ijkl = mu (delta_ik b_lj + b_il delta_jk) + lambda delta_ij delta_kl.
    Tensor<4, dim>
    kirchhoff_tangent(
      const PointState<dim>             &old,
      const FiniteStrainKinematics<dim> &kinematics) const override;
  };
} // namespace qsmpm

#endif
