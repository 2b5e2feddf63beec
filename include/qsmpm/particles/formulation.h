#ifndef qsmpm_particles_formulation_h
#define qsmpm_particles_formulation_h

#include <string>

namespace qsmpm
{
  /**
   * How a load step's kinematics are linearized at the points.
   */
  enum class Kinematics
  {
    /**
     * The paper's formulation (eqs. 2.17-2.25): a small-strain increment
     * d_eps = sym grad du, Cauchy stress updated by the model's
     * update_stress(), volumes updated with 1 + tr d_eps.
     */
    small_strain,
    /**
     * Updated Lagrangian on the reset grid: Delta F = I + grad_n du (the
     * gradient on the grid, i.e. in the configuration at the start of the
     * step), F = Delta F F_old, Kirchhoff stress from the model's
     * update_kirchhoff_stress(), volume det(F) Omega_0, internal force
     * f_i = -Omega_0 tau Delta F^{-T} grad_n N_i (the integral of
     * sigma grad N_i over the current volume).
     */
    finite_strain
  };

  /**
   * The grid functions through which points and nodes exchange
   * displacements and forces.
   */
  enum class ShapeFunctions
  {
    /// The bilinear/trilinear FE_Q(1) functions of the point's cell.
    linear,
    /**
     * Generalized interpolation material point (Bardenhagen & Kober 2004):
     * the weights are averages of the linear functions over the point's
     * box-shaped domain, which keeps its initial size (uGIMP).
     */
    ugimp,
    /**
     * GIMP with the domain's half-lengths l_d = l_d^0 U_dd following the
     * stretch U of F = R U ("contiguous-particle" GIMP as in AMPLE), at
     * small strain l_d = l_d^0 (1 + eps_dd).
     */
    cpgimp
  };

  /// The discretization choices that change what a point carries.
  struct Formulation
  {
    Kinematics     kinematics      = Kinematics::small_strain;
    ShapeFunctions shape_functions = ShapeFunctions::linear;

    bool
    finite_strain() const
    {
      return kinematics == Kinematics::finite_strain;
    }

    bool
    gimp() const
    {
      return shape_functions != ShapeFunctions::linear;
    }
  };

  /// "small strain" or "finite strain".
  Kinematics
  parse_kinematics(const std::string &name);

  /// "linear", "uGIMP" or "cpGIMP".
  ShapeFunctions
  parse_shape_functions(const std::string &name);
} // namespace qsmpm

#endif
