#ifndef qsmpm_base_tensor_functions_h
#define qsmpm_base_tensor_functions_h

#include <array>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <utility>

namespace qsmpm
{
  using namespace dealii;

  /**
   * Isotropic functions of symmetric second-order tensors, evaluated in the
   * eigenbasis, and their derivatives, as needed by finite-strain models
   * (logarithmic strain of the Hencky model).
   *
   * For a symmetric positive definite b = Q diag(lambda) Q^T (columns q_a of
   * Q the eigenvectors),
   *
   *   ln b = sum_a ln(lambda_a) q_a (x) q_a,
   *
   * and by the Daleckii-Krein formula its derivative in the direction of a
   * symmetric db is, in the eigenbasis,
   *
   *   [Q^T d(ln b) Q]_ab = theta_ab [Q^T db Q]_ab,
   *   theta_ab = (ln lambda_a - ln lambda_b) / (lambda_a - lambda_b),
   *   theta_aa = 1 / lambda_a.
   *
   * The divided difference theta_ab is evaluated as
   * 2 atanh(r) / (r (lambda_a + lambda_b)) with
   * r = (lambda_a - lambda_b) / (lambda_a + lambda_b), which is accurate to
   * a few ulps for all pairs, including (nearly) equal eigenvalues, where
   * the naive quotient loses all digits. The derivative is therefore smooth
   * across coincident eigenvalues, for which the eigenvectors are not
   * unique (the result does not depend on the choice).
   *
   * Eigen decompositions use dealii::eigenvectors() with the (accurate)
   * QL method with implicit shifts (Jacobi's method where QL does not
   * converge; NaN for a tensor that is not finite).
   */
  namespace TensorFunctions
  {
    /// The left Cauchy-Green tensor b = F F^T.
    template <int dim>
    SymmetricTensor<2, dim>
    left_cauchy_green(const Tensor<2, dim> &F);

    /**
     * Eigenvalues and unit eigenvectors of a symmetric tensor, eigenvalues
     * in descending order (as returned by dealii::eigenvectors()).
     */
    template <int dim>
    std::array<std::pair<double, Tensor<1, dim>>, dim>
    eigen_decomposition(const SymmetricTensor<2, dim> &b);

    /**
     * The divided difference (ln x - ln y) / (x - y) for x, y > 0, and 1/x
     * for x == y; accurate to a few ulps, also for nearly equal arguments.
     */
    double
    log_divided_difference(const double x, const double y);

    /**
     * The logarithm ln b of a symmetric positive definite tensor. A
     * non-positive eigenvalue gives a result that is not finite.
     */
    template <int dim>
    SymmetricTensor<2, dim>
    log(const SymmetricTensor<2, dim> &b);

    /**
     * The directional derivative d(ln b)[db] of the logarithm at the
     * symmetric positive definite @p b in the (symmetric) direction @p db,
     * by the Daleckii-Krein formula above.
     */
    template <int dim>
    SymmetricTensor<2, dim>
    log_directional_derivative(const SymmetricTensor<2, dim> &b,
                               const SymmetricTensor<2, dim> &db);

    /**
     * The derivative of the logarithm at @p b as a fourth-order tensor L
     * with d(ln b) = L : db for every symmetric db,
     *
     *   L_ijkl = sum_ab theta_ab q_a,i q_b,j (q_a,k q_b,l + q_a,l q_b,k) / 2
     *
     * (minor- and major-symmetric).
     */
    template <int dim>
    SymmetricTensor<4, dim>
    log_derivative(const SymmetricTensor<2, dim> &b);
  } // namespace TensorFunctions
} // namespace qsmpm

#endif
