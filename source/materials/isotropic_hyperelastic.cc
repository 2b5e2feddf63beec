#include <qsmpm/materials/isotropic_hyperelastic.h>

namespace qsmpm
{
  template <int dim>
  IsotropicHyperelastic<dim>::IsotropicHyperelastic(const double young_modulus,
                                                    const double poisson_ratio)
    : LinearElastic<dim>(young_modulus, poisson_ratio, /*plane_stress=*/false)
    , lambda(
        LinearElastic<dim>::lame_parameters(young_modulus, poisson_ratio).first)
    , mu(LinearElastic<dim>::lame_parameters(young_modulus, poisson_ratio)
           .second)
  {
  }



  template <int dim>
  IsotropicHyperelastic<dim>::IsotropicHyperelastic(
    const IsotropicElasticity &parameters)
    : IsotropicHyperelastic(parameters.young_modulus, parameters.poisson_ratio)
  {
  }



  template <int dim>
  void
  IsotropicHyperelastic<dim>::declare_parameters(ParameterHandler &prm)
  {
    IsotropicElasticity::declare_parameters(prm);
  }



  template <int dim>
  bool
  IsotropicHyperelastic<dim>::supports_finite_strain() const
  {
    return true;
  }



  template class IsotropicHyperelastic<2>;
  template class IsotropicHyperelastic<3>;
} // namespace qsmpm
