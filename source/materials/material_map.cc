#include <algorithm>
#include <array>
#include <deal.II/base/exceptions.h>
#include <qsmpm/materials/material_map.h>
#include <qsmpm/materials/smeared_cracks.h>

namespace qsmpm
{
  namespace
  {
    /**
     * Merge @p fields into @p union_fields by name and return, for each
     * component of @p fields, its index in the union.
     */
    std::vector<unsigned int>
    merge_fields(const std::vector<StateField> &fields,
                 std::vector<StateField>       &union_fields,
                 const std::string             &model_name)
    {
      std::vector<unsigned int> index;
      for (const auto &field : fields)
        {
          unsigned int offset = 0;
          auto         match  = union_fields.begin();
          for (; match != union_fields.end(); ++match)
            {
              if (match->name == field.name)
                break;
              offset += match->n_components;
            }
          if (match == union_fields.end())
            union_fields.push_back(field);
          else
            AssertThrow(match->n_components == field.n_components,
                        ExcMessage("Material map: the field <" + field.name +
                                   "> of model <" + model_name + "> has " +
                                   std::to_string(field.n_components) +
                                   " components, another model's field of "
                                   "that name has " +
                                   std::to_string(match->n_components) + "."));
          for (unsigned int c = 0; c < field.n_components; ++c)
            index.push_back(offset + c);
        }
      return index;
    }

    /// Crack tracking edits the smeared-crack model's own fields between
    /// steps, which a map gathers into the union's layout.
    template <int dim>
    void
    refuse_crack_tracking(const ConstitutiveModel<dim> &model)
    {
      const auto *cracks = dynamic_cast<const SmearedCracks<dim> *>(&model);
      AssertThrow(cracks == nullptr || !cracks->tracks_cracks(),
                  ExcMessage("Material map: <Crack tracking> of the smeared "
                             "cracks model is not available in a material "
                             "map; use one model for the body."));
    }
  } // namespace



  template <int dim>
  void
  MaterialMap<dim>::add(const unsigned int                      material_id,
                        std::unique_ptr<ConstitutiveModel<dim>> model)
  {
    AssertThrow(model, ExcMessage("Material map: no model given."));
    refuse_crack_tracking(*model);
    if (by_id.size() <= material_id)
      by_id.resize(material_id + 1);
    AssertThrow(!by_id[material_id],
                ExcMessage("Material map: material id " +
                           std::to_string(material_id) +
                           " has a model already."));
    by_id[material_id]        = std::make_shared<Member>();
    by_id[material_id]->model = std::move(model);
    build_layout();
  }



  template <int dim>
  void
  MaterialMap<dim>::set_default(std::unique_ptr<ConstitutiveModel<dim>> model)
  {
    AssertThrow(model, ExcMessage("Material map: no model given."));
    refuse_crack_tracking(*model);
    default_member        = std::make_shared<Member>();
    default_member->model = std::move(model);
    build_layout();
  }



  template <int dim>
  void
  MaterialMap<dim>::build_layout()
  {
    // The default model first: a map with one model has exactly that
    // model's layout, and its points need no gathering.
    ordered.clear();
    if (default_member)
      ordered.emplace_back(numbers::invalid_unsigned_int, default_member);
    for (unsigned int id = 0; id < by_id.size(); ++id)
      if (by_id[id])
        ordered.emplace_back(id, by_id[id]);

    union_state.clear();
    union_output.clear();
    for (auto &[id, member] : ordered)
      {
        (void)id;
        const std::string name = member->model->name();
        member->state_index =
          merge_fields(member->model->state_fields(), union_state, name);
        member->output_index =
          merge_fields(member->model->output_fields(), union_output, name);
        member->state_is_prefix = true;
        for (unsigned int c = 0; c < member->state_index.size(); ++c)
          member->state_is_prefix =
            member->state_is_prefix && member->state_index[c] == c;
      }
    AssertThrow(this->n_state_components() <= max_components &&
                  this->n_output_components() <= max_components,
                ExcMessage("Material map: the models have more than " +
                           std::to_string(max_components) +
                           " state or output components together."));
  }



  template <int dim>
  const typename MaterialMap<dim>::Member &
  MaterialMap<dim>::member(const unsigned int material_id) const
  {
    if (material_id < by_id.size() && by_id[material_id])
      return *by_id[material_id];
    AssertThrow(default_member,
                ExcMessage("Material map: no model for material id " +
                           std::to_string(material_id) + " in " + name() +
                           ", and no default model."));
    return *default_member;
  }



  template <int dim>
  const ConstitutiveModel<dim> &
  MaterialMap<dim>::model_of(const unsigned int material_id) const
  {
    return *member(material_id).model;
  }



  template <int dim>
  std::vector<StateField>
  MaterialMap<dim>::state_fields() const
  {
    return union_state;
  }



  template <int dim>
  std::vector<StateField>
  MaterialMap<dim>::output_fields() const
  {
    return union_output;
  }



  template <int dim>
  void
  MaterialMap<dim>::initialize_state(const Point<dim> &,
                                     ArrayView<double>) const
  {
    AssertThrow(false,
                ExcMessage("Material map: the state of a point depends on "
                           "its material id; use "
                           "initialize_material_state()."));
  }



  template <int dim>
  void
  MaterialMap<dim>::initialize_material_state(const Point<dim>  &x,
                                              const unsigned int material_id,
                                              ArrayView<double>  state) const
  {
    initialize_point_state(x, material_id, 0, state);
  }



  template <int dim>
  void
  MaterialMap<dim>::initialize_point_state(const Point<dim>  &x,
                                           const unsigned int material_id,
                                           const types::particle_index id,
                                           ArrayView<double> state) const
  {
    const Member &m = member(material_id);
    std::fill(state.begin(), state.end(), 0.);
    std::array<double, max_components> own;
    const unsigned int                 n = m.state_index.size();
    m.model->initialize_point_state(x,
                                    material_id,
                                    id,
                                    ArrayView<double>(own.data(), n));
    for (unsigned int c = 0; c < n; ++c)
      state[m.state_index[c]] = own[c];
  }



  template <int dim>
  SymmetricTensor<2, dim>
  MaterialMap<dim>::initial_stress(const Point<dim>            &x,
                                   const unsigned int           material_id,
                                   const SymmetricTensor<2, 3> *sigma0,
                                   ArrayView<double>            state) const
  {
    const Member                      &m = member(material_id);
    std::array<double, max_components> own;
    const unsigned int                 n = m.state_index.size();
    for (unsigned int c = 0; c < n; ++c)
      own[c] = state[m.state_index[c]];
    const SymmetricTensor<2, dim> sigma = m.model->initial_stress(
      x, material_id, sigma0, ArrayView<double>(own.data(), n));
    for (unsigned int c = 0; c < n; ++c)
      state[m.state_index[c]] = own[c];
    return sigma;
  }



  template <int dim>
  template <typename Function>
  auto
  MaterialMap<dim>::with_own_state(const Member          &m,
                                   const PointState<dim> &old,
                                   const Function        &f) const
  {
    const unsigned int n = m.state_index.size();
    if (m.state_is_prefix)
      {
        PointState<dim> own = old;
        own.state           = ArrayView<const double>(old.state.data(), n);
        return f(own);
      }
    std::array<double, max_components> gathered;
    for (unsigned int c = 0; c < n; ++c)
      gathered[c] = old.state[m.state_index[c]];
    PointState<dim> own = old;
    own.state           = ArrayView<const double>(gathered.data(), n);
    return f(own);
  }



  template <int dim>
  template <typename Function>
  auto
  MaterialMap<dim>::with_own_states(const Member           &m,
                                    const PointState<dim>  &old,
                                    ArrayView<const double> new_state,
                                    const Function         &f) const
  {
    const unsigned int n = m.state_index.size();
    return with_own_state(m, old, [&](const PointState<dim> &own) {
      if (m.state_is_prefix)
        return f(own, ArrayView<const double>(new_state.data(), n));
      std::array<double, max_components> own_new;
      for (unsigned int c = 0; c < n; ++c)
        own_new[c] = new_state[m.state_index[c]];
      return f(own, ArrayView<const double>(own_new.data(), n));
    });
  }



  template <int dim>
  template <typename Function>
  void
  MaterialMap<dim>::update(const PointState<dim> &old,
                           ArrayView<double>      new_state,
                           const Function        &f) const
  {
    const Member      &m = member(old.material_id);
    const unsigned int n = m.state_index.size();
    // The fields of the other models keep their committed values.
    std::copy(old.state.begin(), old.state.end(), new_state.begin());
    with_own_state(m, old, [&](const PointState<dim> &own) {
      if (m.state_is_prefix)
        f(*m.model, own, ArrayView<double>(new_state.data(), n));
      else
        {
          std::array<double, max_components> own_new;
          f(*m.model, own, ArrayView<double>(own_new.data(), n));
          for (unsigned int c = 0; c < n; ++c)
            new_state[m.state_index[c]] = own_new[c];
        }
      return 0;
    });
  }



  template <int dim>
  void
  MaterialMap<dim>::update_stress(
    const PointState<dim>         &old,
    const SymmetricTensor<2, dim> &strain_increment,
    SymmetricTensor<2, dim>       &stress,
    ArrayView<double>              new_state) const
  {
    update(old,
           new_state,
           [&](const ConstitutiveModel<dim> &model,
               const PointState<dim>        &own,
               const ArrayView<double>      &own_new) {
             model.update_stress(own, strain_increment, stress, own_new);
           });
  }



  template <int dim>
  void
  MaterialMap<dim>::update_kirchhoff_stress(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics,
    SymmetricTensor<2, dim>           &tau,
    ArrayView<double>                  new_state) const
  {
    update(old,
           new_state,
           [&](const ConstitutiveModel<dim> &model,
               const PointState<dim>        &own,
               const ArrayView<double>      &own_new) {
             model.update_kirchhoff_stress(own, kinematics, tau, own_new);
           });
  }



  template <int dim>
  void
  MaterialMap<dim>::update_stress_axisymmetric(
    const PointState<dim>         &old,
    const double                   old_hoop_stress,
    const SymmetricTensor<2, dim> &strain_increment,
    const double                   hoop_strain_increment,
    SymmetricTensor<2, dim>       &stress,
    double                        &hoop_stress,
    ArrayView<double>              new_state) const
  {
    update(old,
           new_state,
           [&](const ConstitutiveModel<dim> &model,
               const PointState<dim>        &own,
               const ArrayView<double>      &own_new) {
             model.update_stress_axisymmetric(own,
                                              old_hoop_stress,
                                              strain_increment,
                                              hoop_strain_increment,
                                              stress,
                                              hoop_stress,
                                              own_new);
           });
  }



  template <int dim>
  SymmetricTensor<4, 3>
  MaterialMap<dim>::consistent_tangent_axisymmetric(
    const PointState<dim>         &old,
    const double                   old_hoop_stress,
    const SymmetricTensor<2, dim> &strain_increment,
    const double                   hoop_strain_increment) const
  {
    const Member &m = member(old.material_id);
    return with_own_state(m, old, [&](const PointState<dim> &own) {
      return m.model->consistent_tangent_axisymmetric(own,
                                                      old_hoop_stress,
                                                      strain_increment,
                                                      hoop_strain_increment);
    });
  }



  template <int dim>
  SymmetricTensor<4, dim>
  MaterialMap<dim>::tangent(const PointState<dim> &old) const
  {
    const Member &m = member(old.material_id);
    return with_own_state(m, old, [&](const PointState<dim> &own) {
      return m.model->tangent(own);
    });
  }



  template <int dim>
  SymmetricTensor<4, dim>
  MaterialMap<dim>::loading_tangent(const PointState<dim> &old) const
  {
    const Member &m = member(old.material_id);
    return with_own_state(m, old, [&](const PointState<dim> &own) {
      return m.model->loading_tangent(own);
    });
  }



  template <int dim>
  SymmetricTensor<4, dim>
  MaterialMap<dim>::consistent_tangent(
    const PointState<dim>         &old,
    const SymmetricTensor<2, dim> &strain_increment) const
  {
    const Member &m = member(old.material_id);
    return with_own_state(m, old, [&](const PointState<dim> &own) {
      return m.model->consistent_tangent(own, strain_increment);
    });
  }



  template <int dim>
  Tensor<4, dim>
  MaterialMap<dim>::kirchhoff_tangent(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics) const
  {
    const Member &m = member(old.material_id);
    return with_own_state(m, old, [&](const PointState<dim> &own) {
      return m.model->kirchhoff_tangent(own, kinematics);
    });
  }



  template <int dim>
  Tensor<4, 3>
  MaterialMap<dim>::kirchhoff_tangent_axisymmetric(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics) const
  {
    const Member &m = member(old.material_id);
    return with_own_state(m, old, [&](const PointState<dim> &own) {
      return m.model->kirchhoff_tangent_axisymmetric(own, kinematics);
    });
  }



  template <int dim>
  double
  MaterialMap<dim>::dissipation(const PointState<dim>  &old,
                                ArrayView<const double> new_state) const
  {
    const Member &m = member(old.material_id);
    return with_own_states(m,
                           old,
                           new_state,
                           [&](const PointState<dim> &own, const auto own_new) {
                             return m.model->dissipation(own, own_new);
                           });
  }



  template <int dim>
  void
  MaterialMap<dim>::compute_output_fields(const PointState<dim> &point,
                                          ArrayView<double>      values) const
  {
    const Member &m = member(point.material_id);
    std::fill(values.begin(), values.end(), 0.);
    with_own_state(m, point, [&](const PointState<dim> &own) {
      std::array<double, max_components> own_values;
      const unsigned int                 n = m.output_index.size();
      m.model->compute_output_fields(own,
                                     ArrayView<double>(own_values.data(), n));
      for (unsigned int c = 0; c < n; ++c)
        values[m.output_index[c]] = own_values[c];
      return 0;
    });
  }



  template <int dim>
  std::optional<std::array<double, 2>>
  MaterialMap<dim>::elastic_volume_strains(
    const PointState<dim>  &old,
    ArrayView<const double> new_state) const
  {
    const Member &m = member(old.material_id);
    if (!m.model->plastic_flow_changes_volume())
      return std::nullopt;
    return with_own_states(
      m, old, new_state, [&](const PointState<dim> &own, const auto own_new) {
        return m.model->elastic_volume_strains(own, own_new);
      });
  }



  template <int dim>
  bool
  MaterialMap<dim>::plastic_flow_changes_volume() const
  {
    return std::any_of(ordered.begin(), ordered.end(), [](const auto &entry) {
      return entry.second->model->plastic_flow_changes_volume();
    });
  }



  template <int dim>
  bool
  MaterialMap<dim>::computes_dissipation() const
  {
    return std::any_of(ordered.begin(), ordered.end(), [](const auto &entry) {
      return entry.second->model->computes_dissipation();
    });
  }



  template <int dim>
  bool
  MaterialMap<dim>::supports_finite_strain() const
  {
    return !ordered.empty() &&
           std::all_of(ordered.begin(), ordered.end(), [](const auto &entry) {
             return entry.second->model->supports_finite_strain();
           });
  }



  template <int dim>
  bool
  MaterialMap<dim>::supports_axisymmetric_finite_strain() const
  {
    return !ordered.empty() &&
           std::all_of(ordered.begin(), ordered.end(), [](const auto &entry) {
             return entry.second->model->supports_axisymmetric_finite_strain();
           });
  }



  template <int dim>
  void
  MaterialMap<dim>::update_kirchhoff_stress_axisymmetric(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics,
    SymmetricTensor<2, dim>           &tau,
    double                            &tau_hoop,
    ArrayView<double>                  new_state) const
  {
    update(old,
           new_state,
           [&](const ConstitutiveModel<dim> &model,
               const PointState<dim>        &own,
               const ArrayView<double>      &own_new) {
             model.update_kirchhoff_stress_axisymmetric(
               own, kinematics, tau, tau_hoop, own_new);
           });
  }



  template <int dim>
  bool
  MaterialMap<dim>::supports_axisymmetry() const
  {
    return !ordered.empty() &&
           std::all_of(ordered.begin(), ordered.end(), [](const auto &entry) {
             return entry.second->model->supports_axisymmetry();
           });
  }



  template <int dim>
  bool
  MaterialMap<dim>::is_elastic() const
  {
    return std::all_of(ordered.begin(), ordered.end(), [](const auto &entry) {
      return entry.second->model->is_elastic();
    });
  }



  template <int dim>
  std::string
  MaterialMap<dim>::name() const
  {
    std::string result;
    for (const auto &[id, member] : ordered)
      result +=
        (result.empty() ? "" : ", ") +
        (id == numbers::invalid_unsigned_int ? std::string("other ids") :
                                               std::to_string(id)) +
        ": " + member->model->name();
    return "material map (" + result + ")";
  }



  template class MaterialMap<2>;
  template class MaterialMap<3>;
} // namespace qsmpm
