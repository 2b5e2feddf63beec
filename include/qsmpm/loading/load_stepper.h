#ifndef qsmpm_loading_load_stepper_h
#define qsmpm_loading_load_stepper_h

#include <deal.II/base/parameter_handler.h>
#include <iosfwd>
#include <qsmpm/base/parameter_struct.h>
#include <string>

namespace qsmpm
{
  using namespace dealii;

  /**
   * The sequence of load factors t_0 = 0 < t_1 < ... < t_K = final of a
   * quasi-static run (paper Section 2.3), with cut-back: a step whose Newton
   * solve fails is retried with a smaller increment, a bounded number of
   * times in a row; after that the run stops with an error. Once a step
   * converges, the next step tries the nominal increment again.
   *
   * Optionally (growth factor g > 1; off by default) the increment grows
   * geometrically once the load factor has passed a given value: after
   * each accepted step that ends at |t| >= "Growth from load factor", the
   * next increment is g times the one just taken (at least the nominal
   * one, at most "Maximum increment"). This is meant for long tails of a
   * response that hardly changes any more, e.g. the last stage of a
   * fracture test, where the nominal increment would need thousands of
   * steps. A cut-back in that stage lowers the increment, which then grows
   * again from the lowered value (but restarts at no less than the nominal
   * increment).
   *
   * With <tt>Control = dissipation</tt> the load factor of a step is not
   * prescribed but an unknown of the step (path following, see
   * PathFollowingNewton): each step dissipates a prescribed energy
   * "Dissipation increment" (Gutierrez 2004; Verhoosel, Remmers and
   * Gutierrez 2009), and the load factor may decrease, so that snap-backs
   * are traced. A step that would need a load-factor increment larger than
   * "Maximum increment" (or, if that is 0, the nominal increment) to
   * dissipate that energy, e.g. an elastic one, takes that increment under
   * displacement control instead. The stepper then hands out the target
   * dissipation and the largest increment, both cut back by a failed
   * attempt, and accept(t, force) records where the step ended.
   *
   * <tt>Control = opening</tt> is path following as well, with a linear
   * constraint instead: each step opens a gauge between two material
   * points ("Opening gauge", e.g. across the mouth of a notch) by "Opening
   * increment" (crack-mouth opening displacement control, the way
   * softening fracture tests are run in the laboratory). The opening grows
   * monotonically also where the load-point displacement snaps back.
   */
  class LoadStepper
  {
  public:
    /**
     * The subsection "Load stepping" of a .prm file.
     */
    struct Parameters : ParameterStruct<Parameters>
    {
      unsigned int n_steps           = 1;
      double       final_load_factor = 1.;
      unsigned int max_cut_backs     = 4;
      double       cut_back_factor   = 0.5;
      /// g: increment growth per accepted step; 1 = off.
      double growth_factor = 1.;
      /// |t| from which the increment grows.
      double growth_start = 0.;
      /// Largest |increment| when growing; 0 = no limit. With dissipation
      /// control: largest increment of a step, 0 = the nominal one.
      double max_increment = 0.;
      /// "displacement" (the paper's), "dissipation" or "opening" (path
      /// following).
      std::string control = "displacement";
      /// Energy dissipated per step with dissipation control.
      double dissipation_increment = 0.;
      /// Opening of the gauge per step with opening control.
      double opening_increment = 0.;
      /// With opening control: the gauge, "x_a; x_b" (see OpeningGauge).
      std::string opening_gauge = "";

      /// Declare the entries, bound to the members.
      void
      add_parameters(ParameterHandler &prm);
    };

    /// How the load factor of a step is found (the entry Control).
    enum class Control
    {
      /// Prescribed (the paper's method).
      displacement,
      /// An unknown: the step dissipates a given energy.
      dissipation,
      /// An unknown: the step opens a gauge by a given length.
      opening
    };

    /// The Control of the text of the entry ("displacement",
    /// "dissipation" or "opening"); throws for any other.
    static Control
    parse_control(const std::string &name);

    /// The text of the entry Control for @p control.
    static std::string
    to_string(const Control control);

    explicit LoadStepper(const Parameters &parameters);

    /// The parameters the stepper was made with.
    const Parameters &
    get_parameters() const;

    /// Whether the final load factor has been reached.
    bool
    finished() const;

    /// Load factor of the last accepted step.
    double
    current() const;

    /// Load factor the next attempt goes to.
    double
    target() const;

    /// Number of accepted steps.
    unsigned int
    step() const;

    /// The attempt converged: advance.
    void
    accept();

    /**
     * The attempt failed: cut the increment back. Throws, naming @p reason,
     * when the allowed number of cut-backs in a row is exhausted.
     */
    void
    reject(const std::string &reason);

    /// Whether the load factor is an unknown of each step (Control =
    /// dissipation or opening).
    bool
    path_following() const;

    /// The entry Control.
    Control
    control() const;

    /// With path following: what the next attempt must dissipate (Control
    /// = dissipation) or open the gauge by (Control = opening).
    double
    constraint_target() const;

    /// With path following: the largest load-factor increment of the next
    /// attempt.
    double
    increment_limit() const;

    /**
     * With path following: the largest decrease of the load factor in one
     * step, ten times the uncut increment limit. It is not cut back with
     * the target: a snap-back needs the same step back however small
     * the energy (or opening) of the step.
     */
    double
    backward_limit() const;

    /**
     * With path following: whether the last accepted step decreased the
     * load factor (a step back on a snap-back). A forward step at the
     * limit would then leave the path (reload the softening zone
     * elastically instead of finishing the snap-back), so it is allowed
     * only as the last of the cut-backs: allow_limit().
     */
    bool
    allow_limit() const;

    /**
     * With path following: the generalized force (the work-conjugate of
     * the load factor) at the load factor of the last accepted step.
     */
    double
    force() const;

    /**
     * With path following: the generalized force of largest magnitude of
     * the accepted steps so far (the peak load), with its sign.
     */
    double
    peak_force() const;

    /// With path following: the attempt converged and ended at load factor
    /// @p t_new with generalized force @p force_new.
    void
    accept(const double t_new, const double force_new);

    /// Cut-backs of the current step so far.
    unsigned int
    n_cut_backs() const;

    /**
     * Write the state between two steps (load factor, increment, number of
     * accepted steps; with path following the force, whether the last
     * step went back and the peak force) to @p out, in full precision, for a
     * checkpoint.
     */
    void
    save(std::ostream &out) const;

    /// Read what save() wrote: the next step continues from there.
    void
    load(std::istream &in);

  private:
    /// With path following: the largest increment without cut-backs.
    double
    increment_cap() const;

    const Parameters parameters;
    /// The entry Control, parsed.
    Control      control_type = Control::displacement;
    const double nominal_increment;
    double       t         = 0.;
    double       increment = 0.;
    unsigned int n_steps   = 0;
    unsigned int cut_backs = 0;
    /// Path following: the nominal and the cut-back target of a step's
    /// constraint (dissipation or opening), and the force.
    double nominal_target = 0.;
    double target_value   = 0.;
    double F              = 0.;
    /// Path following: the last accepted step decreased the load factor.
    bool went_back = false;
    /// Path following: the force of largest magnitude so far.
    double F_peak = 0.;
  };
} // namespace qsmpm

#endif
