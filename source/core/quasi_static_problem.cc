#include <algorithm>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <iomanip>
#include <qsmpm/base/parsed_region.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/loading/parsed_boundary_conditions.h>
#include <qsmpm/porous/coupled_step_operator.h>
#include <sstream>
#include <utility>


namespace qsmpm
{
  template <int dim>
  void
  QuasiStaticProblem<dim>::Parameters::declare_parameters(ParameterHandler &prm)
  {
    BackgroundGrid<dim>::Parameters::declare_parameters(prm);
    MaterialPointSet<dim>::Parameters::declare_parameters(prm);
    ConstitutiveModelFactory<dim>::declare_parameters(prm);
    ParsedBoundaryConditions<dim>::Parameters::declare_parameters(prm);
    LoadStepper::Parameters::declare_parameters(prm);
    NewtonParameters::declare_parameters(prm);
    EquilibriumAudit<dim>::Parameters::declare_parameters(prm);
    OutputWriter<dim>::Parameters::declare_parameters(prm);
    PorePressureSolver<dim>::Parameters::declare_parameters(prm);
    BodyContact<dim>::Parameters::declare_parameters(prm);
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::Parameters::parse_parameters(ParameterHandler &prm)
  {
    geometry.parse_parameters(prm);
    material_points.parse_parameters(prm);
    load_stepping.parse_parameters(prm);
    nonlinear_solver.parse_parameters(prm);
    equilibrium_check.parse_parameters(prm);
    output.parse_parameters(prm);
    pore_fluid.parse_parameters(prm);
    body_contact.parse_parameters(prm);
  }



  template <int dim>
  QuasiStaticProblem<dim>::QuasiStaticProblem(const MPI_Comm communicator)
    : communicator(communicator)
    , progress(std::cout,
               dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
    // The timer measures rank 0's sections without MPI: with a communicator,
    // TimerOutput synchronizes every section and, when an error ends a run,
    // prints a six-line banner about skipping that before the message.
    , timer_output(MPI_COMM_SELF,
                   progress,
                   TimerOutput::never,
                   TimerOutput::wall_times)
    , background_grid(communicator)
    , displacement_constraints(bcs)
    , external_force(bcs)
    , surface_tractions(bcs)
    , rigid_contact(bcs)
    , rigid_plates(bcs)
    , constraint_maker(background_grid,
                       bcs,
                       displacement_constraints,
                       cache,
                       communicator)
  {
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::return_large_blocks_to_system()
  {
    // Until the degrees of freedom are known (setup_step_data()), every
    // block of 128 KiB or more comes from mmap: the grid and the points are
    // made once, and the blocks that the particle storage outgrows while it
    // is filled go back to the system instead of fragmenting the heap.
    manage_heap = true;
    Utils::return_large_blocks_to_system(0);
  }



  template <int dim>
  QuasiStaticProblem<dim>::~QuasiStaticProblem()
  {
    // Points refer to the model; destroy them first.
    residual.reset();
    material_points.reset();
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::set_body_contact(
    const typename BodyContact<dim>::Parameters &parameters)
  {
    prm_values.body_contact = parameters;
    body_contact.initialize(parameters);
    if (body_contact.enabled())
      {
        background_grid.set_n_bodies(body_contact.n_bodies());
        cache.set_bodies(body_contact.body_of_material());
      }
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::initialize(ParameterHandler &prm)
  {
    prm_values.parse_parameters(prm);
    set_body_contact(prm_values.body_contact);
    background_grid.make_box(prm_values.geometry);
    // The conditions first: the points carry the area of each surface
    // traction.
    ParsedBoundaryConditions<dim> parsed_conditions;
    parsed_conditions.parse_parameters(prm, bcs);
    set_model(ConstitutiveModelFactory<dim>::create(prm));
    material_points->fill(prm_values.material_points);
    AssertThrow(material_points->n_global_points() > 0,
                ExcMessage("Material points: the region holds no points."));

    // A load or a prescribed displacement that is NaN or infinite somewhere
    // (sqrt(-1), 1/x at x = 0) would only show as a residual that is not a
    // number, after every cut-back of the first step. Check the functions at
    // the vertices of each rank's cells, at most 10^4 of them per rank (a
    // few milliseconds of muParser), at the start and at the end of the
    // loading; all ranks stop together with the message of the first.
    std::string error;
    try
      {
        parsed_conditions.check_functions(
          background_grid.local_vertices(10000),
          {0., prm_values.load_stepping.final_load_factor});
      }
    catch (const std::exception &exc)
      {
        error = Utils::error_message(exc);
      }
    Utils::throw_if_any_rank(error, communicator);
  }



  template <int dim>
  unsigned int
  QuasiStaticProblem<dim>::drained_surface_condition()
  {
    // The points find the drained faces of the body's surface as those of
    // a surface traction (SurfaceTractions::mark()), one without load.
    const std::string region = prm_values.pore_fluid.drained_surface_region;
    const std::string name   = "Pore fluid/Drained surface region = " + region;
    const auto       &conditions = bcs.surface_tractions();
    for (unsigned int k = 0; k < conditions.size(); ++k)
      if (conditions[k].name == name)
        return k;
    bcs.add_surface_traction(
      name,
      parse_region<dim>(region,
                        "Pore fluid: <Drained surface region>",
                        "on the drained surface"),
      std::make_shared<Functions::ZeroFunction<dim>>(dim));
    return conditions.size() - 1;
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::set_model(
    std::unique_ptr<ConstitutiveModel<dim>> new_model)
  {
    residual.reset();
    material_points.reset();
    pore_pressure.reset();
    crack_tracking.reset();
    model = std::move(new_model);
    // Crack tracking edits the points' permissions between steps; it reads
    // the smeared-crack model's own fields.
    const auto *cracks = dynamic_cast<const SmearedCracks<dim> *>(model.get());
    if (cracks != nullptr && cracks->tracks_cracks())
      {
        AssertThrow(!prm_values.pore_fluid.enabled,
                    ExcMessage("smeared cracks: <Crack tracking> is not "
                               "available with a pore fluid."));
        crack_tracking = std::make_unique<CrackTracking<dim>>(*cracks);
      }
    // A saturated body: the model given is the skeleton's, the points
    // carry the total stress and the pore pressure.
    const auto &pore_fluid = prm_values.pore_fluid;
    if (pore_fluid.enabled)
      {
        pore_fluid.check();
        model =
          std::make_unique<PoroelasticModel<dim>>(std::move(model),
                                                  pore_fluid.biot_coefficient,
                                                  pore_fluid.initial_pressure);
        pore_pressure =
          std::make_unique<PorePressureSolver<dim>>(pore_fluid, communicator);
        if (!pore_fluid.drained_surface_region.empty())
          pore_pressure->set_drained_surface(drained_surface_condition(),
                                             surface_tractions);
      }
    const Formulation &formulation = prm_values.material_points.formulation;
    AssertThrow(!formulation.axisymmetric ||
                  pore_fluid.drained_surface_region.empty(),
                ExcMessage("Pore fluid: <Drained surface region> is not "
                           "available with Material points/Axisymmetric = "
                           "true (a load on the body's surface); drain "
                           "through grid faces (Drained boundaries)."));
    AssertThrow(formulation.move_points || !body_contact.enabled(),
                ExcMessage("Material points: <Move points = false> is not "
                           "available with contact between bodies, whose "
                           "grids follow the points' positions."));
    material_points =
      std::make_unique<MaterialPointSet<dim>>(background_grid,
                                              *model,
                                              formulation,
                                              bcs.surface_tractions().size(),
                                              rigid_body_names());
    external_force.set_axisymmetric(formulation.axisymmetric);
    audit.set_axisymmetric(formulation.axisymmetric);
  }



  template <int dim>
  std::vector<std::string>
  QuasiStaticProblem<dim>::rigid_body_names() const
  {
    std::vector<std::string> names;
    for (const auto &body : bcs.rigid_bodies())
      names.push_back(body.name);
    return names;
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::setup_step_data()
  {
    if (!residual)
      {
        TimerOutput::Scope scope(timer_output, "set-up (sparsity pattern)");
        AssertThrow(!(points().get_formulation().gimp() &&
                      bcs.has_macroscopic_gradient()),
                    ExcMessage("GIMP shape functions with a macroscopic "
                               "displacement gradient on a periodic grid are "
                               "not supported (the affine jump is not added "
                               "to nodes reached across periodic faces); use "
                               "Shape functions = linear."));
        // If the program asked for it (return_large_blocks_to_system()):
        // blocks of more than one and a half vectors of the grid's dofs
        // (the points' data, the shape-function cache, the stiffness, ML's
        // temporaries) come from mmap and go back to the system when freed;
        // vectors, which the Krylov solver and ML allocate in every
        // iteration, stay on the heap (see
        // Utils::return_large_blocks_to_system()). Per-point arrays of 8
        // bytes or more per point are already larger than that with 2^dim
        // points per cell.
        if (manage_heap)
          Utils::return_large_blocks_to_system(
            3 * sizeof(double) *
            background_grid.locally_relevant_dofs().n_elements() / 2);
        residual = std::make_unique<QuasiStaticResidual<dim>>(
          background_grid,
          points(),
          cache,
          prm_values.material_points.update_volumes);
        preconditioner         = make_preconditioner();
        direct_retry           = false;
        preconditioner_retried = false;
        secant_retry           = false;
        preconditioner_reuse.reset();
        last_load_increment = 0.;
        // A stiffness handed over on the same degrees of freedom (on
        // every rank) brings the pattern of the same grid.
        const bool gimp = points().get_formulation().gimp();
        if (handover &&
            (handover->preconditioner->type() != preconditioner->type() ||
             handover->tangent->has_step_patterns() != gimp ||
             dealii::Utilities::MPI::min(
               handover->tangent->matrix().locally_owned_range_indices() ==
                   background_grid.locally_owned_dofs() ?
                 1 :
                 0,
               communicator) == 0))
          handover.reset();
        if (handover)
          tangent = std::move(handover->tangent);
        else if (preconditioner->needs_matrix())
          tangent->reinit(background_grid, gimp);
      }
    du.reinit(background_grid.locally_owned_dofs(), communicator);
    R.reinit(du);
    f_ext.reinit(du);
  }



  template <int dim>
  std::unique_ptr<Preconditioner<dim>>
  QuasiStaticProblem<dim>::make_preconditioner() const
  {
    // auto: a direct factorization for small problems, where its cost is
    // that of a few AMG set-ups and it needs no tuning; AMG above, where
    // the fill-in of the factors grows faster than the dofs.
    const auto &solver_prm = prm_values.nonlinear_solver;
    std::string type       = solver_prm.preconditioner;
    if (type == "auto")
      type = background_grid.get_dof_handler().n_dofs() <=
                 solver_prm.direct_threshold_for(dim) ?
               "direct" :
               "amg";
    return std::make_unique<Preconditioner<dim>>(
      Preconditioner<dim>::parse_type(type),
      solver_prm.amg_null_space == "rigid body modes",
      solver_prm.amg_anisotropy_threshold);
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::prepare_step(const double t_old, const double t_new)
  {
    AssertThrow(tangent,
                ExcMessage("This problem handed its stiffness over to "
                           "another (hand_over_preconditioner()) and cannot "
                           "solve again."));
    setup_step_data();

    // N_i(x_p) and grad N_i(x_p) for the whole step (paper Section 2.3);
    // a step solved again with a new contact set between bodies keeps
    // them, as the points have not moved.
    if (!keep_contact_set)
      {
        TimerOutput::Scope scope(timer_output, "shape functions at points");
        cache.reinit(background_grid, points(), residual->ghosted_layout());
      }
    const double gamma = prm_values.material_points.ghost_penalty;
    if (gamma > 0.)
      {
        TimerOutput::Scope scope(timer_output, "ghost penalty");
        ghost_penalty.reinit(background_grid,
                             cache,
                             points().get_offsets().volume,
                             gamma,
                             constraint_maker.mean_stiffness(points()),
                             points().get_formulation().axisymmetric);
      }
    {
      TimerOutput::Scope        scope(timer_output, "constraints and loads");
      AffineConstraints<double> constraints;
      constraint_maker.make(points(),
                            prm_values.material_points,
                            t_old,
                            t_new,
                            constraints,
                            held_dofs,
                            stabilization(),
                            &body_contact,
                            !keep_contact_set);
      step_constraints.reinit(std::move(constraints),
                              background_grid.locally_owned_dofs(),
                              communicator);
      if (!rigid_plates.empty())
        rigid_plates.reinit_step(background_grid,
                                 step_constraints.get(),
                                 constraint_maker.mean_stiffness(points()));
      // At finite strain a body force is per unit initial volume (rho_0 b),
      // so that the load of a point does not change with its volume.
      const auto &offsets = points().get_offsets();
      external_force.assemble(background_grid,
                              cache,
                              points().get_formulation().finite_strain() ?
                                offsets.initial_volume :
                                offsets.volume,
                              t_new,
                              f_ext);
      if (body_contact.enabled())
        {
          body_contact.add_friction_forces(f_ext);
          f_ext.compress(VectorOperation::add);
        }
      if (!surface_tractions.empty())
        {
          surface_tractions.reinit_step(background_grid,
                                        cache,
                                        points(),
                                        residual->ghosted_layout(),
                                        t_new);
          surface_tractions.add_dead_loads(f_ext);
          f_ext.compress(VectorOperation::add);
        }
      if (!rigid_contact.empty())
        rigid_contact.reinit_step(background_grid,
                                  cache,
                                  points(),
                                  residual->ghosted_layout(),
                                  t_old,
                                  t_new,
                                  constraint_maker.mean_stiffness(points()),
                                  run_state.body_displacements);
      residual->set_external_force(f_ext);
    }
    {
      TimerOutput::Scope scope(timer_output, "constraints and loads");
      null_mode_hold.reinit(
        background_grid,
        points(),
        cache,
        step_constraints.get(),
        stabilization(),
        additional_stiffness(false),
        prm_values.material_points.min_nodal_stiffness_fraction,
        constraint_maker.mean_stiffness(points()));
    }
    // The stiffness and its preconditioner, unless the one of an earlier
    // step may serve again (PreconditionerReuse). K is not reassembled
    // either (with GIMP its pattern may change, and AMG and KLU refer to
    // it).
    const bool new_preconditioner =
      preconditioner_reuse.build_for_step(preconditioner->needs_matrix(),
                                          solver_parameters(),
                                          step_constraints.get(),
                                          background_grid.locally_owned_dofs(),
                                          communicator);
    // The first step may take over what another problem built for the
    // same constrained dofs (take_over_preconditioner()); otherwise the
    // handover is freed before the new set-up.
    if (new_preconditioner && handover &&
        handover->constrained == preconditioner_reuse.constrained_signature())
      {
        preconditioner         = std::move(handover->preconditioner);
        preconditioner_tangent = handover->tangent_kind;
        preconditioner_reuse.count_as_taken_over();
        handover.reset();
        complete_preconditioner(true);
        return;
      }
    handover.reset();
    if (new_preconditioner)
      {
        {
          TimerOutput::Scope scope(timer_output, "tangent assembly");
          // A factorization does not need a positive definite K, so it is
          // built from the slope of each point's branch (a softening
          // crack's negative stiffness, as in the Jacobian) instead of the
          // secant that AMG needs, unless the step failed with the slopes
          // (reject_step()).
          preconditioner_tangent =
            (preconditioner->type() == Preconditioner<dim>::Type::direct &&
             !secant_retry) ?
              TangentAssembler<dim>::Tangent::loading :
              TangentAssembler<dim>::Tangent::secant;
          assemble_tangent(nullptr);
        }
        TimerOutput::Scope scope(timer_output, "preconditioner setup");
        preconditioner->setup(tangent->matrix(),
                              background_grid,
                              tangent->pattern_generation());
      }
    complete_preconditioner(new_preconditioner);
  }



  template <int dim>
  std::unique_ptr<PreconditionerHandover<dim>>
  QuasiStaticProblem<dim>::hand_over_preconditioner()
  {
    if (!tangent || preconditioner_reuse.constrained_signature()[0] < 0. ||
        !preconditioner->needs_matrix())
      return nullptr;
    auto given     = std::make_unique<PreconditionerHandover<dim>>();
    given->tangent = std::move(tangent);
    given->preconditioner =
      std::exchange(preconditioner, make_preconditioner());
    given->tangent_kind = preconditioner_tangent;
    given->constrained  = preconditioner_reuse.constrained_signature();
    preconditioner_reuse.reset();
    return given;
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::take_over_preconditioner(
    std::unique_ptr<PreconditionerHandover<dim>> given)
  {
    AssertThrow(!residual,
                ExcMessage("take_over_preconditioner() must be called "
                           "before the first load step."));
    handover = std::move(given);
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::assemble_tangent(
    const IterateKinematics<dim> *iterate)
  {
    tangent->assemble(background_grid,
                      points(),
                      cache,
                      step_constraints.get(),
                      stabilization(),
                      additional_stiffness(true),
                      preconditioner_tangent,
                      iterate,
                      /*fbar_terms=*/iterate != nullptr);
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::build_preconditioner_at(const VectorType &du_iterate)
  {
    residual->iterate_kinematics(du_iterate, iterate_kinematics);
    assemble_tangent(&iterate_kinematics);
    // A factorization starts afresh, with pivoting: KLU's refactorization
    // keeps the pivot order, and so the fill, of its last full
    // factorization, which for the nearly singular tangents of perfect
    // plasticity can be poor (doc/benchmarks.md: a footing twice as slow).
    try
      {
        preconditioner->setup(tangent->matrix(), background_grid);
      }
    catch (const std::exception &)
      {
        // The consistent tangents of perfect plasticity can leave the
        // matrix singular at an iterate (points at the apex of a
        // Mohr-Coulomb surface stiffen nothing): this iteration takes the
        // tangents of the committed state, as the step's first did.
        assemble_tangent(nullptr);
        preconditioner->setup(tangent->matrix(), background_grid);
      }
    complete_preconditioner(true);
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::complete_preconditioner(
    const bool new_preconditioner)
  {
    // The bodies driven by a force (RigidContact) and the plates
    // (RigidPlates) complete the preconditioner; the plates in every step,
    // since their nodes change with the material.
    if (preconditioner->needs_matrix() &&
        !(rigid_contact.empty() && rigid_plates.empty()))
      {
        TimerOutput::Scope scope(timer_output, "preconditioner setup");
        const auto         M = [this](VectorType &dst, const VectorType &src) {
          preconditioner->vmult(dst, src);
        };
        if (!rigid_contact.empty())
          rigid_contact.setup_preconditioner(tangent->matrix(),
                                             M,
                                             new_preconditioner);
        if (!rigid_plates.empty())
          rigid_plates.setup_preconditioner(
            tangent->matrix(),
            M,
            [this](VectorType &v) {
              step_constraints.set_constrained_to_zero(v);
            },
            new_preconditioner);
      }
  }



  template <int dim>
  std::vector<const LocalStiffness *>
  QuasiStaticProblem<dim>::stabilizations() const
  {
    std::vector<const LocalStiffness *> terms;
    if (stabilization() != nullptr)
      terms.push_back(stabilization());
    if (null_mode_hold.active())
      terms.push_back(&null_mode_hold);
    return terms;
  }



  template <int dim>
  typename TangentAssembler<dim>::AdditionalTerm
  QuasiStaticProblem<dim>::additional_stiffness(const bool with_hold) const
  {
    const bool hold = with_hold && null_mode_hold.active();
    if (rigid_contact.empty() && rigid_plates.empty() && !hold)
      return {};
    return [this, hold, with_hold](const AffineConstraints<double> &c,
                                   TrilinosWrappers::SparseMatrix  &K) {
      if (!rigid_contact.empty())
        rigid_contact.add_to(c, K, /*preconditioner's matrix:*/ with_hold);
      if (!rigid_plates.empty())
        rigid_plates.add_to(K, /*preconditioner's matrix:*/ with_hold);
      if (hold)
        null_mode_hold.add_to(c, K);
    };
  }



  template <int dim>
  NewtonParameters
  QuasiStaticProblem<dim>::solver_parameters() const
  {
    NewtonParameters parameters = prm_values.nonlinear_solver.resolve(
      model->is_elastic(), points().get_formulation().finite_strain());
    // Newton's test is relative to the step's first residual, which the
    // penalty forces of a rigid body that moves in the step (into points
    // that have not moved yet) can make larger than any force in the body:
    // no step ends with more left unbalanced than the equilibrium check
    // accepts of the largest force carried so far.
    parameters.residual_ceiling =
      prm_values.equilibrium_check.tolerance * run_state.force_scale;
    return parameters;
  }



  template <int dim>
  bool
  QuasiStaticProblem<dim>::advance(const double  t_old,
                                   const double  t_new,
                                   NewtonReport &report)
  {
    prepare_step(t_old, t_new);

    // A.1 step 1: zero initial guess but for the prescribed increments.
    // Extrapolation instead scales the increments of the last converged
    // step to this step's load increment: on the fixed background grid
    // they are nodal values of the same degrees of freedom, and under
    // proportional loading of a nearly linear problem they are nearly this
    // step's solution, which saves the predictor's linear solve.
    using InitialGuess                 = NewtonParameters::InitialGuess;
    NewtonParameters newton_parameters = solver_parameters();
    // Coulomb friction switches points between stick and slip, and full
    // Newton steps then cycle between the two (the block on a floor of
    // test contact_rigid_bodies: 20 iterations without convergence in its
    // first step, 5-12 with the line search).
    for (const auto &body : bcs.rigid_bodies())
      if (body.friction == RigidBody<dim>::Friction::coulomb)
        newton_parameters.max_line_search_steps =
          std::max(newton_parameters.max_line_search_steps, 8u);
    const bool extrapolate =
      newton_parameters.initial_guess == InitialGuess::extrapolation;
    const double previous_load_increment = last_load_increment;
    if (extrapolate && last_load_increment > 0.)
      extrapolated_guess(t_new - t_old);
    else
      {
        du = 0.;
        if (extrapolate)
          newton_parameters.initial_guess = InitialGuess::linear_predictor;
      }
    step_constraints.distribute(du);

    const auto solve = [&](NewtonReport &solve_report) {
      TimerOutput::Scope scope(timer_output, "Newton-Krylov solve");
      StepOperator<dim>  op = step_operator();
      if (newton_parameters.preconditioner_update == "Newton iteration" &&
          preconditioner->needs_matrix())
        op.set_preconditioner_update([this](const VectorType &iterate) {
          build_preconditioner_at(iterate);
        });
      const NewtonKrylov<StepOperator<dim>, VectorType> newton(
        newton_parameters, &progress);
      typename StepOperator<dim>::Evaluation evaluation;
      solve_report = newton.solve(op, du, R, evaluation);
      if (solve_report.singular_jacobian &&
          !(prm_values.material_points.ghost_penalty > 0.))
        solve_report.failure +=
          ": nodes whose points no longer resist a motion (at the apex of a "
          "perfectly plastic surface, failed); Material points/Ghost penalty "
          "ties them to their neighbours";
      op.reject_inverted_points(evaluation, solve_report);
      // A converged step may still have let points through a rigid body,
      // or into it from beyond the contact's candidates: a smaller step
      // resolves the contact.
      if (solve_report.converged && !rigid_contact.empty())
        {
          const std::string unresolved = rigid_contact.unresolved_contact(du);
          if (!unresolved.empty())
            {
              solve_report.converged = false;
              solve_report.failure   = unresolved;
            }
        }
      preconditioner_reuse.count_use(solve_report, solver_parameters());
    };
    coupling_iterations = 0;
    if (pore_pressure)
      {
        // The flow matrix of the step; the points' pressure iterate starts
        // from their committed pressure (also after a cut-back).
        TimerOutput::Scope scope(timer_output, "pore pressure");
        pore_pressure->begin_step(background_grid,
                                  cache,
                                  points(),
                                  dynamic_cast<const PoroelasticModel<dim> &>(
                                    *model),
                                  t_old,
                                  t_new);
        residual->point_state_changed();
        // The step's load may not change at all (consolidation under a
        // constant load): what moves the body is the change of the pore
        // pressure. The step's first solve, before the pressure changes,
        // stops at 1e-2 of the coupling tolerance times the forces in the
        // body (PorePressureSolver::force_scale()) instead of relative to a
        // residual that is then round-off (the later ones: see
        // couple_pore_pressure()).
        newton_parameters.residual_floor =
          std::max(newton_parameters.residual_floor,
                   pore_pressure->force_scale() * coupling_floor_factor());
      }
    if (pore_pressure && prm_values.pore_fluid.monolithic())
      solve_coupled(newton_parameters, report);
    else
      {
        solve(report);
        if (pore_pressure && report.converged)
          couple_pore_pressure(newton_parameters, solve, report);
      }
    // A step that failed (and is tried again with a smaller increment, or
    // a new preconditioner) starts from the linear predictor.
    last_load_increment        = 0.;
    second_last_load_increment = 0.;
    keep_contact_set           = false;
    if (!report.converged)
      {
        contact_iterations = 0;
        return false;
      }
    if (contact_set_changed(report))
      return advance(t_old, t_new, report);
    if (!report.converged)
      return false;
    audit_equilibrium(t_new, report);
    if (extrapolate)
      {
        if (previous_load_increment > 0.)
          {
            second_last_increment.swap(last_increment);
            second_last_load_increment = previous_load_increment;
          }
        last_load_increment = t_new - t_old;
      }
    commit_step();
    if (pore_pressure)
      update_degree_of_consolidation();
    return true;
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::update_degree_of_consolidation()
  {
    const unsigned int pressure = points().get_layout().offset("pore_pressure");
    const unsigned int volume   = points().get_offsets().volume;
    const double       initial  = prm_values.pore_fluid.initial_pressure;
    double             excess   = 0.;
    for (const auto &particle : points().get_particle_handler())
      {
        const auto data = particle.get_properties();
        excess += (data[pressure] - initial) * data[volume];
      }
    excess = std::abs(dealii::Utilities::MPI::sum(excess, communicator));
    run_state.peak_excess_pressure =
      std::max(run_state.peak_excess_pressure, excess);
    degree_of_consolidation_value =
      run_state.peak_excess_pressure > 0. ?
        1. - excess / run_state.peak_excess_pressure :
        0.;
  }



  template <int dim>
  StepOperator<dim>
  QuasiStaticProblem<dim>::step_operator() const
  {
    return StepOperator<dim>(*residual,
                             step_constraints,
                             *preconditioner,
                             stabilizations(),
                             pressure_loads(),
                             contact_loads(),
                             pore_pressure ?
                               1e-6 * residual->typical_increment_norm() :
                               0.,
                             plates());
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::solve_coupled(NewtonParameters &newton_parameters,
                                         NewtonReport     &report)
  {
    TimerOutput::Scope      scope(timer_output, "Newton-Krylov solve");
    const StepOperator<dim> op = step_operator();
    // The first iterate's pressure: the flow with the volume change of the
    // initial guess (the first half of a fixed-stress iteration), so that
    // the first residual is that of a guess of both fields.
    {
      TimerOutput::Scope scope(timer_output, "pore pressure");
      VectorType         du_ghosted(residual->ghosted_layout());
      residual->import_ghosts(du, du_ghosted);
      pore_pressure->update(cache, points(), du_ghosted);
    }
    const CoupledStepOperator<dim> coupled(
      op, *pore_pressure, *residual, cache, points(), du);
    auto x         = coupled.make_vector(du, pore_pressure->owned_pressure());
    auto R_coupled = x;
    // An extrapolated du is the first iterate itself: the stopping test's
    // reference, the residual of its constrained part alone, would lack
    // the pressure of all the free nodes.
    using InitialGuess = NewtonParameters::InitialGuess;
    if (newton_parameters.initial_guess == InitialGuess::extrapolation)
      newton_parameters.initial_guess = InitialGuess::boundary_values;
    const NewtonKrylov<CoupledStepOperator<dim>,
                       typename CoupledStepOperator<dim>::VectorType>
      newton(newton_parameters, &progress);
    typename CoupledStepOperator<dim>::Evaluation evaluation;
    report = newton.solve(coupled, x, R_coupled, evaluation);
    coupled.reject_inverted_points(evaluation, report);
    preconditioner_reuse.count_use(report, solver_parameters());
    du                  = x.block(0);
    R                   = R_coupled.block(0);
    coupling_iterations = 1;
  }



  template <int dim>
  double
  QuasiStaticProblem<dim>::coupling_floor_factor() const
  {
    // The stopping target is Tolerance times the floor.
    return 1e-2 * prm_values.pore_fluid.coupling_tolerance /
           prm_values.nonlinear_solver.tolerance;
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::couple_pore_pressure(
    NewtonParameters                          &newton_parameters,
    const std::function<void(NewtonReport &)> &solve,
    NewtonReport                              &report)
  {
    // Fixed-stress split: flow with the volume change of the last
    // displacement, then the displacement with the new pressure, until the
    // pressure stops changing. Each solve starts from the last increment.
    const auto &parameters = prm_values.pore_fluid;
    newton_parameters.initial_guess =
      NewtonParameters::InitialGuess::extrapolation;
    // Each solve starts from the last converged increment and reduces the
    // forces of the pressure change by 1e-2, relative to their own size:
    // the floor of the step's first solve (the forces in the body, for a
    // step whose load does not change) would let a solve return at once
    // when the pressure changes little, and the iteration would then only
    // relax the flow problem (measured on Terzaghi's column with 256
    // cpGIMP cells: the pressure changed by the same 1.3e-5 of its largest
    // value in 95 iterations, and the run stopped in step 631). The
    // fixed-stress iteration contracts by about 1/3 per iteration for an
    // elastic skeleton (1 - K / M_c in 1D), so that 1e-2 leaves its rate
    // as it is; a reduction by the Newton tolerance took 1.7 times as long
    // (test footing_consolidation) for the same pressures. The floor guards
    // against round-off: 1e-12 of the forces in the body (with the
    // supports' reactions, as the step's first solve found them). The
    // last solve's residual is then at most 1e-2 of the forces of a
    // pressure change below the coupling tolerance.
    newton_parameters.relative_to_load = false;
    newton_parameters.tolerance        = 1e-2;
    newton_parameters.residual_floor =
      std::max(prm_values.nonlinear_solver.residual_floor,
               1e-10 *
                 std::max(report.force_level, pore_pressure->force_scale()));
    VectorType du_ghosted(residual->ghosted_layout());
    for (;;)
      {
        double change = 0.;
        {
          TimerOutput::Scope scope(timer_output, "pore pressure");
          residual->import_ghosts(du, du_ghosted);
          change = pore_pressure->update(cache, points(), du_ghosted);
          residual->point_state_changed();
        }
        ++coupling_iterations;
        NewtonReport next;
        solve(next);
        report.converged = next.converged;
        report.failure   = next.failure;
        report.newton_iterations += next.newton_iterations;
        report.linear_iterations += next.linear_iterations;
        report.inexact_linear_solves += next.inexact_linear_solves;
        report.line_search_steps += next.line_search_steps;
        report.final_residual = next.final_residual;
        report.stagnated      = report.stagnated || next.stagnated;
        if (!report.converged || change <= parameters.coupling_tolerance)
          return;
        if (coupling_iterations >= parameters.max_coupling_iterations)
          {
            std::ostringstream message;
            message << "the fixed-stress iteration of the pore pressure did "
                       "not converge in "
                    << coupling_iterations
                    << " iterations (Pore fluid/Maximum coupling iterations; "
                       "the last changed the pressure by "
                    << std::setprecision(3) << change
                    << " of its largest value; a skeleton that yields in "
                       "compaction may need a larger Pore fluid/Fixed-stress "
                       "factor)";
            report.converged = false;
            report.failure   = message.str();
            return;
          }
      }
  }



  template <int dim>
  bool
  QuasiStaticProblem<dim>::advance_path_following(const LoadStepper &stepper,
                                                  NewtonReport      &report,
                                                  double            &t_new,
                                                  double            &force_new)
  {
    const double t_old = stepper.current();
    AssertThrow(!pore_pressure,
                ExcMessage("Pore fluid: path following (Load stepping/"
                           "Control) is not available with a pore fluid; "
                           "the load factor is the time."));
    AssertThrow(rigid_plates.empty(),
                ExcMessage("Boundary conditions: path following (Load "
                           "stepping/Control) does not take rigid plates "
                           "(Rigid plate boundaries); the load factor "
                           "scales their load."));
    for (const auto &body : bcs.rigid_bodies())
      AssertThrow(!body.load_driven(),
                  ExcMessage("Rigid body <" + body.name +
                             ">: path following (Load stepping/Control) "
                             "does not take a body driven by a force; the "
                             "load factor scales its load."));
    PathFollowingSetup<dim>::check_problem(stepper, bcs, *model);

    // The constraints of a unit load-factor increment: their
    // inhomogeneities are the direction g of the prescribed increments.
    prepare_step(t_old, t_old + 1.);
    VectorType g(du);
    path_following.make_direction(
      stepper,
      step_constraints,
      [&](AffineConstraints<double> &doubled) {
        // (This also records the dofs of the reactions again: the same
        // ones.)
        constraint_maker.make(points(),
                              prm_values.material_points,
                              t_old,
                              t_old + 2.,
                              doubled,
                              held_dofs,
                              stabilization());
      },
      background_grid.locally_owned_dofs(),
      communicator,
      g);

    double delta_lambda = 0.;
    {
      TimerOutput::Scope      scope(timer_output, "Newton-Krylov solve");
      const StepOperator<dim> op(*residual,
                                 step_constraints,
                                 *preconditioner,
                                 stabilizations(),
                                 pressure_loads(),
                                 contact_loads());
      const typename PathFollowingSetup<dim>::Solver newton(solver_parameters(),
                                                            &progress);
      const auto                                     constraint =
        path_following.constraint(stepper,
                                  cache,
                                  points().get_offsets().displacement,
                                  background_grid.min_cell_size(),
                                  communicator,
                                  du);
      typename StepOperator<dim>::Evaluation evaluation;
      report = newton.solve(op,
                            g,
                            constraint,
                            stepper.increment_limit(),
                            stepper.backward_limit(),
                            stepper.allow_limit(),
                            du,
                            delta_lambda,
                            R,
                            force_new,
                            evaluation,
                            PathFollowingSetup<dim>::force_guard(stepper));
      op.reject_inverted_points(evaluation, report);
      preconditioner_reuse.count_use(report, solver_parameters());
    }
    t_new            = t_old + delta_lambda;
    keep_contact_set = false;
    if (!report.converged)
      {
        contact_iterations = 0;
        return false;
      }
    if (contact_set_changed(report))
      return advance_path_following(stepper, report, t_new, force_new);
    if (!report.converged)
      return false;
    audit_equilibrium(t_new, report);
    commit_step();
    return true;
  }



  template <int dim>
  bool
  QuasiStaticProblem<dim>::contact_set_changed(NewtonReport &report)
  {
    // Bodies that pull on each other come apart, bodies that would overlap
    // touch: the step is solved again with the new contact set.
    if (!body_contact.enabled() || ![&] {
          // The contact forces are the residual of the tied dofs before
          // condensation, which adds them to the other body's rows.
          VectorType R_raw(R);
          residual->evaluate(du, R_raw);
          return body_contact.update(background_grid, du, R_raw);
        }())
      {
        contact_iterations = 0;
        return false;
      }
    if (++contact_iterations >= prm_values.body_contact.max_iterations)
      {
        contact_iterations = 0;
        report.converged   = false;
        report.failure =
          "the contact set between the bodies changed "
          "in every one of " +
          std::to_string(prm_values.body_contact.max_iterations) +
          " solves (Contact between bodies/Max contact "
          "iterations)";
        return false;
      }
    progress << "  contact between bodies changed, solving again" << std::endl;
    keep_contact_set = true;
    return true;
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::extrapolated_guess(const double dt)
  {
    // The rate of the last step, v1 = du_1 / dt_1, is that at the middle of
    // the step. With the step before it, v2 = du_2 / dt_2, the rate is
    // extrapolated linearly to the middle of this step, which is
    // (dt_1 + dt) / 2 after that of the last step:
    //
    //   du = dt (v1 + (v1 - v2) (dt_1 + dt) / (dt_1 + dt_2)).
    //
    // The points move with every step, and the stiffness with them: on the
    // strip of benchmarks/strip256.prm the last step's rate leaves a
    // residual of 2e-3 of the load's, and five GMRES iterations to the
    // Newton tolerance; the extrapolated rate leaves 1e-4 of it, and three
    // GMRES iterations. Where the rate turned within the last two steps (a
    // load reversed), the change of rate says nothing about this step's:
    // the last step's rate alone, if the two rates are more than 60
    // degrees apart.
    const double dt_1 = last_load_increment;
    du                = last_increment;
    du *= dt / dt_1;
    if (second_last_load_increment > 0. &&
        last_increment * second_last_increment >=
          0.5 * last_increment.l2_norm() * second_last_increment.l2_norm())
      {
        const double dt_2 = second_last_load_increment;
        du.add(dt * (dt_1 + dt) / (dt_1 * (dt_1 + dt_2)), last_increment);
        du.add(-dt * (dt_1 + dt) / (dt_2 * (dt_1 + dt_2)),
               second_last_increment);
      }
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::commit_step()
  {
    TimerOutput::Scope scope(timer_output, "commit and move points");
    points_consistent = false;
    // The points read du at the nodes of their cells, some of them owned by
    // other ranks: one exchange of ghost values serves both the new point
    // state and the motion of the points.
    VectorType du_ghosted(background_grid.locally_owned_dofs(),
                          background_grid.locally_relevant_dofs(),
                          communicator);
    du_ghosted     = du;
    last_increment = du;
    residual->commit(du_ghosted);
    if (!surface_tractions.empty())
      surface_tractions.commit(points(), du_ghosted);
    if (!rigid_contact.empty())
      run_state.body_displacements = rigid_contact.commit(points(), du_ghosted);
    if (!rigid_plates.empty())
      {
        const std::vector<double> motion = rigid_plates.means(du);
        run_state.plate_displacements.resize(motion.size(), 0.);
        for (unsigned int k = 0; k < motion.size(); ++k)
          run_state.plate_displacements[k] += motion[k];
      }
    const double moved = points().advect(cache, du_ghosted);
    // The cache is of the points' old positions; the next step makes it
    // anew. While every point stays in its cell, that is all: the points'
    // data stay where they are, and the cache keeps its memory for the
    // next step (fresh pages cost a page fault each). Points that do not
    // move stay in their cells at their reference locations.
    if (points().get_formulation().move_points && !points().locate_in_cells())
      {
        // Sorting moves the points' data in memory. Releasing the cache
        // first keeps it from adding to the copy of all particle data that
        // deal.II makes while sorting, the peak of a step that reuses an
        // earlier preconditioner.
        cache.clear();
        points().sort_into_cells_without_loss(moved);
      }
    points_consistent = true;
    // Which points may crack in the next step: from the cracks of this
    // one, at the points' new places.
    if (crack_tracking)
      {
        crack_tracking->update(points(), communicator);
        residual->point_state_changed();
      }
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::audit_equilibrium(const double        t_new,
                                             const NewtonReport &report)
  {
    const double step_force_scale = report.initial_residual;
    // The applied load includes the pressures and the contact forces at
    // the solution.
    const bool applied_depends_on_du =
      pressure_loads() != nullptr || contact_loads() != nullptr;
    VectorType applied;
    if (applied_depends_on_du)
      {
        applied = f_ext;
        if (pressure_loads() != nullptr)
          surface_tractions.add_pressure_forces(du, applied);
        if (contact_loads() != nullptr)
          {
            rigid_contact.add_contact_forces(du, applied);
            body_loads = rigid_contact.body_loads(du);
          }
      }
    // A body's contact force is a support's reaction: the loss is measured
    // against it too (two tied bodies that hold a body between them apply
    // forces that cancel, and no displacement condition need carry any).
    // The step's own forces count as well: a step that only moves a body
    // that carries no load (a block sliding to another) has no other
    // scale, and Newton removed its initial residual to its tolerance.
    double scale = std::max(run_state.load_scale, step_force_scale);
    for (const auto &load : body_loads)
      scale = std::max(scale, load.force.norm());
    if (contact_loads() != nullptr)
      rigid_contact.check_loads(body_loads, scale);
    last_audit           = audit.evaluate(background_grid,
                                displacement_constraints,
                                held_dofs,
                                R,
                                applied_depends_on_du ? applied : f_ext,
                                scale);
    run_state.reactions  = last_audit.reactions;
    run_state.load_scale = last_audit.scale;
    // The forces count where Newton resolved them: a body moved without
    // load (a block carried across a gap) has supports' forces of the size
    // of what Newton left, and a ceiling relative to them could not be met.
    double forces = last_audit.applied.norm();
    for (const auto &reaction : last_audit.reactions)
      forces = std::max(forces, reaction.norm());
    for (const auto &load : body_loads)
      forces = std::max(forces, load.force.norm());
    const double resolved = prm_values.equilibrium_check.tolerance * forces;
    if (report.final_residual <= resolved)
      run_state.force_scale = std::max(run_state.force_scale, forces);
    const auto       &check = prm_values.equilibrium_check;
    const std::string message =
      last_audit.lost_load(t_new,
                           check.tolerance,
                           prm_values.nonlinear_solver.tolerance);
    if (message.empty())
      return;
    AssertThrow(!check.stop_on_lost_load,
                ExcMessage(
                  message +
                  " The run stops (Equilibrium check/Stop on lost load)."));
    if (!lost_load_warned)
      progress << "  warning: " << message
               << " Further steps that lose load are not reported; see "
                  "the column imbalance of reactions.csv."
               << std::endl;
    lost_load_warned = true;
  }



  template <int dim>
  std::string
  QuasiStaticProblem<dim>::write_last_converged_state(OutputWriter<dim> &writer)
  {
    std::ostringstream sentence;
    sentence << " The last converged state is that of step " << last_step
             << " (t = " << last_load_factor << ")";
    if (prm_values.output.interval == 0)
      return sentence.str() + "; Output/Interval = 0 writes no fields.";
    if (!points_consistent)
      return sentence.str() + "; the points no longer hold it.";
    if (int(last_step) != last_written_step)
      {
        writer.write_points(points(), last_step, last_load_factor);
        if (last_step > 0 && last_increment.size() == du.size())
          writer.write_increment(background_grid,
                                 last_increment,
                                 last_step,
                                 last_load_factor);
        last_written_step = last_step;
      }
    return sentence.str() + ", written to <" + prm_values.output.directory +
           ">.";
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::run()
  {
    LoadStepper       stepper(prm_values.load_stepping);
    OutputWriter<dim> writer(prm_values.output, communicator);
    ProbeWriter<dim>  probes(prm_values.output.probe_positions(),
                            prm_values.output.directory,
                            communicator);
    start_run(stepper, writer, probes);

    // A step that stops the run (a step that does not converge after all
    // its cut-backs, a step that loses load, a point that leaves the grid)
    // leaves the points as the last accepted step made them: their fields
    // are written, and the message says which step that was.
    try
      {
        while (!stepper.finished())
          if (!take_step(stepper, writer, probes))
            break;
      }
    catch (const std::exception &exc)
      {
        const std::string written = write_last_converged_state(writer);
        AssertThrow(false, ExcMessage(Utils::error_message(exc) + written));
      }
    if (progress.is_active())
      timer_output.print_summary();
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::start_run(LoadStepper       &stepper,
                                     OutputWriter<dim> &writer,
                                     ProbeWriter<dim>  &probes)
  {
    // set_model() made the points with the formulation of that moment; a
    // later change of it would be ignored.
    AssertThrow(prm_values.material_points.formulation ==
                  points().get_formulation(),
                ExcMessage("Material points: the formulation (Kinematics, "
                           "Shape functions, Volumetric locking, "
                           "Axisymmetric, Move points) was changed after "
                           "set_model(), which made the points with the one "
                           "before; change it before set_model()."));
    const bool from_checkpoint = run_state.resuming();
    if (from_checkpoint)
      {
        const std::string user = run_state.restore(stepper, writer);
        if (restore_user_state)
          restore_user_state(user);
        last_written_step = -1;
      }
    body_contact.check_points(points(), communicator);
    condition_names.clear();
    for (const auto &condition : bcs.dirichlet_conditions())
      condition_names.push_back(condition.name);
    for (const auto &name : rigid_body_names())
      condition_names.push_back(name);
    body_loads.assign(bcs.rigid_bodies().size(), {});
    if (!from_checkpoint)
      {
        run_state.plate_displacements.assign(bcs.rigid_plates().size(), 0.);
        run_state.body_displacements.assign(bcs.rigid_bodies().size(), 0.);
      }
    condition_names.push_back("applied");
    condition_names.push_back("held");

    progress << "qsmpm: " << dim << "D, "
             << background_grid.get_triangulation().n_global_active_cells()
             << " cells, " << background_grid.get_dof_handler().n_dofs()
             << " dofs, " << points().n_global_points() << " material points, "
             << dealii::Utilities::MPI::n_mpi_processes(communicator)
             << " MPI rank(s)" << std::endl;
    if (from_checkpoint)
      progress << "resumed from the checkpoint of step " << stepper.step()
               << ", t = " << stepper.current() << std::endl;

    // The pressure follows the points' volume changes, which carry the
    // cell-crossing error of linear shape functions at once
    // (doc/example_consolidation.md: half the exact pressure at the base
    // of a column compressed by a fifth, without any check failing).
    const auto &formulation = prm_values.material_points.formulation;
    if (pore_pressure && formulation.finite_strain() &&
        formulation.shape_functions == ShapeFunctions::linear)
      progress << "  warning: a pore fluid at finite strain with linear shape "
                  "functions: once points cross cells their pressures carry "
                  "the cell-crossing error; Material points/Shape functions "
                  "= cpGIMP avoids it."
               << std::endl;

    // A malformed gauge stops the run before any output.
    path_following.make_gauge(stepper);

    // The surface points of each surface traction, from the points where
    // fill() put them (a checkpoint holds their areas).
    if (!from_checkpoint && !surface_tractions.empty())
      {
        const std::vector<double> areas =
          surface_tractions.mark(background_grid, points());
        for (unsigned int k = 0; k < areas.size(); ++k)
          progress << "surface traction <" << bcs.surface_tractions()[k].name
                   << ">: loaded area " << areas[k] << std::endl;
      }

    if (!from_checkpoint && writer.fields_due(0))
      {
        TimerOutput::Scope scope(timer_output, "output");
        writer.write_points(points(), 0, 0.);
        last_written_step = 0;
      }
    last_step        = stepper.step();
    last_load_factor = stepper.current();
    if (!probes.empty())
      probes.select(points());
  }



  template <int dim>
  bool
  QuasiStaticProblem<dim>::take_step(LoadStepper       &stepper,
                                     OutputWriter<dim> &writer,
                                     ProbeWriter<dim>  &probes)
  {
    Timer        wall_timer;
    NewtonReport newton;
    const double t_old = stepper.current();
    double       t_new = stepper.target(), force_new = 0.;
    const bool   converged =
      stepper.path_following() ?
          advance_path_following(stepper, newton, t_new, force_new) :
          advance(t_old, t_new, newton);
    if (!converged)
      {
        reject_step(stepper, newton, t_old, t_new);
        return true;
      }
    const unsigned int cut_backs = stepper.n_cut_backs();
    preconditioner_retried       = false;
    secant_retry                 = false;
    if (direct_retry)
      {
        // The step AMG could not solve is done: AMG again for the next.
        preconditioner = make_preconditioner();
        direct_retry   = false;
        preconditioner_reuse.reset();
      }
    if (stepper.path_following())
      stepper.accept(t_new, force_new);
    else
      stepper.accept();
    last_step        = stepper.step();
    last_load_factor = t_new;
    wall_timer.stop();
    run_state.reports.push_back({stepper.step(),
                                 t_new,
                                 cut_backs,
                                 newton,
                                 wall_timer.wall_time(),
                                 coupling_iterations,
                                 null_mode_hold.n_modes()});
    progress << run_state.reports.back().progress_line(last_audit.imbalance())
             << std::endl;
    const bool stop = step_callback && !step_callback(run_state.reports.back());
    write_step_output(stepper, writer, probes, t_new, stop);
    if (stop)
      return false;
    const unsigned int checkpoints = prm_values.output.checkpoint_interval;
    if (checkpoints > 0 && stepper.step() % checkpoints == 0 &&
        !stepper.finished())
      {
        TimerOutput::Scope scope(timer_output, "checkpoint");
        run_state.write_checkpoint(prm_values.output.directory,
                                   communicator,
                                   stepper,
                                   background_grid,
                                   points(),
                                   writer,
                                   save_user_state);
        progress << "  checkpoint of step " << stepper.step() << " written"
                 << std::endl;
      }
    return true;
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::reject_step(LoadStepper        &stepper,
                                       const NewtonReport &newton,
                                       const double        t_old,
                                       const double        t_new)
  {
    // A preconditioner kept from an earlier step may no longer fit (the
    // paper's one point per cell leaves K nearly singular in its hourglass
    // modes, and those of an older K need not be the Jacobian's): the step
    // is tried again with a new one before its increment is cut. Once per
    // increment: the solves of a step whose contact set between bodies
    // changes keep the step's preconditioner, so an attempt that failed
    // because that set does not settle ends with a kept one every time, and
    // retried without limit the increment would never be cut back.
    if (preconditioner_reuse.reused() && !preconditioner_retried)
      {
        preconditioner_retried = true;
        preconditioner_reuse.reset();
        progress << "  step " << stepper.step() + 1
                 << ": a new preconditioner (the one of an earlier step no "
                    "longer serves)"
                 << std::endl;
        return;
      }
    // The slopes of the points' branches fit the Jacobian while every point
    // stays on its branch; in a step where cracks turn from opening to
    // closing they may not, and the secant, which is right for a crack that
    // unloads, is tried before the increment is cut (b15-opening.prm: step
    // 448 does not converge in 20 Newton iterations with the slopes, and
    // converges in one with the secant).
    if (preconditioner_tangent == TangentAssembler<dim>::Tangent::loading &&
        !secant_retry)
      {
        secant_retry = true;
        preconditioner_reuse.reset();
        progress << "  step " << stepper.step() + 1
                 << ": a new preconditioner from the secant stiffness ("
                 << newton.failure << ")" << std::endl;
        return;
      }
    if (switch_to_direct())
      {
        progress << "  step " << stepper.step() + 1 << ": failed with AMG ("
                 << newton.failure
                 << "), trying again with the direct factorization"
                 << std::endl;
        return;
      }
    progress << "  step " << stepper.step() + 1 << ": t = " << t_old;
    if (stepper.path_following())
      progress << ", " << LoadStepper::to_string(stepper.control()) << " "
               << stepper.constraint_target();
    else
      progress << " -> " << t_new;
    progress << " failed (" << newton.failure << "), cutting back" << std::endl;
    preconditioner_retried = false;
    stepper.reject(newton.failure);
  }



  template <int dim>
  bool
  QuasiStaticProblem<dim>::switch_to_direct()
  {
    const auto &solver_prm = prm_values.nonlinear_solver;
    if (!solver_prm.direct_retry || direct_retry ||
        preconditioner->type() != Preconditioner<dim>::Type::amg ||
        background_grid.get_dof_handler().n_dofs() >
          solver_prm.direct_threshold_for(dim))
      return false;
    preconditioner =
      std::make_unique<Preconditioner<dim>>(Preconditioner<dim>::Type::direct);
    direct_retry = true;
    preconditioner_reuse.reset();
    return true;
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::write_step_output(const LoadStepper &stepper,
                                             OutputWriter<dim> &writer,
                                             ProbeWriter<dim>  &probes,
                                             const double       t_new,
                                             const bool         stop)
  {
    TimerOutput::Scope          scope(timer_output, "output");
    std::vector<Tensor<1, dim>> forces = run_state.reactions;
    for (const auto &load : body_loads)
      forces.push_back(load.force);
    forces.push_back(last_audit.applied);
    forces.push_back(last_audit.held);
    std::vector<std::string> column_names;
    std::vector<double>      columns;
    for (unsigned int k = 0; k < bcs.rigid_plates().size(); ++k)
      {
        column_names.push_back("plate_" +
                               std::to_string(bcs.rigid_plates()[k]) + "_u");
        columns.push_back(run_state.plate_displacements[k]);
      }
    for (unsigned int b = 0; b < bcs.rigid_bodies().size(); ++b)
      if (bcs.rigid_bodies()[b].load_driven())
        {
          column_names.push_back(bcs.rigid_bodies()[b].name + "_u");
          columns.push_back(run_state.body_displacements[b]);
        }
    if (body_contact.enabled())
      {
        column_names.push_back("contact_force_between_bodies");
        columns.push_back(body_contact.total_normal_force());
      }
    if (pore_pressure)
      {
        column_names.push_back("consolidation_degree");
        columns.push_back(degree_of_consolidation_value);
      }
    writer.write_reactions(stepper.step(),
                           t_new,
                           condition_names,
                           forces,
                           column_names,
                           columns,
                           last_audit.imbalance());
    if (!probes.empty())
      probes.write(points(), stepper.step(), t_new);
    if (writer.fields_due(stepper.step()) ||
        ((stepper.finished() || stop) && prm_values.output.interval > 0))
      {
        writer.write_points(points(), stepper.step(), t_new);
        writer.write_increment(background_grid, du, stepper.step(), t_new);
        last_written_step = stepper.step();
      }
  }



  template <int dim>
  unsigned int
  QuasiStaticProblem<dim>::resume()
  {
    // Residual and tangent belong to the grid's old degrees of freedom;
    // setup_step_data() builds them anew for the loaded partition.
    residual.reset();
    return run_state.read_checkpoint(prm_values.output.directory,
                                     communicator,
                                     background_grid,
                                     points());
  }

  template class QuasiStaticProblem<2>;
  template class QuasiStaticProblem<3>;
} // namespace qsmpm
