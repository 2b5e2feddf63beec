#include <deal.II/base/exceptions.h>
#include <map>
#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/materials/constitutive_model.h>

namespace qsmpm
{
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
  bool
  ConstitutiveModel<dim>::computes_dissipation() const
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
  std::string
  ConstitutiveModel<dim>::name() const
  {
    return "unnamed";
  }



  template <int dim>
  unsigned int
  ConstitutiveModel<dim>::n_state_components() const
  {
    unsigned int n = 0;
    for (const auto &field : state_fields())
      n += field.n_components;
    return n;
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
      }
    };
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
    const std::string name = ModelChoice<dim>::from(prm).model;
    AssertThrow(registry<dim>().count(name) == 1,
                ExcMessage("Material: unknown <Model> = <" + name + ">."));
    prm.enter_subsection(name);
    auto model = registry<dim>()[name].create(prm);
    prm.leave_subsection();
    prm.leave_subsection();
    return model;
  }



  template class ConstitutiveModel<2>;
  template class ConstitutiveModel<3>;
  template class ConstitutiveModelFactory<2>;
  template class ConstitutiveModelFactory<3>;
} // namespace qsmpm
