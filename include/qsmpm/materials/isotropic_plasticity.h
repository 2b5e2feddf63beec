#ifndef qsmpm_materials_isotropic_plasticity_h
#define qsmpm_materials_isotropic_plasticity_h

#include <qsmpm/materials/constitutive_model.h>

namespace qsmpm
{
  /// A parameter value as the messages of the plasticity models print it.
  std::string
  to_text(const double x);



  /**
   * The strength entries of the cohesive-frictional models (DruckerPrager,
   * MohrCoulomb): "Cohesion", "Friction angle", "Dilatancy angle" and
   * "Hardening modulus", bound to the given members.
   */
  void
  add_cohesion_friction_parameters(ParameterHandler &prm,
                                   double           &cohesion,
                                   double           &friction_angle,
                                   double           &dilatancy_angle,
                                   double           &hardening_modulus);

  /**
   * Throws, with a message naming @p model and the entry, unless c0 >= 0,
   * 0 <= psi <= phi < 90 (degrees), H >= 0, and phi > 0 or c0 > 0.
   */
  void
  check_cohesion_friction(const std::string &model,
                          const double       c0,
                          const double       friction_angle_deg,
                          const double       dilatancy_angle_deg,
                          const double       H);



  /**
   * What the isotropic elastoplastic models (VonMises, DruckerPrager,
   * MohrCoulomb, ModifiedCamClay) share: isotropic elasticity between the
   * stress and the elastic strain (linear with E, nu unless a model
   * overrides elastic_stress() and elastic_tangent()), the per-point state, the
   * small-strain and the finite-strain drivers of a three-dimensional return
   * mapping, and the tangents built from it. A derived class implements the
   * return mapping of its yield function in 3D (return_map()), its continuum
   * elastoplastic tangent and its yield function.
   *
   * <h3>Three dimensions inside</h3>
   * All computations are three-dimensional. In 2D the model is plane
   * strain: the strain increment is embedded with eps_zz = eps_xz = eps_yz
   * = 0 (finite strain: Delta F_zz = 1), while the out-of-plane elastic and
   * plastic strains and the stress sigma_zz develop freely and are kept in
   * the 3D state; the in-plane block of the stress and of the tangents is
   * returned. The in-plane block of the 3D consistent tangent is exact for
   * plane strain since d eps_zz = 0 (d l_zz = 0).
   *
   * <h3>State fields</h3>
   * - "elastic_strain" (6 components): the elastic strain eps_e as a
   *   SymmetricTensor<2,3> in deal.II's unrolled order (xx, yy, zz, xy, xz,
   *   yz; Utils::read_symmetric<3>). Small strain: the stress is
   *   sigma = elastic_stress(eps_e) (D : eps_e). Finite strain: eps_e = 1/2
   *   ln b_e is the logarithmic elastic strain and the Kirchhoff stress is
   *   tau = elastic_stress(eps_e) (b_e = exp(2 eps_e) is never stored).
   * - "equivalent_plastic_strain" (1): the hardening variable alpha of the
   *   derived model (see there); zero initially.
   * - "plastic_increment" (1): the increment of alpha in the step that
   *   produced this state, zero if the step was elastic. In output it shows
   *   where the material is yielding; tangent() uses it to choose between
   *   the elastic and the continuum elastoplastic tangent.
   *
   * All fields are zero initially (stress-free, virgin material).
   *
   * <h3>Small strain</h3>
   * update_stress(): eps_e_trial = eps_e_old + d eps, then the return
   * mapping gives the stress, the new eps_e and alpha (backward Euler,
   * de Souza Neto, Peric & Owen, Computational Methods for Plasticity,
   * Wiley 2008, ch. 7-8). The committed stress of the point is not used:
   * the stress is always D : eps_e of the state. consistent_tangent() is
   * the algorithmic tangent d sigma / d(d eps) of the same return mapping.
   *
   * tangent() (called at the committed state, with no increment, to build
   * the preconditioner at the start of a step) is the elastic D. At a zero
   * increment the algorithmic tangent of a point on the yield surface is
   * only one-sided; the continuum elastoplastic tangent (continuum_tangent())
   * was tried and is worse as a preconditioner on the footing with
   * F-bar (GMRES stalls, Newton steps fail), because the
   * assembled matrix lacks the F-bar linearization and is nearly singular
   * in the deviatoric and locked in the volumetric directions. The same
   * rule applies to consistent_tangent() with a zero increment.
   *
   * <h3>Finite strain</h3>
   * The multiplicative elastoplasticity of de Souza Neto et al., ch. 14,
   * with the exponential map: with the increment f = Delta F (3x3, f_zz = 1
   * in 2D),
   *
   *   b_e_old = exp(2 eps_e_old),   b_e_trial = f b_e_old f^T,
   *   eps_e_trial = 1/2 ln b_e_trial,
   *
   * and the small-strain return mapping applied to eps_e_trial gives the
   * Kirchhoff stress tau = D : eps_e and the new eps_e. For isotropic
   * models this is exactly objective, and a plastically incompressible flow
   * (von Mises) keeps det b_e = J^2. The consistent tangent (see
   * ConstitutiveModel::kirchhoff_tangent()): with d l = d(Delta F) Delta
   * F^{-1}, d b_e_trial = d l b_e_trial + b_e_trial d l^T and
   *
   *   d tau = D_alg : 1/2 L : d b_e_trial,
   *   c_ijkl = sum_q (D_alg : L)_ijkq (b_e_trial)_ql,
   *
   * with L = d ln b / d b at b_e_trial (TensorFunctions::log_derivative())
   * and D_alg the algorithmic tangent of the return mapping. At Delta F = I
   * (the tangent at the start of a step) the rule of tangent() applies:
   * D_alg is replaced by the elastic D. For det Delta F <= 0 or det F <= 0 (or
   * not finite) tau is NaN, which the Newton line search treats as a failed
   * trial.
   *
   * Parameters (in the derived model's subsection): "Young's modulus",
   * "Poisson's ratio", and the model's own.
   */
  template <int dim>
  class IsotropicPlasticity : public ConstitutiveModel<dim>
  {
  public:
    /// The result of a 3D return mapping.
    struct Return
    {
      /// Stress D : elastic_strain (Cauchy, or Kirchhoff at finite strain).
      SymmetricTensor<2, 3> stress;
      /// The elastic strain after the return.
      SymmetricTensor<2, 3> elastic_strain;
      /// The hardening variable after the return.
      double alpha = 0.;
      /// alpha - alpha_old (zero for an elastic step).
      double increment = 0.;
      /// d stress / d trial_elastic_strain (if requested).
      SymmetricTensor<4, 3> tangent;
    };

    /// Names of the state fields.
    static constexpr const char *elastic_strain_name = "elastic_strain";
    static constexpr const char *alpha_name     = "equivalent_plastic_strain";
    static constexpr const char *increment_name = "plastic_increment";

    IsotropicPlasticity(const double young_modulus, const double poisson_ratio);

    std::vector<StateField>
    state_fields() const override;

    void
    initialize_state(const Point<dim> &x,
                     ArrayView<double> state) const override;

    void
    update_stress(const PointState<dim>         &old,
                  const SymmetricTensor<2, dim> &strain_increment,
                  SymmetricTensor<2, dim>       &stress,
                  ArrayView<double>              new_state) const override;

    /// tr of the 3D elastic strain of the committed and the trial state.
    std::optional<std::array<double, 2>>
    elastic_volume_strains(const PointState<dim>  &old,
                           ArrayView<const double> new_state) const override;

    /// True (but von Mises): the flow rule may change the volume, and the
    /// state holds the elastic strain.
    bool
    plastic_flow_changes_volume() const override;

    /// True in 2D: the hoop strain enters where plane strain has eps_zz.
    bool
    supports_axisymmetry() const override;

    /**
     * update_stress() with eps_zz = @p hoop_strain_increment in the embedded
     * increment; the hoop stress is the returned sigma_zz (the model keeps
     * it in its own state, so @p old_hoop_stress is not read).
     */
    void
    update_stress_axisymmetric(const PointState<dim>         &old,
                               const double                   old_hoop_stress,
                               const SymmetricTensor<2, dim> &strain_increment,
                               const double             hoop_strain_increment,
                               SymmetricTensor<2, dim> &stress,
                               double                  &hoop_stress,
                               ArrayView<double> new_state) const override;

    /// The tangent of the return map of update_stress_axisymmetric().
    SymmetricTensor<4, 3>
    consistent_tangent_axisymmetric(
      const PointState<dim>         &old,
      const double                   old_hoop_stress,
      const SymmetricTensor<2, dim> &strain_increment,
      const double                   hoop_strain_increment) const override;

    /// True in 2D.
    bool
    supports_axisymmetric_finite_strain() const override;

    /**
     * update_kirchhoff_stress() with the hoop stretch of @p kinematics as
     * the embedded increment's zz entry; tau_thetatheta is the returned
     * tau_zz.
     */
    void
    update_kirchhoff_stress_axisymmetric(
      const PointState<dim>             &old,
      const FiniteStrainKinematics<dim> &kinematics,
      SymmetricTensor<2, dim>           &tau,
      double                            &tau_hoop,
      ArrayView<double>                  new_state) const override;

    /// The elastic D (the preconditioner's tangent; see the class description).
    SymmetricTensor<4, dim>
    tangent(const PointState<dim> &old) const override;

    /// In-plane block of the algorithmic tangent of update_stress().
    SymmetricTensor<4, dim>
    consistent_tangent(
      const PointState<dim>         &old,
      const SymmetricTensor<2, dim> &strain_increment) const override;

    bool
    supports_finite_strain() const override;

    void
    update_kirchhoff_stress(const PointState<dim>             &old,
                            const FiniteStrainKinematics<dim> &kinematics,
                            SymmetricTensor<2, dim>           &tau,
                            ArrayView<double> new_state) const override;

    Tensor<4, dim>
    kirchhoff_tangent(
      const PointState<dim>             &old,
      const FiniteStrainKinematics<dim> &kinematics) const override;

    /// The 3D tangent of update_kirchhoff_stress_axisymmetric(), whose
    /// in-plane part kirchhoff_tangent() returns.
    Tensor<4, 3>
    kirchhoff_tangent_axisymmetric(
      const PointState<dim>             &old,
      const FiniteStrainKinematics<dim> &kinematics) const override;

    /**
     * The 3D return mapping at small strain: from the trial elastic strain
     * and the committed hardening variable to the stress, the new elastic
     * strain and alpha, and (if @p want_tangent) the algorithmic tangent
     * d stress / d trial_elastic_strain.
     */
    virtual void
    return_map(const SymmetricTensor<2, 3> &trial_elastic_strain,
               const double                 alpha_old,
               const bool                   want_tangent,
               Return                      &r) const = 0;

    /**
     * The continuum elastoplastic tangent at a stress on the yield surface
     * (plastic loading), for the hardening variable @p alpha.
     */
    virtual SymmetricTensor<4, 3>
    continuum_tangent(const SymmetricTensor<2, 3> &stress,
                      const double                 alpha) const = 0;

    /// The yield function Phi(stress, alpha) (<= 0: admissible).
    virtual double
    yield_function(const SymmetricTensor<2, 3> &stress,
                   const double                 alpha) const = 0;

    /// The 3D stress of a point from its state, elastic_stress() of its
    /// elastic strain (Kirchhoff at finite strain). In 2D this includes
    /// sigma_zz.
    SymmetricTensor<2, 3>
    stress_3d(const ArrayView<const double> &state) const;

    /**
     * The elastic law: the stress of the elastic strain @p eps_e. Here
     * D : eps_e; a model with a nonlinear elastic law (ModifiedCamClay)
     * overrides it together with elastic_tangent().
     */
    virtual SymmetricTensor<2, 3>
    elastic_stress(const SymmetricTensor<2, 3> &eps_e) const;

    /// The elastic strain whose elastic_stress() is @p stress (here
    /// D^{-1} : stress).
    virtual SymmetricTensor<2, 3>
    elastic_strain_of(const SymmetricTensor<2, 3> &stress) const;

    /**
     * With @p sigma0: the elastic strain elastic_strain_of(@p sigma0) in
     * @p state, after checking that @p sigma0 lies inside the yield
     * surface of the virgin point (a message naming `Initial stress` and
     * the point if not). Returns the in-plane part of the state's stress
     * (without @p sigma0: that of the unstrained point, zero unless the
     * model's elastic law has a stress at zero strain, ModifiedCamClay).
     */
    SymmetricTensor<2, dim>
    initial_stress(const Point<dim>            &x,
                   const unsigned int           material_id,
                   const SymmetricTensor<2, 3> *sigma0,
                   ArrayView<double>            state) const override;

    /**
     * d elastic_stress() / d eps_e at @p eps_e: the preconditioner's
     * tangent at a committed state (see the class description). Here D.
     */
    virtual SymmetricTensor<4, 3>
    elastic_tangent(const SymmetricTensor<2, 3> &eps_e) const;

    /// The elastic strain of a point from its state.
    static SymmetricTensor<2, 3>
    elastic_strain(const ArrayView<const double> &state);

    /// The hardening variable alpha of a point from its state.
    static double
    equivalent_plastic_strain(const ArrayView<const double> &state);

    /// The plastic increment of the last step of a point from its state.
    static double
    plastic_increment(const ArrayView<const double> &state);

    /// The 3D isotropic elasticity tensor D = lambda 1 (x) 1 + 2 mu I (of
    /// the constructor's E and nu; for a model with its own elastic law,
    /// that of the unstrained point).
    const SymmetricTensor<4, 3> &
    elastic_stiffness() const;

    /// Bulk modulus K = lambda + 2/3 mu.
    double
    bulk_modulus() const;

    /// Shear modulus G = mu.
    double
    shear_modulus() const;

    /// A dim-tensor as a 3D tensor (zeros out of plane in 2D).
    static SymmetricTensor<2, 3>
    embed(const SymmetricTensor<2, dim> &t);

    /// A dim x dim tensor as 3x3 with @p zz on the out-of-plane diagonal.
    static Tensor<2, 3>
    embed(const Tensor<2, dim> &t, const double zz);

    /// The in-plane block of a 3D tensor.
    static SymmetricTensor<2, dim>
    extract(const SymmetricTensor<2, 3> &t);

    /// The in-plane block of a 3D fourth-order tensor.
    static SymmetricTensor<4, dim>
    extract(const SymmetricTensor<4, 3> &t);

    /// The in-plane block of a 3D fourth-order tensor.
    static Tensor<4, dim>
    extract(const Tensor<4, 3> &t);

  protected:
    /// Set the hardening variable alpha in a point's @p state.
    static void
    set_equivalent_plastic_strain(ArrayView<double> state, const double alpha);

    const double                lambda;
    const double                mu;
    const double                K;
    const SymmetricTensor<4, 3> D;
  };
} // namespace qsmpm

#endif
