#ifndef qsmpm_materials_von_mises_h
#define qsmpm_materials_von_mises_h

#include <qsmpm/materials/isotropic_plasticity.h>
#include <qsmpm/materials/linear_elastic.h>

namespace qsmpm
{
  /**
   * J2 (von Mises) elastoplasticity with linear isotropic hardening,
   * associative flow, small or finite strain (see IsotropicPlasticity for
   * the state fields, the 2D plane-strain treatment and the finite-strain
   * exponential map).
   *
   * Yield function, with the deviatoric stress s and the equivalent plastic
   * strain alpha (state field "equivalent_plastic_strain"):
   *
   *   Phi = q - sigma_y(alpha),   q = sqrt(3/2) |s| = sqrt(3 J2),
   *   sigma_y(alpha) = sigma_y0 + H alpha,
   *
   * (H = 0: perfect plasticity). Flow d eps_p = dgamma sqrt(3/2) s/|s|,
   * d alpha = dgamma = sqrt(2/3) |d eps_p|.
   *
   * Radial return (de Souza Neto, Peric & Owen, Computational Methods for
   * Plasticity, Wiley 2008, Box 7.3): with the trial deviator s_tr =
   * 2 G dev(eps_e_trial), q_tr = sqrt(3/2)|s_tr|, if Phi_tr = q_tr -
   * sigma_y(alpha_n) > 0,
   *
   *   dgamma = Phi_tr / (3 G + H),   s = (1 - 3 G dgamma / q_tr) s_tr,
   *   alpha = alpha_n + dgamma,      p = p_tr
   *
   * (exact for linear hardening). Algorithmic tangent (Box 7.4), with
   * N = s_tr / |s_tr| and I_dev the deviatoric projection:
   *
   *   D_alg = 2G (1 - 3G dgamma/q_tr) I_dev
   *         + 6 G^2 (dgamma/q_tr - 1/(3G + H)) N (x) N + K 1 (x) 1.
   *
   * Continuum tangent (plastic loading at a stress on the yield surface,
   * N = s/|s|): D - 6 G^2/(3G + H) N (x) N.
   *
   * The elastic check uses Phi_tr > 1e-13 sigma_y(alpha_n), so that a
   * committed state re-evaluated with a zero increment stays elastic despite
   * round-off.
   *
   * Selected in a .prm file with `set Model = von Mises`; parameters in
   * subsection "von Mises": "Young's modulus", "Poisson's ratio", "Yield
   * stress" (sigma_y0 > 0), "Hardening modulus" (H >= 0).
   */
  template <int dim>
  class VonMises : public IsotropicPlasticity<dim>
  {
  public:
    using typename IsotropicPlasticity<dim>::Return;

    /// E, nu, the initial yield stress sigma_y0 > 0 and H >= 0.
    VonMises(const double young_modulus,
             const double poisson_ratio,
             const double yield_stress,
             const double hardening_modulus = 0.);

    /// The subsection "von Mises".
    struct Parameters : ParameterStruct<Parameters>
    {
      IsotropicElasticity elasticity;
      double              yield_stress      = 1e-3;
      double              hardening_modulus = 0.;

      /// Declare the entries, bound to the members.
      void
      add_parameters(ParameterHandler &prm);
    };

    explicit VonMises(const Parameters &parameters);

    /// Construct from the subsection "von Mises".
    explicit VonMises(ParameterHandler &prm);

    /// The entries of the subsection "von Mises".
    static void
    declare_parameters(ParameterHandler &prm);

    std::string
    name() const override
    {
      return "von Mises";
    }

    /// False: J2 flow keeps the volume, so plain F-bar is already the
    /// split of the volume change that dilatant models need.
    bool
    plastic_flow_changes_volume() const override
    {
      return false;
    }

    void
    return_map(const SymmetricTensor<2, 3> &trial_elastic_strain,
               const double                 alpha_old,
               const bool                   want_tangent,
               Return                      &r) const override;

    SymmetricTensor<4, 3>
    continuum_tangent(const SymmetricTensor<2, 3> &stress,
                      const double                 alpha) const override;

    /// Phi = sqrt(3/2)|s| - sigma_y(alpha).
    double
    yield_function(const SymmetricTensor<2, 3> &stress,
                   const double                 alpha) const override;

    /// sigma_y(alpha) = sigma_y0 + H alpha.
    double
    yield_stress(const double alpha) const;

  private:
    const double sigma_y0;
    const double H;
  };
} // namespace qsmpm

#endif
