#include <qsmpm/materials/isotropic_hyperelastic.h>

namespace qsmpm
{
  template <int dim>
  std::pair<double, double>
  IsotropicHyperelastic<dim>::lame_parameters(const std::string &model_name,
                                              const double       young_modulus,
                                              const double       poisson_ratio)
  {
    AssertThrow(young_modulus > 0,
                ExcMessage(model_name + ": Young's modulus must be positive."));
    AssertThrow(poisson_ratio > -1 && poisson_ratio < 0.5,
                ExcMessage(model_name +
                           ": Poisson's ratio must lie in (-1, 0.5)."));
    const double mu     = young_modulus / (2. * (1. + poisson_ratio));
    const double lambda = young_modulus * poisson_ratio /
                          ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
    return {lambda, mu};
  }



  template <int dim>
  IsotropicHyperelastic<dim>::IsotropicHyperelastic(
    const std::string &model_name,
    const double       young_modulus,
    const double       poisson_ratio)
    // Check E and nu first, so that a message names this model, not
    // "linear elastic".
    : LinearElastic<dim>(
        (lame_parameters(model_name, young_modulus, poisson_ratio),
         young_modulus),
        poisson_ratio,
        /*plane_stress=*/false)
    , lambda(lame_parameters(model_name, young_modulus, poisson_ratio).first)
    , mu(lame_parameters(model_name, young_modulus, poisson_ratio).second)
  {
  }



  template <int dim>
  void
  IsotropicHyperelastic<dim>::declare_parameters(ParameterHandler &prm)
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
  IsotropicHyperelastic<dim>::supports_finite_strain() const
  {
    return true;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  IsotropicHyperelastic<dim>::left_cauchy_green(const Tensor<2, dim> &F)
  {
    SymmetricTensor<2, dim> b;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          b[i][j] += F[i][k] * F[j][k];
    return b;
  }



  template class IsotropicHyperelastic<2>;
  template class IsotropicHyperelastic<3>;
} // namespace qsmpm
