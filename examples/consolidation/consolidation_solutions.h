/* ---------------------------------------------------------------------
 *
 * qsmpm example: consolidation -- the exact solutions
 *
 * Terzaghi's column and Mandel's specimen for incompressible grains and
 * fluid. The example program consolidation.cc and the test
 * tests/mandel_consolidation.cc compare with them.
 *
 * ---------------------------------------------------------------------
 */
#ifndef qsmpm_examples_consolidation_solutions_h
#define qsmpm_examples_consolidation_solutions_h

#include <algorithm>
#include <cmath>
#include <vector>

namespace Consolidation
{
  // @sect3{The soil}
  //
  // Both exact solutions below are for incompressible grains and fluid
  // (Biot coefficient b = 1, 1/M = 0), for which the undrained Poisson's
  // ratio is 1/2 and Skempton's coefficient 1. The consolidation
  // coefficient is then c = kappa (lambda + 2 mu) = kappa E_oed in both.
  struct Soil
  {
    double E = 0, nu = 0, kappa = 0;

    double
    shear_modulus() const
    {
      return E / (2. * (1. + nu));
    }

    double
    constrained_modulus() const
    {
      return E * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
    }

    double
    consolidation_coefficient() const
    {
      return kappa * constrained_modulus();
    }
  };



  // @sect3{Terzaghi's column: the exact solution}
  //
  // A column of height H, drained at its top, impermeable below and at the
  // sides, loaded at t = 0 by q on its top. With z = H - y the depth and
  // T_v = c t / H^2 (Terzaghi 1943; Verruijt, "Soil Mechanics", ch. 15):
  // @f[
  //   p(z, t) = q \sum_{m \ge 0} \frac{2}{M_m} \sin\frac{M_m z}{H}
  //     e^{-M_m^2 T_v}, \qquad M_m = \frac{\pi (2 m + 1)}{2}.
  // @f]
  inline double
  terzaghi_pressure(const double depth,
                    const double H,
                    const double Tv,
                    const double q)
  {
    double p = 0;
    for (unsigned int m = 0; m < 200; ++m)
      {
        const double M = M_PI * (2 * m + 1) / 2;
        p += 2. / M * std::sin(M * depth / H) * std::exp(-M * M * Tv);
      }
    return q * p;
  }



  // @sect3{Mandel's problem: the exact solution}
  //
  // A specimen -a < x < a, -b < y < b between two rigid, frictionless,
  // impermeable plates that carry the force 2F (per unit thickness) from
  // t = 0 on; its sides x = +-a are drained and free. In plane strain the
  // solution does not depend on y (Mandel 1953; in the form of Abousleiman,
  // Cheng, Cui, Detournay and Roegiers 1996, eqs. 12 and 16, with B = 1 and
  // nu_u = 1/2 for incompressible constituents):
  // @f[
  //   p(x, t) = \frac{2 F B (1 + \nu_u)}{3 a} \sum_{n \ge 1}
  //     \frac{\sin\alpha_n}{\alpha_n - \sin\alpha_n\cos\alpha_n}
  //     \left(\cos\frac{\alpha_n x}{a} - \cos\alpha_n\right)
  //     e^{-\alpha_n^2 c t / a^2},
  // @f]
  // @f[
  //   \frac{u_y(y, t)}{y} = -\frac{F (1 - \nu)}{2 G a}
  //     + \frac{F (1 - \nu_u)}{G a} \sum_{n \ge 1}
  //     \frac{\sin\alpha_n\cos\alpha_n}{\alpha_n - \sin\alpha_n\cos\alpha_n}
  //     e^{-\alpha_n^2 c t / a^2},
  // @f]
  // with alpha_n the positive roots of tan(alpha) = (1 - nu) / (nu_u - nu)
  // alpha, one in each interval ((n - 1) pi, (n - 1) pi + pi / 2). At
  // t = 0+ the pressure is uniform, p_0 = F B (1 + nu_u) / (3 a); as the
  // sides drain, the load moves to the stiffer skeleton near them and the
  // pressure at the centre first rises above p_0 (the Mandel-Cryer effect)
  // before it decays.
  class MandelSolution
  {
  public:
    MandelSolution(const Soil &soil, const double a, const double F)
      : a(a)
      , F(F)
      , G(soil.shear_modulus())
      , nu(soil.nu)
      , c(soil.consolidation_coefficient())
    {
      // tan(alpha) = C alpha, i.e. g(alpha) = sin - C alpha cos = 0, by
      // bisection: g < 0 just above (n - 1) pi (C > 1) and g = +-1 with
      // the sign of sin at (n - 1) pi + pi / 2.
      const double C = (1. - nu) / (nu_u - nu);
      const auto   g = [C](const double x) {
        return std::sin(x) - C * x * std::cos(x);
      };
      for (unsigned int n = 0; n < 200; ++n)
        {
          double lo = n * M_PI + 1e-12, hi = n * M_PI + M_PI / 2 - 1e-12;
          for (unsigned int i = 0; i < 100; ++i)
            {
              const double mid = 0.5 * (lo + hi);
              if ((g(lo) < 0) == (g(mid) < 0))
                lo = mid;
              else
                hi = mid;
            }
          const double alpha = 0.5 * (lo + hi);
          const double sc    = std::sin(alpha) * std::cos(alpha);
          roots.push_back(alpha);
          pressure_weights.push_back(std::sin(alpha) / (alpha - sc));
          displacement_weights.push_back(sc / (alpha - sc));
        }
    }

    /// The dimensionless time c t / a^2.
    double
    dimensionless_time(const double t) const
    {
      return c * t / (a * a);
    }

    double
    initial_pressure() const
    {
      return F * (1. + nu_u) / (3. * a);
    }

    double
    pressure(const double x, const double t) const
    {
      if (t <= 0.)
        return 0.;
      const double tau = dimensionless_time(t);
      double       sum = 0.;
      for (unsigned int n = 0; n < roots.size(); ++n)
        sum += pressure_weights[n] *
               (std::cos(roots[n] * x / a) - std::cos(roots[n])) *
               std::exp(-roots[n] * roots[n] * tau);
      return 2. * initial_pressure() * sum;
    }

    /// u_y / y: the plates approach each other uniformly.
    double
    vertical_strain(const double t) const
    {
      if (t <= 0.)
        return 0.;
      const double tau = dimensionless_time(t);
      double       sum = 0.;
      for (unsigned int n = 0; n < roots.size(); ++n)
        sum += displacement_weights[n] * std::exp(-roots[n] * roots[n] * tau);
      return -F * (1. - nu) / (2. * G * a) + F * (1. - nu_u) / (G * a) * sum;
    }

    /// The largest pressure at @p x over 0 < t <= @p t_end (sampled at
    /// 20000 equal steps; the curve is smooth).
    double
    peak_pressure(const double x, const double t_end) const
    {
      double peak = 0.;
      for (unsigned int i = 1; i <= 20000; ++i)
        peak = std::max(peak, pressure(x, t_end * i / 20000.));
      return peak;
    }

  private:
    static constexpr double nu_u = 0.5;
    const double            a, F, G, nu, c;
    std::vector<double>     roots, pressure_weights, displacement_weights;
  };
} // namespace Consolidation

#endif
