#ifndef qsmpm_materials_cubic_elastic_h
#define qsmpm_materials_cubic_elastic_h

#include <array>
#include <deal.II/base/tensor.h>
#include <functional>
#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/materials/constitutive_model.h>

namespace qsmpm
{
  /**
   * Linear elasticity of a cubic crystal with a per-point orientation, the
   * grain model of paper Section 4 (eq. 4.2): Hooke's law with C11, C12, C44
   * in the crystal frame, the strain increment rotated from the sample to
   * the crystal axes and the stress increment rotated back. Orientations
   * follow Bunge's convention of Rotation (g maps sample to crystal
   * components), so the stiffness in the sample frame is
   * C_s,ijkl = g_mi g_nj g_ok g_pl C_mnop.
   *
   * Rotating strain and stress at every residual evaluation would cost two
   * tensor rotations per point and call; instead initialize_state() stores
   * the rotated stiffness C_s on the point (the state field
   * "rotated_stiffness": the upper triangle of the matrix M_ab = C_s of
   * deal.II's unrolled component order, 21 doubles in 3D, 6 in 2D) and
   * update_stress() is one small matrix-vector product, the same as the
   * two rotations up to round-off. The field is constant in time.
   *
   * The orientation of a point comes from a function of its position (set
   * with set_orientation(), e.g. the grain of a Voronoi tessellation), or,
   * without one, from the parameter "Euler angles" for all points. In 2D the
   * model is plane strain: the in-plane block (xx, yy, xy) of the rotated
   * 3D stiffness.
   *
   * Selected in a .prm file with `set Model = cubic elastic`.
   */
  template <int dim>
  class CubicElastic : public ConstitutiveModel<dim>
  {
  public:
    std::string
    name() const override
    {
      return "cubic elastic";
    }

    /// True: the stress follows from the strain alone.
    bool
    is_elastic() const override
    {
      return true;
    }

    /// Orientation g (Bunge, sample -> crystal) of a point at x.
    using OrientationFunction = std::function<Tensor<2, 3>(const Point<dim> &)>;

    /**
     * Constants C11, C12, C44 in the crystal frame and the orientation
     * (Bunge angles in radians) used where no orientation function is set.
     */
    CubicElastic(const double                 C11,
                 const double                 C12,
                 const double                 C44,
                 const std::array<double, 3> &euler_angles = {{0., 0., 0.}});

    /// The subsection "cubic elastic".
    struct Parameters : ParameterStruct<Parameters>
    {
      double C11 = 249.;
      double C12 = 155.;
      double C44 = 114.;
      /// Bunge angles phi1, Phi, phi2 in degrees.
      std::array<double, 3> euler_angles = {{0., 0., 0.}};

      /// Declare the entries, bound to the members.
      void
      add_parameters(ParameterHandler &prm);
    };

    explicit CubicElastic(const Parameters &parameters);

    /// Construct from the subsection "cubic elastic".
    explicit CubicElastic(ParameterHandler &prm);

    static void
    declare_parameters(ParameterHandler &prm);

    /// Give each new point the orientation @p orientation(x).
    void
    set_orientation(const OrientationFunction &orientation);

    std::vector<StateField>
    state_fields() const override;

    void
    initialize_state(const Point<dim> &x,
                     ArrayView<double> state) const override;

    /// True: the stress is the committed one plus an increment.
    bool
    incremental_stress() const override
    {
      return true;
    }

    void
    update_stress(const PointState<dim>         &old,
                  const SymmetricTensor<2, dim> &strain_increment,
                  SymmetricTensor<2, dim>       &stress,
                  ArrayView<double>              new_state) const override;

    /**
     * All points at once, reading the rotated stiffness in place; the
     * trial fields are not written (state_is_constant()).
     */
    void
    update_stresses(const PointStateBatch<dim>              &old,
                    ArrayView<const SymmetricTensor<2, dim>> strain_increments,
                    ArrayView<SymmetricTensor<2, dim>>       stresses,
                    ArrayView<double> new_states) const override;

    /// The batched update reads the committed stress and the rotated
    /// stiffness (the model's fields) only.
    typename PointStateBatch<dim>::Fields
    batch_fields() const override;

    /// True: a point's rotated stiffness never changes.
    bool
    state_is_constant() const override;

    /// The point's rotated stiffness (exact: the model is linear).
    SymmetricTensor<4, dim>
    tangent(const PointState<dim> &old) const override;

    /// The stiffness in the crystal frame.
    const SymmetricTensor<4, 3> &
    crystal_stiffness() const;

    /**
     * The stiffness of orientation @p g in the sample frame, restricted to
     * dim dimensions (the in-plane block in 2D).
     */
    SymmetricTensor<4, dim>
    sample_stiffness(const Tensor<2, 3> &g) const;

    /// Number of doubles of the state field "rotated_stiffness".
    static constexpr unsigned int n_entries =
      SymmetricTensor<2, dim>::n_independent_components *
      (SymmetricTensor<2, dim>::n_independent_components + 1) / 2;

  private:
    SymmetricTensor<4, 3> C_crystal;
    Tensor<2, 3>          default_orientation;
    OrientationFunction   orientation;
  };
} // namespace qsmpm

#endif
