#ifndef qsmpm_materials_material_map_h
#define qsmpm_materials_material_map_h

#include <memory>
#include <qsmpm/materials/constitutive_model.h>
#include <string>
#include <vector>

namespace qsmpm
{
  /**
   * A constitutive model per material id: a footing on soil, soil layers, a
   * specimen with steel pins. The map is itself a ConstitutiveModel; every
   * call is passed on to the model of the point's material id
   * (PointState::material_id), so the residual, the tangent, commit and
   * checkpoints see one model as before.
   *
   * <h3>State layout</h3>
   * Every point carries the union of the models' state fields, merged by
   * name: a field that several models have (e.g. "equivalent_plastic_strain"
   * of two plastic layers) is one field of the points, written as one field
   * in the output; fields of the same name must have the same number of
   * components. A model sees its own fields in its own order (they are
   * gathered from the union before and scattered back after each call);
   * fields of other models keep their committed values. Output fields are
   * merged the same way, with zeros where a point's model has no such field.
   *
   * <h3>Dissipation</h3>
   * The map computes its dissipation if at least one of its models does; a
   * model without dissipation() counts as dissipating nothing (true for the
   * elastic models).
   *
   * Points whose material id has no model use the default model
   * (set_default()); without one, they are an error when the points are
   * created (initialize_material_state()).
   */
  template <int dim>
  class MaterialMap : public ConstitutiveModel<dim>
  {
  public:
    /**
     * The most state (and output) components of all models together that a
     * point may carry: the gathered copies live on the stack.
     */
    static constexpr unsigned int max_components = 64;

    /// The model of the points of material id @p material_id.
    void
    add(const unsigned int                      material_id,
        std::unique_ptr<ConstitutiveModel<dim>> model);

    /// The model of the points whose id has no model of its own.
    void
    set_default(std::unique_ptr<ConstitutiveModel<dim>> model);

    /// The model that points of @p material_id use (throws if none).
    const ConstitutiveModel<dim> &
    model_of(const unsigned int material_id) const;

    std::vector<StateField>
    state_fields() const override;

    /// Throws: a point's fields depend on its material id.
    void
    initialize_state(const Point<dim> &x,
                     ArrayView<double> state) const override;

    void
    initialize_material_state(const Point<dim>  &x,
                              const unsigned int material_id,
                              ArrayView<double>  state) const override;

    /// The member's initialize_point_state(), gathered like
    /// initialize_material_state().
    void
    initialize_point_state(const Point<dim>           &x,
                           const unsigned int          material_id,
                           const types::particle_index id,
                           ArrayView<double>           state) const override;

    /// The member's initial_stress(), gathered like
    /// initialize_material_state().
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

    double
    dissipation(const PointState<dim>  &old,
                ArrayView<const double> new_state) const override;

    bool
    computes_dissipation() const override;

    /// The member's elastic_volume_strains(), gathered like dissipation().
    std::optional<std::array<double, 2>>
    elastic_volume_strains(const PointState<dim>  &old,
                           ArrayView<const double> new_state) const override;

    /// True if the plastic flow of one of the models can change the volume.
    bool
    plastic_flow_changes_volume() const override;

    /// True if every model supports finite strain.
    bool
    supports_finite_strain() const override;

    /// True if every model supports axisymmetry.
    bool
    supports_axisymmetry() const override;

    SymmetricTensor<4, 3>
    consistent_tangent_axisymmetric(
      const PointState<dim>         &old,
      const double                   old_hoop_stress,
      const SymmetricTensor<2, dim> &strain_increment,
      const double                   hoop_strain_increment) const override;

    /// True if every model supports axisymmetry at finite strain.
    bool
    supports_axisymmetric_finite_strain() const override;

    void
    update_kirchhoff_stress_axisymmetric(
      const PointState<dim>             &old,
      const FiniteStrainKinematics<dim> &kinematics,
      SymmetricTensor<2, dim>           &tau,
      double                            &tau_hoop,
      ArrayView<double>                  new_state) const override;

    void
    update_stress_axisymmetric(const PointState<dim>         &old,
                               const double                   old_hoop_stress,
                               const SymmetricTensor<2, dim> &strain_increment,
                               const double             hoop_strain_increment,
                               SymmetricTensor<2, dim> &stress,
                               double                  &hoop_stress,
                               ArrayView<double> new_state) const override;

    void
    update_kirchhoff_stress(const PointState<dim>             &old,
                            const FiniteStrainKinematics<dim> &kinematics,
                            SymmetricTensor<2, dim>           &tau,
                            ArrayView<double> new_state) const override;

    Tensor<4, dim>
    kirchhoff_tangent(
      const PointState<dim>             &old,
      const FiniteStrainKinematics<dim> &kinematics) const override;

    Tensor<4, 3>
    kirchhoff_tangent_axisymmetric(
      const PointState<dim>             &old,
      const FiniteStrainKinematics<dim> &kinematics) const override;

    /// Whether every model of the map is elastic.
    bool
    is_elastic() const override;

    /// E.g. "material map (0: linear elastic, 1: von Mises)".
    std::string
    name() const override;

  private:
    /**
     * One model with the places of its fields in the union: component c of
     * the model's own state is component state_index[c] of the points'
     * state (likewise for the output fields).
     */
    struct Member
    {
      std::unique_ptr<ConstitutiveModel<dim>> model;
      std::vector<unsigned int>               state_index;
      std::vector<unsigned int>               output_index;
      /// The model's state is the first components of the union, in order:
      /// no gathering needed.
      bool state_is_prefix = false;
    };

    /// The member of @p material_id (the default one if it has none).
    const Member &
    member(const unsigned int material_id) const;

    /**
     * Recompute the union layouts and every member's indices after a model
     * was added.
     */
    void
    build_layout();

    /**
     * Call @p f(state) with the committed state of @p old as the member's
     * own layout.
     */
    template <typename Function>
    auto
    with_own_state(const Member          &member,
                   const PointState<dim> &old,
                   const Function        &f) const;

    /**
     * Call @p f(state, own_new_state) with the committed state of @p old
     * and the trial state @p new_state (the union's) both in the member's
     * own layout, for functions that read a step's two states.
     */
    template <typename Function>
    auto
    with_own_states(const Member           &member,
                    const PointState<dim>  &old,
                    ArrayView<const double> new_state,
                    const Function         &f) const;

    /**
     * Call @p f(point, own_new_state) for an update of @p old, and write the
     * member's new state into @p new_state (the union, whose other fields
     * keep their committed values).
     */
    template <typename Function>
    void
    update(const PointState<dim> &old,
           ArrayView<double>      new_state,
           const Function        &f) const;

    /// Members by material id (nullptr: none) and the default.
    std::vector<std::shared_ptr<Member>> by_id;
    std::shared_ptr<Member>              default_member;
    std::vector<std::pair<unsigned int, std::shared_ptr<Member>>> ordered;

    std::vector<StateField> union_state;
    std::vector<StateField> union_output;
  };
} // namespace qsmpm

#endif
