#ifndef qsmpm_materials_constitutive_model_h
#define qsmpm_materials_constitutive_model_h

#include <array>
#include <deal.II/base/array_view.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/particles/property_pool.h>
#include <functional>
#include <memory>
#include <optional>
#include <qsmpm/materials/point_state.h>
#include <qsmpm/materials/point_state_batch.h>
#include <string>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * A named block of per-point data that a constitutive model keeps on each
   * material point (e.g. "crack_opening" with one component, or
   * "euler_angles" with three).
   */
  struct StateField
  {
    std::string  name;
    unsigned int n_components;
  };

  /**
   * The interface of all constitutive models: the stress update of paper
   * eqs. (2.20)-(2.21) at one material point,
   *
   *   (committed strain, stress and history; strain increment)
   *       -> (trial stress, trial history).
   *
   * Implementations must be pure: update_stress() is called many times per
   * load step (by every residual evaluation of the Jacobian-free
   * Newton-Krylov solver) and must never modify anything but its output
   * arguments. Only the converged result is committed to the point.
   *
   * Models are selected by name in the .prm file (subsection "Material",
   * entry "Model") and register themselves with
   * QSMPM_REGISTER_CONSTITUTIVE_MODEL.
   */
  template <int dim>
  class ConstitutiveModel
  {
  public:
    virtual ~ConstitutiveModel() = default;

    /// The model's per-point fields besides strain and stress.
    virtual std::vector<StateField>
    state_fields() const;

    /// Initial values of the model's fields for a point created at @p x.
    virtual void
    initialize_state(const Point<dim> &x, ArrayView<double> state) const;

    /**
     * Initial values of the model's fields for a point of material id
     * @p material_id created at @p x; what MaterialPointSet calls. The
     * default ignores the id and calls initialize_state(x, state); a
     * MaterialMap passes the point on to the model of its id.
     */
    virtual void
    initialize_material_state(const Point<dim>  &x,
                              const unsigned int material_id,
                              ArrayView<double>  state) const;

    /**
     * Initial values of the model's fields for the point with the id
     * @p id (unique and independent of the number of ranks) and material
     * id @p material_id created at @p x: what MaterialPointSet calls. The
     * default calls initialize_material_state(); a model that numbers its
     * points (the UMAT's NOEL) overrides it, and a MaterialMap passes the
     * point on to the model of its id.
     */
    virtual void
    initialize_point_state(const Point<dim>           &x,
                           const unsigned int          material_id,
                           const types::particle_index id,
                           ArrayView<double>           state) const;

    /**
     * The committed stress of a point created at @p x with @p state (after
     * initialize_point_state()): what MaterialPointSet stores as its stress
     * before the first step. With @p sigma0 (the point's `Material
     * points/Initial stress`, a 3D Cauchy stress whose zz component is the
     * out-of-plane stress in 2D), the model first changes @p state so that
     * the point carries @p sigma0, and returns it; a model that cannot
     * start from a stress, or not from this one, throws a message that
     * names the entry.
     *
     * Default: zero without @p sigma0; with it, the in-plane part of
     * @p sigma0 if incremental_stress(), else an error.
     */
    virtual SymmetricTensor<2, dim>
    initial_stress(const Point<dim>            &x,
                   const unsigned int           material_id,
                   const SymmetricTensor<2, 3> *sigma0,
                   ArrayView<double>            state) const;

    /**
     * Axisymmetric kinematics: the hoop stress a point starts from, given
     * the initial stress @p sigma0 (or none) and the state that
     * initial_stress() wrote. Default: sigma0's out-of-plane entry, or
     * zero.
     */
    virtual double
    initial_hoop_stress(const SymmetricTensor<2, 3> *sigma0,
                        ArrayView<const double>      state) const;

    /**
     * Whether the stress is the committed one plus an increment that
     * depends on the committed state only (LinearElastic, CubicElastic,
     * Umat at small strain), so that any committed stress is a valid start.
     * Default: false.
     */
    virtual bool
    incremental_stress() const;

    /**
     * Fields that are written with the points but are not state: functions
     * of a point's committed state (e.g. a crack opening normalized by the
     * critical opening), computed by compute_output_fields() when the
     * points are written, never stored on the points. Default: none.
     */
    virtual std::vector<StateField>
    output_fields() const;

    /**
     * The values of output_fields() for the committed point state
     * @p point; @p values has the size of output_fields() and must be
     * written completely.
     */
    virtual void
    compute_output_fields(const PointState<dim> &point,
                          ArrayView<double>      values) const;

    /**
     * Trial stress and history for the strain increment @p strain_increment
     * applied to the committed point state @p old. @p new_state has the size
     * of the model's fields and must be written completely.
     */
    virtual void
    update_stress(const PointState<dim>         &old,
                  const SymmetricTensor<2, dim> &strain_increment,
                  SymmetricTensor<2, dim>       &stress,
                  ArrayView<double>              new_state) const = 0;

    /**
     * update_stress() for a batch of points (the points of one cell, as the
     * residual evaluates them): the trial stresses @p stresses[i] of the
     * points @p old[i] for the strain increments @p strain_increments[i],
     * and their trial fields in @p new_states, n_state_components() doubles
     * per point, point after point.
     *
     * The residual of the Jacobian-free Newton-Krylov solver calls this,
     * not update_stress(): once per cell instead of once per point, so that
     * a model whose update is a few multiplications (an elastic one) costs
     * neither a virtual call nor the assembly of a whole PointState per
     * point. The default calls update_stress() point by point; overriding
     * it is optional and must give the same results.
     *
     * If state_is_constant(), the caller ignores @p new_states and a model
     * need not write it.
     */
    virtual void
    update_stresses(const PointStateBatch<dim>              &old,
                    ArrayView<const SymmetricTensor<2, dim>> strain_increments,
                    ArrayView<SymmetricTensor<2, dim>>       stresses,
                    ArrayView<double>                        new_states) const;

    /**
     * The fields of the committed state that update_stresses() reads (and,
     * if the model computes them, dissipation() and the finite-strain
     * functions, which see a whole PointState). The residual keeps a
     * compact copy of just these fields per point for the load step, and
     * reads that copy in every evaluation, instead of the points' whole
     * property arrays: less memory traffic per residual. The default is
     * all fields; a model that reads less may say so (LinearElastic: the
     * stress only). A field read that was not declared is NaN in the
     * batch's operator[] (and an assertion in a debug build).
     */
    virtual typename PointStateBatch<dim>::Fields
    batch_fields() const;

    /**
     * Whether the model's fields never change (e.g. the elastic constants
     * of a crystal kept per point): commit() then leaves them as they are
     * and the batched update need not write trial fields. False by
     * default.
     */
    virtual bool
    state_is_constant() const;

    /**
     * A tangent stiffness d(sigma)/d(epsilon) at the committed state, used by
     * preconditioners. For linear models it is exact.
     */
    virtual SymmetricTensor<4, dim>
    tangent(const PointState<dim> &old) const = 0;

    /**
     * tangent() for a batch of points (the points of one cell): @p C[i] is
     * the tangent of the point @p old[i]. The tangent assembler and the
     * check for nodes without stiffness, which runs in every load step,
     * call this once per cell. The default calls tangent() point by point;
     * a model with the same tangent at every point (linear elasticity)
     * overrides it to copy that tangent without assembling a PointState
     * per point.
     */
    virtual void
    tangents(const PointStateBatch<dim>        &old,
             ArrayView<SymmetricTensor<4, dim>> C) const;

    /**
     * The tangent of the branch the point is on at the committed state,
     * continued into the next step: for a crack that is softening, the
     * slope of its softening law, so that the stiffness across it is
     * negative. The matrix of these tangents may be indefinite; only a
     * preconditioner that factors it (Preconditioner = direct, KLU) is built
     * from it, while AMG, Jacobi and the checks for nodes without stiffness
     * use tangent(). A softening point's tangent() is a secant, and the
     * Krylov solver then has to make up for the difference in every Newton
     * iteration (b15.prm: 5.9 GMRES iterations per Newton iteration with
     * the secant, 1.4 with the slope). Default: tangent().
     */
    virtual SymmetricTensor<4, dim>
    loading_tangent(const PointState<dim> &old) const;

    /**
     * loading_tangent() for a batch of points (the points of one cell).
     * The default calls loading_tangent() point by point.
     */
    virtual void
    loading_tangents(const PointStateBatch<dim>        &old,
                     ArrayView<SymmetricTensor<4, dim>> C) const;

    /**
     * The consistent (algorithmic) tangent d(sigma)/d(strain_increment) of
     * update_stress() at the trial state reached with @p strain_increment
     * from @p old. Path-dependent models (plasticity) override it; the
     * default is tangent(old), exact for linear models.
     */
    virtual SymmetricTensor<4, dim>
    consistent_tangent(const PointState<dim>         &old,
                       const SymmetricTensor<2, dim> &strain_increment) const;

    /**
     * The energy per unit volume dissipated between the committed state
     * @p old and the trial history @p new_state that update_stress() (or
     * update_kirchhoff_stress()) returned. Path following by dissipation
     * (Load stepping/Control = dissipation) prescribes its sum over the
     * points per step. The default is 0: an elastic model dissipates
     * nothing, and a model without this function cannot be used with
     * dissipation control.
     */
    virtual double
    dissipation(const PointState<dim>  &old,
                ArrayView<const double> new_state) const;

    /// Whether the model overrides dissipation() (false by default).
    virtual bool
    computes_dissipation() const;

    /**
     * The elastic volume strain tr eps_e of the point @p old: first at its
     * committed state, second at the trial state @p new_state that
     * update_stress() returned. F-bar at small strain
     * (QuasiStaticResidual::share_plastic_volume_changes()) makes the
     * change of tr eps_e common to the points of a cell and leaves each
     * point its own plastic volume change; without that, a dilatant flow
     * locks (dilatancy locking). The default returns nothing: the model
     * does not separate elastic from plastic strain, and the point's whole
     * volume change counts as elastic (plain F-bar).
     */
    virtual std::optional<std::array<double, 2>>
    elastic_volume_strains(const PointState<dim>  &old,
                           ArrayView<const double> new_state) const;

    /**
     * Whether the model's plastic flow can change a point's volume, and
     * elastic_volume_strains() then tells by how much (false by default).
     * The residual splits the volume changes (and asks each point) only
     * then; where plastic flow keeps the volume (von Mises) plain F-bar is
     * that split already.
     */
    virtual bool
    plastic_flow_changes_volume() const;

    /**
     * Whether the model implements the finite-strain interface below
     * (update_kirchhoff_stress() and kirchhoff_tangent()).
     */
    virtual bool
    supports_finite_strain() const;

    /**
     * Finite strain: the Kirchhoff stress tau = J sigma and the trial history
     * at F = Delta F F_old, from the committed point state @p old (whose
     * stress is the committed Cauchy stress). Pure, like update_stress().
     * The default throws: the model is small-strain only.
     */
    virtual void
    update_kirchhoff_stress(const PointState<dim>             &old,
                            const FiniteStrainKinematics<dim> &kinematics,
                            SymmetricTensor<2, dim>           &tau,
                            ArrayView<double>                  new_state) const;

    /**
     * Finite strain: the consistent tangent of the Kirchhoff stress returned
     * by update_kirchhoff_stress() for the same arguments, as the
     * fourth-order tensor c with
     *
     *   d tau_ij = c_ijkl d l_kl,   d l = d(Delta F) Delta F^{-1},
     *
     * i.e. the derivative with respect to the spatial gradient of a
     * variation of the increment (c is in general not minor-symmetric in
     * kl). The default throws.
     */
    virtual Tensor<4, dim>
    kirchhoff_tangent(const PointState<dim>             &old,
                      const FiniteStrainKinematics<dim> &kinematics) const;

    /**
     * Whether the model implements update_stress_axisymmetric() (axisymmetric
     * (r, z) kinematics in 2D, `Material points/Axisymmetric`). False by
     * default.
     */
    virtual bool
    supports_axisymmetry() const;

    /**
     * Axisymmetric (r, z) kinematics at small strain: update_stress() with
     * the hoop strain increment @p hoop_strain_increment = d u_r / r beside
     * the in-plane increment (r, z as x, y). The model's 3D stress has the
     * hoop stress sigma_thetatheta where plane strain has sigma_zz: returned
     * in @p hoop_stress, from the committed @p old_hoop_stress (kept by the
     * residual on every point, for models that do not keep the
     * out-of-plane stress in their own state). Pure, like update_stress().
     * The default throws: the model is plane only.
     */
    virtual void
    update_stress_axisymmetric(const PointState<dim>         &old,
                               const double                   old_hoop_stress,
                               const SymmetricTensor<2, dim> &strain_increment,
                               const double             hoop_strain_increment,
                               SymmetricTensor<2, dim> &stress,
                               double                  &hoop_stress,
                               ArrayView<double>        new_state) const;

    /**
     * Axisymmetric (r, z) kinematics at small strain: the consistent
     * tangent d(sigma)/d(epsilon) of update_stress_axisymmetric() at the
     * trial state reached with @p strain_increment and
     * @p hoop_strain_increment from @p old, as a 3D tensor whose index 2 is
     * the hoop direction. The default is tangent(old) with the hoop
     * entries of an isotropic tangent, C_2222 = C_0000 and C_22kk = C_kk22
     * = C_0011 (exact for isotropic elasticity).
     */
    virtual SymmetricTensor<4, 3>
    consistent_tangent_axisymmetric(
      const PointState<dim>         &old,
      const double                   old_hoop_stress,
      const SymmetricTensor<2, dim> &strain_increment,
      const double                   hoop_strain_increment) const;

    /**
     * Whether the model implements update_kirchhoff_stress_axisymmetric()
     * (axisymmetric kinematics at finite strain). False by default.
     */
    virtual bool
    supports_axisymmetric_finite_strain() const;

    /**
     * Axisymmetric kinematics at finite strain: update_kirchhoff_stress()
     * with the step's hoop stretch kinematics.delta_hoop_stretch where
     * plane strain has Delta F_zz = 1, and the hoop Kirchhoff stress
     * tau_thetatheta in @p tau_hoop. kirchhoff_tangent() then takes the
     * same hoop stretch. The default throws.
     */
    virtual void
    update_kirchhoff_stress_axisymmetric(
      const PointState<dim>             &old,
      const FiniteStrainKinematics<dim> &kinematics,
      SymmetricTensor<2, dim>           &tau,
      double                            &tau_hoop,
      ArrayView<double>                  new_state) const;

    /**
     * Axisymmetric kinematics at finite strain: the consistent tangent of
     * update_kirchhoff_stress_axisymmetric() for the same arguments, the 3D
     * c with d tau_ij = c_ijkl d l_kl (as kirchhoff_tangent(), index 2 the
     * hoop direction, d l_22 = d(Delta F_tt) / Delta F_tt). Its hoop entries
     * are what the stiffness at a Newton iterate needs (`Preconditioner
     * update = Newton iteration`). The default embeds kirchhoff_tangent()
     * with the hoop entries of an isotropic tangent (c_2222 = c_0000,
     * c_22kk = c_kk22 = c_0011): exact for none but isotropic
     * elasticity at Delta F = I, a preconditioner's estimate otherwise.
     */
    virtual Tensor<4, 3>
    kirchhoff_tangent_axisymmetric(
      const PointState<dim>             &old,
      const FiniteStrainKinematics<dim> &kinematics) const;

    /**
     * Whether the stress is a function of the strain (or deformation)
     * alone, without history: the solver's `auto` settings
     * (NewtonParameters::resolve()) then extrapolate the last step's
     * increment, adapt GMRES's tolerance and keep a preconditioner over
     * several steps (measured safe for such models, not for perfect
     * plasticity). False by default.
     */
    virtual bool
    is_elastic() const;

    /// The model's name in messages.
    virtual std::string
    name() const;

    /// Total number of doubles in state_fields().
    unsigned int
    n_state_components() const;

    /// Total number of doubles in output_fields().
    unsigned int
    n_output_components() const;
  };



  /**
   * The registry of constitutive models, in the manner of ASPECT's plugins:
   * each model registers its name, a description, the declaration of its
   * parameters (in a subsection named after the model inside "Material") and
   * a factory function.
   */
  template <int dim>
  class ConstitutiveModelFactory
  {
  public:
    using Declarer = std::function<void(ParameterHandler &)>;
    using Creator  = std::function<std::unique_ptr<ConstitutiveModel<dim>>(
      ParameterHandler &)>;

    /// Add a model to the registry. Called by
    /// QSMPM_REGISTER_CONSTITUTIVE_MODEL.
    static bool
    register_model(const std::string &name,
                   const std::string &description,
                   const Declarer    &declare_parameters,
                   const Creator     &create);

    /**
     * Declare subsection "Material" with the entry "Model" and one
     * subsection per registered model.
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /// Create the model named in subsection "Material".
    static std::unique_ptr<ConstitutiveModel<dim>>
    create(ParameterHandler &prm);

    /// Names of all registered models.
    static std::vector<std::string>
    names();
  };
} // namespace qsmpm

/**
 * Register a model class for dim = 2 and 3. Use it at namespace scope in
 * the namespace of the class (qsmpm, or a user's own namespace: everything
 * of qsmpm is fully qualified here), in a .cc file, once per class. The
 * class template `classname<dim>` must provide
 * `static void declare_parameters(dealii::ParameterHandler &)` (entries of
 * its own subsection, which is named @p name) and a constructor taking the
 * ParameterHandler positioned in that subsection. @p name is what
 * `set Model = ...` selects; it must be unique among all models.
 *
 * The registration runs during static initialization: of libqsmpm.so for
 * the built-in models, of the user's executable for a model compiled into
 * it, and of a plugin library when the driver loads it with
 * `qsmpm --plugin` (see doc/user_models.md).
 */
#define QSMPM_REGISTER_CONSTITUTIVE_MODEL(classname, name, description) \
  namespace                                                             \
  {                                                                     \
    template <int dim>                                                  \
    bool register_##classname()                                         \
    {                                                                   \
      return ::qsmpm::ConstitutiveModelFactory<dim>::register_model(    \
        name,                                                           \
        description,                                                    \
        [](::dealii::ParameterHandler &prm) {                           \
          classname<dim>::declare_parameters(prm);                      \
        },                                                              \
        [](::dealii::ParameterHandler &prm) {                           \
          return std::unique_ptr<::qsmpm::ConstitutiveModel<dim>>(      \
            new classname<dim>(prm));                                   \
        });                                                             \
    }                                                                   \
    const bool classname##_registered_2 = register_##classname<2>();    \
    const bool classname##_registered_3 = register_##classname<3>();    \
  }

#endif
