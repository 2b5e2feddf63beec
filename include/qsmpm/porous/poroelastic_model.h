#ifndef qsmpm_porous_poroelastic_model_h
#define qsmpm_porous_poroelastic_model_h

#include <memory>
#include <qsmpm/materials/constitutive_model.h>

namespace qsmpm
{
  /**
   * A saturated porous solid: Terzaghi-Biot effective stress around any
   * model of the skeleton,
   *
   *   sigma = sigma' - b p I,
   *
   * with sigma' the skeleton's (effective) stress and p the pore pressure.
   * The point's stress field holds the total stress sigma, which is what
   * the residual integrates and the equilibrium check audits; the skeleton
   * model sees its own effective stress, sigma + b p_n I.
   *
   * Within a load step the pore pressure is data: PorePressureSolver writes
   * the current iterate p_k (and its gradient) into each point's fields
   * (pressure_offset() and following), the residual and the tangent then
   * see a fixed p, and the Jacobian is the skeleton's. Committing the step
   * makes p_k the committed pressure p_n of the next step.
   *
   * The fields after the skeleton's own: p_n, p_k, grad p_n (dim), grad
   * p_k (dim), and the total stress the point started from. Output: the
   * skeleton's fields, "pore_pressure" (the committed p) and the effective
   * stress sigma' = sigma + b p I
   * ("effective_stress_xx", "_yy", "_xy", ...; the output stress is the
   * total stress sigma).
   */
  template <int dim>
  class PoroelasticModel : public ConstitutiveModel<dim>
  {
  public:
    /// Wrap @p skeleton, with Biot coefficient @p biot_coefficient.
    PoroelasticModel(std::unique_ptr<ConstitutiveModel<dim>> skeleton,
                     const double                            biot_coefficient,
                     const double initial_pore_pressure);

    /// The skeleton model.
    const ConstitutiveModel<dim> &
    skeleton() const
    {
      return *skeleton_model;
    }

    /// Offset of p_n among the model's fields; p_k follows, then grad p_n
    /// and grad p_k.
    unsigned int
    pressure_offset() const
    {
      return n_skeleton;
    }

    /// Offset among the model's fields of the total stress the point
    /// started from (written by initial_stress(), kept thereafter): the
    /// pore pressure solver measures the stress the loads have added
    /// against it.
    unsigned int
    initial_stress_offset() const
    {
      return n_skeleton + 2 + 2 * dim;
    }

    /// The offset of the total hoop stretch r / R in the state
    /// (axisymmetric at finite strain; one otherwise).
    unsigned int
    hoop_stretch_offset() const
    {
      return initial_stress_offset() +
             SymmetricTensor<2, dim>::n_independent_components;
    }

    double
    biot_coefficient() const
    {
      return b;
    }

    std::vector<StateField>
    state_fields() const override;

    void
    initialize_point_state(const Point<dim>           &x,
                           const unsigned int          material_id,
                           const types::particle_index id,
                           ArrayView<double>           state) const override;

    /**
     * The total stress of the skeleton's initial_stress() (@p sigma0 is
     * the effective stress) with the initial pore pressure: sigma0' - b p
     * I.
     */
    SymmetricTensor<2, dim>
    initial_stress(const Point<dim>            &x,
                   const unsigned int           material_id,
                   const SymmetricTensor<2, 3> *sigma0,
                   ArrayView<double>            state) const override;

    std::vector<StateField>
    output_fields() const override;

    void
    compute_output_fields(const PointState<dim> &point,
                          ArrayView<double>      values) const override;

    void
    update_stress(const PointState<dim>         &old,
                  const SymmetricTensor<2, dim> &strain_increment,
                  SymmetricTensor<2, dim>       &stress,
                  ArrayView<double>              new_state) const override;

    SymmetricTensor<4, dim>
    tangent(const PointState<dim> &old) const override;

    SymmetricTensor<4, dim>
    loading_tangent(const PointState<dim> &old) const override;

    SymmetricTensor<4, dim>
    consistent_tangent(
      const PointState<dim>         &old,
      const SymmetricTensor<2, dim> &strain_increment) const override;

    /// The skeleton's initial hoop stress less b p_0.
    double
    initial_hoop_stress(const SymmetricTensor<2, 3> *sigma0,
                        ArrayView<const double>      state) const override;

    /// The skeleton's.
    bool
    supports_axisymmetry() const override;

    /**
     * The skeleton's update with the effective hoop stress
     * sigma'_tt = sigma_tt + b p beside the in-plane one; the pressure of
     * the current iterate acts on the new hoop stress as on the normal
     * in-plane ones.
     */
    void
    update_stress_axisymmetric(const PointState<dim>         &old,
                               const double                   old_hoop_stress,
                               const SymmetricTensor<2, dim> &strain_increment,
                               const double             hoop_strain_increment,
                               SymmetricTensor<2, dim> &stress,
                               double                  &hoop_stress,
                               ArrayView<double> new_state) const override;

    /// The skeleton's, at the effective stresses.
    SymmetricTensor<4, 3>
    consistent_tangent_axisymmetric(
      const PointState<dim>         &old,
      const double                   old_hoop_stress,
      const SymmetricTensor<2, dim> &strain_increment,
      const double                   hoop_strain_increment) const override;

    /// The skeleton's.
    bool
    supports_axisymmetric_finite_strain() const override;

    /**
     * The skeleton's update; the pressure of the current iterate acts on
     * the new Kirchhoff stress as -J b p, the hoop entry included, with J
     * the in-plane det F times the total hoop stretch r / R (which the
     * state keeps).
     */
    void
    update_kirchhoff_stress_axisymmetric(
      const PointState<dim>             &old,
      const FiniteStrainKinematics<dim> &kinematics,
      SymmetricTensor<2, dim>           &tau,
      double                            &tau_hoop,
      ArrayView<double>                  new_state) const override;

    /// The skeleton's less J b p on every c_iikk (the hoop index 2 too).
    Tensor<4, 3>
    kirchhoff_tangent_axisymmetric(
      const PointState<dim>             &old,
      const FiniteStrainKinematics<dim> &kinematics) const override;

    /// The skeleton's.
    bool
    supports_finite_strain() const override;

    /**
     * Finite strain: the Kirchhoff stress tau = tau' - J b p I, with tau'
     * the skeleton's and J = det F (the Cauchy stress is sigma' - b p I, as
     * at small strain).
     */
    void
    update_kirchhoff_stress(const PointState<dim>             &old,
                            const FiniteStrainKinematics<dim> &kinematics,
                            SymmetricTensor<2, dim>           &tau,
                            ArrayView<double> new_state) const override;

    /**
     * The skeleton's tangent minus that of J b p I at fixed p:
     * c_ijkl - J b p delta_ij delta_kl (dJ = J tr dl).
     */
    Tensor<4, dim>
    kirchhoff_tangent(
      const PointState<dim>             &old,
      const FiniteStrainKinematics<dim> &kinematics) const override;

    double
    dissipation(const PointState<dim>  &old,
                ArrayView<const double> new_state) const override;

    bool
    computes_dissipation() const override;

    /// The skeleton's: tr eps_e of its effective-stress model.
    std::optional<std::array<double, 2>>
    elastic_volume_strains(const PointState<dim>  &old,
                           ArrayView<const double> new_state) const override;

    /// The skeleton's.
    bool
    plastic_flow_changes_volume() const override;

    bool
    is_elastic() const override;

    std::string
    name() const override;

  private:
    /// The skeleton's view of a point: effective stress, its own fields.
    PointState<dim>
    skeleton_state(const PointState<dim> &point) const;

    /**
     * The pressure fields of the trial state: the current iterate p_k (and
     * its gradient) becomes the committed pressure; the initial total
     * stress is kept.
     */
    void
    write_pressure_state(const PointState<dim> &old,
                         ArrayView<double>      new_state) const;

    std::unique_ptr<ConstitutiveModel<dim>> skeleton_model;
    const double                            b;
    const double                            p_initial;
    const unsigned int                      n_skeleton;
  };
} // namespace qsmpm

#endif
