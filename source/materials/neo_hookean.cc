#include <cmath>
#include <limits>
#include <qsmpm/materials/linear_elastic.h>
#include <qsmpm/materials/neo_hookean.h>

namespace qsmpm
{
  namespace
  {
    /// b = F F^T.
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
  } // namespace



  template <int dim>
  std::pair<double, double>
  NeoHookean<dim>::lame_parameters(const double young_modulus,
                                   const double poisson_ratio)
  {
    AssertThrow(young_modulus > 0,
                ExcMessage("neo-Hookean: Young's modulus must be positive."));
    AssertThrow(poisson_ratio > -1 && poisson_ratio < 0.5,
                ExcMessage(
                  "neo-Hookean: Poisson's ratio must lie in (-1, 0.5)."));
    const double mu     = young_modulus / (2. * (1. + poisson_ratio));
    const double lambda = young_modulus * poisson_ratio /
                          ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
    return {lambda, mu};
  }



  template <int dim>
  NeoHookean<dim>::NeoHookean(const double young_modulus,
                              const double poisson_ratio)
    : lambda(lame_parameters(young_modulus, poisson_ratio).first)
    , mu(lame_parameters(young_modulus, poisson_ratio).second)
    , C(LinearElastic<dim>::isotropic_stiffness(young_modulus,
                                                poisson_ratio,
                                                false))
  {
  }



  template <int dim>
  NeoHookean<dim>::NeoHookean(ParameterHandler &prm)
    : NeoHookean(prm.get_double("Young's modulus"),
                 prm.get_double("Poisson's ratio"))
  {
  }



  template <int dim>
  void
  NeoHookean<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Young's modulus",
                      "1.0",
                      Patterns::Double(0.),
                      "Young's modulus E (Pa, or any consistent unit).");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      Patterns::Double(-1., 0.5),
                      "Poisson's ratio nu, in (-1, 0.5).");
  }



  template <int dim>
  bool
  NeoHookean<dim>::supports_finite_strain() const
  {
    return true;
  }



  template <int dim>
  void
  NeoHookean<dim>::update_stress(
    const PointState<dim>         &old,
    const SymmetricTensor<2, dim> &strain_increment,
    SymmetricTensor<2, dim>       &stress,
    ArrayView<double>) const
  {
    stress = old.stress + C * strain_increment;
  }



  template <int dim>
  SymmetricTensor<4, dim>
  NeoHookean<dim>::tangent(const PointState<dim> &) const
  {
    return C;
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
    tau = mu * (left_cauchy_green(kinematics.F) - I) + lambda * std::log(J) * I;
  }



  template <int dim>
  Tensor<4, dim>
  NeoHookean<dim>::kirchhoff_tangent(
    const PointState<dim> &,
    const FiniteStrainKinematics<dim> &kinematics) const
  {
    const SymmetricTensor<2, dim> b = left_cauchy_green(kinematics.F);
    Tensor<4, dim>                c;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        {
          for (unsigned int l = 0; l < dim; ++l)
            {
              c[i][j][i][l] += mu * b[l][j];
              c[i][j][j][l] += mu * b[i][l];
            }
          if (i == j)
            for (unsigned int k = 0; k < dim; ++k)
              c[i][i][k][k] += lambda;
        }
    return c;
  }



  template <int dim>
  const SymmetricTensor<4, dim> &
  NeoHookean<dim>::stiffness() const
  {
    return C;
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
