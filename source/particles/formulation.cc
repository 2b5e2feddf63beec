#include <deal.II/base/exceptions.h>
#include <qsmpm/particles/formulation.h>

namespace qsmpm
{
  Kinematics
  parse_kinematics(const std::string &name)
  {
    if (name == "small strain")
      return Kinematics::small_strain;
    AssertThrow(name == "finite strain",
                dealii::ExcMessage("Unknown kinematics <" + name +
                                   ">: use small strain or finite strain."));
    return Kinematics::finite_strain;
  }



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
