#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <map>
#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/materials/constitutive_model.h>
#include <qsmpm/materials/material_map.h>

namespace qsmpm
{
  namespace
  {
    /**
     * The hoop entries of the 3D tangent @p C3 (index 2 the hoop
     * direction) from the in-plane tangent @p C of a 2D model, as those of
     * an isotropic tangent: C3_2222 = C_0000, C3_22kk = C3_kk22 = C_0011.
     */
    template <typename Tangent2D, typename Tangent3D>
    void
    add_isotropic_hoop_entries(const Tangent2D &C, Tangent3D &C3)
    {
      C3[2][2][2][2] = C[0][0][0][0];
      for (unsigned int k = 0; k < 2; ++k)
        C3[2][2][k][k] = C3[k][k][2][2] = C[0][0][1][1];
    }
  } // namespace



  namespace
  {
    /// The number of doubles of @p fields together.
    unsigned int
    count_components(const std::vector<StateField> &fields)
    {
      unsigned int n = 0;
      for (const auto &field : fields)
        n += field.n_components;
      return n;
    }
  } // namespace



  template <int dim>
  std::vector<StateField>
  ConstitutiveModel<dim>::state_fields() const
  {
    return {};
  }



  template <int dim>
  void
  ConstitutiveModel<dim>::initialize_state(const Point<dim> &,
                                           ArrayView<double> state) const
  {
    for (double &s : state)
      s = 0.;
  }



  template <int dim>
  void
  ConstitutiveModel<dim>::initialize_material_state(
    const Point<dim> &x,
    const unsigned int,
    ArrayView<double> state) const
  {
    initialize_state(x, state);
  }



  template <int dim>
  void
  ConstitutiveModel<dim>::initialize_point_state(const Point<dim>  &x,
                                                 const unsigned int material_id,
                                                 const types::particle_index,
                                                 ArrayView<double> state) const
  {
    initialize_material_state(x, material_id, state);
  }



  template <int dim>
  SymmetricTensor<2, dim>
  ConstitutiveModel<dim>::initial_stress(const Point<dim> &,
                                         const unsigned int,
                                         const SymmetricTensor<2, 3> *sigma0,
                                         ArrayView<double>) const
  {
    SymmetricTensor<2, dim> result;
    if (sigma0 == nullptr)
      return result;
    AssertThrow(incremental_stress(),
                ExcMessage("Material points: <Initial stress> is given, but "
                           "the model '" +
                           name() +
                           "' cannot start from a stress (its stress is a "
                           "function of the deformation from the unstressed "
                           "state, or of crack states that a stress does not "
                           "determine)."));
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        result[i][j] = (*sigma0)[i][j];
    return result;
  }



  template <int dim>
  bool
  ConstitutiveModel<dim>::incremental_stress() const
  {
    return false;
  }



  template <int dim>
  std::vector<StateField>
  ConstitutiveModel<dim>::output_fields() const
  {
    return {};
  }



  template <int dim>
  void
  ConstitutiveModel<dim>::compute_output_fields(const PointState<dim> &,
                                                ArrayView<double> values) const
  {
    for (double &v : values)
      v = 0.;
  }



  template <int dim>
  SymmetricTensor<4, dim>
  ConstitutiveModel<dim>::consistent_tangent(
    const PointState<dim> &old,
    const SymmetricTensor<2, dim> &) const
  {
    return tangent(old);
  }



  template <int dim>
  double
  ConstitutiveModel<dim>::dissipation(const PointState<dim> &,
                                      ArrayView<const double>) const
  {
    return 0.;
  }



  template <int dim>
  void
  ConstitutiveModel<dim>::update_stresses(
    const PointStateBatch<dim>              &old,
    ArrayView<const SymmetricTensor<2, dim>> strain_increments,
    ArrayView<SymmetricTensor<2, dim>>       stresses,
    ArrayView<double>                        new_states) const
  {
    const unsigned int n_state = old.n_state_components();
    AssertDimension(strain_increments.size(), old.size());
    AssertDimension(stresses.size(), old.size());
    AssertDimension(new_states.size(), old.size() * n_state);
    for (unsigned int i = 0; i < old.size(); ++i)
      update_stress(old[i],
                    strain_increments[i],
                    stresses[i],
                    ArrayView<double>(new_states.data() + i * n_state,
                                      n_state));
  }



  template <int dim>
  void
  ConstitutiveModel<dim>::tangents(const PointStateBatch<dim>        &old,
                                   ArrayView<SymmetricTensor<4, dim>> C) const
  {
    AssertDimension(C.size(), old.size());
    for (unsigned int i = 0; i < old.size(); ++i)
      C[i] = tangent(old[i]);
  }



  template <int dim>
  SymmetricTensor<4, dim>
  ConstitutiveModel<dim>::loading_tangent(const PointState<dim> &old) const
  {
    return tangent(old);
  }



  template <int dim>
  void
  ConstitutiveModel<dim>::loading_tangents(
    const PointStateBatch<dim>        &old,
    ArrayView<SymmetricTensor<4, dim>> C) const
  {
    AssertDimension(C.size(), old.size());
    for (unsigned int i = 0; i < old.size(); ++i)
      C[i] = loading_tangent(old[i]);
  }



  template <int dim>
  typename PointStateBatch<dim>::Fields
  ConstitutiveModel<dim>::batch_fields() const
  {
    return {};
  }



  template <int dim>
  bool
  ConstitutiveModel<dim>::state_is_constant() const
  {
    return false;
  }



  template <int dim>
  bool
  ConstitutiveModel<dim>::computes_dissipation() const
  {
    return false;
  }



  template <int dim>
  std::optional<std::array<double, 2>>
  ConstitutiveModel<dim>::elastic_volume_strains(const PointState<dim> &,
                                                 ArrayView<const double>) const
  {
    return std::nullopt;
  }



  template <int dim>
  bool
  ConstitutiveModel<dim>::plastic_flow_changes_volume() const
  {
    return false;
  }



  template <int dim>
  bool
  ConstitutiveModel<dim>::supports_finite_strain() const
  {
    return false;
  }



  template <int dim>
  double
  ConstitutiveModel<dim>::initial_hoop_stress(
    const SymmetricTensor<2, 3> *sigma0,
    ArrayView<const double>) const
  {
    return sigma0 != nullptr ? (*sigma0)[2][2] : 0.;
  }



  template <int dim>
  bool
  ConstitutiveModel<dim>::supports_axisymmetry() const
  {
    return false;
  }



  template <int dim>
  void
  ConstitutiveModel<dim>::update_stress_axisymmetric(
    const PointState<dim> &,
    const double,
    const SymmetricTensor<2, dim> &,
    const double,
    SymmetricTensor<2, dim> &,
    double &,
    ArrayView<double>) const
  {
    AssertThrow(false,
                ExcMessage("The constitutive model <" + name() +
                           "> does not support Material points/Axisymmetric "
                           "= true; choose linear elastic or a plasticity "
                           "model (von Mises, Drucker-Prager, Mohr-Coulomb, "
                           "modified Cam clay)."));
  }



  template <int dim>
  SymmetricTensor<4, 3>
  ConstitutiveModel<dim>::consistent_tangent_axisymmetric(
    const PointState<dim> &old,
    const double,
    const SymmetricTensor<2, dim> &,
    const double) const
  {
    const SymmetricTensor<4, dim> C = tangent(old);
    SymmetricTensor<4, 3>         C3;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = k; l < dim; ++l)
            C3[i][j][k][l] = C[i][j][k][l];
    if (dim == 2)
      add_isotropic_hoop_entries(C, C3);
    return C3;
  }



  template <int dim>
  bool
  ConstitutiveModel<dim>::supports_axisymmetric_finite_strain() const
  {
    return false;
  }



  template <int dim>
  void
  ConstitutiveModel<dim>::update_kirchhoff_stress_axisymmetric(
    const PointState<dim> &,
    const FiniteStrainKinematics<dim> &,
    SymmetricTensor<2, dim> &,
    double &,
    ArrayView<double>) const
  {
    AssertThrow(false,
                ExcMessage("The constitutive model <" + name() +
                           "> does not support Material points/Axisymmetric "
                           "= true at finite strain; choose a plasticity "
                           "model (von Mises, Drucker-Prager, Mohr-Coulomb, "
                           "modified Cam clay: Hencky elasticity inside the "
                           "yield surface)."));
  }



  template <int dim>
  Tensor<4, 3>
  ConstitutiveModel<dim>::kirchhoff_tangent_axisymmetric(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics) const
  {
    const Tensor<4, dim> c = kirchhoff_tangent(old, kinematics);
    Tensor<4, 3>         c3;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            c3[i][j][k][l] = c[i][j][k][l];
    // Axisymmetry is two-dimensional: a 3D model's tangent is its own.
    if (dim == 2)
      add_isotropic_hoop_entries(c, c3);
    return c3;
  }



  template <int dim>
  void
  ConstitutiveModel<dim>::update_kirchhoff_stress(
    const PointState<dim> &,
    const FiniteStrainKinematics<dim> &,
    SymmetricTensor<2, dim> &,
    ArrayView<double>) const
  {
    AssertThrow(false,
                ExcMessage("The constitutive model <" + name() +
                           "> is small-strain only; choose a finite-strain "
                           "model (e.g. hencky or neo-Hookean) or Kinematics "
                           "= small strain."));
  }



  template <int dim>
  Tensor<4, dim>
  ConstitutiveModel<dim>::kirchhoff_tangent(
    const PointState<dim> &,
    const FiniteStrainKinematics<dim> &) const
  {
    AssertThrow(false,
                ExcMessage("The constitutive model <" + name() +
                           "> is small-strain only; choose a finite-strain "
                           "model (e.g. hencky or neo-Hookean) or Kinematics "
                           "= small strain."));
    return {};
  }



  template <int dim>
  bool
  ConstitutiveModel<dim>::is_elastic() const
  {
    return false;
  }



  template <int dim>
  std::string
  ConstitutiveModel<dim>::name() const
  {
    return "unnamed";
  }



  template <int dim>
  unsigned int
  ConstitutiveModel<dim>::n_state_components() const
  {
    return count_components(state_fields());
  }



  template <int dim>
  unsigned int
  ConstitutiveModel<dim>::n_output_components() const
  {
    return count_components(output_fields());
  }



  namespace
  {
    template <int dim>
    struct Entry
    {
      std::string                                      description;
      typename ConstitutiveModelFactory<dim>::Declarer declare;
      typename ConstitutiveModelFactory<dim>::Creator  create;
    };

    // A function-local static avoids the static initialization order
    // problem: models register themselves from static objects in other
    // translation units.
    template <int dim>
    std::map<std::string, Entry<dim>> &
    registry()
    {
      static std::map<std::string, Entry<dim>> models;
      return models;
    }
  } // namespace



  template <int dim>
  bool
  ConstitutiveModelFactory<dim>::register_model(const std::string &name,
                                                const std::string &description,
                                                const Declarer    &declare,
                                                const Creator     &create)
  {
    AssertThrow(registry<dim>().count(name) == 0,
                ExcMessage("Constitutive model <" + name +
                           "> is registered twice."));
    registry<dim>()[name] = {description, declare, create};
    return true;
  }



  template <int dim>
  std::vector<std::string>
  ConstitutiveModelFactory<dim>::names()
  {
    std::vector<std::string> result;
    for (const auto &entry : registry<dim>())
      result.push_back(entry.first);
    return result;
  }



  namespace
  {
    /// The entry "Model" of subsection "Material": one of the registered
    /// models.
    template <int dim>
    struct ModelChoice : ParameterStruct<ModelChoice<dim>>
    {
      std::string model = "linear elastic";
      std::string models_by_id;

      void
      add_parameters(ParameterHandler &prm)
      {
        std::string selection, documentation = "The constitutive model of "
                                               "the material points. "
                                               "Available models:";
        for (const auto &entry : registry<dim>())
          {
            selection += (selection.empty() ? "" : "|") + entry.first;
            documentation +=
              "\n  <" + entry.first + ">: " + entry.second.description;
          }
        prm.add_parameter("Model",
                          model,
                          documentation,
                          Patterns::Selection(selection));
        prm.add_parameter(
          "Models by material id",
          models_by_id,
          "Models for particular material ids (Material points/<Material "
          "id>), as 'id: model, id: model', e.g. '1: von Mises'; points of "
          "other ids use <Model>. Each model takes its parameters from its "
          "subsection here, so two ids with the same model share them (a "
          "map of differently parameterized models of one kind is built in "
          "C++ with MaterialMap). Empty: <Model> for every point.",
          Patterns::Anything());
      }
    };

    /// The model named @p name, from its subsection of "Material" (where
    /// @p prm is).
    template <int dim>
    std::unique_ptr<ConstitutiveModel<dim>>
    create_named(ParameterHandler &prm, const std::string &name)
    {
      AssertThrow(registry<dim>().count(name) == 1,
                  ExcMessage("Material: unknown model <" + name + ">."));
      prm.enter_subsection(name);
      auto model = registry<dim>()[name].create(prm);
      prm.leave_subsection();
      return model;
    }

    /// The pairs (id, model name) of "Models by material id".
    template <int dim>
    std::vector<std::pair<unsigned int, std::string>>
    parse_models_by_id(const std::string &text)
    {
      std::vector<std::pair<unsigned int, std::string>> result;
      const auto fail = [&text](const std::string &why) {
        AssertThrow(false,
                    ExcMessage("Material: <Models by material id> = <" + text +
                               ">: " + why +
                               " (expected 'id: model, id: model')."));
      };
      for (const std::string &item :
           dealii::Utilities::split_string_list(text, ','))
        {
          const auto colon = item.find(':');
          if (colon == std::string::npos)
            fail("<" + item + "> has no ':'");
          const std::string id_text =
            dealii::Utilities::trim(item.substr(0, colon));
          const std::string name =
            dealii::Utilities::trim(item.substr(colon + 1));
          if (id_text.empty() ||
              id_text.find_first_not_of("0123456789") != std::string::npos ||
              id_text.size() > 9)
            fail("<" + id_text + "> is not a material id");
          if (registry<dim>().count(name) == 0)
            fail("<" + name + "> is not a model");
          result.emplace_back(std::stoul(id_text), name);
        }
      return result;
    }
  } // namespace



  template <int dim>
  void
  ConstitutiveModelFactory<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      ModelChoice<dim>::declare_parameters(prm);
      for (const auto &entry : registry<dim>())
        {
          prm.enter_subsection(entry.first);
          entry.second.declare(prm);
          prm.leave_subsection();
        }
    }
    prm.leave_subsection();
  }



  template <int dim>
  std::unique_ptr<ConstitutiveModel<dim>>
  ConstitutiveModelFactory<dim>::create(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    const ModelChoice<dim> choice = ModelChoice<dim>::from(prm);
    std::unique_ptr<ConstitutiveModel<dim>> model;
    if (dealii::Utilities::trim(choice.models_by_id).empty())
      model = create_named<dim>(prm, choice.model);
    else
      {
        const auto by_id = parse_models_by_id<dim>(choice.models_by_id);
        auto       map   = std::make_unique<MaterialMap<dim>>();
        map->set_default(create_named<dim>(prm, choice.model));
        for (const auto &[id, name] : by_id)
          map->add(id, create_named<dim>(prm, name));
        model = std::move(map);
      }
    prm.leave_subsection();
    return model;
  }



  template class ConstitutiveModel<2>;
  template class ConstitutiveModel<3>;
  template class ConstitutiveModelFactory<2>;
  template class ConstitutiveModelFactory<3>;
} // namespace qsmpm
