#include <cmath>
#include <limits>
#include <qsmpm/base/tensor_functions.h>

namespace qsmpm
{
  namespace TensorFunctions
  {
    template <int dim>
    SymmetricTensor<2, dim>
    left_cauchy_green(const Tensor<2, dim> &F)
    {
      SymmetricTensor<2, dim> b;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            b[i][j] += F[i][k] * F[j][k];
      return b;
    }



    template <int dim>
    std::array<std::pair<double, Tensor<1, dim>>, dim>
    eigen_decomposition(const SymmetricTensor<2, dim> &b)
    {
      // A tensor that is not finite (a trial of Newton's line search far
      // from the solution) has no eigenvalues: NaN, so that the residual
      // is not finite and the step is cut back, where QL threw and stopped
      // the run. Where QL does not converge for a finite tensor, Jacobi's
      // method, which always does.
      if (!std::isfinite(b.norm()))
        {
          std::array<std::pair<double, Tensor<1, dim>>, dim> undefined;
          for (auto &pair : undefined)
            {
              pair.first = std::numeric_limits<double>::quiet_NaN();
              for (unsigned int d = 0; d < dim; ++d)
                pair.second[d] = std::numeric_limits<double>::quiet_NaN();
            }
          return undefined;
        }
      try
        {
          return eigenvectors(
            b, SymmetricTensorEigenvectorMethod::ql_implicit_shifts);
        }
      catch (const std::exception &)
        {
          return eigenvectors(b, SymmetricTensorEigenvectorMethod::jacobi);
        }
    }



    double
    log_divided_difference(const double x, const double y)
    {
      // With r = (x - y)/(x + y): ln x - ln y = ln((1 + r)/(1 - r))
      // = 2 atanh(r) and x - y = r (x + y). x - y is exact for close x, y
      // and atanh(r)/r = 1 + r^2/3 + ... has no cancellation.
      const double sum = x + y;
      const double r   = (x - y) / sum;
      if (r == 0.)
        return 2. / sum;
      return 2. * std::atanh(r) / (r * sum);
    }



    template <int dim>
    SymmetricTensor<2, dim>
    log(const SymmetricTensor<2, dim> &b)
    {
      const auto              eigen = eigen_decomposition(b);
      SymmetricTensor<2, dim> result;
      for (unsigned int a = 0; a < dim; ++a)
        {
          const double log_lambda = std::log(eigen[a].first);
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              result[i][j] +=
                log_lambda * eigen[a].second[i] * eigen[a].second[j];
        }
      return result;
    }



    namespace
    {
      /// The matrix theta_ab of divided differences of the eigenvalues.
      template <int dim>
      Tensor<2, dim>
      divided_differences(
        const std::array<std::pair<double, Tensor<1, dim>>, dim> &eigen)
      {
        Tensor<2, dim> theta;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            theta[a][b] =
              log_divided_difference(eigen[a].first, eigen[b].first);
        return theta;
      }
    } // namespace



    template <int dim>
    SymmetricTensor<2, dim>
    log_directional_derivative(const SymmetricTensor<2, dim> &b,
                               const SymmetricTensor<2, dim> &db)
    {
      const auto           eigen = eigen_decomposition(b);
      const Tensor<2, dim> theta = divided_differences<dim>(eigen);
      // The direction in the eigenbasis, scaled by theta_ab, and back.
      Tensor<2, dim> scaled;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int c = 0; c < dim; ++c)
          scaled[a][c] =
            theta[a][c] * (eigen[a].second * (db * eigen[c].second));
      SymmetricTensor<2, dim> result;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int c = 0; c < dim; ++c)
              result[i][j] +=
                scaled[a][c] * eigen[a].second[i] * eigen[c].second[j];
      return result;
    }



    template <int dim>
    SymmetricTensor<4, dim>
    log_derivative(const SymmetricTensor<2, dim> &b)
    {
      const auto              eigen = eigen_decomposition(b);
      const Tensor<2, dim>    theta = divided_differences<dim>(eigen);
      SymmetricTensor<4, dim> L;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = k; l < dim; ++l)
              {
                double value = 0.;
                for (unsigned int a = 0; a < dim; ++a)
                  for (unsigned int c = 0; c < dim; ++c)
                    {
                      const Tensor<1, dim> &qa = eigen[a].second;
                      const Tensor<1, dim> &qc = eigen[c].second;
                      value += theta[a][c] * qa[i] * qc[j] *
                               (qa[k] * qc[l] + qa[l] * qc[k]);
                    }
                L[i][j][k][l] = 0.5 * value;
              }
      return L;
    }



    template SymmetricTensor<2, 2>
    left_cauchy_green<2>(const Tensor<2, 2> &);
    template SymmetricTensor<2, 3>
    left_cauchy_green<3>(const Tensor<2, 3> &);
    template std::array<std::pair<double, Tensor<1, 2>>, 2>
    eigen_decomposition<2>(const SymmetricTensor<2, 2> &);
    template std::array<std::pair<double, Tensor<1, 3>>, 3>
    eigen_decomposition<3>(const SymmetricTensor<2, 3> &);
    template SymmetricTensor<2, 2>
    log<2>(const SymmetricTensor<2, 2> &);
    template SymmetricTensor<2, 3>
    log<3>(const SymmetricTensor<2, 3> &);
    template SymmetricTensor<2, 2>
    log_directional_derivative<2>(const SymmetricTensor<2, 2> &,
                                  const SymmetricTensor<2, 2> &);
    template SymmetricTensor<2, 3>
    log_directional_derivative<3>(const SymmetricTensor<2, 3> &,
                                  const SymmetricTensor<2, 3> &);
    template SymmetricTensor<4, 2>
    log_derivative<2>(const SymmetricTensor<2, 2> &);
    template SymmetricTensor<4, 3>
    log_derivative<3>(const SymmetricTensor<2, 3> &);
  } // namespace TensorFunctions
} // namespace qsmpm
