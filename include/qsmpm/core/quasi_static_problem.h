#ifndef qsmpm_core_quasi_static_problem_h
#define qsmpm_core_quasi_static_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <functional>
#include <memory>
#include <qsmpm/assembly/ghost_penalty.h>
#include <qsmpm/assembly/null_mode_hold.h>
#include <qsmpm/assembly/quasi_static_residual.h>
#include <qsmpm/assembly/tangent_assembler.h>
#include <qsmpm/core/path_following_setup.h>
#include <qsmpm/core/preconditioner_handover.h>
#include <qsmpm/core/step_constraint_maker.h>
#include <qsmpm/core/step_operator.h>
#include <qsmpm/core/step_report.h>
#include <qsmpm/fracture/crack_tracking.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/io/output_writer.h>
#include <qsmpm/io/probe_writer.h>
#include <qsmpm/io/run_state.h>
#include <qsmpm/loading/body_contact.h>
#include <qsmpm/loading/boundary_descriptor.h>
#include <qsmpm/loading/displacement_constraints.h>
#include <qsmpm/loading/equilibrium_audit.h>
#include <qsmpm/loading/external_force_assembler.h>
#include <qsmpm/loading/load_stepper.h>
#include <qsmpm/loading/rigid_contact.h>
#include <qsmpm/loading/rigid_plates.h>
#include <qsmpm/loading/step_constraints.h>
#include <qsmpm/loading/surface_tractions.h>
#include <qsmpm/materials/constitutive_model.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>
#include <qsmpm/porous/pore_pressure_solver.h>
#include <qsmpm/solvers/newton_krylov.h>
#include <qsmpm/solvers/preconditioner.h>
#include <qsmpm/solvers/preconditioner_reuse.h>
#include <string>
#include <utility>
#include <vector>

namespace qsmpm
{
  /**
   * A quasi-static MPM simulation: the background grid, the material points
   * with their constitutive model, boundary conditions and loads, and the
   * load-step cycle of paper Section 2.3:
   *
   *   for each load step t_k -> t_{k+1}:
   *     shape functions at the points, once (ShapeCache);
   *     constraints: displacement increments, nodes without points;
   *     f_ext(t_{k+1});
   *     solve R(du) = 0 with Jacobian-free Newton-Krylov;
   *     if converged: commit point state, move points, re-sort them
   *     (the grid is thereby reset); else cut the increment back.
   *
   * It can be set up from a .prm file (initialize()) or piece by piece from
   * C++ (grid(), set_model(), points(), boundary_conditions(),
   * parameters()).
   *
   * run() is a loop over load steps, each a call of take_step(): an attempt
   * (advance(), or advance_path_following() with Load stepping/Control =
   * dissipation or opening), then either reject_step() (a cut-back) or the
   * progress line, write_step_output() and a checkpoint. Its parts live in
   * classes of their own: the step's constraints (StepConstraintMaker), the
   * reuse of preconditioners (PreconditionerReuse), path following
   * (PathFollowingSetup) and the state of the run that checkpoints keep
   * (RunState).
   */
  template <int dim>
  class QuasiStaticProblem
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    /**
     * All parameters of a .prm file.
     */
    struct Parameters
    {
      typename BackgroundGrid<dim>::Parameters     geometry;
      typename MaterialPointSet<dim>::Parameters   material_points;
      LoadStepper::Parameters                      load_stepping;
      NewtonParameters                             nonlinear_solver;
      typename EquilibriumAudit<dim>::Parameters   equilibrium_check;
      typename OutputWriter<dim>::Parameters       output;
      typename PorePressureSolver<dim>::Parameters pore_fluid;
      typename BodyContact<dim>::Parameters        body_contact;

      /// Declare every subsection, including "Material" and "Boundary
      /// conditions" with all registered models.
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /// What happened in one accepted load step.
    using StepReport = qsmpm::StepReport;

    explicit QuasiStaticProblem(const MPI_Comm communicator);
    ~QuasiStaticProblem();

    /**
     * Opt in to the memory policy of qsmpm's programs (the driver, the
     * examples and the benchmarks call it right after construction). It
     * changes the C library's allocator for the whole process, which is
     * why the library does not do it by itself: from now on every block
     * of 128 KiB or more comes from mmap and goes back to the system when
     * freed, and once the degrees of freedom are known (the first load
     * step) only blocks of more than one and a half vectors of the grid's
     * dofs do, while the vectors that the Krylov solver and the
     * preconditioner allocate in every iteration stay on the heap. Without
     * it the large temporaries of an AMG set-up and of the sorting of the
     * points stay resident for the rest of the run (see
     * Utils::return_large_blocks_to_system()).
     */
    void
    return_large_blocks_to_system();

    /**
     * Set up everything from a parsed ParameterHandler (declared with
     * Parameters::declare_parameters): grid, model, points, loads.
     */
    void
    initialize(ParameterHandler &prm);

    /// The background grid (call make_box() before adding points).
    BackgroundGrid<dim> &
    grid();

    /**
     * Bodies that touch each other (BodyContact): one displacement field
     * per body on the grid. From C++, call it before grid().make_box();
     * initialize() calls it with the subsection "Contact between bodies".
     */
    void
    set_body_contact(const typename BodyContact<dim>::Parameters &parameters);

    /// Choose the constitutive model; creates the (empty) point set, whose
    /// points carry an area for each surface traction given so far.
    void
    set_model(std::unique_ptr<ConstitutiveModel<dim>> model);

    /// The material points (after set_model()).
    MaterialPointSet<dim> &
    points();
    const MaterialPointSet<dim> &
    points() const;

    /// The boundary conditions and loads, as a description that every
    /// load step reads.
    BoundaryDescriptor<dim> &
    boundary_conditions();

    /// Solver, stepping and output settings, read when run() starts.
    Parameters &
    parameters();

    /// Run all load steps, writing output and progress.
    void
    run();

    /**
     * Continue from the newest complete checkpoint in the output directory
     * (written by a run with <tt>Output/Checkpoint interval</tt> > 0),
     * possibly on another number of MPI ranks. Set the problem up exactly
     * as for a fresh run (initialize(), or the pieces; the points are then
     * replaced by those of the checkpoint), call this, then run(): the run
     * continues after the checkpoint's step and writes the same output as
     * an uninterrupted one. Throws with a message if there is no checkpoint
     * or it belongs to another grid or body. Returns the checkpoint's
     * step.
     */
    unsigned int
    resume();

    /**
     * Include a caller's own state between steps in checkpoints (e.g. what
     * a step callback accumulates): @p save is called on rank 0 when a
     * checkpoint is written, @p restore on all ranks by run() after
     * resume(), with the text that @p save returned.
     */
    void
    set_checkpoint_state(
      const std::function<std::string()>             &save,
      const std::function<void(const std::string &)> &restore);

    /**
     * One attempt at the step t_old -> t_new. If Newton converges, commit it
     * and return true; otherwise leave every point untouched and return
     * false. @p report receives the Newton statistics.
     */
    bool
    advance(const double t_old, const double t_new, NewtonReport &report);

    /**
     * One attempt at a step of path following (Load stepping/Control =
     * dissipation or opening) from the load factor of @p stepper: the load
     * factor is an unknown, and the step dissipates, or opens the gauge by,
     * stepper.constraint_target(), or, if that needs a larger increment
     * and stepper.allow_limit(), goes to the increment_limit() (see
     * PathFollowingNewton); it may go back by at most backward_limit(), and
     * its load must keep the sign of peak_force() (up to 1e-3 of it). If
     * Newton converges, commit it, set @p t_new and @p force_new (the
     * generalized force, the work-conjugate of the load factor) and return
     * true; otherwise leave every point untouched and return false.
     */
    bool
    advance_path_following(const LoadStepper &stepper,
                           NewtonReport      &report,
                           double            &t_new,
                           double            &force_new);

    /**
     * After a converged solve with contact between bodies: whether the
     * contact set changed (bodies that pull on each other come apart,
     * bodies that would overlap touch), so that the step must be solved
     * again with the new one (#keep_contact_set is then true). If it
     * changed in <Max contact iterations> solves in a row, @p report is
     * marked as not converged instead, and false returned.
     */
    bool
    contact_set_changed(NewtonReport &report);

    /// Reports of the accepted steps of run().
    const std::vector<StepReport> &
    step_reports() const;

    /**
     * A function that run() calls after every accepted step (before that
     * step's output) with the step's report. If it returns false, run()
     * writes the fields of that step (if output is enabled) and stops, e.g.
     * once the load has fallen below a fraction of its peak.
     */
    void
    set_step_callback(const std::function<bool(const StepReport &)> &callback);

    /// How many times the preconditioner has been built in this run (once
    /// per load step unless Nonlinear solver/Preconditioner reuse steps > 1).
    unsigned int
    n_preconditioner_builds() const;

    /// Reaction forces of the last accepted step, per displacement condition.
    const std::vector<Tensor<1, dim>> &
    reactions() const;

    /// The displacement of each rigid plate along its normal so far
    /// (BoundaryDescriptor::add_rigid_plate(), in that order).
    const std::vector<double> &
    rigid_plate_displacements() const
    {
      return run_state.plate_displacements;
    }

    /// The displacement of each rigid body along its load direction so
    /// far (the bodies driven by a force, RigidBody::load_direction; 0
    /// for the others; add_rigid_body() order).
    const std::vector<double> &
    rigid_body_load_displacements() const
    {
      return run_state.body_displacements;
    }

    /**
     * With a pore fluid, the average degree of consolidation after the
     * last accepted step, U = 1 - P / P_max: P = sum_p (p_p - p_initial)
     * Omega_p, the excess pore pressure integrated over the body, P_max
     * the largest |P| of the steps so far (the undrained response to the
     * load). The column consolidation_degree of reactions.csv; 0 without
     * a pore fluid or before any excess pressure.
     */
    double
    degree_of_consolidation() const
    {
      return degree_of_consolidation_value;
    }

    /// The material's force on each rigid body in the last accepted step,
    /// the number of points in contact and the deepest penetration.
    const std::vector<typename RigidContact<dim>::BodyLoad> &
    rigid_body_loads() const
    {
      return body_loads;
    }

    /**
     * The force balance of the last accepted step: applied load, reactions,
     * the force of the held nodes and the lost load (see EquilibriumAudit).
     */
    const typename EquilibriumAudit<dim>::Result &
    equilibrium() const;

    /// The last converged grid displacement increment.
    const VectorType &
    increment() const;

    /// The stiffness at the points of the last step (if a preconditioner
    /// needed it).
    const TrilinosWrappers::SparseMatrix &
    stiffness() const;

    /**
     * Give away the stiffness matrix and the preconditioner this problem
     * built last (null if it built none), for take_over_preconditioner()
     * of another problem. This problem cannot solve again afterwards.
     */
    std::unique_ptr<PreconditionerHandover<dim>>
    hand_over_preconditioner();

    /**
     * Let the first load step use @p handover, which another problem gave
     * away (hand_over_preconditioner()), instead of assembling the
     * stiffness and building a preconditioner: if it holds the same kind
     * of preconditioner for the same degrees of freedom and was built for
     * the same constrained ones (compared as PreconditionerReuse compares
     * them). Otherwise it is freed before the step builds its own. Call
     * before the first step.
     *
     * The caller vouches for the rest: the same grid, and points at the
     * same places with the same state as those the other problem built
     * from, as the load cases of one sample have (VirtualTests). A
     * preconditioner changes the GMRES iterations a step needs, not its
     * answer: GMRES multiplies with the Jacobian of the residual itself,
     * and Newton's stopping test is on the residual.
     */
    void
    take_over_preconditioner(
      std::unique_ptr<PreconditionerHandover<dim>> handover);

    /// Progress and summary printing (rank 0); silence with set_condition().
    ConditionalOStream &
    pcout();

    TimerOutput &
    timer();

  private:
    /**
     * The index among the surface tractions of the condition without load
     * that marks the faces of Pore fluid/Drained surface region (added to
     * the boundary conditions on the first call).
     */
    unsigned int
    drained_surface_condition();

    /// Residual, preconditioner and vectors for the grid's degrees of
    /// freedom (made again after resume()).
    void
    setup_step_data();

    /// Shape functions, constraints of t_old -> t_new, loads and the
    /// preconditioner of a step.
    void
    prepare_step(const double t_old, const double t_new);

    /// The preconditioner's matrix (tangent) from the committed state, or
    /// with @p iterate at a Newton iterate, with F-bar's terms.
    void
    assemble_tangent(const IterateKinematics<dim> *iterate);

    /// The preconditioner of the stiffness at the Newton iterate
    /// @p du_iterate (Nonlinear solver/Preconditioner update = Newton
    /// iteration).
    void
    build_preconditioner_at(const VectorType &du_iterate);

    /// The rigid bodies driven by a force and the plates complete the
    /// preconditioner (@p new_preconditioner: it was just built).
    void
    complete_preconditioner(const bool new_preconditioner);

    /**
     * The force balance of the converged step to @p t_new (before it is
     * committed): recorded for reactions.csv, and a step that lost more
     * load than Equilibrium check/Lost load tolerance stops the run (or
     * warns once). The forces of a step that Newton (@p report) resolved
     * to that tolerance raise RunState::force_scale, and with it the
     * ceiling of Newton's later stopping tests (solver_parameters()).
     */
    void
    audit_equilibrium(const double t_new, const NewtonReport &report);

    /**
     * The fixed-stress iteration of a step with a pore fluid, after the
     * first displacement @p solve: flow and displacement in turn until the
     * pressure changes by less than Pore fluid/Coupling tolerance. Adds the
     * iterations to @p report; not converged if a solve fails or the
     * iteration does not converge.
     */
    void
    couple_pore_pressure(NewtonParameters &newton_parameters,
                         const std::function<void(NewtonReport &)> &solve,
                         NewtonReport                              &report);

    /**
     * A step with a pore fluid solved for the displacement and the
     * pressure at once (Pore fluid/Coupling = monolithic,
     * CoupledStepOperator): the first iterate's pressure is the flow
     * solve with the volume change of the initial guess du.
     */
    void
    solve_coupled(NewtonParameters &newton_parameters, NewtonReport &report);

    /// The displacement's nonlinear problem of the prepared step.
    StepOperator<dim>
    step_operator() const;

    /// With a pore fluid: the displacement solves stop at 1e-2 Coupling
    /// tolerance of the forces in the body; the residual floor is this
    /// factor times those forces.
    double
    coupling_floor_factor() const;

    /**
     * Set du to the extrapolated first iterate of a step of load-factor
     * increment @p dt from the last converged steps' increments (without
     * the prescribed increments, which the caller distributes).
     */
    void
    extrapolated_guess(const double dt);

    /// Commit du: point state, positions.
    void
    commit_step();

    /// The start of run(): restore a resumed run, print the header, write
    /// the initial fields and choose the probes.
    void
    start_run(LoadStepper       &stepper,
              OutputWriter<dim> &writer,
              ProbeWriter<dim>  &probes);

    /**
     * One attempt at the next load step of run(), with its progress line
     * and output; false if the step callback asked to stop.
     */
    bool
    take_step(LoadStepper       &stepper,
              OutputWriter<dim> &writer,
              ProbeWriter<dim>  &probes);

    /// After a failed attempt at t_old -> t_new: try again with a new
    /// preconditioner (once per increment, if the attempt kept one from an
    /// earlier solve; see also switch_to_direct()), or cut the increment
    /// back.
    void
    reject_step(LoadStepper        &stepper,
                const NewtonReport &newton,
                const double        t_old,
                const double        t_new);

    /**
     * Whether a step that failed with AMG is tried again with the direct
     * factorization (NewtonParameters::direct_retry): the preconditioner is
     * AMG and the problem has at most
     * NewtonParameters::direct_threshold_for() dofs. If so, the
     * preconditioner is replaced until the next accepted step (cut-backs of
     * the step included), after which AMG returns. At the knee of a rigid
     * footing's load curve on von Mises soil, Newton with AMG stalled in
     * steps where GMRES converged in every iteration as well as in steps
     * where it did not, and the direct factorization solved both kinds.
     */
    bool
    switch_to_direct();

    /// The preconditioner of the settings (Preconditioner, with auto
    /// decided by the number of dofs).
    std::unique_ptr<Preconditioner<dim>>
    make_preconditioner() const;

    /// reactions.csv, probes.csv and the fields of an accepted step to
    /// @p t_new (@p stop: the last step of the run).
    void
    write_step_output(const LoadStepper &stepper,
                      OutputWriter<dim> &writer,
                      ProbeWriter<dim>  &probes,
                      const double       t_new,
                      const bool         stop);

    /**
     * After an error in run(): write the fields of the last accepted step
     * if they have not been written and the points still hold it, and
     * return a sentence that names that step and where it is.
     */
    std::string
    write_last_converged_state(OutputWriter<dim> &writer);

    /// The parameters of subsection "Nonlinear solver" with their `auto`
    /// settings decided for the model (NewtonParameters::resolve()).
    NewtonParameters
    solver_parameters() const;

    MPI_Comm                                communicator;
    ConditionalOStream                      progress;
    TimerOutput                             timer_output;
    Parameters                              prm_values;
    BackgroundGrid<dim>                     background_grid;
    std::unique_ptr<ConstitutiveModel<dim>> model;
    /// With a pore fluid: the pressure on the grid (set_model() makes it).
    std::unique_ptr<PorePressureSolver<dim>> pore_pressure;
    /// With `Crack tracking` of the smeared-crack model (set_model()).
    std::unique_ptr<CrackTracking<dim>> crack_tracking;
    /// Fixed-stress iterations of the last step advance() took.
    unsigned int                           coupling_iterations = 0;
    std::unique_ptr<MaterialPointSet<dim>> material_points;
    BoundaryDescriptor<dim>                bcs;
    DisplacementConstraints<dim>           displacement_constraints;
    ExternalForceAssembler<dim>            external_force;
    SurfaceTractions<dim>                  surface_tractions;
    RigidContact<dim>                      rigid_contact;
    RigidPlates<dim>                       rigid_plates;
    /// Contact between the bodies of a multi-field grid.
    BodyContact<dim> body_contact;
    /// Solves of the current step with a changed contact set so far, and
    /// whether advance() solves the step again with the contact set of the
    /// last solve (instead of a new one from the points).
    unsigned int contact_iterations = 0;
    bool         keep_contact_set   = false;
    /// The material's force on each rigid body in the last accepted step.
    std::vector<typename RigidContact<dim>::BodyLoad> body_loads;
    /// degree_of_consolidation() of the last accepted step.
    double degree_of_consolidation_value = 0.;
    /// With a pore fluid: degree_of_consolidation() from the points'
    /// committed pressures (collective).
    void
    update_degree_of_consolidation();
    /// The names of the rigid bodies.
    std::vector<std::string>
    rigid_body_names() const;
    /// The rigid bodies' contact if there are any, else null.
    const RigidContact<dim> *
    contact_loads() const
    {
      return rigid_contact.empty() ? nullptr : &rigid_contact;
    }
    /// The rigid plates if there are any, else null.
    const RigidPlates<dim> *
    plates() const
    {
      return rigid_plates.empty() ? nullptr : &rigid_plates;
    }
    EquilibriumAudit<dim>                  audit;
    typename EquilibriumAudit<dim>::Result last_audit;
    bool                                   lost_load_warned = false;
    /// Whether return_large_blocks_to_system() was called.
    bool manage_heap = false;
    /// The degrees of freedom of the step held for lack of material or
    /// stiffness.
    IndexSet held_dofs;
    /// Whether the points hold the state of the last accepted step (false
    /// while commit_step() works), its step and load factor, and the last
    /// step whose fields were written.
    bool                                      points_consistent = true;
    unsigned int                              last_step         = 0;
    double                                    last_load_factor  = 0.;
    int                                       last_written_step = -1;
    ShapeCache<dim>                           cache;
    StepConstraintMaker<dim>                  constraint_maker;
    std::unique_ptr<QuasiStaticResidual<dim>> residual;
    /// The stiffness at the points (null once handed over).
    std::unique_ptr<TangentAssembler<dim>> tangent =
      std::make_unique<TangentAssembler<dim>>();
    /// The stiffness and preconditioner another problem handed over, until
    /// the first step takes or frees them (take_over_preconditioner()).
    std::unique_ptr<PreconditionerHandover<dim>> handover;
    GhostPenalty<dim>                            ghost_penalty;
    NullModeHold<dim>                            null_mode_hold;
    /// The ghost penalty if Material points/Ghost penalty > 0, else null.
    const GhostPenalty<dim> *
    stabilization() const
    {
      return prm_values.material_points.ghost_penalty > 0. ? &ghost_penalty :
                                                             nullptr;
    }
    /// The linear stabilizations of the step's residual: the ghost penalty
    /// and the springs of the null-mode hold, where they have terms.
    std::vector<const LocalStiffness *>
    stabilizations() const;
    /// The stiffness of the step's rigid bodies and plates for
    /// TangentAssembler, and with @p with_hold that of the null-mode hold.
    typename TangentAssembler<dim>::AdditionalTerm
    additional_stiffness(const bool with_hold) const;
    /// The surface tractions if a pressure acts in this step, else null.
    const SurfaceTractions<dim> *
    pressure_loads() const
    {
      return surface_tractions.has_pressure() ? &surface_tractions : nullptr;
    }
    std::unique_ptr<Preconditioner<dim>> preconditioner =
      std::make_unique<Preconditioner<dim>>();
    /// Whether #preconditioner is the direct factorization that replaced
    /// AMG for a step that failed with it (switch_to_direct()).
    bool direct_retry = false;
    /// Whether the current increment was already tried again with a new
    /// preconditioner (reject_step() does so once per increment).
    bool preconditioner_retried = false;
    /// The tangent #preconditioner was built from.
    typename TangentAssembler<dim>::Tangent preconditioner_tangent =
      TangentAssembler<dim>::Tangent::secant;
    /// Whether the current step failed with a preconditioner from the
    /// points' loading slopes and is tried with the secant (reject_step());
    /// cleared when a step is accepted.
    bool secant_retry = false;
    /// The points' kinematics at a Newton iterate
    /// (build_preconditioner_at()).
    IterateKinematics<dim>  iterate_kinematics;
    PreconditionerReuse     preconditioner_reuse;
    PathFollowingSetup<dim> path_following;
    StepConstraints         step_constraints;
    VectorType              du;
    /// With Initial guess = extrapolation: the increments of the last
    /// converged load step and its load-factor increment (0: none, the
    /// next step starts from the linear predictor).
    VectorType last_increment;
    double     last_load_increment = 0.;
    /// The same for the step before it (0: none, or not a step the last
    /// one followed from; extrapolated_guess()).
    VectorType second_last_increment;
    double     second_last_load_increment = 0.;
    VectorType R;
    VectorType f_ext;
    /// Reactions, load scale and step reports; checkpoints.
    RunState<dim> run_state;
    /// The names of the columns of reactions.csv.
    std::vector<std::string>                 condition_names;
    std::function<bool(const StepReport &)>  step_callback;
    std::function<std::string()>             save_user_state;
    std::function<void(const std::string &)> restore_user_state;
  };



  template <int dim>
  inline BackgroundGrid<dim> &
  QuasiStaticProblem<dim>::grid()
  {
    return background_grid;
  }



  template <int dim>
  inline MaterialPointSet<dim> &
  QuasiStaticProblem<dim>::points()
  {
    return const_cast<MaterialPointSet<dim> &>(std::as_const(*this).points());
  }



  template <int dim>
  inline const MaterialPointSet<dim> &
  QuasiStaticProblem<dim>::points() const
  {
    AssertThrow(material_points,
                ExcMessage("Choose a constitutive model (set_model) before "
                           "adding material points."));
    return *material_points;
  }



  template <int dim>
  inline BoundaryDescriptor<dim> &
  QuasiStaticProblem<dim>::boundary_conditions()
  {
    return bcs;
  }



  template <int dim>
  inline typename QuasiStaticProblem<dim>::Parameters &
  QuasiStaticProblem<dim>::parameters()
  {
    return prm_values;
  }



  template <int dim>
  inline void
  QuasiStaticProblem<dim>::set_checkpoint_state(
    const std::function<std::string()>             &save,
    const std::function<void(const std::string &)> &restore)
  {
    save_user_state    = save;
    restore_user_state = restore;
  }



  template <int dim>
  inline unsigned int
  QuasiStaticProblem<dim>::n_preconditioner_builds() const
  {
    return preconditioner_reuse.n_builds();
  }



  template <int dim>
  inline const std::vector<typename QuasiStaticProblem<dim>::StepReport> &
  QuasiStaticProblem<dim>::step_reports() const
  {
    return run_state.reports;
  }



  template <int dim>
  inline void
  QuasiStaticProblem<dim>::set_step_callback(
    const std::function<bool(const StepReport &)> &callback)
  {
    step_callback = callback;
  }



  template <int dim>
  inline const std::vector<Tensor<1, dim>> &
  QuasiStaticProblem<dim>::reactions() const
  {
    return run_state.reactions;
  }



  template <int dim>
  inline const typename QuasiStaticProblem<dim>::VectorType &
  QuasiStaticProblem<dim>::increment() const
  {
    return du;
  }



  template <int dim>
  inline const typename EquilibriumAudit<dim>::Result &
  QuasiStaticProblem<dim>::equilibrium() const
  {
    return last_audit;
  }



  template <int dim>
  inline const TrilinosWrappers::SparseMatrix &
  QuasiStaticProblem<dim>::stiffness() const
  {
    AssertThrow(tangent,
                ExcMessage("The stiffness was handed over to another "
                           "problem (hand_over_preconditioner())."));
    return tangent->matrix();
  }



  template <int dim>
  inline ConditionalOStream &
  QuasiStaticProblem<dim>::pcout()
  {
    return progress;
  }



  template <int dim>
  inline TimerOutput &
  QuasiStaticProblem<dim>::timer()
  {
    return timer_output;
  }
} // namespace qsmpm

#endif
