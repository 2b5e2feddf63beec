#include <cmath>
#include <limits>
#include <qsmpm/base/tensor_functions.h>
#include <qsmpm/materials/linear_elastic.h>
#include <qsmpm/materials/neo_hookean.h>

namespace qsmpm
{
  template <int dim>
  NeoHookean<dim>::NeoHookean(const double young_modulus,
                              const double poisson_ratio)
    : IsotropicHyperelastic<dim>(young_modulus, poisson_ratio)
  {
  }



  template <int dim>
  NeoHookean<dim>::NeoHookean(ParameterHandler &prm)
    : IsotropicHyperelastic<dim>(IsotropicElasticity::from(prm))
  {
  }



  template <int dim>
  void
  NeoHookean<dim>::update_kirchhoff_stress(
    const PointState<dim> &,
    const FiniteStrainKinematics<dim> &kinematics,
    SymmetricTensor<2, dim>           &tau,
    ArrayView<double>) const
  {
    const double                  J = determinant(kinematics.F);
    const SymmetricTensor<2, dim> I = unit_symmetric_tensor<dim>();
    if (!(J > 0.) || !std::isfinite(J))
      {
        tau = std::numeric_limits<double>::quiet_NaN() * I;
        return;
      }
    tau = this->mu * (TensorFunctions::left_cauchy_green(kinematics.F) - I) +
          this->lambda * std::log(J) * I;
  }



  template <int dim>
  Tensor<4, dim>
  NeoHookean<dim>::kirchhoff_tangent(
    const PointState<dim> &,
    const FiniteStrainKinematics<dim> &kinematics) const
  {
    const SymmetricTensor<2, dim> b =
      TensorFunctions::left_cauchy_green(kinematics.F);
    Tensor<4, dim> c;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        {
          for (unsigned int l = 0; l < dim; ++l)
            {
              c[i][j][i][l] += this->mu * b[l][j];
              c[i][j][j][l] += this->mu * b[i][l];
            }
          if (i == j)
            for (unsigned int k = 0; k < dim; ++k)
              c[i][i][k][k] += this->lambda;
        }
    return c;
  }



  template class NeoHookean<2>;
  template class NeoHookean<3>;

  QSMPM_REGISTER_CONSTITUTIVE_MODEL(NeoHookean,
                                    "neo-Hookean",
                                    "compressible neo-Hookean "
                                    "hyperelasticity, tau = mu (b - I) + "
                                    "lambda ln J I (E, nu; plane strain in "
                                    "2D; linear elastic for small strain).")
} // namespace qsmpm
