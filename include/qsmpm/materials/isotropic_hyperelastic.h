#ifndef qsmpm_materials_isotropic_hyperelastic_h
#define qsmpm_materials_isotropic_hyperelastic_h

#include <qsmpm/materials/linear_elastic.h>

namespace qsmpm
{
  /**
   * What the isotropic hyperelastic models (Hencky, NeoHookean) share: the
   * constants E and nu with their Lame constants lambda, mu, the parameters
   * "Young's modulus" and "Poisson's ratio" of their .prm subsection, and
   * the small-strain interface, which is LinearElastic's with the same E,
   * nu (sigma = sigma_old + C : d eps; plane strain in 2D), so that each
   * model also serves Kinematics = small strain. A derived class provides
   * the Kirchhoff stress and its consistent tangent.
   */
  template <int dim>
  class IsotropicHyperelastic : public LinearElastic<dim>
  {
  public:
    IsotropicHyperelastic(const double young_modulus,
                          const double poisson_ratio);

    explicit IsotropicHyperelastic(const IsotropicElasticity &parameters);

    /// "Young's modulus" and "Poisson's ratio" (no plane stress).
    static void
    declare_parameters(ParameterHandler &prm);

    bool
    supports_finite_strain() const override;

    /// False: at finite strain the stress is a function of the
    /// deformation from the stress-free reference, so no initial stress.
    bool
    incremental_stress() const override
    {
      return false;
    }

  protected:
    const double lambda;
    const double mu;
  };
} // namespace qsmpm

#endif
