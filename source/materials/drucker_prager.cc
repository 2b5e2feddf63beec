#include <cmath>
#include <qsmpm/materials/drucker_prager.h>
#include <sstream>

namespace qsmpm
{
  template <int dim>
  std::pair<double, double>
  DruckerPrager<dim>::matching_coefficients(const double   angle_deg,
                                            const Matching matching)
  {
    const double a = angle_deg * M_PI / 180.;
    switch (matching)
      {
        case Matching::outer_cone:
          return {6. * std::sin(a) / (std::sqrt(3.) * (3. - std::sin(a))),
                  6. * std::cos(a) / (std::sqrt(3.) * (3. - std::sin(a)))};
        case Matching::inner_cone:
          return {6. * std::sin(a) / (std::sqrt(3.) * (3. + std::sin(a))),
                  6. * std::cos(a) / (std::sqrt(3.) * (3. + std::sin(a)))};
        case Matching::plane_strain:
        default:
          {
            const double t = std::tan(a);
            const double r = std::sqrt(9. + 12. * t * t);
            return {3. * t / r, 3. / r};
          }
      }
  }



  template <int dim>
  DruckerPrager<dim>::DruckerPrager(const double   young_modulus,
                                    const double   poisson_ratio,
                                    const double   cohesion,
                                    const double   friction_angle_deg,
                                    const double   dilatancy_angle_deg,
                                    const double   hardening_modulus,
                                    const Matching matching)
    : IsotropicPlasticity<dim>(young_modulus, poisson_ratio)
    , c0(cohesion)
    , H(hardening_modulus)
  {
    check_cohesion_friction(
      "Drucker-Prager", c0, friction_angle_deg, dilatancy_angle_deg, H);
    const auto f = matching_coefficients(friction_angle_deg, matching);
    eta_f        = f.first;
    xi_c         = f.second;
    eta_d        = matching_coefficients(dilatancy_angle_deg, matching).first;
  }



  template <int dim>
  DruckerPrager<dim>::DruckerPrager(const Parameters &parameters)
    : DruckerPrager(parameters.elasticity.young_modulus,
                    parameters.elasticity.poisson_ratio,
                    parameters.cohesion,
                    parameters.friction_angle,
                    parameters.dilatancy_angle,
                    parameters.hardening_modulus,
                    parameters.matching)
  {
  }



  template <int dim>
  DruckerPrager<dim>::DruckerPrager(ParameterHandler &prm)
    : DruckerPrager(Parameters::from(prm))
  {
  }



  template <int dim>
  void
  DruckerPrager<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    elasticity.add_parameters(prm);
    add_cohesion_friction_parameters(
      prm, cohesion, friction_angle, dilatancy_angle, hardening_modulus);
    Utils::add_selection<Matching>(
      prm,
      "Mohr-Coulomb matching",
      matching,
      {{"outer cone", Matching::outer_cone},
       {"inner cone", Matching::inner_cone},
       {"plane strain", Matching::plane_strain}},
      "How the cone is fitted to Mohr-Coulomb: through its "
      "compressive (outer cone) or tensile (inner cone) "
      "meridians, or to give Mohr-Coulomb's limit loads in "
      "plane strain with associative flow (plane strain).");
  }



  template <int dim>
  void
  DruckerPrager<dim>::declare_parameters(ParameterHandler &prm)
  {
    Parameters::declare_parameters(prm);
  }



  template <int dim>
  double
  DruckerPrager<dim>::cohesion(const double alpha) const
  {
    return c0 + H * alpha;
  }



  template <int dim>
  double
  DruckerPrager<dim>::yield_function(const SymmetricTensor<2, 3> &stress,
                                     const double                 alpha) const
  {
    return deviator(stress).norm() / std::sqrt(2.) +
           eta_f * trace(stress) / 3. - xi_c * cohesion(alpha);
  }



  template <int dim>
  void
  DruckerPrager<dim>::return_map(const SymmetricTensor<2, 3> &eps_tr,
                                 const double                 alpha_old,
                                 const bool                   want_tangent,
                                 Return                      &r) const
  {
    const double                G       = this->mu;
    const double                K       = this->K;
    const SymmetricTensor<2, 3> one     = unit_symmetric_tensor<3>();
    const SymmetricTensor<2, 3> e_tr    = deviator(eps_tr);
    const double                e_nrm   = e_tr.norm();
    const SymmetricTensor<2, 3> s_tr    = 2. * G * e_tr;
    const double                p_tr    = K * trace(eps_tr);
    const double                sqJ2_tr = std::sqrt(2.) * G * e_nrm;
    const double                c_n     = cohesion(alpha_old);
    const double                phi_tr  = sqJ2_tr + eta_f * p_tr - xi_c * c_n;
    if (!(phi_tr > 1e-13 * (sqJ2_tr + std::abs(eta_f * p_tr) + xi_c * c_n)))
      {
        r.stress         = s_tr + p_tr * one;
        r.elastic_strain = eps_tr;
        r.alpha          = alpha_old;
        r.increment      = 0.;
        if (want_tangent)
          r.tangent = this->D;
        return;
      }

    // Smooth portion of the cone.
    const double A      = 1. / (G + K * eta_f * eta_d + xi_c * xi_c * H);
    const double dgamma = phi_tr * A;
    if (sqJ2_tr - G * dgamma >= 0. || eta_f == 0.)
      {
        const double factor = 1. - G * dgamma / sqJ2_tr;
        const double p      = p_tr - K * eta_d * dgamma;
        r.stress            = factor * s_tr + p * one;
        r.elastic_strain    = factor * e_tr + p / (3. * K) * one;
        r.alpha             = alpha_old + xi_c * dgamma;
        r.increment         = xi_c * dgamma;
        if (want_tangent)
          {
            const SymmetricTensor<2, 3> n = e_tr / e_nrm;
            const double                a = dgamma / (std::sqrt(2.) * e_nrm);
            r.tangent =
              2. * G * (1. - a) * deviator_tensor<3>() +
              2. * G * (a - G * A) * outer_product(n, n) -
              std::sqrt(2.) * G * A * K *
                (eta_f * outer_product(n, one) +
                 eta_d * outer_product(one, n)) +
              K * (1. - K * eta_f * eta_d * A) * outer_product(one, one);
          }
        return;
      }

    // Apex. With eta_bar = 0 the flow has no volumetric part and the
    // book's alpha_ = xi / eta_bar is infinite: use the associative value
    // (see the class documentation).
    const double beta    = xi_c / eta_f;
    const double alpha_v = eta_d > 0. ? xi_c / eta_d : beta;
    const double deps_v  = (p_tr - beta * c_n) / (alpha_v * beta * H + K);
    const double p       = p_tr - K * deps_v;
    r.stress             = p * one;
    r.elastic_strain     = p / (3. * K) * one;
    r.alpha              = alpha_old + alpha_v * deps_v;
    r.increment          = alpha_v * deps_v;
    if (want_tangent)
      r.tangent =
        K * (1. - K / (K + alpha_v * beta * H)) * outer_product(one, one);
  }



  template <int dim>
  SymmetricTensor<4, 3>
  DruckerPrager<dim>::continuum_tangent(const SymmetricTensor<2, 3> &stress,
                                        const double) const
  {
    const SymmetricTensor<2, 3> s     = deviator(stress);
    const double                s_nrm = s.norm();
    // At (or next to) the apex: the elastic tangent.
    if (!(s_nrm > 1e-12 * std::abs(trace(stress))))
      return this->D;
    const double G = this->mu;
    const double K = this->K;
    const double A = 1. / (G + K * eta_f * eta_d + xi_c * xi_c * H);
    const SymmetricTensor<2, 3> one = unit_symmetric_tensor<3>();
    const SymmetricTensor<2, 3> n   = s / s_nrm;
    return this->D - A * outer_product(std::sqrt(2.) * G * n + K * eta_d * one,
                                       std::sqrt(2.) * G * n + K * eta_f * one);
  }



  template class DruckerPrager<2>;
  template class DruckerPrager<3>;

  QSMPM_REGISTER_CONSTITUTIVE_MODEL(DruckerPrager,
                                    "Drucker-Prager",
                                    "Drucker-Prager elastoplasticity with "
                                    "cohesion hardening and non-associative "
                                    "flow (E, nu, cohesion, friction and "
                                    "dilatancy angles, hardening modulus, "
                                    "Mohr-Coulomb matching; return to the "
                                    "cone or its apex, consistent tangent; "
                                    "plane strain in 2D; finite strain by the "
                                    "exponential map).")
} // namespace qsmpm
