#include <cmath>
#include <qsmpm/base/tensor_functions.h>
#include <qsmpm/materials/mohr_coulomb.h>
#include <sstream>

namespace qsmpm
{
  namespace
  {
    using Vector3 = std::array<double, 3>;

    double
    dot(const Vector3 &a, const Vector3 &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    /// The principal stresses in descending order and their directions.
    std::array<std::pair<double, Tensor<1, 3>>, 3>
    principal(const SymmetricTensor<2, 3> &stress)
    {
      return TensorFunctions::eigen_decomposition(stress);
    }
  } // namespace



  template <int dim>
  MohrCoulomb<dim>::MohrCoulomb(const double young_modulus,
                                const double poisson_ratio,
                                const double cohesion,
                                const double friction_angle_deg,
                                const double dilatancy_angle_deg,
                                const double hardening_modulus)
    : IsotropicPlasticity<dim>(young_modulus, poisson_ratio)
    , c0(cohesion)
    , H(hardening_modulus)
    , sin_phi(std::sin(friction_angle_deg * M_PI / 180.))
    , cos_phi(std::cos(friction_angle_deg * M_PI / 180.))
    , sin_psi(std::sin(dilatancy_angle_deg * M_PI / 180.))
  {
    check_cohesion_friction(
      "Mohr-Coulomb", c0, friction_angle_deg, dilatancy_angle_deg, H);
  }



  template <int dim>
  MohrCoulomb<dim>::MohrCoulomb(const Parameters &parameters)
    : MohrCoulomb(parameters.elasticity.young_modulus,
                  parameters.elasticity.poisson_ratio,
                  parameters.cohesion,
                  parameters.friction_angle,
                  parameters.dilatancy_angle,
                  parameters.hardening_modulus)
  {
  }



  template <int dim>
  MohrCoulomb<dim>::MohrCoulomb(ParameterHandler &prm)
    : MohrCoulomb(Parameters::from(prm))
  {
  }



  template <int dim>
  void
  MohrCoulomb<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    elasticity.add_parameters(prm);
    add_cohesion_friction_parameters(
      prm, cohesion, friction_angle, dilatancy_angle, hardening_modulus);
  }



  template <int dim>
  void
  MohrCoulomb<dim>::declare_parameters(ParameterHandler &prm)
  {
    Parameters::declare_parameters(prm);
  }



  template <int dim>
  double
  MohrCoulomb<dim>::cohesion(const double alpha) const
  {
    return c0 + H * alpha;
  }



  template <int dim>
  double
  MohrCoulomb<dim>::yield_function(const SymmetricTensor<2, 3> &stress,
                                   const double                 alpha) const
  {
    const auto p = principal(stress);
    return (p[0].first - p[2].first) + (p[0].first + p[2].first) * sin_phi -
           2. * cohesion(alpha) * cos_phi;
  }



  template <int dim>
  double
  MohrCoulomb<dim>::principal_return(Vector3 &s, const double alpha_old) const
  {
    const double G = this->mu, K = this->K, lambda = K - 2. * G / 3.;
    const double c = cohesion(alpha_old);
    // D m for a vector m of principal strains.
    const auto D_times = [&](const Vector3 &m) -> Vector3 {
      const double tr = m[0] + m[1] + m[2];
      return {{2. * G * m[0] + lambda * tr,
               2. * G * m[1] + lambda * tr,
               2. * G * m[2] + lambda * tr}};
    };
    // Gradients n and flow directions m of the three planes that meet the
    // sextant sigma_1 >= sigma_2 >= sigma_3: the main plane (sigma_1,
    // sigma_3), and those of the edges sigma_1 = sigma_2 (sigma_2,
    // sigma_3) and sigma_2 = sigma_3 (sigma_1, sigma_2).
    const double  sf = sin_phi, sp = sin_psi;
    const Vector3 n_main{{1. + sf, 0., -(1. - sf)}},
      m_main{{1. + sp, 0., -(1. - sp)}};
    const Vector3 n_12{{0., 1. + sf, -(1. - sf)}},
      m_12{{0., 1. + sp, -(1. - sp)}};
    const Vector3 n_23{{1. + sf, -(1. - sf), 0.}},
      m_23{{1. + sp, -(1. - sp), 0.}};
    const double hardening = 4. * H * cos_phi * cos_phi;

    const double phi_trial = dot(n_main, s) - 2. * c * cos_phi;
    const double scale =
      std::abs(s[0] - s[2]) + std::abs(s[0] + s[2]) + 2. * c * cos_phi;
    if (!(phi_trial > 1e-13 * scale))
      return -1.;
    const double tolerance = 1e-12 * scale;
    const auto   ordered   = [&](const Vector3 &t) {
      return t[0] >= t[1] - tolerance && t[1] >= t[2] - tolerance;
    };

    // 1. The main plane.
    const Vector3 Dm     = D_times(m_main);
    const double  dgamma = phi_trial / (dot(n_main, Dm) + hardening);
    Vector3       t{
      {s[0] - dgamma * Dm[0], s[1] - dgamma * Dm[1], s[2] - dgamma * Dm[2]}};
    if (ordered(t))
      {
        s = t;
        return 2. * cos_phi * dgamma;
      }

    // 2. The edge that the main return passed: sigma_1 = sigma_2 if it
    // put sigma_2 above sigma_1, else sigma_2 = sigma_3.
    const bool     edge_12 = t[1] > t[0];
    const Vector3 &n2      = edge_12 ? n_12 : n_23;
    const Vector3  Dm2     = D_times(edge_12 ? m_12 : m_23);
    const double   a11     = dot(n_main, Dm) + hardening,
                 a12       = dot(n_main, Dm2) + hardening,
                 a21 = dot(n2, Dm) + hardening, a22 = dot(n2, Dm2) + hardening;
    const double r1 = phi_trial, r2 = dot(n2, s) - 2. * c * cos_phi;
    const double det = a11 * a22 - a12 * a21;
    const double g1  = (r1 * a22 - a12 * r2) / det;
    const double g2  = (a11 * r2 - a21 * r1) / det;
    for (unsigned int i = 0; i < 3; ++i)
      t[i] = s[i] - g1 * Dm[i] - g2 * Dm2[i];
    if ((g1 >= 0. && g2 >= 0. && ordered(t)) || sf == 0.)
      {
        s = t;
        return 2. * cos_phi * (g1 + g2);
      }

    // 3. The apex, p = c(alpha) cot(phi).
    const double cot_phi   = cos_phi / sf;
    const double sin_psi_a = sp > 0. ? sp : sf;
    const double p_trial   = (s[0] + s[1] + s[2]) / 3.;
    const double d_eps_v =
      (p_trial - c * cot_phi) / (K + H * cos_phi * cot_phi / sin_psi_a);
    // The apex lies beyond the edges only in tension (p_trial above the
    // apex); a trial state below it that got here (the edge return missed
    // its checks by round-off) keeps the edge return.
    if (!(d_eps_v > 0.))
      {
        s = t;
        return 2. * cos_phi * std::max(g1 + g2, 0.);
      }
    const double p = p_trial - K * d_eps_v;
    s              = {{p, p, p}};
    return cos_phi / sin_psi_a * d_eps_v;
  }



  template <int dim>
  bool
  MohrCoulomb<dim>::return_stress(
    const SymmetricTensor<2, 3> &trial_elastic_strain,
    const double                 alpha_old,
    Return                      &r) const
  {
    const SymmetricTensor<2, 3> trial = this->D * trial_elastic_strain;
    const auto                  eig   = principal(trial);
    Vector3                     s{{eig[0].first, eig[1].first, eig[2].first}};
    const double                d_alpha = principal_return(s, alpha_old);
    r.alpha                             = alpha_old + std::max(d_alpha, 0.);
    r.increment                         = std::max(d_alpha, 0.);
    if (d_alpha < 0.)
      {
        r.stress         = trial;
        r.elastic_strain = trial_elastic_strain;
        return false;
      }
    r.stress = SymmetricTensor<2, 3>();
    for (unsigned int a = 0; a < 3; ++a)
      r.stress +=
        s[a] * symmetrize(outer_product(eig[a].second, eig[a].second));
    const double G = this->mu, K = this->K;
    r.elastic_strain = deviator(r.stress) / (2. * G) +
                       trace(r.stress) / (9. * K) * unit_symmetric_tensor<3>();
    return true;
  }



  template <int dim>
  void
  MohrCoulomb<dim>::return_map(
    const SymmetricTensor<2, 3> &trial_elastic_strain,
    const double                 alpha_old,
    const bool                   want_tangent,
    Return                      &r) const
  {
    const bool plastic = return_stress(trial_elastic_strain, alpha_old, r);
    if (!want_tangent)
      return;
    if (!plastic)
      {
        r.tangent = this->D;
        return;
      }
    // Central differences in the six independent trial strains; an
    // off-diagonal entry of a SymmetricTensor moves eps_ij and eps_ji
    // together, hence the factor 1/2.
    const double h =
      1e-6 * std::max(trial_elastic_strain.norm(),
                      1e-6 * cohesion(alpha_old) / (2. * this->mu) + 1e-300);
    Return plus, minus;
    for (unsigned int k = 0;
         k < SymmetricTensor<2, 3>::n_independent_components;
         ++k)
      {
        const TableIndices<2> ij =
          SymmetricTensor<2, 3>::unrolled_to_component_indices(k);
        const unsigned int    i = ij[0], j = ij[1];
        SymmetricTensor<2, 3> e = trial_elastic_strain;
        e[i][j] += h;
        return_stress(e, alpha_old, plus);
        e[i][j] -= 2. * h;
        return_stress(e, alpha_old, minus);
        const SymmetricTensor<2, 3> d =
          (plus.stress - minus.stress) / (2. * h) * (i == j ? 1. : 0.5);
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = a; b < 3; ++b)
            r.tangent[a][b][i][j] = d[a][b];
      }
  }



  template <int dim>
  SymmetricTensor<4, 3>
  MohrCoulomb<dim>::continuum_tangent(const SymmetricTensor<2, 3> &stress,
                                      const double                 alpha) const
  {
    // The algorithmic tangent an infinitesimal plastic step past the
    // surface, along the main plane's normal in strain space.
    const auto            eig = principal(stress);
    SymmetricTensor<2, 3> n;
    const double          f[3] = {1. + sin_phi, 0., -(1. - sin_phi)};
    for (unsigned int a = 0; a < 3; ++a)
      n += f[a] * symmetrize(outer_product(eig[a].second, eig[a].second));
    const SymmetricTensor<2, 3> eps =
      deviator(stress) / (2. * this->mu) +
      trace(stress) / (9. * this->K) * unit_symmetric_tensor<3>();
    const double scale = std::max(eps.norm(), 1e-12);
    Return       r;
    return_map(eps + 1e-4 * scale * n / n.norm(), alpha, true, r);
    return r.tangent;
  }



  template class MohrCoulomb<2>;
  template class MohrCoulomb<3>;

  QSMPM_REGISTER_CONSTITUTIVE_MODEL(
    MohrCoulomb,
    "Mohr-Coulomb",
    "Mohr-Coulomb elastoplasticity with its edges and apex returned exactly "
    "in principal stresses, cohesion hardening and non-associative flow "
    "(E, nu, cohesion, friction and dilatancy angles, hardening modulus); "
    "plane strain in 2D; finite strain by the exponential map of "
    "IsotropicPlasticity.")
} // namespace qsmpm
