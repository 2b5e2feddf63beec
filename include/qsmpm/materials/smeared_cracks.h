#ifndef qsmpm_materials_smeared_cracks_h
#define qsmpm_materials_smeared_cracks_h

#include <array>
#include <deal.II/base/tensor.h>
#include <functional>
#include <qsmpm/materials/constitutive_model.h>
#include <qsmpm/materials/linear_elastic.h>

namespace qsmpm
{
  /**
   * Several smeared cracks per point, at any angle, mixed mode: the
   * elastic-decohesive idea of the paper (Section 3.2; Decohesion) without
   * its restrictions of Section 3.3 (one crack per point, its normal fixed
   * along x, cracking only where the crack is expected). Small strain.
   *
   * <h3>Kinematics</h3>
   * A point carries up to `Maximum cracks per point` (at most dim) cracks
   * k, each with a normal n_k fixed when it starts and a displacement jump
   * [[u]]_k (dim components: the opening w_k = [[u]]_k . n_k and the slip
   * s_k, the rest) smeared over the length L_k:
   *
   *   sigma = C : (eps - sum_k sym([[u]]_k (x) n_k) / L_k).
   *
   * Each crack's traction t_k = sigma n_k balances its cohesive law, for
   * all cracks at once: a local Newton method on the dim x (number of
   * cracks) jumps, with the exact Jacobian.
   *
   * <h3>The cohesive law</h3>
   * A damage variable per crack, the history delta* = max(delta, largest
   * delta so far) of a separation delta, and the traction
   *
   *   t = (T(delta*) / delta*) (<w> n + b s) + K_c min(w, 0) n,
   *
   * T(delta) = K_0 delta up to delta_e = tau_nf / K_0, then softening to
   * zero at delta_0, the area under T being G_f. `Softening` chooses the
   * branch:
   *  - linear (default): a straight line from (delta_e, tau_nf) to
   *    delta_0 = 2 G_f / tau_nf (the triangle with base delta_0 and height
   *    tau_nf).
   *  - bilinear: Petersson's law for concrete (Petersson 1981, the CEB-FIP
   *    Model Code 1990 shape): from (delta_e, tau_nf) to the kink
   *    (delta_k, tau_nf / 3), then to delta_0 = 3.6 G_f / tau_nf, with
   *    delta_k = 0.8 G_f / tau_nf + delta_e / 3 so that the area is G_f
   *    exactly (Petersson's 0.8 G_f / tau_nf for delta_e -> 0). The steep
   *    first branch and the long tail are what concrete shows; at the same
   *    G_f it gives lower peak loads than the linear law.
   *
   * `Mixed mode` chooses delta:
   *  - opening (default): delta = <w> (the positive part of the opening:
   *    a crack in contact does not soften) and b = 1: the shear traction
   *    is carried by the same secant stiffness, which falls with the
   *    opening to zero at complete failure (Rots' shear retention); slip
   *    alone does not damage the crack.
   *  - effective separation: delta = sqrt(<w>^2 + beta^2 |s|^2) and
   *    b = beta^2: slip damages as well (shear strength beta tau_nf,
   *    energy G_f in pure slip too). Measured in the notched plate in
   *    tension, Newton's method stalled at the peak with it, not with the
   *    default.
   * Unloading goes back to zero jump along the secant T(delta*) / delta*
   * (damage), so that a crack closes and opens again along the same line;
   * beyond closure the penalty K_c carries compression. K_0 = 100 M / L and
   * K_c = 1000 M / L (M = lambda + 2 mu) are stiff against the band; the
   * initial branch only regularizes the start of the crack (its energy is
   * part of the triangle).
   *
   * <h3>Integration of the damage</h3>
   * `Damage integration = implicit` (default) follows the law exactly
   * within each Newton iterate. `IMPL-EX` (Oliver, Huespe and Cante 2008)
   * fixes the history of a step at the committed one plus the last step's
   * increment, so that a step is linear in the jumps, and updates it from
   * the converged jumps: robust where many points sit on the kink between
   * loading and unloading (measured in a notched plate in tension: the
   * implicit runs stopped with Newton cycling at the peak, IMPL-EX ran
   * through), first order in the step size (the peak stress of a point
   * overshoots tau_nf by a few per cent while its damage catches up).
   *
   * <h3>Starting a crack</h3>
   * Where cracking is allowed, a crack starts when the largest principal
   * stress of the point (with its existing cracks; by default the
   * committed stress at the start of the step, `Crack initiation`)
   * reaches tau_nf, with its
   * normal along the principal direction, if the point has fewer than the
   * maximum number of cracks and that direction makes more than
   * `Threshold angle` with each existing normal; otherwise the existing
   * cracks take the load in mixed mode.
   *
   * <h3>The smearing length</h3>
   * The crack band is the band of cells that cracks (with n x n points per
   * cell and bilinear shape functions all points of a cell see the same
   * normal strain across the band; see Decohesion). A crack at an angle to
   * the grid opens a band of cells that share faces (cells that touch only
   * at corners cannot open apart: the grid bridges them), whose width
   * along n is the projection of a cell onto n, L = h sum_i |n_i| (Oliver
   * 1989): h along a cell edge, h sqrt 2 at 45 degrees in 2D. This is the
   * default `Smearing length = projection`; `mid-plane`, L = h max_i |n_i|
   * (the cell volume over its mid-plane normal to n, the Decohesion
   * model's length), counts the cells of a diagonal chain only. Measured
   * with a notched plate rotated against the grid (IMPL-EX): the work of
   * fracture over G_f times the ligament was 1.12 at 0 and 2.36 at 45
   * degrees with mid-plane, 1.06 and 1.21 with projection.
   *
   * The band's direction is that of the path, not of each point's normal:
   * near a crack's tip the principal directions of neighbouring points
   * differ by several degrees, and where the band runs along the grid's
   * lines, L = h sum_i |n_i| of a normal a few degrees off the band's
   * exceeds the band's width h for every such point, and the band
   * dissipates less than G_f per unit area (the notched plate along the
   * grid: L = 1.05 h on average over the band's points). With crack
   * tracking, the first crack of a point therefore takes L from the mean
   * normal of the cracks whose bands contain its cell (CrackTracking)
   * from the step after it started on (the notched plate: L = 1.03 h on
   * average; the first cracks at the notch start before there is a band);
   * the crack's own normal still carries its opening and its path.
   *
   * <h3>Dissipation</h3>
   * For the damage law the energy dissipated by a crack whose history
   * grows to delta* is D(delta*) = int_0^delta* T - T(delta*) delta* / 2
   * (the work minus what unloading along the secant gives back): 0 on the
   * initial branch, G_f at complete failure; per unit volume D / L_k.
   *
   * <h3>Failed points</h3>
   * A completely failed crack (delta* >= delta_0, open) is traction free on
   * its plane, but its point would still carry the stress along the crack,
   * which locks a band of cells that crosses the grid at an angle (the
   * grid stretches the broken points along the band as the halves
   * separate). With `Failed points = no tension` (default) such a point
   * breaks apart from the next step on: sigma = K <tr eps>_- I (K the bulk
   * modulus; a pressure only, so that closed cracks carry contact), and the
   * elastic energy it held is dissipated in that step. Measured in the
   * notched plate at 15 degrees to the grid: the work of fracture over G_f
   * times the ligament 1.065 instead of 1.93 (and still rising) with
   * `keep cracks`.
   *
   * <h3>Crack tracking</h3>
   * With `Crack tracking = true` a point may start its first crack only
   * where a crack path may run: away from existing cracks (further than
   * `Crack tracking radius` cell sizes from every crack path point), or
   * inside the band of cells that the path of a nearby crack crosses. The
   * decision is made for every point after each step (CrackTracking, which
   * the problem calls at commit) and stored in its `crack_allowed` field
   * (1: may start, -1: held back in this step, 0: outside the `Cracking
   * region` for good); the points of a crack keep their path point in the
   * field `crack_anchor` (a flag and dim coordinates). See CrackTracking for
   * the rule and why it is needed.
   *
   * Selected with `set Model = smeared cracks` (subsection
   * "Material/smeared cracks").
   */
  template <int dim>
  class SmearedCracks : public ConstitutiveModel<dim>
  {
  public:
    std::string
    name() const override
    {
      return "smeared cracks";
    }

    /// Which stress decides that a crack starts.
    enum class Initiation
    {
      /// The committed stress at the start of the step.
      step_start,
      /// The trial stress of each evaluation.
      trial_state
    };

    /// What drives the damage of a crack.
    enum class MixedMode
    {
      /// The normal opening <w>; shear traction q s.
      opening,
      /// The effective separation sqrt(<w>^2 + beta^2 |s|^2).
      effective_separation
    };

    /// The smearing length of a crack with normal n.
    enum class SmearingLength
    {
      /// h max_i |n_i|.
      mid_plane,
      /// h sum_i |n_i| (Oliver 1989).
      projection
    };

    /// How the damage history is integrated in a step.
    enum class DamageIntegration
    {
      /// From the trial jumps (exact).
      implicit,
      /// Extrapolated from the last step, fixed within the step.
      impl_ex
    };

    /// The shape of the softening branch of T.
    enum class Softening
    {
      /// A straight line to delta_0 = 2 G_f / tau_nf.
      linear,
      /// Petersson's bilinear law, delta_0 = 3.6 G_f / tau_nf.
      bilinear
    };

    enum class FailedPoints
    {
      /// A point goes on with its cracks.
      keep_cracks,
      /// A point with a completely failed, open crack carries no tension.
      no_tension
    };

    /// The subsection "smeared cracks".
    struct Parameters : ParameterStruct<Parameters>
    {
      typename LinearElastic<dim>::Parameters elastic;
      double                                  tensile_strength = 1.;
      double                                  fracture_energy  = 1.;
      double                                  crack_band_width = 0.;
      unsigned int                            max_cracks       = dim;
      double                                  threshold_angle  = 60.;
      double                                  shear_factor     = 1.;
      Initiation        initiation  = Initiation::step_start;
      MixedMode         mixed_mode  = MixedMode::opening;
      DamageIntegration integration = DamageIntegration::implicit;
      SmearingLength    smearing    = SmearingLength::projection;
      FailedPoints      failed      = FailedPoints::no_tension;
      Softening         softening   = Softening::linear;
      /// An expression in x, y (, z): cracking where it is > 0.5.
      std::string cracking_region = "1";
      /// Crack tracking (CrackTracking) and its radius in cell sizes.
      bool   crack_tracking  = false;
      double tracking_radius = 2.;
      /// With crack tracking: once a crack has dissipated this fraction of
      /// G_f, no new path starts away from the existing ones (0: off).
      double tracking_localization = 0.;
      /// The stress along the plane of a point's single crack fades with
      /// the crack's softening (`Crack-parallel softening`).
      bool parallel_softening = false;

      void
      add_parameters(ParameterHandler &prm);

      /// Check the values (stops with a message naming the entry).
      void
      check() const;
    };

    explicit SmearedCracks(const Parameters &parameters);

    /// Construct from the subsection "smeared cracks".
    explicit SmearedCracks(ParameterHandler &prm);

    static void
    declare_parameters(ParameterHandler &prm);

    /// Cracking only at points created where @p region is true.
    void
    set_crack_region(const std::function<bool(const Point<dim> &)> &region);

    std::vector<StateField>
    state_fields() const override;

    void
    initialize_state(const Point<dim> &x,
                     ArrayView<double> state) const override;

    /**
     * For pictures: the number of cracks, the largest delta* / delta_0
     * (1: a crack has failed completely) and the angle of the first
     * crack's normal to the x axis in degrees (0 without a crack).
     */
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

    /**
     * For preconditioning: the secant stiffness at the committed state,
     * every crack's cohesive law replaced by its secant T(delta*)/delta*
     * (K_0 for a crack that has not opened), condensed onto the strain.
     * Symmetric and positive semi-definite.
     */
    SymmetricTensor<4, dim>
    tangent(const PointState<dim> &old) const override;

    double
    dissipation(const PointState<dim>  &old,
                ArrayView<const double> new_state) const override;

    bool
    computes_dissipation() const override
    {
      return true;
    }

    /// delta_0: 2 G_f / tau_nf (linear) or 3.6 G_f / tau_nf (bilinear).
    double
    critical_separation() const;

    /// G_f.
    double
    fracture_energy() const;

    /// Whether the points' permission to crack follows crack tracking.
    bool
    tracks_cracks() const
    {
      return tracking;
    }

    /// The radius of crack tracking (`Crack tracking radius` times h).
    double
    tracking_radius() const
    {
      return tracking_radius_in_cells * band_width;
    }

    /// `Crack tracking localization`: the fraction of G_f that one crack
    /// must have dissipated before new paths may start only near existing
    /// ones (0: never).
    double
    tracking_localization() const
    {
      return localization;
    }

    /// L for the crack normal @p n.
    double
    smearing_length(const Tensor<1, dim> &n) const;

    /// The cohesive traction magnitude T(delta).
    double
    cohesive_traction(const double delta, const double L) const;

    /// D(delta*) of the class documentation, per unit crack area.
    double
    dissipated_energy(const double delta_star, const double L) const;

    /// A crack of a point, for post-processing: its normal, its smearing
    /// length and the energy it has dissipated per unit crack area (0 to
    /// G_f).
    struct CrackSummary
    {
      Tensor<1, dim> normal;
      double         length     = 0.;
      double         dissipated = 0.;
    };

    /**
     * The cracks of a point whose model fields are @p state (the
     * state_fields() in order): written to the first entries of @p cracks,
     * their number returned. Programs read a point's cracks through this
     * rather than through the layout of the fields.
     */
    unsigned int
    crack_summaries(ArrayView<const double>        state,
                    std::array<CrackSummary, dim> &cracks) const;

    /// The energy the cracks of a point with model fields @p state have
    /// dissipated per unit crack area, summed over its cracks, over G_f
    /// (0 before any crack, 1 for one crack that failed completely).
    double
    dissipated_over_fracture_energy(ArrayView<const double> state) const;

    /// Names of the state fields.
    static constexpr const char *allowed_name    = "crack_allowed";
    static constexpr const char *count_name      = "crack_count";
    static constexpr const char *normals_name    = "crack_normals";
    static constexpr const char *jumps_name      = "crack_jumps";
    static constexpr const char *separation_name = "crack_separation";
    static constexpr const char *separation_increment_name =
      "crack_separation_increment";
    static constexpr const char *failed_name      = "point_failed";
    static constexpr const char *anchor_name      = "crack_anchor";
    static constexpr const char *band_length_name = "crack_band_length";

  private:
    /// CrackTracking reads and writes the tracking fields of the state.
    template <int>
    friend class CrackTracking;

    /// The cracks of a point during a stress update.
    struct Cracks
    {
      unsigned int                    count = 0;
      std::array<Tensor<1, dim>, dim> normal;
      std::array<Tensor<1, dim>, dim> jump;
      std::array<double, dim>         history{};
      /// The history's increment in the last committed step (IMPL-EX).
      std::array<double, dim> increment{};
      std::array<double, dim> length{};
      /// Whether the secants use the extrapolated history of IMPL-EX
      /// (step_history()) rather than the implicit law.
      bool extrapolated = false;
    };

    /// K_0 = 100 M / L, the stiffness of a crack's initial branch.
    double
    initial_stiffness(const double L) const;

    /// K_c = 1000 M / L, the penalty of a crack in contact.
    double
    contact_stiffness(const double L) const;

    /// The secant T(delta*) / delta* (K_0 on the initial branch).
    double
    secant(const double delta_star, const double L) const;

    /// The corners of T after the initial branch, (delta, T): (delta_e,
    /// tau_nf), for the bilinear law the kink, and (delta_0, 0). Returns
    /// their number.
    unsigned int
    softening_corners(const double                          L,
                      std::array<std::array<double, 2>, 3> &corners) const;

    /// dT/d delta on the softening branch (delta_e < delta < delta_0).
    double
    softening_slope(const double delta, const double L) const;

    /// b of the traction: 1 (opening) or beta^2 (effective separation).
    double
    shear_weight() const;

    /// Read the cracks from a point's state.
    Cracks
    read(ArrayView<const double> state) const;

    /// The stress for the strain @p eps with the cracks' jumps.
    SymmetricTensor<2, dim>
    stress_of(const SymmetricTensor<2, dim> &eps, const Cracks &cracks) const;

    /**
     * The history delta* of crack @p k that the secant of a step uses: the
     * committed one, plus (IMPL-EX) the last step's increment, fixed within
     * the step. (With the implicit law a loading crack uses its trial
     * separation instead; see traction().)
     */
    double
    step_history(const Cracks &cracks, const unsigned int k) const;

    /**
     * `Crack-parallel softening`: for a point with one crack, remove the
     * fraction 1 - T(delta*) / tau_nf of the stress along the crack's
     * plane, P sigma P with P = I - n n (delta* the history the step's
     * secant uses: fixed within a step, so that @p sigma stays linear in
     * the jumps). The traction on the crack's plane, sigma n, is
     * unchanged. Does nothing otherwise.
     */
    void
    fade_parallel_stress(const Cracks            &cracks,
                         SymmetricTensor<2, dim> &sigma) const;

    /// The cohesive traction of crack @p k at @p jump, and its derivative.
    Tensor<1, dim>
    traction(const Cracks         &cracks,
             const unsigned int    k,
             const Tensor<1, dim> &jump,
             Tensor<2, dim>       *derivative) const;

    /// Solve for the jumps of all cracks at the strain @p eps (local
    /// Newton); returns false if it did not converge.
    bool
    solve_jumps(const SymmetricTensor<2, dim> &eps, Cracks &cracks) const;

    /// The index of the point_failed flag in a point's state: 0 intact or
    /// cracking, 1 a crack failed completely in the last step (the point
    /// carries no tension from the next step on), 2 failed.
    static constexpr unsigned int failed_index = 2 + 2 * dim * dim + 2 * dim;

    /// With crack tracking only: the index of the crack_anchor field, 1 once
    /// the point's crack path point is set, followed by its dim
    /// coordinates.
    static constexpr unsigned int anchor_index = failed_index + 1;

    /// With crack tracking only: the index of the crack_band_length field,
    /// the smearing length of the first crack from the direction of its
    /// band (0 until CrackTracking sets it; see "The smearing length").
    static constexpr unsigned int band_length_index = anchor_index + dim + 1;

    /// A failed point: only a pressure, sigma = K <tr eps>_- I with the bulk
    /// modulus K = lambda + 2 mu / dim (plane stress: the reduced lambda),
    /// from the total strain: no tension and no shear; with @p tangent, its
    /// derivative.
    SymmetricTensor<2, dim>
    no_tension_stress(const SymmetricTensor<2, dim> &eps,
                      SymmetricTensor<4, dim>       *tangent = nullptr) const;

    /// The energy K/2 <tr eps>_-^2 of a failed point.
    double
    no_tension_energy(const SymmetricTensor<2, dim> &eps) const;

    const SymmetricTensor<4, dim> C;
    const double                  tau_nf;
    const double                  G_f;
    const double                  delta_0;
    const double                  band_width;
    const unsigned int            max_cracks;
    const double                  cos_threshold;
    const double                  beta;
    const Initiation              initiation;
    const MixedMode               mixed_mode;
    const DamageIntegration       integration;
    const SmearingLength          smearing;
    const FailedPoints            failed_points;
    const Softening               softening;
    const bool                    tracking;
    const double                  tracking_radius_in_cells;
    const double                  localization;
    const bool                    parallel_softening;
    /// M = lambda + 2 mu.
    const double M;
    /// K = lambda + 2 mu / dim, the bulk modulus of C (plane stress: with
    /// the reduced lambda), which a failed point keeps in compression.
    const double bulk;
    /// The compliance C^-1.
    const SymmetricTensor<4, dim>           compliance;
    std::function<bool(const Point<dim> &)> crack_region;
  };
} // namespace qsmpm

#endif
