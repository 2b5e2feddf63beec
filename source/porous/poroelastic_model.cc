#include <qsmpm/base/utilities.h>
#include <qsmpm/porous/poroelastic_model.h>

namespace qsmpm
{
  namespace
  {
    /// The pore pressure's share -J b p of the Kirchhoff stress: J = det F
    /// times the total hoop stretch @p hoop_stretch (one in plane strain
    /// and 3D), @p bp = b p.
    template <int dim>
    double
    pressure_kirchhoff(const FiniteStrainKinematics<dim> &kinematics,
                       const double                       hoop_stretch,
                       const double                       bp)
    {
      return determinant(kinematics.F) * hoop_stretch * bp;
    }
  } // namespace



  template <int dim>
  PoroelasticModel<dim>::PoroelasticModel(
    std::unique_ptr<ConstitutiveModel<dim>> skeleton,
    const double                            biot_coefficient,
    const double                            initial_pore_pressure)
    : skeleton_model(std::move(skeleton))
    , b(biot_coefficient)
    , p_initial(initial_pore_pressure)
    , n_skeleton(skeleton_model->n_state_components())
  {
    AssertThrow(biot_coefficient > 0. && biot_coefficient <= 1.,
                ExcMessage("Pore fluid: the Biot coefficient must lie in "
                           "(0, 1]."));
  }



  template <int dim>
  std::vector<StateField>
  PoroelasticModel<dim>::state_fields() const
  {
    auto fields = skeleton_model->state_fields();
    fields.push_back({"pore_pressure", 1});
    fields.push_back({"pore_pressure_iterate", 1});
    fields.push_back({"pore_pressure_gradient", dim});
    fields.push_back({"pore_pressure_gradient_iterate", dim});
    fields.push_back({"initial_total_stress",
                      SymmetricTensor<2, dim>::n_independent_components});
    fields.push_back({"hoop_stretch", 1});
    return fields;
  }



  template <int dim>
  void
  PoroelasticModel<dim>::initialize_point_state(const Point<dim>  &x,
                                                const unsigned int material_id,
                                                const types::particle_index id,
                                                ArrayView<double> state) const
  {
    skeleton_model->initialize_point_state(
      x, material_id, id, ArrayView<double>(state.data(), n_skeleton));
    for (unsigned int k = n_skeleton; k < state.size(); ++k)
      state[k] = 0.;
    state[n_skeleton]            = p_initial;
    state[n_skeleton + 1]        = p_initial;
    state[hoop_stretch_offset()] = 1.;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  PoroelasticModel<dim>::initial_stress(const Point<dim>  &x,
                                        const unsigned int material_id,
                                        const SymmetricTensor<2, 3> *sigma0,
                                        ArrayView<double> state) const
  {
    const SymmetricTensor<2, dim> sigma =
      skeleton_model->initial_stress(
        x, material_id, sigma0, ArrayView<double>(state.data(), n_skeleton)) -
      b * p_initial * unit_symmetric_tensor<dim>();
    Utils::write_symmetric<dim>(sigma, state.data() + initial_stress_offset());
    return sigma;
  }



  template <int dim>
  std::vector<StateField>
  PoroelasticModel<dim>::output_fields() const
  {
    auto fields = skeleton_model->output_fields();
    fields.push_back({"pore_pressure", 1});
    for (const auto &component : Utils::symmetric_component_names<dim>())
      fields.push_back({"effective_stress_" + component, 1});
    return fields;
  }



  template <int dim>
  void
  PoroelasticModel<dim>::compute_output_fields(const PointState<dim> &point,
                                               ArrayView<double> values) const
  {
    // The skeleton's fields, p, then sigma' = sigma + b p I.
    constexpr unsigned int n_stress =
      SymmetricTensor<2, dim>::n_independent_components;
    const unsigned int    n        = values.size() - 1 - n_stress;
    const PointState<dim> skeleton = skeleton_state(point);
    skeleton_model->compute_output_fields(skeleton,
                                          ArrayView<double>(values.data(), n));
    values[n] = point.state[n_skeleton];
    for (unsigned int k = 0; k < n_stress; ++k)
      values[n + 1 + k] = skeleton.stress.access_raw_entry(k);
  }



  template <int dim>
  PointState<dim>
  PoroelasticModel<dim>::skeleton_state(const PointState<dim> &point) const
  {
    PointState<dim> s = point;
    s.stress += b * point.state[n_skeleton] * unit_symmetric_tensor<dim>();
    s.state = ArrayView<const double>(point.state.data(), n_skeleton);
    return s;
  }



  template <int dim>
  void
  PoroelasticModel<dim>::update_stress(
    const PointState<dim>         &old,
    const SymmetricTensor<2, dim> &strain_increment,
    SymmetricTensor<2, dim>       &stress,
    ArrayView<double>              new_state) const
  {
    skeleton_model->update_stress(skeleton_state(old),
                                  strain_increment,
                                  stress,
                                  ArrayView<double>(new_state.data(),
                                                    n_skeleton));
    // The pressure of the current iterate acts on the new total stress.
    stress -= b * old.state[n_skeleton + 1] * unit_symmetric_tensor<dim>();
    write_pressure_state(old, new_state);
  }



  template <int dim>
  void
  PoroelasticModel<dim>::write_pressure_state(const PointState<dim> &old,
                                              ArrayView<double> new_state) const
  {
    // p_n <- p_k, grad p_n <- grad p_k.
    const double *p           = old.state.data() + n_skeleton;
    new_state[n_skeleton]     = p[1];
    new_state[n_skeleton + 1] = p[1];
    for (unsigned int d = 0; d < dim; ++d)
      {
        new_state[n_skeleton + 2 + d]       = p[2 + dim + d];
        new_state[n_skeleton + 2 + dim + d] = p[2 + dim + d];
      }
    std::copy(old.state.begin() + initial_stress_offset(),
              old.state.end(),
              new_state.begin() + initial_stress_offset());
  }



  template <int dim>
  SymmetricTensor<4, dim>
  PoroelasticModel<dim>::tangent(const PointState<dim> &old) const
  {
    return skeleton_model->tangent(skeleton_state(old));
  }



  template <int dim>
  SymmetricTensor<4, dim>
  PoroelasticModel<dim>::loading_tangent(const PointState<dim> &old) const
  {
    return skeleton_model->loading_tangent(skeleton_state(old));
  }



  template <int dim>
  SymmetricTensor<4, dim>
  PoroelasticModel<dim>::consistent_tangent(
    const PointState<dim>         &old,
    const SymmetricTensor<2, dim> &strain_increment) const
  {
    return skeleton_model->consistent_tangent(skeleton_state(old),
                                              strain_increment);
  }



  template <int dim>
  double
  PoroelasticModel<dim>::initial_hoop_stress(
    const SymmetricTensor<2, 3> *sigma0,
    ArrayView<const double>      state) const
  {
    return skeleton_model->initial_hoop_stress(
             sigma0, ArrayView<const double>(state.data(), n_skeleton)) -
           b * p_initial;
  }



  template <int dim>
  bool
  PoroelasticModel<dim>::supports_axisymmetry() const
  {
    return skeleton_model->supports_axisymmetry();
  }



  template <int dim>
  void
  PoroelasticModel<dim>::update_stress_axisymmetric(
    const PointState<dim>         &old,
    const double                   old_hoop_stress,
    const SymmetricTensor<2, dim> &strain_increment,
    const double                   hoop_strain_increment,
    SymmetricTensor<2, dim>       &stress,
    double                        &hoop_stress,
    ArrayView<double>              new_state) const
  {
    skeleton_model->update_stress_axisymmetric(
      skeleton_state(old),
      old_hoop_stress + b * old.state[n_skeleton],
      strain_increment,
      hoop_strain_increment,
      stress,
      hoop_stress,
      ArrayView<double>(new_state.data(), n_skeleton));
    const double p = old.state[n_skeleton + 1];
    stress -= b * p * unit_symmetric_tensor<dim>();
    hoop_stress -= b * p;
    write_pressure_state(old, new_state);
  }



  template <int dim>
  SymmetricTensor<4, 3>
  PoroelasticModel<dim>::consistent_tangent_axisymmetric(
    const PointState<dim>         &old,
    const double                   old_hoop_stress,
    const SymmetricTensor<2, dim> &strain_increment,
    const double                   hoop_strain_increment) const
  {
    return skeleton_model->consistent_tangent_axisymmetric(
      skeleton_state(old),
      old_hoop_stress + b * old.state[n_skeleton],
      strain_increment,
      hoop_strain_increment);
  }



  template <int dim>
  bool
  PoroelasticModel<dim>::supports_axisymmetric_finite_strain() const
  {
    return skeleton_model->supports_axisymmetric_finite_strain();
  }



  template <int dim>
  void
  PoroelasticModel<dim>::update_kirchhoff_stress_axisymmetric(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics,
    SymmetricTensor<2, dim>           &tau,
    double                            &tau_hoop,
    ArrayView<double>                  new_state) const
  {
    skeleton_model->update_kirchhoff_stress_axisymmetric(
      skeleton_state(old),
      kinematics,
      tau,
      tau_hoop,
      ArrayView<double>(new_state.data(), n_skeleton));
    write_pressure_state(old, new_state);
    const double hoop_stretch =
      old.state[hoop_stretch_offset()] * kinematics.delta_hoop_stretch;
    new_state[hoop_stretch_offset()] = hoop_stretch;
    const double pressure_stress =
      pressure_kirchhoff(kinematics,
                         hoop_stretch,
                         b * old.state[n_skeleton + 1]);
    tau -= pressure_stress * unit_symmetric_tensor<dim>();
    tau_hoop -= pressure_stress;
  }



  template <int dim>
  Tensor<4, 3>
  PoroelasticModel<dim>::kirchhoff_tangent_axisymmetric(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics) const
  {
    Tensor<4, 3> c =
      skeleton_model->kirchhoff_tangent_axisymmetric(skeleton_state(old),
                                                     kinematics);
    const double pressure_stress =
      pressure_kirchhoff(kinematics,
                         old.state[hoop_stretch_offset()] *
                           kinematics.delta_hoop_stretch,
                         b * old.state[n_skeleton + 1]);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int k = 0; k < 3; ++k)
        c[i][i][k][k] -= pressure_stress;
    return c;
  }



  template <int dim>
  bool
  PoroelasticModel<dim>::supports_finite_strain() const
  {
    return skeleton_model->supports_finite_strain();
  }



  template <int dim>
  void
  PoroelasticModel<dim>::update_kirchhoff_stress(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics,
    SymmetricTensor<2, dim>           &tau,
    ArrayView<double>                  new_state) const
  {
    skeleton_model->update_kirchhoff_stress(skeleton_state(old),
                                            kinematics,
                                            tau,
                                            ArrayView<double>(new_state.data(),
                                                              n_skeleton));
    tau -= pressure_kirchhoff(kinematics, 1., b * old.state[n_skeleton + 1]) *
           unit_symmetric_tensor<dim>();
    write_pressure_state(old, new_state);
  }



  template <int dim>
  Tensor<4, dim>
  PoroelasticModel<dim>::kirchhoff_tangent(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics) const
  {
    Tensor<4, dim> c =
      skeleton_model->kirchhoff_tangent(skeleton_state(old), kinematics);
    const double scale =
      pressure_kirchhoff(kinematics, 1., b * old.state[n_skeleton + 1]);
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int k = 0; k < dim; ++k)
        c[i][i][k][k] -= scale;
    return c;
  }



  template <int dim>
  double
  PoroelasticModel<dim>::dissipation(const PointState<dim>  &old,
                                     ArrayView<const double> new_state) const
  {
    return skeleton_model->dissipation(skeleton_state(old),
                                       ArrayView<const double>(new_state.data(),
                                                               n_skeleton));
  }



  template <int dim>
  bool
  PoroelasticModel<dim>::computes_dissipation() const
  {
    return skeleton_model->computes_dissipation();
  }



  template <int dim>
  std::optional<std::array<double, 2>>
  PoroelasticModel<dim>::elastic_volume_strains(
    const PointState<dim>  &old,
    ArrayView<const double> new_state) const
  {
    return skeleton_model->elastic_volume_strains(
      skeleton_state(old),
      ArrayView<const double>(new_state.data(), n_skeleton));
  }



  template <int dim>
  bool
  PoroelasticModel<dim>::plastic_flow_changes_volume() const
  {
    return skeleton_model->plastic_flow_changes_volume();
  }



  template <int dim>
  bool
  PoroelasticModel<dim>::is_elastic() const
  {
    return skeleton_model->is_elastic();
  }



  template <int dim>
  std::string
  PoroelasticModel<dim>::name() const
  {
    return "poroelastic (" + skeleton_model->name() + ")";
  }



  template class PoroelasticModel<2>;
  template class PoroelasticModel<3>;
} // namespace qsmpm
