#ifndef qsmpm_tests_cam_clay_closed_forms_h
#define qsmpm_tests_cam_clay_closed_forms_h

// Closed forms of Modified Cam Clay under triaxial compression (Wood, Soil
// Behaviour and Critical State Soil Mechanics, CUP 1990, ch. 6-7), for the
// model of qsmpm::ModifiedCamClay: p = p0 exp(v_e / kappa), s = 2 G e_e,
// f = q^2 / M^2 + p (p - p_c), p_c = p_c0 exp(v_p / (lambda - kappa)),
// soil signs (p, v > 0 in compression), from the isotropic state p0.
// Independent of the model's code: the tests compare the model with these.

#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <functional>

namespace qsmpm_tests
{
  /// int_a^b f by the composite 5-point Gauss-Legendre rule (deal.II's
  /// QGauss on [0, 1]) on @p panels panels.
  inline double
  integrate(const std::function<double(double)> &f,
            const double                         a,
            const double                         b,
            const unsigned int                   panels = 2000)
  {
    const dealii::QGauss<1> rule(5);
    const double            h   = (b - a) / panels;
    double                  sum = 0.;
    for (unsigned int i = 0; i < panels; ++i)
      for (unsigned int k = 0; k < rule.size(); ++k)
        sum += h * rule.weight(k) * f(a + (i + rule.point(k)[0]) * h);
    return sum;
  }

  struct CamClayTriaxial
  {
    double G, kappa, lambda, M, p0, pc0;

    double
    theta() const
    {
      return lambda - kappa;
    }

    /// Undrained (v = 0): p_c on the path at the pressure p,
    /// kappa ln(p / p0) + theta ln(p_c / p_c0) = 0.
    double
    undrained_pc(const double p) const
    {
      return pc0 * std::pow(p0 / p, kappa / theta());
    }

    /// Undrained: q on the yield surface at the pressure p.
    double
    undrained_q(const double p) const
    {
      return M * p * std::sqrt(undrained_pc(p) / p - 1.);
    }

    /// Undrained: q at first yield (the path is elastic at p = p0 before).
    double
    undrained_yield_q() const
    {
      return M * p0 * std::sqrt(pc0 / p0 - 1.);
    }

    /// Undrained: the critical state, p_c = 2 p.
    double
    undrained_critical_pressure() const
    {
      return std::pow(0.5 * pc0 * std::pow(p0, kappa / theta()),
                      theta() / lambda);
    }

    /// Undrained: the shear strain at the pressure p on the surface,
    /// q / (3 G) + int 2 eta / (M^2 - eta^2) d v_p with d v_p = -kappa dp / p.
    double
    undrained_shear_strain(const double p) const
    {
      const auto   eta     = [&](const double s) { return undrained_q(s) / s; };
      const double plastic = integrate(
        [&](const double s) {
          return 2. * eta(s) / (M * M - eta(s) * eta(s)) * kappa / s;
        },
        p,
        p0);
      return undrained_q(p) / (3. * G) + plastic;
    }

    /// Drained (the cell pressure p0 held, p_c0 = p0): q = 3 (p - p0), and
    /// p_c on the surface.
    double
    drained_pc(const double p) const
    {
      const double q = 3. * (p - p0);
      return p + q * q / (M * M * p);
    }

    /// Drained: the volumetric strain at the pressure p,
    /// kappa ln(p / p0) + theta ln(p_c / p_c0).
    double
    drained_volumetric_strain(const double p) const
    {
      return kappa * std::log(p / p0) + theta() * std::log(drained_pc(p) / pc0);
    }

    /// Drained: the shear strain at the pressure p,
    /// q / (3 G) + int 2 eta / (M^2 - eta^2) theta d ln p_c.
    double
    drained_shear_strain(const double p) const
    {
      const auto q      = [&](const double s) { return 3. * (s - p0); };
      const auto dpc_dp = [&](const double s) {
        return 1. + 6. * q(s) / (M * M * s) - q(s) * q(s) / (M * M * s * s);
      };
      const double plastic = integrate(
        [&](const double s) {
          const double eta = q(s) / s;
          return 2. * eta / (M * M - eta * eta) * theta() * dpc_dp(s) /
                 drained_pc(s);
        },
        p0,
        p);
      return q(p) / (3. * G) + plastic;
    }
  };
} // namespace qsmpm_tests

#endif
