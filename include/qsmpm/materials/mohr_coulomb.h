#ifndef qsmpm_materials_mohr_coulomb_h
#define qsmpm_materials_mohr_coulomb_h

#include <array>
#include <qsmpm/materials/isotropic_plasticity.h>
#include <qsmpm/materials/linear_elastic.h>

namespace qsmpm
{
  /**
   * Mohr-Coulomb elastoplasticity with its corners: cohesion hardening and
   * non-associative flow, small or finite strain (see IsotropicPlasticity
   * for the state fields, the 2D plane-strain treatment and the
   * finite-strain exponential map).
   *
   * In principal stresses sigma_1 >= sigma_2 >= sigma_3 (tension positive)
   * the yield function and the plastic potential are
   *
   *   Phi = (sigma_1 - sigma_3) + (sigma_1 + sigma_3) sin(phi)
   *         - 2 c(alpha) cos(phi),
   *   Psi = (sigma_1 - sigma_3) + (sigma_1 + sigma_3) sin(psi),
   *
   * c(alpha) = c0 + H alpha, with d alpha = 2 cos(phi) dgamma summed over
   * the active planes (at the apex d alpha = cos(phi)/sin(psi) d eps_v^p,
   * the same relation).
   *
   * Return mapping in principal stresses (de Souza Neto, Peric & Owen,
   * Computational Methods for Plasticity, Wiley 2008, Boxes 8.4 and 8.5):
   * the trial stress's eigenvectors are kept and, with the linear elastic
   * law and linear hardening, each return is the solution of a linear
   * system, tried in this order until one is admissible:
   *  1. the main plane (one multiplier): admissible if the returned
   *     principal stresses keep their order;
   *  2. the edge sigma_1 = sigma_2 (if the main return gave sigma_2 >
   *     sigma_1) or sigma_2 = sigma_3 (if it gave sigma_3 > sigma_2), with
   *     two planes and two multipliers: admissible if both multipliers are
   *     non-negative and the order holds;
   *  3. the apex p = c(alpha) cot(phi) (phi > 0): hydrostatic.
   * With psi = 0 and H > 0 the apex's hardening uses psi = phi (the
   * relation above has no limit); with phi = 0 (Tresca) there is no apex.
   *
   * Tangents: the elastic D as the preconditioner's tangent() (the rule of
   * IsotropicPlasticity). The algorithmic tangent that consistent_tangent()
   * and the finite-strain kirchhoff_tangent() return is the central
   * difference of the return mapping in the six trial elastic strains
   * (relative step 1e-6; an exact spectral tangent is not derived here:
   * Newton's Jacobian is the Jacobian-free one, the tangents serve the
   * preconditioner). continuum_tangent() is that difference an
   * infinitesimal plastic step past the surface.
   *
   * The elastic check uses Phi_tr > 1e-13 (|sigma_1 - sigma_3| + |sigma_1 +
   * sigma_3| + 2 c cos(phi)).
   *
   * Selected in a .prm file with `set Model = Mohr-Coulomb`; parameters in
   * subsection "Mohr-Coulomb": "Young's modulus", "Poisson's ratio",
   * "Cohesion", "Friction angle", "Dilatancy angle", "Hardening modulus".
   */
  template <int dim>
  class MohrCoulomb : public IsotropicPlasticity<dim>
  {
  public:
    using typename IsotropicPlasticity<dim>::Return;

    /**
     * E, nu, the cohesion c0 >= 0, the friction and dilatancy angles in
     * degrees (0 <= psi <= phi < 90) and the cohesion hardening modulus
     * H >= 0. phi = 0 (Tresca) needs c0 > 0.
     */
    MohrCoulomb(const double young_modulus,
                const double poisson_ratio,
                const double cohesion,
                const double friction_angle_deg,
                const double dilatancy_angle_deg,
                const double hardening_modulus = 0.);

    /// The subsection "Mohr-Coulomb".
    struct Parameters : ParameterStruct<Parameters>
    {
      IsotropicElasticity elasticity;
      double              cohesion          = 1.;
      double              friction_angle    = 30.;
      double              dilatancy_angle   = 0.;
      double              hardening_modulus = 0.;

      /// Declare the entries, bound to the members.
      void
      add_parameters(ParameterHandler &prm);
    };

    explicit MohrCoulomb(const Parameters &parameters);

    /// Construct from the subsection "Mohr-Coulomb".
    explicit MohrCoulomb(ParameterHandler &prm);

    static void
    declare_parameters(ParameterHandler &prm);

    std::string
    name() const override
    {
      return "Mohr-Coulomb";
    }

    /// The cohesion c(alpha) = c0 + H alpha.
    double
    cohesion(const double alpha) const;

    void
    return_map(const SymmetricTensor<2, 3> &trial_elastic_strain,
               const double                 alpha_old,
               const bool                   want_tangent,
               Return                      &r) const override;

    SymmetricTensor<4, 3>
    continuum_tangent(const SymmetricTensor<2, 3> &stress,
                      const double                 alpha) const override;

    /// Phi of the principal stresses of @p stress.
    double
    yield_function(const SymmetricTensor<2, 3> &stress,
                   const double                 alpha) const override;

  private:
    /// The return mapping without the tangent; whether it was plastic.
    bool
    return_stress(const SymmetricTensor<2, 3> &trial_elastic_strain,
                  const double                 alpha_old,
                  Return                      &r) const;

    /**
     * The return in principal stresses: from the trial principal stresses
     * @p s (descending) to the returned ones; returns the increment of
     * alpha, or -1 if the trial state is admissible (@p s unchanged).
     */
    double
    principal_return(std::array<double, 3> &s, const double alpha_old) const;

    const double c0;
    const double H;
    const double sin_phi, cos_phi, sin_psi;
  };
} // namespace qsmpm

#endif
