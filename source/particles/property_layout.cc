#include <deal.II/base/exceptions.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/particles/property_layout.h>

namespace qsmpm
{
  unsigned int
  PropertyLayout::add(const std::string &name,
                      const unsigned int n_components,
                      const Kind         kind)
  {
    AssertThrow(!has(name),
                ExcMessage("Material-point property <" + name +
                           "> is defined twice."));
    fields.push_back({name, total, n_components, kind});
    total += n_components;
    return fields.back().offset;
  }



  const PropertyLayout::Field &
  PropertyLayout::find(const std::string &name) const
  {
    for (const auto &field : fields)
      if (field.name == name)
        return field;
    AssertThrow(false,
                ExcMessage("There is no material-point property <" + name +
                           ">."));
    return fields.front();
  }



  unsigned int
  PropertyLayout::offset(const std::string &name) const
  {
    return find(name).offset;
  }



  bool
  PropertyLayout::has(const std::string &name) const
  {
    for (const auto &field : fields)
      if (field.name == name)
        return true;
    return false;
  }



  unsigned int
  PropertyLayout::n_components(const std::string &name) const
  {
    return find(name).n_components;
  }



  unsigned int
  PropertyLayout::size() const
  {
    return total;
  }



  std::vector<std::string>
  PropertyLayout::component_names(const unsigned int dim) const
  {
    const std::vector<std::string> tensor_names =
      dim == 2 ? Utils::symmetric_component_names<2>() :
                 Utils::symmetric_component_names<3>();
    std::vector<std::string> names;
    for (const auto &field : fields)
      for (unsigned int c = 0; c < field.n_components; ++c)
        switch (field.kind)
          {
            case Kind::vector:
              names.push_back(field.name);
              break;
            case Kind::symmetric:
              names.push_back(field.name + "_" + tensor_names[c]);
              break;
            default:
              names.push_back(field.n_components == 1 ?
                                field.name :
                                field.name + "_" + std::to_string(c));
          }
    return names;
  }



  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  PropertyLayout::component_interpretations() const
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      result;
    for (const auto &field : fields)
      for (unsigned int c = 0; c < field.n_components; ++c)
        result.push_back(
          field.kind == Kind::vector ?
            DataComponentInterpretation::component_is_part_of_vector :
            DataComponentInterpretation::component_is_scalar);
    return result;
  }
} // namespace qsmpm
