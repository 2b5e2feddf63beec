#include <algorithm>
#include <cmath>
#include <qsmpm/base/rotation.h>

namespace qsmpm
{
  namespace
  {
    // Voigt index -> tensor index pair, order 11, 22, 33, 23, 13, 12.
    constexpr unsigned int voigt_i[6] = {0, 1, 2, 1, 0, 0};
    constexpr unsigned int voigt_j[6] = {0, 1, 2, 2, 2, 1};
  } // namespace



  Tensor<2, 3>
  Rotation::from_bunge(const double phi1, const double Phi, const double phi2)
  {
    const double c1 = std::cos(phi1), s1 = std::sin(phi1);
    const double c = std::cos(Phi), s = std::sin(Phi);
    const double c2 = std::cos(phi2), s2 = std::sin(phi2);
    Tensor<2, 3> g;
    g[0][0] = c1 * c2 - s1 * s2 * c;
    g[0][1] = s1 * c2 + c1 * s2 * c;
    g[0][2] = s2 * s;
    g[1][0] = -c1 * s2 - s1 * c2 * c;
    g[1][1] = -s1 * s2 + c1 * c2 * c;
    g[1][2] = c2 * s;
    g[2][0] = s1 * s;
    g[2][1] = -c1 * s;
    g[2][2] = c;
    return g;
  }



  std::array<double, 3>
  Rotation::to_bunge(const Tensor<2, 3> &g)
  {
    const double two_pi = 2. * M_PI;
    auto         wrap   = [two_pi](double a) {
      a = std::fmod(a, two_pi);
      return a < 0 ? a + two_pi : a;
    };
    const double Phi = std::acos(std::clamp(g[2][2], -1., 1.));
    double       phi1, phi2;
    if (std::sin(Phi) > 1e-10)
      {
        phi1 = std::atan2(g[2][0], -g[2][1]);
        phi2 = std::atan2(g[0][2], g[1][2]);
      }
    else
      {
        // Phi = 0 or pi: only phi1 +- phi2 is defined; put it in phi1.
        phi1 = std::atan2(g[0][1], g[0][0]);
        phi2 = 0.;
      }
    return {{wrap(phi1), Phi, wrap(phi2)}};
  }



  const std::vector<Tensor<2, 3>> &
  Rotation::cubic_symmetry()
  {
    static const std::vector<Tensor<2, 3>> operations = [] {
      // All signed permutation matrices with determinant +1.
      std::vector<Tensor<2, 3>>   ops;
      std::array<unsigned int, 3> perm = {{0, 1, 2}};
      do
        for (unsigned int signs = 0; signs < 8; ++signs)
          {
            Tensor<2, 3> S;
            for (unsigned int i = 0; i < 3; ++i)
              S[i][perm[i]] = (signs & (1u << i)) ? -1. : 1.;
            if (determinant(S) > 0)
              ops.push_back(S);
          }
      while (std::next_permutation(perm.begin(), perm.end()));
      return ops;
    }();
    return operations;
  }



  const std::vector<Tensor<2, 3>> &
  Rotation::orthorhombic_symmetry()
  {
    static const std::vector<Tensor<2, 3>> operations = [] {
      std::vector<Tensor<2, 3>> ops;
      for (const auto &d : {std::array<double, 3>{{1, 1, 1}},
                            std::array<double, 3>{{1, -1, -1}},
                            std::array<double, 3>{{-1, 1, -1}},
                            std::array<double, 3>{{-1, -1, 1}}})
        {
          Tensor<2, 3> S;
          for (unsigned int i = 0; i < 3; ++i)
            S[i][i] = d[i];
          ops.push_back(S);
        }
      return ops;
    }();
    return operations;
  }



  double
  Rotation::angle(const Tensor<2, 3> &g)
  {
    // atan2 of sine and cosine: accurate also near 0, where the acos of the
    // trace loses half the digits. g_32 - g_23 = 2 sin(angle) n_x etc.
    const double a = g[2][1] - g[1][2], b = g[0][2] - g[2][0],
                 c = g[1][0] - g[0][1];
    return std::atan2(0.5 * std::sqrt(a * a + b * b + c * c),
                      0.5 * (trace(g) - 1.));
  }



  namespace
  {
    /**
     * The cubic symmetry S (its index in Rotation::cubic_symmetry()) with
     * the largest trace of S dg, dg = g_b g_a^T, and that trace.
     */
    std::pair<unsigned int, double>
    closest_symmetry(const Tensor<2, 3> &dg)
    {
      // trace(S dg) for all S at once: the largest trace is the smallest angle.
      // Every S is a signed permutation, S_i,p(i) = +-1, so
      // trace(S dg) = sum_i S_i,p(i) dg_p(i),i: three terms per S.
      struct SignedPermutation
      {
        unsigned int p[3];
        double       sign[3];
      };
      static const std::vector<SignedPermutation> table = [] {
        std::vector<SignedPermutation> t;
        for (const auto &S : Rotation::cubic_symmetry())
          {
            SignedPermutation sp;
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                if (S[i][j] != 0.)
                  {
                    sp.p[i]    = j;
                    sp.sign[i] = S[i][j];
                  }
            t.push_back(sp);
          }
        return t;
      }();
      double       max_trace = -2.;
      unsigned int best      = 0;
      for (unsigned int s = 0; s < table.size(); ++s)
        {
          const auto  &sp = table[s];
          const double t  = sp.sign[0] * dg[sp.p[0]][0] +
                           sp.sign[1] * dg[sp.p[1]][1] +
                           sp.sign[2] * dg[sp.p[2]][2];
          if (t > max_trace)
            {
              max_trace = t;
              best      = s;
            }
        }
      return {best, max_trace};
    }
  } // namespace



  double
  Rotation::disorientation(const Tensor<2, 3> &g_a, const Tensor<2, 3> &g_b)
  {
    const Tensor<2, 3> dg = g_b * transpose(g_a);
    return angle(cubic_symmetry()[closest_symmetry(dg).first] * dg);
  }



  double
  Rotation::disorientation(const Tensor<2, 3> &g_a,
                           const Tensor<2, 3> &g_b,
                           const double        bound)
  {
    const Tensor<2, 3> dg        = g_b * transpose(g_a);
    const auto [best, max_trace] = closest_symmetry(dg);
    if (max_trace < 1. + 2. * std::cos(bound) - 1e-12)
      return bound;
    return angle(cubic_symmetry()[best] * dg);
  }



  Tensor<2, 3>
  Rotation::closest_equivalent(const Tensor<2, 3> &g,
                               const Tensor<2, 3> &reference)
  {
    return cubic_symmetry()[closest_symmetry(g * transpose(reference)).first] *
           g;
  }



  std::array<double, 4>
  Rotation::to_quaternion(const Tensor<2, 3> &g)
  {
    // Shepperd's method: the largest of the four diagonal combinations.
    std::array<double, 4> q;
    const double          t = trace(g);
    if (t >= g[0][0] && t >= g[1][1] && t >= g[2][2])
      {
        const double r = std::sqrt(1. + t);
        q              = {{0.5 * r,
                           0.5 * (g[2][1] - g[1][2]) / r,
                           0.5 * (g[0][2] - g[2][0]) / r,
                           0.5 * (g[1][0] - g[0][1]) / r}};
      }
    else
      {
        unsigned int i = 0;
        if (g[1][1] > g[i][i])
          i = 1;
        if (g[2][2] > g[i][i])
          i = 2;
        const unsigned int j = (i + 1) % 3, k = (i + 2) % 3;
        const double       r = std::sqrt(1. + g[i][i] - g[j][j] - g[k][k]);
        q[0]                 = 0.5 * (g[k][j] - g[j][k]) / r;
        q[1 + i]             = 0.5 * r;
        q[1 + j]             = 0.5 * (g[j][i] + g[i][j]) / r;
        q[1 + k]             = 0.5 * (g[k][i] + g[i][k]) / r;
      }
    if (q[0] < 0)
      for (double &c : q)
        c = -c;
    return q;
  }



  Tensor<2, 3>
  Rotation::from_quaternion(const std::array<double, 4> &q_in)
  {
    const double norm = std::sqrt(q_in[0] * q_in[0] + q_in[1] * q_in[1] +
                                  q_in[2] * q_in[2] + q_in[3] * q_in[3]);
    const double w = q_in[0] / norm, x = q_in[1] / norm, y = q_in[2] / norm,
                 z = q_in[3] / norm;
    Tensor<2, 3> g;
    g[0][0] = 1 - 2 * (y * y + z * z);
    g[0][1] = 2 * (x * y - w * z);
    g[0][2] = 2 * (x * z + w * y);
    g[1][0] = 2 * (x * y + w * z);
    g[1][1] = 1 - 2 * (x * x + z * z);
    g[1][2] = 2 * (y * z - w * x);
    g[2][0] = 2 * (x * z - w * y);
    g[2][1] = 2 * (y * z + w * x);
    g[2][2] = 1 - 2 * (x * x + y * y);
    return g;
  }



  Tensor<2, 3>
  Rotation::mean(const std::vector<Tensor<2, 3>> &orientations,
                 const std::vector<double>       &weights)
  {
    Assert(!orientations.empty(), ExcInternalError());
    const std::array<double, 4> q0 = to_quaternion(orientations[0]);
    std::array<double, 4>       sum{{0., 0., 0., 0.}};
    for (unsigned int n = 0; n < orientations.size(); ++n)
      {
        std::array<double, 4> q =
          to_quaternion(closest_equivalent(orientations[n], orientations[0]));
        // q and -q are the same rotation: take the one next to q0.
        const double dot =
          q[0] * q0[0] + q[1] * q0[1] + q[2] * q0[2] + q[3] * q0[3];
        const double w =
          (weights.empty() ? 1. : weights[n]) * (dot < 0 ? -1. : 1.);
        for (unsigned int c = 0; c < 4; ++c)
          sum[c] += w * q[c];
      }
    return from_quaternion(sum);
  }



  SymmetricTensor<4, 3>
  Rotation::rotate_to_sample(const SymmetricTensor<4, 3> &C,
                             const Tensor<2, 3>          &g)
  {
    // Two-index contractions one at a time: 4 x 81 x 3 operations.
    const Tensor<4, 3> Cc(C);
    Tensor<4, 3>       A, B;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int n = 0; n < 3; ++n)
        for (unsigned int o = 0; o < 3; ++o)
          for (unsigned int p = 0; p < 3; ++p)
            {
              double s = 0;
              for (unsigned int m = 0; m < 3; ++m)
                s += g[m][i] * Cc[m][n][o][p];
              A[i][n][o][p] = s;
            }
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int o = 0; o < 3; ++o)
          for (unsigned int p = 0; p < 3; ++p)
            {
              double s = 0;
              for (unsigned int n = 0; n < 3; ++n)
                s += g[n][j] * A[i][n][o][p];
              B[i][j][o][p] = s;
            }
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int p = 0; p < 3; ++p)
            {
              double s = 0;
              for (unsigned int o = 0; o < 3; ++o)
                s += g[o][k] * B[i][j][o][p];
              A[i][j][k][p] = s;
            }
    SymmetricTensor<4, 3> result;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = k; l < 3; ++l)
            {
              double s = 0;
              for (unsigned int p = 0; p < 3; ++p)
                s += g[p][l] * A[i][j][k][p];
              result[i][j][k][l] = s;
            }
    return result;
  }



  SymmetricTensor<4, 3>
  Rotation::cubic_stiffness(const double C11,
                            const double C12,
                            const double C44)
  {
    SymmetricTensor<4, 3> C;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        C[i][i][j][j] = (i == j ? C11 : C12);
    C[1][2][1][2] = C44;
    C[0][2][0][2] = C44;
    C[0][1][0][1] = C44;
    return C;
  }



  std::array<std::array<double, 6>, 6>
  Rotation::to_voigt(const SymmetricTensor<4, 3> &C)
  {
    std::array<std::array<double, 6>, 6> M;
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = 0; b < 6; ++b)
        M[a][b] = C[voigt_i[a]][voigt_j[a]][voigt_i[b]][voigt_j[b]];
    return M;
  }
} // namespace qsmpm
