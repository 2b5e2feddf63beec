#ifndef qsmpm_materials_drucker_prager_h
#define qsmpm_materials_drucker_prager_h

#include <qsmpm/materials/isotropic_plasticity.h>
#include <qsmpm/materials/linear_elastic.h>

namespace qsmpm
{
  /**
   * Drucker-Prager elastoplasticity with linear cohesion hardening and a
   * non-associative flow through the dilatancy angle, small or finite
   * strain (see IsotropicPlasticity for the state fields, the 2D
   * plane-strain treatment and the finite-strain exponential map). After de
   * Souza Neto, Peric & Owen, Computational Methods for Plasticity, Wiley
   * 2008, sections 6.4.6 and 8.3.
   *
   * Stress invariants: p = tr(sigma)/3 (tension positive), s = dev sigma,
   * J2 = 1/2 s : s. Yield function and plastic potential
   *
   *   Phi = sqrt(J2) + eta p - xi c(alpha),   Psi = sqrt(J2) + eta_bar p,
   *   c(alpha) = c0 + H alpha,
   *
   * with the hardening variable alpha (state field
   * "equivalent_plastic_strain") evolving as d alpha = xi dgamma (de Souza
   * Neto eq. 8.41), and d eps_p = dgamma dPsi/dsigma = dgamma (s /
   * (2 sqrt(J2)) + eta_bar/3 1). The ratio of plastic volumetric strain to
   * the norm of the plastic deviatoric strain is sqrt(2) eta_bar.
   *
   * Mohr-Coulomb matching ("Mohr-Coulomb matching", friction angle phi,
   * dilatancy angle psi):
   * - outer cone (compressive meridian):
   *   eta = 6 sin phi / (sqrt(3)(3 - sin phi)),
   *   xi  = 6 cos phi / (sqrt(3)(3 - sin phi));
   * - inner cone (tensile meridian): the same with 3 + sin phi;
   * - plane strain: eta = 3 tan phi / sqrt(9 + 12 tan^2 phi),
   *   xi = 3 / sqrt(9 + 12 tan^2 phi): under plane strain with associative
   *   flow the limit loads equal Mohr-Coulomb's (e.g. the limit shear
   *   stress on a zero-extension plane of zero normal stress is c);
   * and eta_bar is eta's formula with psi in place of phi.
   *
   * Return mapping (ibid., sec. 8.3, Box 8.9), exact for linear hardening, if
   * Phi_tr > 0:
   * - smooth cone:
   *   dgamma = Phi_tr / (G + K eta eta_bar + xi^2 H),
   *   s = (1 - G dgamma / sqrt(J2_tr)) s_tr, p = p_tr - K eta_bar dgamma,
   *   alpha = alpha_n + xi dgamma,
   *   valid if sqrt(J2_tr) - G dgamma >= 0;
   * - otherwise the apex: with alpha_ = xi / eta_bar and beta = xi / eta,
   *   d eps_v = (p_tr - beta c(alpha_n)) / (alpha_ beta H + K),
   *   p = p_tr - K d eps_v (= beta c(alpha)), s = 0,
   *   alpha = alpha_n + alpha_ d eps_v.
   *
   *   A non-dilatant flow (psi = 0, eta_bar = 0) has no volumetric plastic
   *   strain, so a trial state beyond the apex has no admissible return in
   *   the book's scheme (alpha_ is infinite). This implementation then
   *   returns to the apex as if the flow were associative at the apex
   *   (alpha_ = xi/eta, a tension cut-off at the apex): the stress is the
   *   apex stress beta c(alpha) 1 and the cohesion hardens as for psi =
   *   phi. Such states arise only under (near) hydrostatic tension beyond
   *   the apex pressure.
   *
   * Consistent tangents (ibid., sec. 8.3; derived from the return above),
   * with the trial
   * deviatoric elastic strain e_tr, n = e_tr/|e_tr| and
   * A = 1/(G + K eta eta_bar + xi^2 H):
   * - smooth cone:
   *   D = 2G (1 - dgamma/(sqrt(2)|e_tr|)) I_dev
   *     + 2G (dgamma/(sqrt(2)|e_tr|) - G A) n (x) n
   *     - sqrt(2) G A K (eta n (x) 1 + eta_bar 1 (x) n)
   *     + K (1 - K eta eta_bar A) 1 (x) 1,
   * - apex: D = K (1 - K/(K + alpha_ beta H)) 1 (x) 1
   * (not major-symmetric unless psi = phi). Continuum tangent on the
   * smooth cone (plastic loading, n = s/|s|):
   *   D_ep = D - A (sqrt(2) G n + K eta_bar 1) (x) (sqrt(2) G n + K eta 1);
   * at the apex (s = 0) the elastic D is used instead, since the cone
   * normal is not defined there and the apex tangent vanishes for H = 0.
   *
   * The elastic check uses Phi_tr > 1e-13 (sqrt(J2_tr) + |eta p_tr| +
   * xi c(alpha_n)).
   *
   * Selected in a .prm file with `set Model = Drucker-Prager`; parameters
   * in subsection "Drucker-Prager": "Young's modulus", "Poisson's ratio",
   * "Cohesion" (c0 >= 0), "Friction angle" (phi in [0, 90) degrees),
   * "Dilatancy angle" (psi in [0, phi] degrees), "Hardening modulus" (H >=
   * 0, of the cohesion) and "Mohr-Coulomb matching" (outer cone, inner cone
   * or plane strain).
   */
  template <int dim>
  class DruckerPrager : public IsotropicPlasticity<dim>
  {
  public:
    using typename IsotropicPlasticity<dim>::Return;

    /// How eta and xi are matched to the Mohr-Coulomb parameters.
    enum class Matching
    {
      outer_cone,
      inner_cone,
      plane_strain
    };

    /**
     * E, nu, the cohesion c0 >= 0, the friction angle phi and the
     * dilatancy angle psi in degrees (0 <= psi <= phi < 90), the cohesion
     * hardening modulus H >= 0 and the matching. phi = 0 (a von Mises-like
     * cylinder, sqrt(J2) <= xi c) needs c0 > 0.
     */
    DruckerPrager(const double   young_modulus,
                  const double   poisson_ratio,
                  const double   cohesion,
                  const double   friction_angle_deg,
                  const double   dilatancy_angle_deg = 0.,
                  const double   hardening_modulus   = 0.,
                  const Matching matching            = Matching::plane_strain);

    /// The subsection "Drucker-Prager".
    struct Parameters : ParameterStruct<Parameters>
    {
      IsotropicElasticity elasticity;
      double              cohesion          = 1e-3;
      double              friction_angle    = 30.;
      double              dilatancy_angle   = 0.;
      double              hardening_modulus = 0.;
      Matching            matching          = Matching::plane_strain;

      /// Declare the entries, bound to the members.
      void
      add_parameters(ParameterHandler &prm);
    };

    explicit DruckerPrager(const Parameters &parameters);

    /// Construct from the subsection "Drucker-Prager".
    explicit DruckerPrager(ParameterHandler &prm);

    /// The entries of the subsection "Drucker-Prager".
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * The coefficients (eta, xi) of the matching for the angle @p angle_deg
     * (for eta_bar: the first of the pair at the dilatancy angle).
     */
    static std::pair<double, double>
    matching_coefficients(const double angle_deg, const Matching matching);

    std::string
    name() const override
    {
      return "Drucker-Prager";
    }

    void
    return_map(const SymmetricTensor<2, 3> &trial_elastic_strain,
               const double                 alpha_old,
               const bool                   want_tangent,
               Return                      &r) const override;

    SymmetricTensor<4, 3>
    continuum_tangent(const SymmetricTensor<2, 3> &stress,
                      const double                 alpha) const override;

    /// Phi = sqrt(J2) + eta p - xi c(alpha).
    double
    yield_function(const SymmetricTensor<2, 3> &stress,
                   const double                 alpha) const override;

    /// c(alpha) = c0 + H alpha.
    double
    cohesion(const double alpha) const;

    /// eta (friction).
    double
    eta() const
    {
      return eta_f;
    }

    /// eta_bar (dilatancy).
    double
    eta_bar() const
    {
      return eta_d;
    }

    /// xi (cohesion).
    double
    xi() const
    {
      return xi_c;
    }

  private:
    const double c0;
    const double H;
    double       eta_f;
    double       xi_c;
    double       eta_d;
  };
} // namespace qsmpm

#endif
