#include <deal.II/lac/full_matrix.h>
#include <qsmpm/base/rotation.h>
#include <qsmpm/homogenization/stiffness_bounds.h>

namespace qsmpm
{
  StiffnessBounds::StiffnessBounds(const SymmetricTensor<4, 3>     &C_crystal,
                                   const std::vector<Tensor<2, 3>> &g,
                                   const std::vector<double>       &w)
  {
    AssertThrow(g.size() == w.size() && !g.empty(),
                ExcMessage("StiffnessBounds: one weight per orientation."));
    Matrix6 S_mean{};
    C_voigt     = Matrix6{};
    double wsum = 0;
    for (unsigned int n = 0; n < g.size(); ++n)
      if (w[n] != 0.)
        {
          const Matrix6 C =
            Rotation::to_voigt(Rotation::rotate_to_sample(C_crystal, g[n]));
          const Matrix6 S = inverse(C);
          for (unsigned int a = 0; a < 6; ++a)
            for (unsigned int b = 0; b < 6; ++b)
              {
                C_voigt[a][b] += w[n] * C[a][b];
                S_mean[a][b] += w[n] * S[a][b];
              }
          wsum += w[n];
        }
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = 0; b < 6; ++b)
        {
          C_voigt[a][b] /= wsum;
          S_mean[a][b] /= wsum;
        }
    C_reuss = inverse(S_mean);
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = 0; b < 6; ++b)
        C_hill[a][b] = 0.5 * (C_voigt[a][b] + C_reuss[a][b]);
  }



  const StiffnessBounds::Matrix6 &
  StiffnessBounds::voigt() const
  {
    return C_voigt;
  }



  const StiffnessBounds::Matrix6 &
  StiffnessBounds::reuss() const
  {
    return C_reuss;
  }



  const StiffnessBounds::Matrix6 &
  StiffnessBounds::hill() const
  {
    return C_hill;
  }



  StiffnessBounds::Matrix6
  StiffnessBounds::inverse(const Matrix6 &C)
  {
    FullMatrix<double> M(6, 6);
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = 0; b < 6; ++b)
        M(a, b) = C[a][b];
    M.gauss_jordan();
    Matrix6 S;
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = 0; b < 6; ++b)
        {
          S[a][b] = M(a, b);
          AssertThrow(std::isfinite(S[a][b]),
                      ExcMessage("A 6x6 stiffness is singular."));
        }
    return S;
  }



  StiffnessBounds::InPlane
  StiffnessBounds::in_plane(const Matrix6 &C)
  {
    const Matrix6 S = inverse(C);
    InPlane       r;
    r.E_x        = 1. / S[0][0];
    r.E_y        = 1. / S[1][1];
    r.E_in_plane = 0.5 * (r.E_x + r.E_y);
    return r;
  }
} // namespace qsmpm
