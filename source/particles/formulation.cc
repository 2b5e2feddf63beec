#include <deal.II/base/exceptions.h>
#include <qsmpm/particles/formulation.h>

namespace qsmpm
{
  ShapeFunctions
  parse_shape_functions(const std::string &name)
  {
    if (name == "linear")
      return ShapeFunctions::linear;
    if (name == "uGIMP")
      return ShapeFunctions::ugimp;
    AssertThrow(name == "cpGIMP",
                dealii::ExcMessage("Unknown shape functions <" + name +
                                   ">: use linear, uGIMP or cpGIMP."));
    return ShapeFunctions::cpgimp;
  }



  VolumetricTreatment
  parse_volumetric_treatment(const std::string &name)
  {
    if (name == "none")
      return VolumetricTreatment::none;
    AssertThrow(name == "F-bar",
                dealii::ExcMessage("Unknown volumetric locking treatment <" +
                                   name + ">: use none or F-bar."));
    return VolumetricTreatment::fbar;
  }
} // namespace qsmpm
