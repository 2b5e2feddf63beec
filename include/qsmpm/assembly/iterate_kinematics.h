#ifndef qsmpm_assembly_iterate_kinematics_h
#define qsmpm_assembly_iterate_kinematics_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * What the material points see at a Newton iterate du, one entry per
   * point of the ShapeCache in its order: the kinematics that
   * QuasiStaticResidual::evaluate() hands the constitutive model there
   * (QuasiStaticResidual::iterate_kinematics()), from which
   * TangentAssembler::assemble() builds the stiffness at the iterate.
   */
  template <int dim>
  struct IterateKinematics
  {
    /// Small strain: the strain increments, F-bar's shift included.
    std::vector<SymmetricTensor<2, dim>> strain_increments;
    /// Axisymmetric: the hoop strain increments d u_r / r, at small strain
    /// with F-bar's shift; at finite strain the hoop stretch Delta F_tt
    /// minus one, before F-bar's scaling.
    std::vector<double> hoop_strain_increments;
    /// Finite strain: Delta F = I + grad_n du, before F-bar's scaling.
    std::vector<Tensor<2, dim>> deformation_increments;
    /// Finite strain with F-bar: the mean volume change of the point's
    /// cell, det Delta F (times Delta F_tt if axisymmetric) averaged with
    /// the volumes at the step's start.
    std::vector<double> mean_volume_changes;
  };
} // namespace qsmpm

#endif
