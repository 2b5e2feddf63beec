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
     * f_int_i = Omega_0 tau Delta F^{-T} grad_n N_i (the integral of
     * sigma grad N_i over the current volume; R = f_ext - f_int).
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

  /**
   * How the volumetric part of the kinematics is treated. Plastic flow
   * (von Mises, Drucker-Prager without dilatancy) and nearly incompressible
   * elasticity constrain the volume change at every material point;
   * bilinear/trilinear grid functions cannot satisfy as many constraints as
   * a cell has points and the response locks (limit loads far too high).
   */
  enum class VolumetricTreatment
  {
    /// Every point uses its own kinematics (the paper).
    none,
    /**
     * F-bar with the cell as the patch (Coombs, Charlton, Cortis, Augarde
     * 2018, "Overcoming volumetric locking in material point methods";
     * de Souza Neto et al. 1996): the volume change of each point is
     * replaced by the volume-weighted average over the points of its cell,
     *
     *   Delta F_bar_p = (Delta J_bar / Delta J_p)^(1/dim) Delta F_p,
     *   Delta J_bar = sum_q Omega_q Delta J_q / sum_q Omega_q,
     *
     * (q over the cell's points, Omega_q the volume at the start of the
     * step), which the model sees and the point stores (F <- Delta F_bar F,
     * volume det(F_bar) Omega_0). At small strain the same idea on the
     * increment: d eps_bar = d eps + (theta_bar - tr d eps)/dim I, theta_bar
     * the cell's volume-weighted mean of tr d eps. At finite strain the
     * internal force is integrated with the standard gradients (the
     * original F-bar), so the Jacobian is not symmetric, which GMRES does
     * not mind. At small strain the internal force is the work on the
     * virtual F-bar strain (B-bar): its volumetric part is that of the
     * cell's mean stress trace, so that pressures which differ between the
     * points of a cell (dilatant plastic flow, Drucker-Prager) do not act
     * on the points' own volume changes (QuasiStaticResidual). In 2D (plane
     * strain) the exponent is 1/2: only the in-plane stretches carry volume.
     *
     * At small strain, with a model whose plastic flow changes the volume
     * and that keeps its elastic strain apart (ConstitutiveModel::
     * elastic_volume_strains(): the IsotropicPlasticity models Drucker-Prager,
     * Mohr-Coulomb, Modified Cam Clay, also in a MaterialMap or as the
     * skeleton of a PoroelasticModel) only the elastic part of the volume
     * change is the cell's:
     * point p changes its volume by theta_bar + g_p - g_bar, g_p its own
     * plastic volume change in the step and g_bar the cell's mean of them,
     * which removes the dilatancy locking of associated flow (QuasiStatic
     * Residual::share_plastic_volume_changes(); at small strain, not in
     * axisymmetric problems).
     */
    fbar
  };

  /// The discretization choices that change what a point carries.
  struct Formulation
  {
    Kinematics          kinematics      = Kinematics::small_strain;
    ShapeFunctions      shape_functions = ShapeFunctions::linear;
    VolumetricTreatment volumetric      = VolumetricTreatment::none;
    /**
     * 2D only: axisymmetric (r, z) kinematics with x = r >= 0, y = z. The
     * points' volumes and every force are per radian (volume r dA), and the
     * strain has the hoop component u_r / r (finite strain: the stretch
     * r / R), which the models see where plane strain has eps_zz
     * (ConstitutiveModel::update_stress_axisymmetric(),
     * update_kirchhoff_stress_axisymmetric()).
     */
    bool axisymmetric = false;
    /**
     * The points move with the grid's increment at the end of each step
     * (paper eqs. 2.26-2.27). false: they stay where they were created, a
     * fixed quadrature, and only accumulate their displacement u_p (the
     * small-displacement theory); what meets the deformed body, a rigid
     * body's contact, sees them at X_p + u_p.
     */
    bool move_points = true;

    bool
    operator==(const Formulation &other) const
    {
      return kinematics == other.kinematics &&
             shape_functions == other.shape_functions &&
             volumetric == other.volumetric &&
             axisymmetric == other.axisymmetric &&
             move_points == other.move_points;
    }

    bool
    fbar() const
    {
      return volumetric == VolumetricTreatment::fbar;
    }

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

  /// "linear", "uGIMP" or "cpGIMP".
  ShapeFunctions
  parse_shape_functions(const std::string &name);

  /// "none" or "F-bar".
  VolumetricTreatment
  parse_volumetric_treatment(const std::string &name);
} // namespace qsmpm

#endif
