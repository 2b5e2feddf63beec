#ifndef qsmpm_materials_linear_elastic_h
#define qsmpm_materials_linear_elastic_h

#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/materials/constitutive_model.h>
#include <utility>

namespace qsmpm
{
  /**
   * The entries "Young's modulus" and "Poisson's ratio" of the subsections
   * of the isotropic models.
   */
  struct IsotropicElasticity : ParameterStruct<IsotropicElasticity>
  {
    double young_modulus = 1.;
    double poisson_ratio = 0.3;

    /// Declare the entries, bound to the members.
    void
    add_parameters(ParameterHandler &prm);
  };



  /**
   * Isotropic linear elasticity, sigma^{k+1} = sigma^k + C : d_epsilon
   * (paper eqs. 2.20-2.21 with a constant C). In 2D the model is plane strain
   * by default; with "Plane stress = true" C is the plane-stress stiffness
   * (sigma_zz = 0).
   *
   * Selected in a .prm file with `set Model = linear elastic`.
   */
  template <int dim>
  class LinearElastic : public ConstitutiveModel<dim>
  {
  public:
    std::string
    name() const override
    {
      return "linear elastic";
    }

    /// True: the stress follows from the strain alone.
    bool
    is_elastic() const override
    {
      return true;
    }

    LinearElastic(const double young_modulus,
                  const double poisson_ratio,
                  const bool   plane_stress = false);

    /// The subsection "linear elastic".
    struct Parameters : ParameterStruct<Parameters>
    {
      IsotropicElasticity elasticity;
      bool                plane_stress = false;

      /// Declare the entries, bound to the members.
      void
      add_parameters(ParameterHandler &prm);
    };

    explicit LinearElastic(const Parameters &parameters);

    /// Construct from the subsection "linear elastic".
    explicit LinearElastic(ParameterHandler &prm);

    static void
    declare_parameters(ParameterHandler &prm);

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

    /// All points at once: sigma_i = sigma_old,i + C : d_epsilon_i.
    void
    update_stresses(const PointStateBatch<dim>              &old,
                    ArrayView<const SymmetricTensor<2, dim>> strain_increments,
                    ArrayView<SymmetricTensor<2, dim>>       stresses,
                    ArrayView<double> new_states) const override;

    /// True unless plane stress.
    bool
    supports_axisymmetry() const override;

    /**
     * sigma = sigma_old + lambda (tr d_eps + d_eps_hoop) I + 2 mu d_eps,
     * sigma_hoop = sigma_hoop_old + lambda (tr d_eps + d_eps_hoop) + 2 mu
     * d_eps_hoop: the 3D law with the hoop direction out of the plane.
     */
    void
    update_stress_axisymmetric(const PointState<dim>         &old,
                               const double                   old_hoop_stress,
                               const SymmetricTensor<2, dim> &strain_increment,
                               const double             hoop_strain_increment,
                               SymmetricTensor<2, dim> &stress,
                               double                  &hoop_stress,
                               ArrayView<double> new_state) const override;

    /// The batched update reads the committed stress only.
    typename PointStateBatch<dim>::Fields
    batch_fields() const override;

    SymmetricTensor<4, dim>
    tangent(const PointState<dim> &old) const override;

    /// C at every point.
    void
    tangents(const PointStateBatch<dim>        &old,
             ArrayView<SymmetricTensor<4, dim>> C) const override;

    /// C at every point.
    void
    loading_tangents(const PointStateBatch<dim>        &old,
                     ArrayView<SymmetricTensor<4, dim>> C) const override;

    /// The elastic stiffness.
    const SymmetricTensor<4, dim> &
    stiffness() const;

    /**
     * The Lame constants (lambda, mu) of E and nu (3D formulas, which are
     * also those of plane strain); throws if E <= 0 or nu is outside
     * (-1, 0.5).
     */
    static std::pair<double, double>
    lame_parameters(const double young_modulus, const double poisson_ratio);

    /**
     * The isotropic stiffness for E, nu; in 2D plane strain or, with
     * @p plane_stress, the plane-stress reduction.
     */
    static SymmetricTensor<4, dim>
    isotropic_stiffness(const double young_modulus,
                        const double poisson_ratio,
                        const bool   plane_stress);

  private:
    SymmetricTensor<4, dim> C;
    /// C = lambda I (x) I + 2 mu II (lambda of plane stress in 2D if so
    /// chosen): the two constants the batched update uses.
    double lambda;
    double two_mu;
    /// Plane stress (2D): no out-of-plane strain, so no axisymmetry.
    bool is_plane_stress;
  };
} // namespace qsmpm

#endif
