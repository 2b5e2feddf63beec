#ifndef qsmpm_loading_equilibrium_audit_h
#define qsmpm_loading_equilibrium_audit_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>
#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/loading/displacement_constraints.h>
#include <string>
#include <vector>

namespace qsmpm
{
  /**
   * The global force balance of a converged load step: does every load that
   * was applied reach the supports the user prescribed?
   *
   * Summing the residual R = f_ext - f_int of the step over all degrees of
   * freedom, component by component, gives
   *
   *   A + C + H + F = E,
   *
   * with
   *  - A = sum f_ext, the applied load (tractions, body forces, point loads);
   *  - C = -sum R over the degrees of freedom of the displacement
   *    conditions (each once): the force of the supports the user set;
   *  - H = -sum R over the nodes held fixed because they carry no, or too
   *    little, material or stiffness (Material points/Minimum nodal volume,
   *    Minimum nodal stiffness): a support the user did not set. Its part
   *    H_load = -sum f_ext there is load put on nodes without material, e.g.
   *    a traction on a grid face that the body has left;
   *  - F = -sum R over the free degrees of freedom, what Newton's stopping
   *    test left (zero at convergence);
   *  - E = sum f_int = sum_p sigma_p . sum_i grad N_i(x_p) V_p, zero because
   *    the shape functions are a partition of unity on the grid (GIMP
   *    domains are cut at the grid's edge, ShapeCache); checked all the
   *    same.
   *
   * The load a user has lost is A + C: what the prescribed supports do not
   * carry of the applied load (for a body loaded by displacements only, the
   * amount by which the supports' forces fail to balance each other). It
   * is measured relative to the size of the loads (a run stops when the
   * part E - H exceeds the tolerance, or when F exceeds what Newton's
   * stopping test leaves, see QuasiStaticProblem): the largest of |A|,
   * |C_k|, 1e-6 of the sum of the magnitudes of all nodal forces (supports
   * that balance each other, as when every node is prescribed, have a
   * resultant of round-off size), and the size of the earlier steps (after
   * a crack has cut a body, its supports' forces vanish, and their
   * round-off is no lost load),
   * and each term of H, F and E larger than the tolerance names its cause.
   */
  template <int dim>
  class EquilibriumAudit
  {
  public:
    /// The subsection "Equilibrium check".
    struct Parameters : ParameterStruct<Parameters>
    {
      /// Largest |A + C| / max(|A|, |C_k|) accepted without a warning.
      double tolerance = 1e-3;
      /// Whether a larger imbalance stops the run (otherwise: a warning).
      bool stop_on_lost_load = true;

      void
      add_parameters(ParameterHandler &prm);
    };

    /// The terms of the balance of one step (summed over all ranks).
    struct Result
    {
      /// A: the applied load.
      Tensor<1, dim> applied;
      /// The reaction of each displacement condition (a degree of freedom
      /// of two conditions counts for both).
      std::vector<Tensor<1, dim>> reactions;
      /// C: the force of all displacement conditions, each dof once.
      Tensor<1, dim> supports;
      /// H: the force of the held nodes, and H_load, its part that is
      /// load applied to them.
      Tensor<1, dim> held;
      Tensor<1, dim> held_load;
      /// F: minus the residual left on the free degrees of freedom.
      Tensor<1, dim> free_residual;
      /// E: the sum of the internal forces over the grid.
      Tensor<1, dim> internal;
      /// The number of held degrees of freedom with a force on them.
      unsigned int n_held_loaded = 0;
      /// The size of the loads the imbalance is measured against.
      double scale = 0.;

      /// |A + C| / scale (0 if nothing is loaded): the load the supports
      /// do not carry, as a user reads it from reactions.csv.
      double
      imbalance() const;

      /// |E - H| / scale = |A + C + F| / scale: the part of it that went to
      /// the held nodes or that the internal forces did not balance.
      double
      structural_loss() const;

      /// |F| / scale: the part Newton's stopping test left.
      double
      solver_residual() const;

      /**
       * The causes of an imbalance, in words: each of H - H_load, H_load
       * and E whose size exceeds @p tolerance times the scale, and F if it
       * exceeds @p residual_tolerance times the scale.
       */
      std::string
      causes(const double tolerance, const double residual_tolerance) const;

      /**
       * Empty if the step to load factor @p t_new lost no load: the part
       * E - H within @p tolerance, and the residual F within
       * max(@p tolerance, 10 @p newton_tolerance). Otherwise the sentence
       * that reports the loss with its causes.
       *
       * The residual Newton leaves is the accuracy the user asked for:
       * with the paper's gamma = 1e-3 of the step's first residual it is
       * 0.1 % of the early, small reactions of the compact-tension
       * specimen. The stopping test bounds the free residual's norm by
       * gamma ||R(du_0)||, and the first residual is of the size of the
       * step's loads (a sum over many dofs may exceed a norm, hence ten
       * times); an absolute floor too large for the units leaves residuals
       * of the size of the load.
       */
      std::string
      lost_load(const double t_new,
                const double tolerance,
                const double newton_tolerance) const;
    };

    /**
     * The balance of a converged step: @p R is the condensed residual at
     * the solution (prescribed rows: minus the reactions), @p f_ext the
     * external force of the step, @p conditions the supports of the step's
     * constraints and @p held the degrees of freedom held for lack of
     * material or stiffness that no condition prescribes (locally relevant
     * indices; only the owned ones are read). @p reference_scale is the
     * smallest scale of the loads to measure the imbalance against (the
     * largest of the earlier steps).
     */
    Result
    evaluate(const BackgroundGrid<dim>           &grid,
             const DisplacementConstraints<dim>  &conditions,
             const IndexSet                      &held,
             const TrilinosWrappers::MPI::Vector &R,
             const TrilinosWrappers::MPI::Vector &f_ext,
             const double                         reference_scale);

    /**
     * Axisymmetric (r, z) kinematics: the forces are per radian, and the
     * radial ones have no resultant to balance (the hoop stresses carry
     * them: the internal forces' radial sum is sum_p Omega_p
     * sigma_thetatheta / r_p). The radial components of A, C, H and E are
     * then left out of the balance; the axial ones and the residual F are
     * checked as in plane problems, and the reactions keep both.
     */
    void
    set_axisymmetric(const bool axisymmetric);

  private:
    bool axisymmetric = false;
    /// The vector component of each locally owned degree of freedom, made
    /// again when the grid's degrees of freedom change.
    std::vector<unsigned char> component;
    IndexSet                   component_owned;
  };
} // namespace qsmpm

#endif
