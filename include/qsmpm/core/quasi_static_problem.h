#ifndef qsmpm_core_quasi_static_problem_h
#define qsmpm_core_quasi_static_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <functional>
#include <memory>
#include <qsmpm/assembly/quasi_static_residual.h>
#include <qsmpm/assembly/tangent_assembler.h>
#include <qsmpm/core/step_operator.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/io/output_writer.h>
#include <qsmpm/io/probe_writer.h>
#include <qsmpm/loading/boundary_descriptor.h>
#include <qsmpm/loading/displacement_constraints.h>
#include <qsmpm/loading/equilibrium_audit.h>
#include <qsmpm/loading/external_force_assembler.h>
#include <qsmpm/loading/load_stepper.h>
#include <qsmpm/loading/opening_gauge.h>
#include <qsmpm/loading/step_constraints.h>
#include <qsmpm/materials/constitutive_model.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>
#include <qsmpm/solvers/newton_krylov.h>
#include <qsmpm/solvers/preconditioner.h>
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
      typename BackgroundGrid<dim>::Parameters   geometry;
      typename MaterialPointSet<dim>::Parameters material_points;
      LoadStepper::Parameters                    load_stepping;
      NewtonParameters                           nonlinear_solver;
      typename EquilibriumAudit<dim>::Parameters equilibrium_check;
      typename OutputWriter<dim>::Parameters     output;

      /// Declare every subsection, including "Material" and "Boundary
      /// conditions" with all registered models.
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /// What happened in one accepted load step.
    struct StepReport
    {
      unsigned int step;
      double       load_factor;
      unsigned int cut_backs;
      NewtonReport newton;
      double       wall_time;
    };

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

    /// Choose the constitutive model; creates the (empty) point set.
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

    /// Progress and summary printing (rank 0); silence with set_condition().
    ConditionalOStream &
    pcout();

    TimerOutput &
    timer();

  private:
    void
    setup_step_data();

    /// The degrees of freedom without enough material (no equation).
    IndexSet
    inactive_dofs() const;

    /**
     * The degrees of freedom whose stiffness against their own motion (the
     * diagonal of the tangent, TangentAssembler::assemble_diagonal()) is at
     * most <Material points/Minimum nodal stiffness> times the mean over
     * the dofs: held fixed in the step.
     */
    IndexSet
    dofs_without_stiffness() const;

    /**
     * The closed constraints of the step t_old -> t_new: those of the
     * displacement conditions (and periodicity), checked against the
     * material, and zero increments on the nodes without enough material.
     */
    void
    make_step_constraints(const double               t_old,
                          const double               t_new,
                          AffineConstraints<double> &constraints);

    /// Shape functions, constraints of t_old -> t_new, loads and the
    /// preconditioner of a step.
    void
    prepare_step(const double t_old, const double t_new);

    /// Count a step of the current preconditioner; mark it for a rebuild
    /// after a failure (including a step check_volume_ratios() rejected)
    /// or when GMRES slowed down (reuse growth).
    void
    count_preconditioner_use(const NewtonReport &report);

    /// Reject a converged step that turned a point inside out. If
    /// @p last_evaluation_at_du, the solver's last residual evaluation was
    /// at du (NewtonKrylov guarantees it), and its volume ratios serve.
    void
    check_volume_ratios(const StepOperator<dim> &op,
                        NewtonReport            &report,
                        const bool               last_evaluation_at_du);

    /**
     * The force balance of the converged step to @p t_new (before it is
     * committed): recorded for reactions.csv, and a step that lost more
     * load than Equilibrium check/Lost load tolerance stops the run (or
     * warns once).
     */
    void
    audit_equilibrium(const double t_new);

    /// Commit du: point state, positions.
    void
    commit_step();

    /**
     * One attempt at the next load step of run(), with its progress line
     * and output; false if the step callback asked to stop.
     */
    bool
    take_step(LoadStepper                    &stepper,
              OutputWriter<dim>              &writer,
              ProbeWriter<dim>               &probes,
              const std::vector<std::string> &names);

    /**
     * After an error in run(): write the fields of the last accepted step
     * if they have not been written and the points still hold it, and
     * return a sentence that names that step and where it is.
     */
    std::string
    write_last_converged_state(OutputWriter<dim> &writer);

    /// Whether path following has checked that the prescribed
    /// displacements are proportional to the load factor.
    bool proportionality_checked = false;
    /// With Control = opening: the gauge (made by run()).
    std::unique_ptr<OpeningGauge<dim>> gauge;

    MPI_Comm                                  communicator;
    ConditionalOStream                        progress;
    TimerOutput                               timer_output;
    Parameters                                prm_values;
    BackgroundGrid<dim>                       background_grid;
    std::unique_ptr<ConstitutiveModel<dim>>   model;
    std::unique_ptr<MaterialPointSet<dim>>    material_points;
    BoundaryDescriptor<dim>                   bcs;
    DisplacementConstraints<dim>              displacement_constraints;
    ExternalForceAssembler<dim>               external_force;
    EquilibriumAudit<dim>                     audit;
    typename EquilibriumAudit<dim>::Result    last_audit;
    /// The largest scale of the loads of the steps so far (see
    /// EquilibriumAudit::evaluate()).
    double load_scale = 0.;
    bool   lost_load_warned = false;
    /// Whether return_large_blocks_to_system() was called.
    bool manage_heap = false;
    /// The degrees of freedom of the step held for lack of material or
    /// stiffness.
    IndexSet held_dofs;
    /// Whether the points hold the state of the last accepted step (false
    /// while commit_step() works), its step and load factor, and the last
    /// step whose fields were written.
    bool         points_consistent  = true;
    unsigned int last_step          = 0;
    double       last_load_factor   = 0.;
    int          last_written_step  = -1;
    ShapeCache<dim>                           cache;
    std::unique_ptr<QuasiStaticResidual<dim>> residual;
    TangentAssembler<dim>                     tangent;
    Preconditioner<dim>                       preconditioner;
    /// Load steps the preconditioner has served (0: build one before the
    /// next step), and its GMRES iterations per Newton iteration in the
    /// first of them (see Nonlinear solver/Preconditioner reuse steps).
    unsigned int preconditioner_age    = 0;
    double       preconditioner_rate   = 0.;
    unsigned int preconditioner_builds = 0;
    /// Whether the last prepare_step() kept an earlier preconditioner.
    bool            preconditioner_reused = false;
    StepConstraints step_constraints;
    VectorType      du;
    /// With Initial guess = extrapolation: the increments of the last
    /// converged load step and its load-factor increment (0: none, the
    /// next step starts from the linear predictor).
    VectorType                              last_increment;
    double                                  last_load_increment = 0.;
    VectorType                              R;
    VectorType                              f_ext;
    std::vector<Tensor<1, dim>>             last_reactions;
    std::vector<StepReport>                 reports;
    std::function<bool(const StepReport &)> step_callback;

    // Checkpoints: what resume() read, for run(), and the caller's state.
    void
    write_checkpoint(const LoadStepper       &stepper,
                     const OutputWriter<dim> &writer);
    void
    restore_run_state(LoadStepper &stepper, OutputWriter<dim> &writer);

    bool                                     resumed      = false;
    unsigned int                             resumed_step = 0;
    std::string                              resume_state;
    std::function<std::string()>             save_user_state;
    std::function<void(const std::string &)> restore_user_state;
  };
} // namespace qsmpm

#endif
