// The elastoplastic models VonMises and DruckerPrager: return mappings at
// single points, small strain (2D plane strain and 3D) and finite strain,
// against closed forms and exact properties:
//
// - von Mises, uniaxial stress (3D, lateral strains solved for zero lateral
//   stress): sigma = E eps before yield, sigma_y0 + E_t (eps - eps_y) after,
//   E_t = E H / (E + H), and alpha = eps - sigma / E;
// - von Mises, pure shear eps_xy = gamma/2 (3D and plane strain): tau = G
//   gamma, then tau_y + G H / (3G + H) (gamma - gamma_y), tau_y =
//   sigma_y0/sqrt(3); the yield point is detected within 1e-6;
// - Drucker-Prager: the three Mohr-Coulomb matchings (outer and inner cone
//   through stress states on the Mohr-Coulomb compressive and tensile
//   meridians; plane strain through the limit shear stress c of a plane
//   strain simple shear with associative flow and zero normal stress on the
//   shear plane), the return to the apex under hydrostatic tension, and
//   the return to the smooth cone (Phi = 0, the dilatancy relation
//   tr d eps_p = sqrt(2) eta_bar |dev d eps_p|, d alpha = xi dgamma);
// - finite strain (exponential map), von Mises: uniaxial Kirchhoff stress
//   against the small-strain closed form in the logarithmic strain ln(stretch);
//   J = det F = det(b_e)^(1/2) = exp(tr eps_e) along a general large
//   deformation path (plastic incompressibility); objectivity of a rigid
//   rotation of a yielded state and of a rotated plastic increment;
// - creation through the registry, and messages for bad parameters.
//
// Tolerances: the returns are closed form (von Mises radial return with
// linear hardening, Drucker-Prager cone and apex), so only round-off
// remains: 1e-10 relative (1e-12 for single evaluations, 1e-15 for the
// matching formulas) is 1e3 ... 1e5 times the errors measured (1e-16 ...
// 1e-13, QSMPM_VERBOSE prints them) and orders of magnitude below what a
// wrong term gives (E instead of E_t, a missing hardening or dilatancy
// term: O(H / E) = 5e-2 or O(1)). The plane strain simple shear approaches
// its limit state asymptotically: 1e-6 bounds what is left after 80 c / G
// of shear (measured: round-off), while a wrong matching changes c by
// O(10 %).
#include "tests.h"

#include <cstdlib>
#include <deal.II/physics/transformations.h>
#include <iostream>
#include <qsmpm/base/utilities.h>
#include <qsmpm/materials/drucker_prager.h>
#include <qsmpm/materials/von_mises.h>
#include <vector>

using namespace qsmpm;

namespace
{
  /// check() (which, with QSMPM_VERBOSE set, prints the measured value to
  /// stdout, not to the compared output).
  void
  check_v(const std::string &what, const double value, const double tolerance)
  {
    check(what, value, tolerance);
  }

  const double E = 1e6, nu = 0.3, sigma_y0 = 1e3;
  const double G = E / (2. * (1. + nu));
  const double K = E / (3. * (1. - 2. * nu));

  /// A material point: its committed state, driven by increments.
  template <int dim>
  struct Driver
  {
    explicit Driver(const IsotropicPlasticity<dim> &model)
      : model(model)
    {
    }

    const IsotropicPlasticity<dim> &model;
    std::vector<double>             state = std::vector<double>(8, 0.);
    SymmetricTensor<2, dim>         stress;
    Tensor<2, dim>                  F = unit_symmetric_tensor<dim>();

    PointState<dim>
    old() const
    {
      return {SymmetricTensor<2, dim>(),
              stress,
              ArrayView<const double>(state.data(), state.size()),
              1.};
    }

    /// Small strain: the trial stress (and state) of an increment.
    SymmetricTensor<2, dim>
    trial(const SymmetricTensor<2, dim> &d, std::vector<double> &s) const
    {
      s.resize(8);
      SymmetricTensor<2, dim> sigma;
      model.update_stress(old(), d, sigma, make_array_view(s));
      return sigma;
    }

    void
    step(const SymmetricTensor<2, dim> &d)
    {
      std::vector<double> s;
      stress = trial(d, s);
      state  = s;
    }

    /// Finite strain: trial tau for Delta F.
    SymmetricTensor<2, dim>
    trial_tau(const Tensor<2, dim> &dF, std::vector<double> &s) const
    {
      s.resize(8);
      SymmetricTensor<2, dim> tau;
      model.update_kirchhoff_stress(old(),
                                    {F, dF, Tensor<2, dim>(dF * F)},
                                    tau,
                                    make_array_view(s));
      return tau;
    }

    void
    step_F(const Tensor<2, dim> &dF)
    {
      std::vector<double> s;
      stress = trial_tau(dF, s) / determinant(dF * F);
      state  = s;
      F      = dF * F;
    }

    ArrayView<const double>
    view() const
    {
      return ArrayView<const double>(state.data(), state.size());
    }

    double
    alpha() const
    {
      return IsotropicPlasticity<dim>::equivalent_plastic_strain(view());
    }

    double
    increment() const
    {
      return IsotropicPlasticity<dim>::plastic_increment(view());
    }
  };

  SymmetricTensor<2, 3>
  diag3(const double a, const double b, const double c)
  {
    SymmetricTensor<2, 3> t;
    t[0][0] = a;
    t[1][1] = b;
    t[2][2] = c;
    return t;
  }

  template <int dim>
  Tensor<2, dim>
  rotation(const double angle)
  {
    if constexpr (dim == 2)
      return Physics::Transformations::Rotations::rotation_matrix_2d(angle);
    else
      {
        Point<3> axis(0.3, -0.5, 0.8);
        axis /= axis.norm();
        return Physics::Transformations::Rotations::rotation_matrix_3d(axis,
                                                                       angle);
      }
  }

  /// A general increment of the deformation gradient.
  template <int dim>
  Tensor<2, dim>
  general_delta_F(const double scale)
  {
    const double   rows[3][3] = {{0.8, 0.5, -0.2},
                                 {0.1, -0.6, 0.3},
                                 {-0.3, 0.2, 0.4}};
    Tensor<2, dim> dF         = unit_symmetric_tensor<dim>();
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        dF[i][j] += scale * rows[i][j];
    return dF;
  }

  /// Uniaxial stress by lateral strains eps_yy = eps_zz from a Newton loop.
  void
  von_mises_uniaxial(const double H)
  {
    const VonMises<3>  model(E, nu, sigma_y0, H);
    Driver<3>          p{model};
    const double       eps_y = sigma_y0 / E, E_t = E * H / (E + H);
    const unsigned int n           = 40;
    double             sigma_error = 0., lateral = 0., alpha_error = 0.;
    double             eps_lat = 0.;
    for (unsigned int k = 1; k <= n; ++k)
      {
        const double eps = 4. * eps_y * k / n;
        // Newton on the lateral strain increment for sigma_yy = 0.
        double              d_lat = -nu * 4. * eps_y / n;
        std::vector<double> s;
        for (unsigned int it = 0; it < 30; ++it)
          {
            const SymmetricTensor<2, 3> d = diag3(4. * eps_y / n, d_lat, d_lat);
            const double                r = p.trial(d, s)[1][1];
            if (std::abs(r) < 1e-13 * sigma_y0)
              break;
            const SymmetricTensor<4, 3> C =
              model.consistent_tangent(p.old(), d);
            d_lat -= r / (C[1][1][1][1] + C[1][1][2][2]);
          }
        p.step(diag3(4. * eps_y / n, d_lat, d_lat));
        eps_lat += d_lat;
        const double exact =
          eps <= eps_y ? E * eps : sigma_y0 + E_t * (eps - eps_y);
        sigma_error =
          std::max(sigma_error, std::abs(p.stress[0][0] - exact) / exact);
        lateral =
          std::max(lateral,
                   (std::abs(p.stress[1][1]) + std::abs(p.stress[2][2]) +
                    std::abs(p.stress[0][1])) /
                     exact);
        alpha_error = std::max(
          alpha_error,
          std::abs(p.alpha() - std::max(0., eps - p.stress[0][0] / E)) / eps_y);
      }
    const std::string prefix =
      "  3D uniaxial stress, H = " + format(H) + ", eps = 0 ... 4 eps_y: ";
    check_v(prefix + "max |sigma_xx - closed form| / sigma_xx",
            sigma_error,
            1e-10);
    check_v(prefix + "lateral and shear stress / sigma_xx", lateral, 1e-10);
    check_v(prefix + "|alpha - (eps - sigma / E)| / eps_y", alpha_error, 1e-10);
    check_that(prefix + "yielded (alpha > 0) and lateral strain < -nu eps",
               p.alpha() > 0.5 * eps_y && eps_lat < -nu * 4. * eps_y);
  }

  /// Pure shear eps_xy = gamma/2, 3D or plane strain.
  template <int dim>
  void
  von_mises_shear(const double H)
  {
    const VonMises<dim> model(E, nu, sigma_y0, H);
    Driver<dim>         p{model};
    const double        tau_y = sigma_y0 / std::sqrt(3.), gamma_y = tau_y / G;
    const double        slope = G * H / (3. * G + H);
    const unsigned int  n     = 25;
    double              error = 0., alpha_error = 0., others = 0.;
    for (unsigned int k = 1; k <= n; ++k)
      {
        const double            gamma = 5. * gamma_y * k / n;
        SymmetricTensor<2, dim> d;
        d[0][1] = 0.5 * 5. * gamma_y / n;
        p.step(d);
        const double exact =
          gamma <= gamma_y ? G * gamma : tau_y + slope * (gamma - gamma_y);
        error = std::max(error, std::abs(p.stress[0][1] - exact) / exact);
        // alpha = gamma_p / sqrt(3), gamma_p = gamma - tau / G.
        alpha_error =
          std::max(alpha_error,
                   std::abs(p.alpha() -
                            (gamma - p.stress[0][1] / G) / std::sqrt(3.)) /
                     gamma_y);
        SymmetricTensor<2, dim> rest = p.stress;
        rest[0][1]                   = 0.;
        others                       = std::max(others, rest.norm() / exact);
      }
    const std::string prefix = "  " + std::to_string(dim) +
                               "D pure shear, H = " + format(H) +
                               ", gamma = 0 ... 5 gamma_y: ";
    check_v(prefix + "max |tau - closed form| / tau", error, 1e-10);
    check_v(prefix + "|alpha - gamma_p / sqrt(3)| / gamma_y",
            alpha_error,
            1e-10);
    check_v(prefix + "other stress components / tau", others, 1e-10);
    // sigma_zz = 0 in plane strain pure shear (deviatoric, p = 0).
    check_v(prefix + "|sigma_zz| / tau (3D state)",
            std::abs(model.stress_3d(p.view())[2][2]) / tau_y,
            1e-10);

    // Yield point detection from the virgin state.
    Driver<dim>             below{model}, above{model};
    SymmetricTensor<2, dim> d;
    d[0][1] = 0.5 * gamma_y * (1. - 1e-6);
    below.step(d);
    d[0][1] = 0.5 * gamma_y * (1. + 1e-6);
    above.step(d);
    check_that(prefix + "gamma = (1 -+ 1e-6) gamma_y: elastic, then plastic",
               below.increment() == 0. && above.increment() > 0. &&
                 below.alpha() == 0.);
  }

  /// Drucker-Prager: matchings through Mohr-Coulomb stress states.
  void
  drucker_prager_matching()
  {
    using DP         = DruckerPrager<3>;
    const double phi = 30., c = 2e3;
    const double sp = std::sin(phi * M_PI / 180.),
                 cp = std::cos(phi * M_PI / 180.);
    // Mohr-Coulomb (tension positive, s1 >= s2 >= s3):
    // (s1 - s3) + (s1 + s3) sin phi = 2 c cos phi.
    const auto mc_major = [&](const double s3) {
      return (2. * c * cp + s3 * (1. - sp)) / (1. + sp);
    };
    double outer = 0., inner = 0.;
    for (const double s3 : {-5e3, -1e3, 0.})
      {
        const double s1 = mc_major(s3);
        // Compressive meridian: s1 = s2 > s3. Tensile meridian: s1 > s2 = s3.
        const DP o(E, nu, c, phi, 0., 0., DP::Matching::outer_cone);
        const DP i(E, nu, c, phi, 0., 0., DP::Matching::inner_cone);
        outer = std::max(outer,
                         std::abs(o.yield_function(diag3(s1, s1, s3), 0.)) / c);
        inner = std::max(inner,
                         std::abs(i.yield_function(diag3(s1, s3, s3), 0.)) / c);
      }
    check_v("  outer cone: |Phi| / c on the Mohr-Coulomb compressive meridian",
            outer,
            1e-12);
    check_v("  inner cone: |Phi| / c on the Mohr-Coulomb tensile meridian",
            inner,
            1e-12);
    const DP     ps(E, nu, c, phi, 0., 0., DP::Matching::plane_strain);
    const double t = std::tan(phi * M_PI / 180.);
    check_v("  plane strain: |eta - 3 tan phi / sqrt(9 + 12 tan^2 phi)|",
            ps.eta() - 3. * t / std::sqrt(9. + 12. * t * t),
            1e-15);
    check_v("  plane strain: |xi - 3 / sqrt(9 + 12 tan^2 phi)|",
            ps.xi() - 3. / std::sqrt(9. + 12. * t * t),
            1e-15);
    check_v("  psi = 20: |eta_bar - eta(20 degrees)|",
            DP(E, nu, c, phi, 20., 0., DP::Matching::outer_cone).eta_bar() -
              DP(E, nu, c, 20., 0., 0., DP::Matching::outer_cone).eta(),
            1e-15);

    // Plane strain simple shear, associative flow: eps_xx = 0, sigma_yy =
    // 0 (Newton on eps_yy), eps_xy increasing. The x axis is a
    // zero-extension direction, hence (associative flow) a Mohr-Coulomb
    // slip line, with zero normal stress: the limit shear stress is c.
    for (const double angle : {20., 35.})
      {
        const DruckerPrager<2> model(
          E, nu, c, angle, angle, 0., DruckerPrager<2>::Matching::plane_strain);
        Driver<2>    p{model};
        const double d_gamma = 0.2 * c / G;
        for (unsigned int k = 0; k < 400; ++k)
          {
            SymmetricTensor<2, 2> d;
            d[0][1] = 0.5 * d_gamma;
            std::vector<double> s;
            for (unsigned int it = 0; it < 50; ++it)
              {
                const double r = p.trial(d, s)[1][1];
                if (std::abs(r) < 1e-12 * c)
                  break;
                d[1][1] -= r / model.consistent_tangent(p.old(), d)[1][1][1][1];
              }
            p.step(d);
          }
        const std::string prefix =
          "  plane strain simple shear, phi = psi = " + format(angle) + ": ";
        check_v(prefix + "|tau_xy / c - 1| after 80 c / G of shear",
                std::abs(p.stress[0][1]) / c - 1.,
                1e-6);
        check_v(prefix + "|sigma_yy| / c", p.stress[1][1] / c, 1e-10);
        check_that(
          prefix + "(the matching matters) the limit state lies "
                   "strictly inside the outer cone",
          DruckerPrager<2>(
            E, nu, c, angle, angle, 0., DruckerPrager<2>::Matching::outer_cone)
              .yield_function(model.stress_3d(p.view()), 0.) < -1e-3 * c);
      }
  }

  /// Drucker-Prager: apex and smooth cone, 3D.
  template <int dim>
  void
  drucker_prager_returns()
  {
    using DP                 = DruckerPrager<dim>;
    const double      c      = 2e3;
    const std::string prefix = "  " + std::to_string(dim) + "D ";
    for (const double psi : {0., 10.})
      {
        // Hydrostatic tension beyond the apex p = xi c / eta = c cot(phi)
        // (plane-strain matching: xi/eta = 1/tan(phi)).
        const DP     model(E, nu, c, 30., psi, 0., DP::Matching::plane_strain);
        Driver<dim>  p{model};
        const double p_apex = c / std::tan(M_PI / 6.);
        // In 2D the in-plane strain is tension, eps_zz = 0: still beyond the
        // apex for a large enough strain.
        p.step(3. * p_apex / K * unit_symmetric_tensor<dim>());
        const SymmetricTensor<2, 3> sigma = model.stress_3d(p.view());
        check_v(prefix + "apex, psi = " + format(psi) +
                  ": |p - c cot phi| / c and |s| / c",
                std::abs(trace(sigma) / 3. - p_apex) / c +
                  deviator(sigma).norm() / c,
                1e-10);
        check_that(prefix + "apex, psi = " + format(psi) +
                     ": plastic, and sigma_xx from update_stress equals p",
                   p.increment() > 0. &&
                     std::abs(p.stress[0][0] - p_apex) < 1e-10 * c);
      }

    // Smooth cone: shear with compression, non-associative, hardening.
    for (const double H : {0., 5e4})
      {
        const DP    model(E, nu, c, 30., 10., H, DP::Matching::outer_cone);
        Driver<dim> p{model};
        SymmetricTensor<2, dim> d;
        d[0][0] = -2e-3;
        d[1][1] = -1e-3;
        d[0][1] = 6e-3;
        std::vector<double>           s;
        const SymmetricTensor<2, dim> sigma = p.trial(d, s);
        const ArrayView<const double> sv(s.data(), s.size());
        const SymmetricTensor<2, 3>   sigma3 = model.stress_3d(sv);
        const double                  alpha =
          IsotropicPlasticity<dim>::equivalent_plastic_strain(sv);
        const std::string what =
          prefix + "smooth cone, psi = 10, H = " + format(H) + ": ";
        check_v(what + "|Phi(sigma_new, alpha_new)| / c",
                model.yield_function(sigma3, alpha) / c,
                1e-10);
        check_v(what + "|sigma - in-plane part of D : eps_e| / c",
                (sigma - IsotropicPlasticity<dim>::extract(sigma3)).norm() / c,
                1e-10);
        const SymmetricTensor<2, 3> d_eps_p =
          IsotropicPlasticity<dim>::embed(d) -
          IsotropicPlasticity<dim>::elastic_strain(sv);
        const double dev_norm = deviator(d_eps_p).norm();
        check_v(what + "tr d eps_p / |dev d eps_p| - sqrt(2) eta_bar",
                trace(d_eps_p) / dev_norm - std::sqrt(2.) * model.eta_bar(),
                1e-10);
        // dgamma = sqrt(2) |dev d eps_p|, d alpha = xi dgamma.
        check_v(what + "|d alpha - xi sqrt(2) |dev d eps_p|| / d alpha",
                (alpha - model.xi() * std::sqrt(2.) * dev_norm) / alpha,
                1e-10);
        check_that(what + "not at the apex (|s| > 0.1 |p|)",
                   deviator(sigma3).norm() > 0.1 * std::abs(trace(sigma3)));
      }
  }

  /// Finite strain von Mises.
  template <int dim>
  void
  finite_strain()
  {
    const std::string   prefix = "  " + std::to_string(dim) + "D ";
    const double        H      = 2e4;
    const VonMises<dim> model(E, nu, sigma_y0, H);

    if (dim == 3)
      {
        // Uniaxial stress: F = diag(lambda, l, l) with tau_yy = 0; all
        // tensors coaxial, so tau_xx follows the small-strain closed form
        // in the logarithmic strain ln(lambda).
        Driver<dim>        p{model};
        const double       eps_y = sigma_y0 / E, E_t = E * H / (E + H);
        const unsigned int n     = 50;
        double             error = 0.;
        for (unsigned int k = 1; k <= n; ++k)
          {
            const double   ratio = std::exp(0.5 / n); // ln lambda to 0.5
            Tensor<2, dim> dF;
            dF[0][0]                = ratio;
            double              lat = std::pow(ratio, -0.5);
            std::vector<double> s;
            for (unsigned int it = 0; it < 30; ++it)
              {
                dF[1][1] = dF[2][2] = lat;
                const double r      = p.trial_tau(dF, s)[1][1];
                if (std::abs(r) < 1e-13 * sigma_y0)
                  break;
                const Tensor<4, dim> c =
                  model.kirchhoff_tangent(p.old(),
                                          {p.F, dF, Tensor<2, dim>(dF * p.F)});
                lat -= r / ((c[1][1][1][1] + c[1][1][2][2]) / lat);
              }
            p.step_F(dF);
            const double tau_xx = p.stress[0][0] * determinant(p.F);
            const double eps    = std::log(p.F[0][0]);
            const double exact =
              eps <= eps_y ? E * eps : sigma_y0 + E_t * (eps - eps_y);
            error = std::max(error, std::abs(tau_xx - exact) / exact);
          }
        check_v(prefix + "finite uniaxial stress to ln(stretch) = 0.5: "
                         "|tau_xx - closed form in ln(stretch)| / tau_xx",
                error,
                1e-10);
        check_v(prefix + "finite uniaxial stress: |alpha - (0.5 - tau / E)| "
                         "(closed form)",
                p.alpha() - (0.5 - p.stress[0][0] * determinant(p.F) / E),
                1e-10);
      }

    // A general path with volume change and large plastic flow.
    Driver<dim>          p{model};
    double               j_error = 0.;
    const Tensor<2, dim> dF      = general_delta_F<dim>(0.02);
    for (unsigned int k = 0; k < 40; ++k)
      {
        p.step_F(dF);
        const double J = determinant(p.F);
        j_error =
          std::max(j_error,
                   std::abs(
                     std::exp(trace(
                       IsotropicPlasticity<dim>::elastic_strain(p.view()))) -
                     J) /
                     J);
      }
    check_v(prefix + "general path, 40 steps: |det(b_e)^(1/2) - det F| / det F",
            j_error,
            1e-12);
    check_at_least(prefix + "(the test is not trivial) alpha / eps_y",
                   p.alpha() / (sigma_y0 / E),
                   50.);
    check_at_least(prefix + "(the test is not trivial) |ln det F|",
                   std::abs(std::log(determinant(p.F))),
                   0.05);

    // Objectivity: a rigid rotation of the yielded state.
    const Tensor<2, dim>        Q    = rotation<dim>(0.9);
    const SymmetricTensor<2, 3> tau0 = model.stress_3d(p.view());
    Tensor<2, dim>              tau0_dim;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        tau0_dim[i][j] = tau0[i][j];
    std::vector<double>           s;
    const SymmetricTensor<2, dim> tau_rot = p.trial_tau(Q, s);
    const ArrayView<const double> sv(s.data(), s.size());
    check_v(prefix + "rigid rotation of a yielded state: |tau - Q tau_old Q^T| "
                     "/ |tau_old|",
            (Tensor<2, dim>(tau_rot) - Q * tau0_dim * transpose(Q)).norm() /
              tau0.norm(),
            1e-12);
    check_that(prefix + "rigid rotation: alpha unchanged, increment 0",
               IsotropicPlasticity<dim>::equivalent_plastic_strain(sv) ==
                   p.alpha() &&
                 IsotropicPlasticity<dim>::plastic_increment(sv) == 0.);

    // A rotated plastic increment: tau(Q dF) = Q tau(dF) Q^T.
    const Tensor<2, dim>          dF2 = general_delta_F<dim>(-0.03);
    std::vector<double>           s1, s2;
    const SymmetricTensor<2, dim> t1 = p.trial_tau(dF2, s1);
    const SymmetricTensor<2, dim> t2 = p.trial_tau(Tensor<2, dim>(Q * dF2), s2);
    check_v(
      prefix + "rotated plastic increment: |tau(Q dF) - Q tau(dF) Q^T| / "
               "|tau|",
      (Tensor<2, dim>(t2) - Q * Tensor<2, dim>(t1) * transpose(Q)).norm() /
        t1.norm(),
      1e-12);
    check_v(prefix + "rotated plastic increment: |d alpha(Q dF) - d alpha(dF)| "
                     "/ d alpha",
            (s2[7] - s1[7]) / s1[7],
            1e-12);
    check_that(prefix + "rotated plastic increment: plastic", s1[7] > 0.);
  }

  template <int dim>
  std::string
  error_of(const std::string &model,
           const std::string &entry,
           const std::string &value)
  {
    ParameterHandler prm;
    ConstitutiveModelFactory<dim>::declare_parameters(prm);
    prm.enter_subsection("Material");
    prm.set("Model", model);
    prm.enter_subsection(model);
    prm.set(entry, value);
    prm.leave_subsection();
    prm.leave_subsection();
    try
      {
        ConstitutiveModelFactory<dim>::create(prm);
      }
    catch (const std::exception &e)
      {
        return Utils::error_message(e);
      }
    return "";
  }
} // namespace

int
main()
{
  initlog();

  deallog << "von Mises, small strain" << std::endl;
  von_mises_uniaxial(0.);
  von_mises_uniaxial(5e4);
  von_mises_shear<3>(0.);
  von_mises_shear<3>(5e4);
  von_mises_shear<2>(0.);
  von_mises_shear<2>(5e4);

  deallog << "Drucker-Prager, small strain" << std::endl;
  drucker_prager_matching();
  drucker_prager_returns<2>();
  drucker_prager_returns<3>();

  deallog << "von Mises, finite strain" << std::endl;
  finite_strain<2>();
  finite_strain<3>();

  deallog << "Registry" << std::endl;
  {
    ParameterHandler prm;
    ConstitutiveModelFactory<2>::declare_parameters(prm);
    prm.enter_subsection("Material");
    prm.set("Model", "von Mises");
    prm.enter_subsection("von Mises");
    prm.set("Yield stress", "250");
    prm.set("Hardening modulus", "1000");
    prm.leave_subsection();
    prm.enter_subsection("Drucker-Prager");
    prm.set("Friction angle", "30");
    prm.set("Mohr-Coulomb matching", "outer cone");
    prm.leave_subsection();
    prm.leave_subsection();
    const auto  vm = ConstitutiveModelFactory<2>::create(prm);
    const auto *v  = dynamic_cast<const VonMises<2> *>(vm.get());
    check_that("  <von Mises>: created, name(), finite strain, yield stress "
               "sigma_y(2) = 250 + 1000 * 2",
               v != nullptr && vm->name() == "von Mises" &&
                 vm->supports_finite_strain() && v->yield_stress(2.) == 2250.);
    // The state the Driver above reads: the 3D elastic strain (6
    // components, also in plane strain, where eps_e_zz need not vanish),
    // then alpha and the last plastic increment (components 6 and 7).
    std::string  fields;
    unsigned int n_components = 0, alpha_at = 0, increment_at = 0;
    for (const auto &f : vm->state_fields())
      {
        fields += " " + f.name + "(" + std::to_string(f.n_components) + ")";
        if (f.name == "equivalent_plastic_strain")
          alpha_at = n_components;
        if (f.name == "plastic_increment")
          increment_at = n_components;
        n_components += f.n_components;
      }
    std::cout << "state fields:" << fields << std::endl;
    check_that("  <von Mises>: 8 state components, alpha at 6, plastic "
               "increment at 7",
               n_components == 8 && vm->n_state_components() == 8 &&
                 alpha_at == 6 && increment_at == 7);
    prm.enter_subsection("Material");
    prm.set("Model", "Drucker-Prager");
    prm.leave_subsection();
    const auto   dp = ConstitutiveModelFactory<2>::create(prm);
    const auto  *d  = dynamic_cast<const DruckerPrager<2> *>(dp.get());
    const double s  = 0.5;
    check_that("  <Drucker-Prager>: created, name(), outer cone eta",
               d != nullptr && dp->name() == "Drucker-Prager" &&
                 std::abs(d->eta() - 6. * s / (std::sqrt(3.) * (3. - s))) <
                   1e-12);
  }
  for (const auto &row : std::vector<std::vector<std::string>>{
         {"von Mises", "Yield stress", "0", "Yield stress"},
         {"Drucker-Prager", "Dilatancy angle", "40", "Dilatancy angle"},
         {"Drucker-Prager", "Friction angle", "90", "Friction angle"}})
    {
      const std::string &model = row[0], &entry = row[1], &value = row[2],
                        &expected = row[3];
      const std::string message   = error_of<3>(model, entry, value);
      check_that("  <" + model + "> " + entry + " = " + value +
                   ": throws a message naming '" + expected + "'",
                 message.find(expected) != std::string::npos);
      std::cout << message << std::endl;
    }
}
