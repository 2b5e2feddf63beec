#include <cmath>
#include <limits>
#include <qsmpm/base/tensor_functions.h>
#include <qsmpm/materials/hencky.h>
#include <qsmpm/materials/linear_elastic.h>

namespace qsmpm
{
  template <int dim>
  Hencky<dim>::Hencky(const double young_modulus, const double poisson_ratio)
    : IsotropicHyperelastic<dim>(young_modulus, poisson_ratio)
  {
  }



  template <int dim>
  Hencky<dim>::Hencky(ParameterHandler &prm)
    : IsotropicHyperelastic<dim>(IsotropicElasticity::from(prm))
  {
  }



  template <int dim>
  void
  Hencky<dim>::update_kirchhoff_stress(
    const PointState<dim> &,
    const FiniteStrainKinematics<dim> &kinematics,
    SymmetricTensor<2, dim>           &tau,
    ArrayView<double>) const
  {
    const double J = determinant(kinematics.F);
    // Not only a guard against inverted points: the eigen solver should not
    // see NaN entries.
    if (!(J > 0.) || !std::isfinite(J))
      {
        tau = std::numeric_limits<double>::quiet_NaN() *
              unit_symmetric_tensor<dim>();
        return;
      }
    tau = this->stiffness() *
          (0.5 * TensorFunctions::log(
                   TensorFunctions::left_cauchy_green(kinematics.F)));
  }



  template <int dim>
  Tensor<4, dim>
  Hencky<dim>::kirchhoff_tangent(
    const PointState<dim> &,
    const FiniteStrainKinematics<dim> &kinematics) const
  {
    const SymmetricTensor<2, dim> b =
      TensorFunctions::left_cauchy_green(kinematics.F);
    // M = D : d(ln b)/d b; d tau = 1/2 M : (dl b + b dl^T) and, M being
    // minor-symmetric, d tau_ij / d l_kl = sum_q M_ijkq b_ql.
    const SymmetricTensor<4, dim> M =
      this->stiffness() * TensorFunctions::log_derivative(b);
    Tensor<4, dim> c;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            for (unsigned int q = 0; q < dim; ++q)
              c[i][j][k][l] += M[i][j][k][q] * b[q][l];
    return c;
  }



  template class Hencky<2>;
  template class Hencky<3>;

  QSMPM_REGISTER_CONSTITUTIVE_MODEL(Hencky,
                                    "hencky",
                                    "isotropic Hencky hyperelasticity, "
                                    "tau = lambda tr(eps) I + 2 mu eps with "
                                    "the logarithmic strain eps = 1/2 ln b "
                                    "(E, nu; plane strain in 2D; linear "
                                    "elastic for small strain).")
} // namespace qsmpm
