#ifndef qsmpm_materials_point_state_h
#define qsmpm_materials_point_state_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace qsmpm
{
  using namespace dealii;

  /**
   * What a constitutive model may read of a material point: its committed
   * state at the start of the load step, its material id and its position.
   */
  template <int dim>
  struct PointState
  {
    /// Committed small strain (paper eq. 2.19, at step k).
    SymmetricTensor<2, dim> strain;
    /// Committed Cauchy stress (paper eq. 2.21, at step k).
    SymmetricTensor<2, dim> stress;
    /// The model's own committed per-point fields (see state_fields()).
    ArrayView<const double> state;
    /// Volume of the point at the start of the step.
    double volume;
    /// The point's material id (MaterialPointSet::fill()).
    unsigned int material_id = 0;
    /// The point's position at the start of the step.
    Point<dim> position = Point<dim>();
  };



  /**
   * The kinematics of one finite-strain load step at a point (updated
   * Lagrangian on the reset grid): the deformation gradient committed at
   * the start of the step, the increment Delta F = I + grad_n(Delta u)
   * (gradient on the grid, i.e. in the configuration at the start of the
   * step), and F = Delta F F_old. In 2D (plane strain) the out-of-plane
   * stretch is one and all tensors are 2x2; axisymmetric (r, z), the
   * out-of-plane (hoop) stretch of the step is delta_hoop_stretch =
   * r_{n+1} / r_n = 1 + d u_r / r_n.
   */
  template <int dim>
  struct FiniteStrainKinematics
  {
    Tensor<2, dim> F_old;
    Tensor<2, dim> delta_F;
    Tensor<2, dim> F;
    double         delta_hoop_stretch = 1.;
  };
} // namespace qsmpm

#endif
