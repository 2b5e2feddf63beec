#include <algorithm>
#include <qsmpm/materials/linear_elastic.h>

namespace qsmpm
{
  template <int dim>
  std::pair<double, double>
  LinearElastic<dim>::lame_parameters(const double young_modulus,
                                      const double poisson_ratio)
  {
    AssertThrow(young_modulus > 0,
                ExcMessage("Young's modulus must be positive."));
    AssertThrow(poisson_ratio > -1 && poisson_ratio < 0.5,
                ExcMessage("Poisson's ratio must lie in (-1, 0.5)."));
    const double mu     = young_modulus / (2. * (1. + poisson_ratio));
    const double lambda = young_modulus * poisson_ratio /
                          ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
    return {lambda, mu};
  }



  template <int dim>
  SymmetricTensor<4, dim>
  LinearElastic<dim>::isotropic_stiffness(const double young_modulus,
                                          const double poisson_ratio,
                                          const bool   plane_stress)
  {
    auto [lambda, mu] = lame_parameters(young_modulus, poisson_ratio);
    // Plane stress: eliminating eps_zz from sigma_zz = 0 replaces lambda by
    // 2 lambda mu / (lambda + 2 mu).
    if (dim == 2 && plane_stress)
      lambda = 2. * lambda * mu / (lambda + 2. * mu);
    return lambda * outer_product(unit_symmetric_tensor<dim>(),
                                  unit_symmetric_tensor<dim>()) +
           2. * mu * identity_tensor<dim>();
  }



  template <int dim>
  LinearElastic<dim>::LinearElastic(const double young_modulus,
                                    const double poisson_ratio,
                                    const bool   plane_stress)
    : C(isotropic_stiffness(young_modulus, poisson_ratio, plane_stress))
    , lambda(C[0][0][1][1])
    , two_mu(2. * C[0][1][0][1])
    , is_plane_stress(dim == 2 && plane_stress)
  {
  }



  template <int dim>
  bool
  LinearElastic<dim>::supports_axisymmetry() const
  {
    return dim == 2 && !is_plane_stress;
  }



  template <int dim>
  void
  LinearElastic<dim>::update_stress_axisymmetric(
    const PointState<dim>         &old,
    const double                   old_hoop_stress,
    const SymmetricTensor<2, dim> &strain_increment,
    const double                   hoop_strain_increment,
    SymmetricTensor<2, dim>       &stress,
    double                        &hoop_stress,
    ArrayView<double>) const
  {
    AssertThrow(supports_axisymmetry(),
                ExcMessage("linear elastic: <Plane stress = true> and "
                           "Material points/Axisymmetric = true exclude each "
                           "other."));
    const double volumetric =
      lambda * (trace(strain_increment) + hoop_strain_increment);
    stress = old.stress + two_mu * strain_increment +
             volumetric * unit_symmetric_tensor<dim>();
    hoop_stress = old_hoop_stress + volumetric + two_mu * hoop_strain_increment;
  }



  template <int dim>
  LinearElastic<dim>::LinearElastic(const Parameters &parameters)
    : LinearElastic(parameters.elasticity.young_modulus,
                    parameters.elasticity.poisson_ratio,
                    parameters.plane_stress)
  {
  }



  template <int dim>
  LinearElastic<dim>::LinearElastic(ParameterHandler &prm)
    : LinearElastic(Parameters::from(prm))
  {
  }



  void
  IsotropicElasticity::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Young's modulus",
                      young_modulus,
                      "Young's modulus E (Pa, or any consistent unit).",
                      Patterns::Double(0.));
    prm.add_parameter("Poisson's ratio",
                      poisson_ratio,
                      "Poisson's ratio nu, in (-1, 0.5).",
                      Patterns::Double(-1., 0.5));
  }



  template <int dim>
  void
  LinearElastic<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    elasticity.add_parameters(prm);
    prm.add_parameter("Plane stress",
                      plane_stress,
                      "2D only: plane stress (sigma_zz = 0) instead of plane "
                      "strain (eps_zz = 0).",
                      Patterns::Bool());
  }



  template <int dim>
  void
  LinearElastic<dim>::declare_parameters(ParameterHandler &prm)
  {
    Parameters::declare_parameters(prm);
  }



  template <int dim>
  void
  LinearElastic<dim>::update_stress(
    const PointState<dim>         &old,
    const SymmetricTensor<2, dim> &strain_increment,
    SymmetricTensor<2, dim>       &stress,
    ArrayView<double>) const
  {
    stress = old.stress + C * strain_increment;
  }



  template <int dim>
  void
  LinearElastic<dim>::update_stresses(
    const PointStateBatch<dim>              &old,
    ArrayView<const SymmetricTensor<2, dim>> strain_increments,
    ArrayView<SymmetricTensor<2, dim>>       stresses,
    ArrayView<double>) const
  {
    // C : d_eps = lambda tr(d_eps) I + 2 mu d_eps, without the
    // contraction with all entries of C.
    for (unsigned int i = 0; i < old.size(); ++i)
      {
        const SymmetricTensor<2, dim> &d_eps = strain_increments[i];
        SymmetricTensor<2, dim>       &sigma = stresses[i];
        sigma                                = old.stress(i) + two_mu * d_eps;
        const double lambda_trace            = lambda * trace(d_eps);
        for (unsigned int d = 0; d < dim; ++d)
          sigma[d][d] += lambda_trace;
      }
  }



  template <int dim>
  typename PointStateBatch<dim>::Fields
  LinearElastic<dim>::batch_fields() const
  {
    return {false, true, false, false, false};
  }



  template <int dim>
  SymmetricTensor<4, dim>
  LinearElastic<dim>::tangent(const PointState<dim> &) const
  {
    return C;
  }



  template <int dim>
  void
  LinearElastic<dim>::tangents(
    [[maybe_unused]] const PointStateBatch<dim> &old,
    ArrayView<SymmetricTensor<4, dim>>           C_points) const
  {
    AssertDimension(C_points.size(), old.size());
    std::fill(C_points.begin(), C_points.end(), C);
  }



  template <int dim>
  void
  LinearElastic<dim>::loading_tangents(
    const PointStateBatch<dim>        &old,
    ArrayView<SymmetricTensor<4, dim>> C_points) const
  {
    tangents(old, C_points);
  }



  template <int dim>
  const SymmetricTensor<4, dim> &
  LinearElastic<dim>::stiffness() const
  {
    return C;
  }



  template class LinearElastic<2>;
  template class LinearElastic<3>;

  QSMPM_REGISTER_CONSTITUTIVE_MODEL(LinearElastic,
                                    "linear elastic",
                                    "isotropic linear elasticity (E, nu; "
                                    "plane strain or plane stress in 2D).")
} // namespace qsmpm
