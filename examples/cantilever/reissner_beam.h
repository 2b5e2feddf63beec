// The reference solution of the cantilever example: Reissner's
// geometrically exact plane beam (E. Reissner, "On one-dimensional
// finite-strain beam theory: the plane problem", Z. angew. Math. Phys. 23,
// 795-804, 1972), extensible and shear-deformable, with linear relations
// between the stress resultants and the strains, under a dead distributed
// load, clamped at s = 0 and free at s = L; solved by shooting on the
// clamp's moment with a fourth-order Runge-Kutta integration.
#ifndef qsmpm_examples_cantilever_reissner_beam_h
#define qsmpm_examples_cantilever_reissner_beam_h

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace Cantilever
{
  /**
   * A clamped beam of length L along x with axial stiffness EA, shear
   * stiffness kGA and bending stiffness EI under the dead load w per unit
   * length in -y. The state along the arc length s of the undeformed axis
   * is z = (x, y, theta, M): the axis' position, the cross-section's
   * rotation and the bending moment. The resultant of the load beyond s,
   * N(s) = (0, -w (L - s)), is known in closed form (the load is dead),
   * and with it
   *
   *   N_a = N . (cos, sin),  N_s = N . (-sin, cos)   (axial, shear force),
   *   x' = (1 + N_a/EA) cos theta - (N_s/kGA) sin theta,
   *   y' = (1 + N_a/EA) sin theta + (N_s/kGA) cos theta,
   *   theta' = M / EI,          M' = w (L - s) x'.
   *
   * The clamp gives x = y = theta = 0 at s = 0, the free end M(L) = 0; the
   * unknown M(0) is found by the secant method.
   */
  class ReissnerBeam
  {
  public:
    ReissnerBeam(const double       L,
                 const double       EA,
                 const double       kGA,
                 const double       EI,
                 const double       w,
                 const unsigned int n_intervals = 4000)
      : L(L)
      , EA(EA)
      , kGA(kGA)
      , EI(EI)
      , w(w)
      , n(n_intervals)
    {
      // The moment at the clamp of the linear theory starts the secant
      // iteration; with large rotations the lever arm shrinks.
      double m0 = -0.5 * w * L * L, m1 = 0.9 * m0;
      double r0 = integrate(m0).back()[3], r1 = integrate(m1).back()[3];
      for (unsigned int k = 0; k < 100 && std::abs(r1) > 1e-12 * std::abs(m0);
           ++k)
        {
          const double m2 = m1 - r1 * (m1 - m0) / (r1 - r0);
          m0              = m1;
          r0              = r1;
          m1              = m2;
          r1              = integrate(m1).back()[3];
        }
      if (!(std::abs(r1) <= 1e-10 * std::abs(0.5 * w * L * L) + 1e-300))
        throw std::runtime_error("ReissnerBeam: the shooting did not converge");
      states = integrate(m1);
    }

    /// (x, y, theta, M) at the arc length s of the undeformed axis.
    std::array<double, 4>
    at(const double s) const
    {
      const double       h = L / n;
      const unsigned int i =
        std::min<unsigned int>(n - 1, static_cast<unsigned int>(s / h));
      const double          t = (s - i * h) / h;
      std::array<double, 4> z;
      for (unsigned int c = 0; c < 4; ++c)
        z[c] = (1. - t) * states[i][c] + t * states[i + 1][c];
      return z;
    }

  private:
    std::array<double, 4>
    derivative(const double s, const std::array<double, 4> &z) const
    {
      const double c = std::cos(z[2]), sn = std::sin(z[2]);
      const double Ny = -w * (L - s);
      const double Na = Ny * sn, Ns = Ny * c;
      const double dx = (1. + Na / EA) * c - (Ns / kGA) * sn;
      const double dy = (1. + Na / EA) * sn + (Ns / kGA) * c;
      return {{dx, dy, z[3] / EI, w * (L - s) * dx}};
    }

    std::vector<std::array<double, 4>>
    integrate(const double M0) const
    {
      std::vector<std::array<double, 4>> z(n + 1);
      z[0]           = {{0., 0., 0., M0}};
      const double h = L / n;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double          s  = i * h;
          const auto            k1 = derivative(s, z[i]);
          std::array<double, 4> y;
          for (unsigned int c = 0; c < 4; ++c)
            y[c] = z[i][c] + 0.5 * h * k1[c];
          const auto k2 = derivative(s + 0.5 * h, y);
          for (unsigned int c = 0; c < 4; ++c)
            y[c] = z[i][c] + 0.5 * h * k2[c];
          const auto k3 = derivative(s + 0.5 * h, y);
          for (unsigned int c = 0; c < 4; ++c)
            y[c] = z[i][c] + h * k3[c];
          const auto k4 = derivative(s + h, y);
          for (unsigned int c = 0; c < 4; ++c)
            z[i + 1][c] =
              z[i][c] + h / 6. * (k1[c] + 2. * k2[c] + 2. * k3[c] + k4[c]);
        }
      return z;
    }

    const double                       L, EA, kGA, EI, w;
    const unsigned int                 n;
    std::vector<std::array<double, 4>> states;
  };
} // namespace Cantilever

#endif
