#ifndef qsmpm_materials_decohesion_h
#define qsmpm_materials_decohesion_h

#include <deal.II/base/tensor.h>
#include <functional>
#include <qsmpm/materials/constitutive_model.h>
#include <qsmpm/materials/linear_elastic.h>

namespace qsmpm
{
  /**
   * Schreyer's elastic-decohesive model for quasi-brittle materials in mode
   * I with linear softening (paper Section 3.2, eqs. 3.1-3.2), as a smeared
   * crack ("crack band") at each material point:
   *
   *   F_n = tau_n / tau_nf + [[u_n]] / u0 - 1,     u0 = 2 G_f / tau_nf,
   *   sigma = C : (eps - eps_dc),
   *   eps_dc = (1 / (2 L_c)) ([[u]] (x) n + n (x) [[u]]) = ([[u_n]]/L_c) n(x)n.
   *
   * - Isotropic linear elasticity until the Rankine criterion F_n(sigma.n, 0)
   *   = 0 is met in the region where cracking is allowed. The crack normal n
   *   is then either the direction of the largest principal stress of that
   *   moment or a fixed direction (the paper fixes it to x). One crack per
   *   point; n never changes afterwards.
   * - Softening: tau_n = n.sigma.n <= tau_nf max(0, 1 - [[u_n]]/u0); the
   *   opening [[u_n]] is an internal variable that never decreases, as the
   *   plastic strain of a rate-independent plasticity model. Because C is
   *   constant and the softening law is linear in [[u_n]], the return
   *   mapping has a closed form (see update_stress()).
   * - Unloading and reloading are elastic at the current opening; after
   *   complete failure ([[u_n]] >= u0) the crack carries no tensile normal
   *   traction, ever again. Compression across an open crack is carried
   *   elastically (there is no separate crack-closure law).
   * - Mode I only: shear tractions on the crack plane are not softened,
   *   but a completely failed crack that opens is traction free, its shear
   *   traction is released too (by a tangential jump). With one point per
   *   cell, on the centre line of the band, the shear strain there vanishes
   *   by symmetry and this changes little; with 2x2 points per cell it
   *   removes part of the shear locking of the broken band (see the
   *   example's documentation). Releasing the shear already while the
   *   crack softens (zero shear retention) makes the stress update jump
   *   at initiation, and Newton's method then fails to converge.
   *
   * <h3>The smearing length</h3>
   * The paper defines L_c as the point volume divided by the crack area
   * across the point, which is the cell size h for one point per cell and a
   * crack parallel to a cell edge. With n x n points per cell and bilinear
   * shape functions, however, eps_xx is constant in x inside a cell: all n
   * points of a cell row see the same strain and crack together, so the
   * crack band is one cell wide whatever the number of points. The model
   * therefore uses the width of the band of cells that cracks,
   *
   *   L_c = h_band max_i |n_i|,
   *
   * with h_band the parameter "Crack band width" (the cell size of the
   * background grid) and max_i |n_i| = V_cell / (area of the cell's mid
   * plane normal to n), exact for a square cell in 2D and for normals in a
   * coordinate plane in 3D. Each point then dissipates
   * G_f V_p / L_c, and the points of one cell together dissipate G_f times
   * the crack area through the cell, for any number of points per cell and
   * any h (Bazant and Oh's crack band).
   *
   * <h3>Local stability</h3>
   * The softening branch of one point is stable under strain control only if
   * L_c < M u0 / tau_nf with M = n.C:(n(x)n).n (for isotropic C, M = lambda
   * + 2 mu whatever n). The constructor checks this with h_band and stops
   * with a message if it is violated.
   *
   * Selected in a .prm file with `set Model = decohesion` (subsection
   * "Material/decohesion").
   */
  template <int dim>
  class Decohesion : public ConstitutiveModel<dim>
  {
  public:
    std::string
    name() const override
    {
      return "decohesion";
    }

    /**
     * @p fixed_normal: the crack normal, or the zero tensor for the direction
     * of the largest principal stress at initiation.
     * @p band_width: h_band of the class documentation.
     */
    Decohesion(const double          young_modulus,
               const double          poisson_ratio,
               const bool            plane_stress,
               const double          tensile_strength,
               const double          fracture_energy,
               const Tensor<1, dim> &fixed_normal,
               const double          band_width);

    /**
     * What the crack does with the shear traction on its plane.
     */
    enum class ShearRetention
    {
      /// Carried elastically until complete failure, then released at once
      /// (the default; the results of the paper's runs).
      abrupt,
      /// A secant shear stiffness that falls linearly with the opening: the
      /// shear traction across the band is t_s = beta mu gamma_s,
      /// beta = max(0, 1 - [[u_n]]/u0), where gamma_s is the band's shear
      /// strain since initiation (Rots' shear retention factor). The
      /// traction goes to zero continuously at complete failure instead of
      /// jumping there. A completely failed crack then also closes without
      /// traction, down to the opening u0 (contact); with abrupt retention
      /// a crack that unloads keeps its opening, as in the paper.
      linear
    };

    /// The subsection "decohesion".
    struct Parameters : ParameterStruct<Parameters>
    {
      /// E, nu and plane stress as for linear elasticity.
      typename LinearElastic<dim>::Parameters elastic;
      double                                  tensile_strength = 1.;
      double                                  fracture_energy  = 1.;
      /// "principal" or a direction "1,0" ("1,0,0").
      std::string crack_normal     = "principal";
      double      crack_band_width = 0.;
      /// An expression in x, y (, z): cracking where it is > 0.5.
      std::string    cracking_region = "1";
      ShearRetention shear_retention = ShearRetention::abrupt;

      /// Declare the entries, bound to the members.
      void
      add_parameters(ParameterHandler &prm);
    };

    explicit Decohesion(const Parameters &parameters);

    /// Construct from the subsection "decohesion".
    explicit Decohesion(ParameterHandler &prm);

    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Cracking is allowed only at points created where @p region is true
     * (evaluated by initialize_state(), i.e. when the points are made).
     * Replaces the "Cracking region" expression of the parameter file.
     */
    void
    set_crack_region(const std::function<bool(const Point<dim> &)> &region);

    /**
     * Choose the shear retention (abrupt by default). With
     * ShearRetention::linear the points carry the crack's tangential slip
     * as one more state field ("crack_slip"); call this before points are
     * made.
     */
    void
    set_shear_retention(const ShearRetention retention);

    std::vector<StateField>
    state_fields() const override;

    void
    initialize_state(const Point<dim> &x,
                     ArrayView<double> state) const override;

    /**
     * For pictures of the crack (paper Fig. 4): the opening over the
     * critical opening, w / u0, and sigma_xx / tau_nf, sigma_yy / tau_nf.
     */
    std::vector<StateField>
    output_fields() const override;

    void
    compute_output_fields(const PointState<dim> &point,
                          ArrayView<double>      values) const override;

    /**
     * The closed-form return mapping. With the trial stress
     * sigma_tr = sigma^k + C : d_eps and tau_tr = n.sigma_tr.n, the opening
     * increment d_w >= 0 solves
     *
     *   tau_tr - (M / L_c) d_w = tau_nf max(0, 1 - (w^k + d_w) / u0)
     *
     * (a piecewise linear, decreasing function of d_w when the point is
     * locally stable), and sigma = sigma_tr - (d_w / L_c) C:(n(x)n).
     */
    void
    update_stress(const PointState<dim>         &old,
                  const SymmetricTensor<2, dim> &strain_increment,
                  SymmetricTensor<2, dim>       &stress,
                  ArrayView<double>              new_state) const override;

    /**
     * The work of the crack traction over the opening increment per unit
     * volume, (1 / L_c) int tau_nf max(0, 1 - w / u0) dw from the committed
     * to the trial opening: G_f / L_c once a point has failed completely.
     */
    double
    dissipation(const PointState<dim>  &old,
                ArrayView<const double> new_state) const override;

    bool
    computes_dissipation() const override
    {
      return true;
    }

    /**
     * For preconditioning: the elastic stiffness C, with the secant normal
     * stiffness k across a softening crack, C - (1 - k/M) C:nn (x) nn:C / M,
     * k / M = tau_n / (tau_n + M w / L_c), tau_n = tau_nf (1 - w/u0), and no
     * normal stiffness across a completely failed one (k = 0).
     */
    SymmetricTensor<4, dim>
    tangent(const PointState<dim> &old) const override;

    /**
     * tangent() with the slope of the softening line instead of the secant
     * across a softening crack whose committed normal stress is on that
     * line (it opened in the last step, and is taken to keep opening):
     * k / M = -a / (M - a), a = L_c tau_nf / u0. A crack below the line has
     * unloaded and keeps the secant. For a preconditioner that factors the
     * matrix.
     */
    SymmetricTensor<4, dim>
    loading_tangent(const PointState<dim> &old) const override;

    /// u0 = 2 G_f / tau_nf: the opening at complete failure.
    double
    critical_opening() const;

    /// tau_nf.
    double
    tensile_strength() const;

    /// The smearing length L_c for the crack normal @p n.
    double
    smearing_length(const Tensor<1, dim> &n) const;

    /// M u0 / tau_nf: L_c must stay below this.
    double
    stability_limit() const;

    /// The elastic stiffness C.
    const SymmetricTensor<4, dim> &
    stiffness() const;

    /// Names of the model's state fields (see state_fields()).
    static constexpr const char *crack_allowed_name = "crack_allowed";
    static constexpr const char *crack_normal_name  = "crack_normal";
    static constexpr const char *crack_opening_name = "crack_opening";
    static constexpr const char *crack_slip_name    = "crack_slip";
    /// Names of the model's output fields (see output_fields()).
    static constexpr const char *opening_ratio_name  = "opening_over_u0";
    static constexpr const char *sigma_xx_ratio_name = "sigma_xx_over_tau_nf";
    static constexpr const char *sigma_yy_ratio_name = "sigma_yy_over_tau_nf";

  private:
    /// tangent() (@p loading false) or loading_tangent() (true).
    SymmetricTensor<4, dim>
    crack_tangent(const PointState<dim> &old, const bool loading) const;

    /// The crack normal for the trial stress @p sigma_trial of an uncracked
    /// point, or the zero tensor if the Rankine criterion is not met.
    Tensor<1, dim>
    initiation_normal(const SymmetricTensor<2, dim> &sigma_trial) const;

    const SymmetricTensor<4, dim> C;
    const double                  tau_nf;
    const double                  G_f;
    const double                  u0;
    const Tensor<1, dim>          fixed_normal;
    const double                  band_width;
    /// M = n.C:(n(x)n).n, the same for every n (isotropic C).
    const double M;
    /// The shear modulus C_xyxy.
    const double                            mu;
    std::function<bool(const Point<dim> &)> crack_region;

    ShearRetention shear_retention = ShearRetention::abrupt;

    /// Offsets of the fields within the model's state (from state_fields();
    /// slip_offset only with linear shear retention).
    unsigned int allowed_offset, normal_offset, opening_offset,
      slip_offset = numbers::invalid_unsigned_int;

    /// Recompute the offsets from state_fields().
    void
    compute_offsets();
  };
} // namespace qsmpm

#endif
