#include <cmath>
#include <qsmpm/materials/von_mises.h>
#include <sstream>

namespace qsmpm
{

  template <int dim>
  VonMises<dim>::VonMises(const double young_modulus,
                          const double poisson_ratio,
                          const double yield_stress,
                          const double hardening_modulus)
    : IsotropicPlasticity<dim>(young_modulus, poisson_ratio)
    , sigma_y0(yield_stress)
    , H(hardening_modulus)
  {
    AssertThrow(sigma_y0 > 0 && std::isfinite(sigma_y0),
                ExcMessage("von Mises: the 'Yield stress' must be positive "
                           "(is " +
                           to_text(sigma_y0) + ")."));
    AssertThrow(H >= 0 && std::isfinite(H),
                ExcMessage("von Mises: the 'Hardening modulus' must be "
                           "non-negative (softening is not supported; is " +
                           to_text(H) + ")."));
  }



  template <int dim>
  VonMises<dim>::VonMises(const Parameters &parameters)
    : VonMises(parameters.elasticity.young_modulus,
               parameters.elasticity.poisson_ratio,
               parameters.yield_stress,
               parameters.hardening_modulus)
  {
  }



  template <int dim>
  VonMises<dim>::VonMises(ParameterHandler &prm)
    : VonMises(Parameters::from(prm))
  {
  }



  template <int dim>
  void
  VonMises<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    elasticity.add_parameters(prm);
    prm.add_parameter("Yield stress",
                      yield_stress,
                      "sigma_y0 > 0: the initial uniaxial yield stress "
                      "(same unit as Young's modulus).",
                      Patterns::Double(0.));
    prm.add_parameter("Hardening modulus",
                      hardening_modulus,
                      "H >= 0: linear isotropic hardening, sigma_y = "
                      "sigma_y0 + H alpha with the equivalent plastic strain "
                      "alpha (0: perfect plasticity).",
                      Patterns::Double(0.));
  }



  template <int dim>
  void
  VonMises<dim>::declare_parameters(ParameterHandler &prm)
  {
    Parameters::declare_parameters(prm);
  }



  template <int dim>
  double
  VonMises<dim>::yield_stress(const double alpha) const
  {
    return sigma_y0 + H * alpha;
  }



  template <int dim>
  double
  VonMises<dim>::yield_function(const SymmetricTensor<2, 3> &stress,
                                const double                 alpha) const
  {
    return std::sqrt(1.5) * deviator(stress).norm() - yield_stress(alpha);
  }



  template <int dim>
  void
  VonMises<dim>::return_map(const SymmetricTensor<2, 3> &eps_tr,
                            const double                 alpha_old,
                            const bool                   want_tangent,
                            Return                      &r) const
  {
    const double                G     = this->mu;
    const double                K     = this->K;
    const SymmetricTensor<2, 3> s_tr  = 2. * G * deviator(eps_tr);
    const double                p_tr  = K * trace(eps_tr);
    const double                s_nrm = s_tr.norm();
    const double                q_tr  = std::sqrt(1.5) * s_nrm;
    const double                sy    = yield_stress(alpha_old);
    const double                phi   = q_tr - sy;
    if (!(phi > 1e-13 * sy))
      {
        r.stress         = s_tr + p_tr * unit_symmetric_tensor<3>();
        r.elastic_strain = eps_tr;
        r.alpha          = alpha_old;
        r.increment      = 0.;
        if (want_tangent)
          r.tangent = this->D;
        return;
      }
    const double                dgamma = phi / (3. * G + H);
    const SymmetricTensor<2, 3> N      = s_tr / s_nrm;
    const double                factor = 1. - 3. * G * dgamma / q_tr;
    r.stress         = factor * s_tr + p_tr * unit_symmetric_tensor<3>();
    r.elastic_strain = eps_tr - dgamma * std::sqrt(1.5) * N;
    r.alpha          = alpha_old + dgamma;
    r.increment      = dgamma;
    if (want_tangent)
      r.tangent =
        2. * G * factor * deviator_tensor<3>() +
        6. * G * G * (dgamma / q_tr - 1. / (3. * G + H)) * outer_product(N, N) +
        K *
          outer_product(unit_symmetric_tensor<3>(), unit_symmetric_tensor<3>());
  }



  template <int dim>
  SymmetricTensor<4, 3>
  VonMises<dim>::continuum_tangent(const SymmetricTensor<2, 3> &stress,
                                   const double) const
  {
    const SymmetricTensor<2, 3> s = deviator(stress);
    if (s.norm() == 0.)
      return this->D;
    const SymmetricTensor<2, 3> N = s / s.norm();
    const double                G = this->mu;
    return this->D - 6. * G * G / (3. * G + H) * outer_product(N, N);
  }



  template class VonMises<2>;
  template class VonMises<3>;

  QSMPM_REGISTER_CONSTITUTIVE_MODEL(VonMises,
                                    "von Mises",
                                    "J2 elastoplasticity with linear "
                                    "isotropic hardening (E, nu, yield "
                                    "stress, hardening modulus; radial "
                                    "return, consistent tangent; plane strain "
                                    "in 2D; finite strain by the exponential "
                                    "map).")
} // namespace qsmpm
