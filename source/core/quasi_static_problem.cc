#include <cmath>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <map>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/core/step_operator.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/io/checkpoint.h>
#include <qsmpm/loading/constraint_checks.h>
#include <qsmpm/loading/parsed_boundary_conditions.h>
#include <qsmpm/solvers/path_following_newton.h>
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
  {}



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
  QuasiStaticProblem<dim>::initialize(ParameterHandler &prm)
  {
    prm_values.parse_parameters(prm);
    background_grid.make_box(prm_values.geometry);
    set_model(ConstitutiveModelFactory<dim>::create(prm));
    material_points->fill(prm_values.material_points);
    AssertThrow(material_points->n_global_points() > 0,
                ExcMessage("Material points: the region holds no points."));
    ParsedBoundaryConditions<dim> parsed_conditions;
    parsed_conditions.parse_parameters(prm, bcs);

    // A load or a prescribed displacement that is NaN or infinite somewhere
    // (sqrt(-1), 1/x at x = 0) would only show as a residual that is not a
    // number, after every cut-back of the first step. Check the functions at
    // the vertices of the coarse grid, which every rank holds (so that all
    // ranks stop together), at the start and at the end of the loading. On
    // large grids every k-th vertex (in the same order on every rank) keeps
    // this below 10^4 points, a few milliseconds of muParser.
    const auto             &triangulation = background_grid.get_triangulation();
    std::vector<bool>       seen(triangulation.n_vertices(), false);
    std::vector<Point<dim>> vertices;
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const unsigned int v : cell->vertex_indices())
        if (!seen[cell->vertex_index(v)])
          {
            seen[cell->vertex_index(v)] = true;
            vertices.push_back(cell->vertex(v));
          }
    const std::size_t stride = 1 + vertices.size() / 10000;
    if (stride > 1)
      {
        std::size_t n = 0;
        for (std::size_t i = 0; i < vertices.size(); i += stride)
          vertices[n++] = vertices[i];
        vertices.resize(n);
      }
    parsed_conditions.check_functions(
      vertices, {0., prm_values.load_stepping.final_load_factor});
  }



  template <int dim>
  BackgroundGrid<dim> &
  QuasiStaticProblem<dim>::grid()
  {
    return background_grid;
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::set_model(
    std::unique_ptr<ConstitutiveModel<dim>> new_model)
  {
    residual.reset();
    material_points.reset();
    model           = std::move(new_model);
    material_points = std::make_unique<MaterialPointSet<dim>>(
      background_grid, *model, prm_values.material_points.formulation);
  }



  template <int dim>
  MaterialPointSet<dim> &
  QuasiStaticProblem<dim>::points()
  {
    return const_cast<MaterialPointSet<dim> &>(std::as_const(*this).points());
  }



  template <int dim>
  const MaterialPointSet<dim> &
  QuasiStaticProblem<dim>::points() const
  {
    AssertThrow(material_points,
                ExcMessage("Choose a constitutive model (set_model) before "
                           "adding material points."));
    return *material_points;
  }



  template <int dim>
  BoundaryDescriptor<dim> &
  QuasiStaticProblem<dim>::boundary_conditions()
  {
    return bcs;
  }



  template <int dim>
  typename QuasiStaticProblem<dim>::Parameters &
  QuasiStaticProblem<dim>::parameters()
  {
    return prm_values;
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
        // auto: a direct factorization for small problems, where its cost
        // is that of a few AMG set-ups and it needs no tuning; AMG above,
        // where the fill-in of the factors grows faster than the dofs.
        const auto &solver_prm = prm_values.nonlinear_solver;
        std::string type       = solver_prm.preconditioner;
        if (type == "auto")
          type = background_grid.get_dof_handler().n_dofs() <=
                     solver_prm.direct_threshold ?
                   "direct" :
                   "amg";
        preconditioner =
          Preconditioner<dim>(Preconditioner<dim>::parse_type(type));
        preconditioner_age  = 0;
        last_load_increment = 0.;
        if (preconditioner.needs_matrix())
          tangent.reinit(background_grid, points().get_formulation().gimp());
      }
    du.reinit(background_grid.locally_owned_dofs(), communicator);
    R.reinit(du);
    f_ext.reinit(du);
  }



  template <int dim>
  IndexSet
  QuasiStaticProblem<dim>::inactive_dofs() const
  {
    const double h_dim = std::pow(background_grid.min_cell_size(), dim);
    return cache.dofs_without_points(
      background_grid,
      points().get_offsets().volume,
      prm_values.material_points.min_nodal_volume_fraction * h_dim);
  }



  template <int dim>
  IndexSet
  QuasiStaticProblem<dim>::dofs_without_stiffness() const
  {
    // The stiffness of each dof against its own motion, compared with the
    // mean over the dofs that have any: relative, so that the threshold
    // does not depend on the units or the material.
    TrilinosWrappers::MPI::Vector diagonal(background_grid.locally_owned_dofs(),
                                           communicator);
    TangentAssembler<dim>::assemble_diagonal(points(), cache, diagonal);
    double sum = 0., count = 0.;
    for (const auto dof : background_grid.locally_owned_dofs())
      if (diagonal(dof) > 0.)
        {
          sum += diagonal(dof);
          count += 1.;
        }
    sum   = dealii::Utilities::MPI::sum(sum, communicator);
    count = dealii::Utilities::MPI::sum(count, communicator);
    const double threshold =
      prm_values.material_points.min_nodal_stiffness_fraction *
      (count > 0. ? sum / count : 0.);

    return background_grid.dofs_at_most(diagonal, threshold);
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::make_step_constraints(
    const double               t_old,
    const double               t_new,
    AffineConstraints<double> &constraints)
  {
    displacement_constraints.make(background_grid, t_old, t_new, constraints);

    // Which nodes carry material is a matter of the step, not of the
    // boundary conditions: the points move, and a node may lose or gain
    // material from one step to the next (paper Section 2.2).
    const IndexSet inactive = inactive_dofs();

    // Each displacement condition that moves its nodes must still hold
    // material; and all the nodes with material that the conditions hold
    // (each once, in the order of their dofs) must prevent every rigid-body
    // motion, or the step's linear systems are singular. Periodicity holds
    // the body itself.
    const auto &conditions = bcs.dirichlet_conditions();
    std::map<types::global_dof_index, std::pair<Point<dim>, unsigned int>> held;
    for (unsigned int k = 0; k < conditions.size(); ++k)
      {
        unsigned int n_active          = 0;
        double       largest_increment = 0.;
        for (const auto &dof : displacement_constraints.prescribed_dofs(k))
          {
            largest_increment =
              std::max(largest_increment, std::abs(dof.increment));
            if (!inactive.is_element(dof.index))
              {
                ++n_active;
                held.emplace(dof.index,
                             std::make_pair(dof.node, dof.component));
              }
          }
        ConstraintChecks::assert_condition_acts(conditions[k].name,
                                                n_active,
                                                largest_increment,
                                                t_old,
                                                t_new,
                                                communicator);
      }
    if (background_grid.periodic_directions().empty())
      {
        std::vector<std::pair<Point<dim>, unsigned int>> held_nodes;
        held_nodes.reserve(held.size());
        for (const auto &entry : held)
          held_nodes.push_back(entry.second);
        const Point<dim> &lower = background_grid.lower_corner();
        const Point<dim> &upper = background_grid.upper_corner();
        ConstraintChecks::assert_no_rigid_body_motion<dim>(
          held_nodes,
          lower + 0.5 * (upper - lower),
          lower.distance(upper),
          communicator);
      }

    // Nodes with no point in their support have no equation: fix their
    // increment to zero. It does not influence any point. Any load on them
    // is lost; the equilibrium audit of the step says so.
    held_dofs = inactive;
    for (const auto dof : inactive)
      if (!constraints.is_constrained(dof))
        constraints.add_line(dof);

    // A node may have points but no stiffness in a direction: all of them
    // have lost it, as the points of a completely failed crack band that
    // opens, when the intact points beside it have moved out of the node's
    // cells. Its equation in that direction is 0 = 0 (the points carry no
    // stress that it could balance), the step's Jacobian is singular, and
    // Newton diverges. Holding it, like a node without points, leaves the
    // equilibrium of the other nodes unchanged.
    if (prm_values.material_points.min_nodal_stiffness_fraction > 0.)
      {
        const IndexSet without_stiffness = dofs_without_stiffness();
        held_dofs.add_indices(without_stiffness);
        for (const auto dof : without_stiffness)
          if (!constraints.is_constrained(dof))
            constraints.add_line(dof);
      }
    constraints.close();
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::prepare_step(const double t_old, const double t_new)
  {
    setup_step_data();

    // N_i(x_p) and grad N_i(x_p) for the whole step (paper Section 2.3).
    {
      TimerOutput::Scope scope(timer_output, "shape functions at points");
      cache.reinit(background_grid, points(), residual->ghosted_layout());
    }
    {
      TimerOutput::Scope        scope(timer_output, "constraints and loads");
      AffineConstraints<double> constraints;
      make_step_constraints(t_old, t_new, constraints);
      step_constraints.reinit(std::move(constraints),
                              background_grid.locally_owned_dofs(),
                              communicator);
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
      residual->set_external_force(f_ext);
    }
    // The stiffness and its preconditioner, unless the one of an earlier
    // step may serve again: it stays an approximate inverse of the tangent
    // as long as the points and their state change little, and GMRES, which
    // works with the exact Jacobian-vector products, only needs a few more
    // iterations. K is not reassembled either (with GIMP its pattern may
    // change, and AMG and KLU refer to it).
    const auto &solver_prm = prm_values.nonlinear_solver;
    const bool  build =
      preconditioner.needs_matrix() &&
      (preconditioner_age == 0 ||
       preconditioner_age >= solver_prm.preconditioner_reuse_steps);
    preconditioner_reused = preconditioner.needs_matrix() && !build;
    if (build)
      {
        preconditioner_age = 0;
        ++preconditioner_builds;
        {
          TimerOutput::Scope scope(timer_output, "tangent assembly");
          tangent.assemble(background_grid,
                           points(),
                           cache,
                           step_constraints.get());
        }
        TimerOutput::Scope scope(timer_output, "preconditioner setup");
        preconditioner.setup(tangent.matrix(),
                             background_grid,
                             tangent.pattern_generation());
      }
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::count_preconditioner_use(const NewtonReport &report)
  {
    // Reuse bookkeeping: a failed step, or one in which GMRES slowed down
    // by more than the growth factor, gets a new preconditioner next time.
    const double rate = double(report.linear_iterations) /
                        std::max<unsigned int>(1, report.newton_iterations);
    if (preconditioner_age == 0)
      preconditioner_rate = std::max(rate, 1.);
    ++preconditioner_age;
    if (!report.converged ||
        rate > prm_values.nonlinear_solver.preconditioner_reuse_growth *
                 preconditioner_rate)
      preconditioner_age = 0;
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::check_volume_ratios(const StepOperator<dim> &op,
                                               NewtonReport            &report,
                                               const bool last_evaluation_at_du)
  {
    // A converged increment may still have turned a point inside out: at
    // small strain J = (1 + tr d eps) J_old can pass zero while the
    // residual stays finite. Such a step is rejected (and cut back) like
    // one that did not converge. The J the residual records must be that
    // of the accepted increment: unless the solver's last evaluation was
    // at du, the residual is evaluated once more there (R itself is
    // unchanged). Path following may have evaluated a trial last.
    if (report.converged)
      {
        if (!last_evaluation_at_du)
          op.residual(du, R);
        const double min_J =
          dealii::Utilities::MPI::min(residual->minimum_volume_ratio(),
                                      communicator);
        if (!(min_J > 0.))
          {
            std::ostringstream message;
            message << "a material point was turned inside out (J = "
                    << std::setprecision(3) << min_J << " <= 0)";
            report.converged = false;
            report.failure   = message.str();
          }
      }
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
    NewtonParameters newton_parameters = prm_values.nonlinear_solver;
    const bool       extrapolate =
      newton_parameters.initial_guess == InitialGuess::extrapolation;
    if (extrapolate && last_load_increment > 0.)
      {
        du = last_increment;
        du *= (t_new - t_old) / last_load_increment;
      }
    else
      {
        du = 0.;
        if (extrapolate)
          newton_parameters.initial_guess = InitialGuess::linear_predictor;
      }
    step_constraints.distribute(du);

    {
      TimerOutput::Scope      scope(timer_output, "Newton-Krylov solve");
      const StepOperator<dim> op(*residual, step_constraints, preconditioner);
      const NewtonKrylov<StepOperator<dim>, VectorType> newton(
        newton_parameters, &progress);
      report = newton.solve(op, du, R);
      check_volume_ratios(op, report, true);
      count_preconditioner_use(report);
    }
    // A step that failed (and is tried again with a smaller increment, or
    // a new preconditioner) starts from the linear predictor.
    last_load_increment = 0.;
    if (!report.converged)
      return false;
    audit_equilibrium(t_new);
    if (extrapolate)
      last_load_increment = t_new - t_old;
    commit_step();
    return true;
  }



  template <int dim>
  bool
  QuasiStaticProblem<dim>::advance_path_following(const LoadStepper &stepper,
                                                  NewtonReport      &report,
                                                  double            &t_new,
                                                  double            &force_new)
  {
    const std::string &control = stepper.control();
    const double       t_old   = stepper.current();
    // Path following scales the prescribed displacements with the unknown
    // load factor; loads that are functions of t would need their own
    // scaling, and the generalized force (the sign guard) assumes that the
    // prescribed displacements are the only work-conjugate of the load
    // factor.
    AssertThrow(!bcs.has_loads() && !bcs.has_macroscopic_gradient(),
                ExcMessage("Load stepping: Control = " + control +
                           " needs a problem loaded by prescribed "
                           "displacements only (no body force, traction, "
                           "point load or macroscopic displacement "
                           "gradient)."));

    AssertThrow(control != "dissipation" || model->computes_dissipation(),
                ExcMessage("Load stepping: Control = dissipation needs a "
                           "material model that computes its dissipation; <" +
                           model->name() + "> does not."));

    // The constraints of a unit load-factor increment: their
    // inhomogeneities are the direction g of the prescribed increments.
    prepare_step(t_old, t_old + 1.);
    VectorType g(du);
    g = 0.;
    step_constraints.distribute(g);
    AssertThrow(g.linfty_norm() > 0.,
                ExcMessage("Load stepping: Control = " + control +
                           " needs a displacement condition that changes "
                           "with the load factor; none does."));
    if (!proportionality_checked)
      {
        // The increments of a step are Delta lambda g only if the
        // prescribed displacements are t g; with another dependence on t
        // the step would be wrong without any sign of it.
        AffineConstraints<double> doubled;
        make_step_constraints(t_old, t_old + 2., doubled);
        double mismatch = 0.;
        for (const auto i : background_grid.locally_owned_dofs())
          if (doubled.is_constrained(i))
            mismatch =
              std::max(mismatch,
                       std::abs(doubled.get_inhomogeneity(i) - 2. * g[i]));
        mismatch = dealii::Utilities::MPI::max(mismatch, communicator);
        AssertThrow(mismatch <= 1e-10 * g.linfty_norm(),
                    ExcMessage("Load stepping: Control = " + control +
                               " needs prescribed displacements "
                               "proportional to the load factor t (u = t "
                               "g(x))."));
        // (make_step_constraints() also recorded the dofs of the reactions
        // again: the same ones.)
        proportionality_checked = true;
      }

    // The opening of the gauge as a function of du, for this step's shape
    // functions.
    VectorType w;
    if (control == "opening")
      {
        if (!gauge)
          gauge = std::make_unique<OpeningGauge<dim>>(
            stepper.get_parameters().opening_gauge);
        w.reinit(du);
        gauge->make_vector(cache,
                           points().get_offsets().displacement,
                           background_grid.min_cell_size(),
                           communicator,
                           w);
      }

    double delta_lambda = 0.;
    {
      TimerOutput::Scope      scope(timer_output, "Newton-Krylov solve");
      const StepOperator<dim> op(*residual, step_constraints, preconditioner);
      using Solver = PathFollowingNewton<StepOperator<dim>, VectorType>;
      const Solver newton(prm_values.nonlinear_solver, &progress);
      // Either the energy the points dissipate in the step (see
      // PathFollowingNewton for why not the global formula of Gutierrez)
      // or the opening of the gauge.
      typename Solver::Constraint constraint{0., 0., 0., 0.};
      constraint.value = stepper.constraint_target();
      if (control == "opening")
        {
          constraint.gauge        = &w;
          constraint.gauge_weight = 1.;
        }
      else
        constraint.dissipation_weight = 1.;
      // The load keeps the sign of its peak, up to 1e-3 of the peak (the
      // noise of a converged step in the tail is far below that).
      const double                      peak_force = stepper.peak_force();
      const typename Solver::ForceGuard guard{peak_force > 0. ?
                                                1. :
                                                (peak_force < 0. ? -1. : 0.),
                                              1e-3 * std::abs(peak_force)};
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
                            guard);
      check_volume_ratios(op, report, false);
      count_preconditioner_use(report);
    }
    t_new = t_old + delta_lambda;
    if (!report.converged)
      return false;
    audit_equilibrium(t_new);
    commit_step();
    return true;
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
    residual->commit(du_ghosted, points());
    const double moved = points().advect(cache, du_ghosted);
    // The cache is of the points' old positions; the next step makes it
    // anew. While every point stays in its cell, that is all: the points'
    // data stay where they are, and the cache keeps its memory for the
    // next step (fresh pages cost a page fault each).
    if (points().locate_in_cells())
      {
        points_consistent = true;
        return;
      }
    // Sorting moves the points' data in memory. Releasing the cache first
    // keeps it from adding to the copy of all particle data that deal.II
    // makes while sorting, the peak of a step that reuses an earlier
    // preconditioner.
    cache.clear();
    const auto lost = points().sort_into_cells();
    // In parallel, deal.II finds a point's new cell only among the
    // neighbours of its old one (the ghost layer).
    if (lost > 0 && dealii::Utilities::MPI::n_mpi_processes(communicator) > 1 &&
        moved >= background_grid.min_cell_size())
      {
        std::ostringstream message;
        message << lost
                << " material points were lost: in a parallel run a point "
                   "may move at most one cell per load step, and in this "
                   "step a point moved "
                << std::setprecision(3)
                << moved / background_grid.min_cell_size()
                << " cells. Use more load steps.";
        AssertThrow(false, ExcMessage(message.str()));
      }
    AssertThrow(lost == 0,
                ExcMessage(std::to_string(lost) +
                           " material points left the background grid. "
                           "Enlarge the grid around the body."));
    points_consistent = true;
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::audit_equilibrium(const double t_new)
  {
    last_audit     = audit.evaluate(background_grid,
                                displacement_constraints,
                                held_dofs,
                                R,
                                f_ext,
                                load_scale);
    last_reactions = last_audit.reactions;
    load_scale     = last_audit.scale;
    // Where load leaves through the grid's edge: the GIMP points whose
    // domains reach beyond it; the rank of the one with the most weight
    // there tells where it is.
    last_audit.n_points_beyond_grid =
      dealii::Utilities::MPI::sum(cache.n_points_beyond_grid(), communicator);
    if (last_audit.n_points_beyond_grid > 0)
      {
        const double largest = dealii::Utilities::MPI::max(
          cache.largest_weight_beyond_grid(), communicator);
        const unsigned int n_ranks =
          dealii::Utilities::MPI::n_mpi_processes(communicator);
        const unsigned int rank = dealii::Utilities::MPI::min(
          cache.largest_weight_beyond_grid() == largest ?
            dealii::Utilities::MPI::this_mpi_process(communicator) :
            n_ranks,
          communicator);
        last_audit.point_beyond_grid = dealii::Utilities::MPI::broadcast(
          communicator, cache.point_beyond_grid(), rank);
      }

    const auto  &check     = prm_values.equilibrium_check;
    const double imbalance = last_audit.imbalance();
    if (!(imbalance > check.tolerance))
      return;
    std::ostringstream message;
    message << "the converged step to t = " << t_new << " lost "
            << std::setprecision(3) << 100. * imbalance
            << " % of the load (the applied load is not carried by the "
               "displacement conditions; Equilibrium check/Lost load "
               "tolerance = "
            << check.tolerance << "): " << last_audit.causes(check.tolerance)
            << '.';
    AssertThrow(!check.stop_on_lost_load,
                ExcMessage(
                  message.str() +
                  " The run stops (Equilibrium check/Stop on lost load)."));
    if (!lost_load_warned)
      progress << "  warning: " << message.str()
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
    const bool        from_checkpoint = resumed;
    if (from_checkpoint)
      restore_run_state(stepper, writer);
    std::vector<std::string> names;
    for (const auto &condition : bcs.dirichlet_conditions())
      names.push_back(condition.name);
    names.push_back("applied");
    names.push_back("held");

    progress << "qsmpm: " << dim << "D, "
             << background_grid.get_triangulation().n_global_active_cells()
             << " cells, " << background_grid.get_dof_handler().n_dofs()
             << " dofs, " << points().n_global_points() << " material points, "
             << dealii::Utilities::MPI::n_mpi_processes(communicator)
             << " MPI rank(s)" << std::endl;
    if (from_checkpoint)
      progress << "resumed from the checkpoint of step " << stepper.step()
               << ", t = " << stepper.current() << std::endl;

    // A malformed gauge stops the run before any output.
    if (stepper.control() == "opening")
      gauge = std::make_unique<OpeningGauge<dim>>(
        stepper.get_parameters().opening_gauge);

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

    // A step that stops the run (a step that does not converge after all
    // its cut-backs, a step that loses load, a point that leaves the grid)
    // leaves the points as the last accepted step made them: their fields
    // are written, and the message says which step that was.
    try
      {
        while (!stepper.finished())
          if (!take_step(stepper, writer, probes, names))
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
  bool
  QuasiStaticProblem<dim>::take_step(LoadStepper                    &stepper,
                                     OutputWriter<dim>              &writer,
                                     ProbeWriter<dim>               &probes,
                                     const std::vector<std::string> &names)
  {
    Timer        wall_timer;
    NewtonReport newton;
    const double t_old = stepper.current();
    double       t_new = stepper.target(), force_new = 0.;
    const bool   converged =
      stepper.path_following() ?
          advance_path_following(stepper, newton, t_new, force_new) :
          advance(t_old, t_new, newton);
    // A preconditioner kept from an earlier step may no longer fit (the
    // paper's one point per cell leaves K nearly singular in its hourglass
    // modes, and those of an older K need not be the Jacobian's): the step
    // is tried again with a new one before its increment is cut.
    // count_preconditioner_use() has marked it for rebuilding.
    if (!converged && preconditioner_reused)
      {
        progress << "  step " << stepper.step() + 1
                 << ": a new preconditioner (the one of an earlier step no "
                    "longer serves)"
                 << std::endl;
        return true;
      }
    if (!converged)
      {
        progress << "  step " << stepper.step() + 1 << ": t = " << t_old;
        if (stepper.path_following())
          progress << ", " << stepper.control() << " "
                   << stepper.constraint_target();
        else
          progress << " -> " << t_new;
        progress << " failed (" << newton.failure << "), cutting back"
                 << std::endl;
        stepper.reject(newton.failure);
        return true;
      }
    const unsigned int cut_backs = stepper.n_cut_backs();
    if (stepper.path_following())
      stepper.accept(t_new, force_new);
    else
      stepper.accept();
    last_step        = stepper.step();
    last_load_factor = t_new;
    wall_timer.stop();
    reports.push_back(
      {stepper.step(), t_new, cut_backs, newton, wall_timer.wall_time()});

    std::ostringstream line;
    line << "step " << std::setw(5) << stepper.step() << "  t = "
         << std::setw(10) << std::setprecision(5) << t_new << "  newton "
         << std::setw(2) << newton.newton_iterations << "  gmres "
         << std::setw(4) << newton.linear_iterations << "  |R| "
         << std::scientific << std::setprecision(2) << newton.initial_residual
         << " -> " << newton.final_residual << "  lost "
         << std::setprecision(1) << last_audit.imbalance() << std::defaultfloat
         << "  " << std::fixed << std::setprecision(3)
         << wall_timer.wall_time() << " s";
    if (cut_backs > 0)
      line << "  cut-backs " << cut_backs;
    if (newton.line_search_steps > 0)
      line << "  line search " << newton.line_search_steps;
    progress << line.str() << std::endl;
    const bool stop = step_callback && !step_callback(reports.back());

    {
      TimerOutput::Scope scope(timer_output, "output");
      std::vector<Tensor<1, dim>> forces = last_reactions;
      forces.push_back(last_audit.applied);
      forces.push_back(last_audit.held);
      writer.write_reactions(
        stepper.step(), t_new, names, forces, last_audit.imbalance());
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
    if (stop)
      return false;
    const unsigned int checkpoints = prm_values.output.checkpoint_interval;
    if (checkpoints > 0 && stepper.step() % checkpoints == 0 &&
        !stepper.finished())
      {
        TimerOutput::Scope scope(timer_output, "checkpoint");
        write_checkpoint(stepper, writer);
      }
    return true;
  }




  // Checkpoint and restart. Grid and points are written by Checkpoint;
  // everything else that carries over from one step to the next goes into
  // its text: the load stepper
  // (load factor, increment, step count), the reports of the steps so far
  // (summaries of a resumed run count all steps), the reactions of the
  // last step, the output records, and the caller's own state. Doubles are
  // written with max_digits10 digits, which reads back exactly.
  template <int dim>
  void
  QuasiStaticProblem<dim>::write_checkpoint(const LoadStepper       &stepper,
                                            const OutputWriter<dim> &writer)
  {
    std::ostringstream state;
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        state << std::setprecision(std::numeric_limits<double>::max_digits10);
        state << "stepper ";
        stepper.save(state);
        state << "\nreactions " << last_reactions.size();
        for (const auto &reaction : last_reactions)
          for (unsigned int d = 0; d < dim; ++d)
            state << ' ' << reaction[d];
        state << "\nload_scale " << load_scale;
        state << "\nreports " << reports.size() << '\n';
        for (const auto &r : reports)
          state << r.step << ' ' << r.load_factor << ' ' << r.cut_backs << ' '
                << r.newton.converged << ' ' << r.newton.newton_iterations
                << ' ' << r.newton.linear_iterations << ' '
                << r.newton.inexact_linear_solves << ' '
                << r.newton.line_search_steps << ' '
                << r.newton.initial_residual << ' ' << r.newton.final_residual
                << ' ' << r.wall_time << '\n';
        state << "output ";
        writer.save(state);
        const std::string user = save_user_state ? save_user_state() : "";
        state << "user " << user.size() << '\n' << user;
      }
    Checkpoint<dim>(prm_values.output.directory, communicator)
      .write(stepper.step(), background_grid, points(), state.str());
    progress << "  checkpoint of step " << stepper.step() << " written"
             << std::endl;
  }



  template <int dim>
  unsigned int
  QuasiStaticProblem<dim>::resume()
  {
    const Checkpoint<dim> checkpoint(prm_values.output.directory, communicator);
    const std::string     path = checkpoint.newest();
    AssertThrow(!path.empty(),
                ExcMessage("Cannot resume: there is no complete checkpoint "
                           "(checkpoint-<step>) in the output directory <" +
                           prm_values.output.directory +
                           ">; write them with Output/Checkpoint interval."));
    // Residual and tangent belong to the grid's old degrees of freedom;
    // setup_step_data() builds them anew for the loaded partition.
    residual.reset();
    resume_state = checkpoint.read(path, background_grid, points());
    resumed      = true;
    resumed_step =
      Checkpoint<dim>::step_of(std::filesystem::path(path).filename().string());
    return resumed_step;
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::restore_run_state(LoadStepper       &stepper,
                                             OutputWriter<dim> &writer)
  {
    std::istringstream in(resume_state);
    std::string        keyword;
    const auto         expect = [&](const std::string &word) {
      in >> keyword;
      AssertThrow(in && keyword == word,
                  ExcMessage("Cannot resume: the checkpoint's state has no <" +
                             word + "> entry."));
    };
    expect("stepper");
    stepper.load(in);
    AssertThrow(stepper.step() == resumed_step,
                ExcMessage("Cannot resume: the checkpoint's load stepping "
                           "state does not belong to its step."));
    expect("reactions");
    std::size_t n = 0;
    in >> n;
    last_reactions.assign(n, Tensor<1, dim>());
    for (auto &reaction : last_reactions)
      for (unsigned int d = 0; d < dim; ++d)
        in >> reaction[d];
    expect("load_scale");
    in >> load_scale;
    expect("reports");
    in >> n;
    reports.assign(n, StepReport());
    for (auto &r : reports)
      in >> r.step >> r.load_factor >> r.cut_backs >> r.newton.converged >>
        r.newton.newton_iterations >> r.newton.linear_iterations >>
        r.newton.inexact_linear_solves >> r.newton.line_search_steps >>
        r.newton.initial_residual >> r.newton.final_residual >> r.wall_time;
    expect("output");
    writer.resume(in, resumed_step);
    expect("user");
    in >> n;
    in.get();
    std::string user(n, '\0');
    in.read(user.data(), n);
    AssertThrow(in,
                ExcMessage("Cannot resume: the checkpoint's state is "
                           "incomplete."));
    if (restore_user_state)
      restore_user_state(user);
    last_step         = stepper.step();
    last_load_factor  = stepper.current();
    last_written_step = -1;
    resumed           = false;
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::set_checkpoint_state(
    const std::function<std::string()>             &save,
    const std::function<void(const std::string &)> &restore)
  {
    save_user_state    = save;
    restore_user_state = restore;
  }



  template <int dim>
  unsigned int
  QuasiStaticProblem<dim>::n_preconditioner_builds() const
  {
    return preconditioner_builds;
  }



  template <int dim>
  const std::vector<typename QuasiStaticProblem<dim>::StepReport> &
  QuasiStaticProblem<dim>::step_reports() const
  {
    return reports;
  }



  template <int dim>
  void
  QuasiStaticProblem<dim>::set_step_callback(
    const std::function<bool(const StepReport &)> &callback)
  {
    step_callback = callback;
  }



  template <int dim>
  const std::vector<Tensor<1, dim>> &
  QuasiStaticProblem<dim>::reactions() const
  {
    return last_reactions;
  }



  template <int dim>
  const typename QuasiStaticProblem<dim>::VectorType &
  QuasiStaticProblem<dim>::increment() const
  {
    return du;
  }



  template <int dim>
  const typename EquilibriumAudit<dim>::Result &
  QuasiStaticProblem<dim>::equilibrium() const
  {
    return last_audit;
  }



  template <int dim>
  const TrilinosWrappers::SparseMatrix &
  QuasiStaticProblem<dim>::stiffness() const
  {
    return tangent.matrix();
  }



  template <int dim>
  ConditionalOStream &
  QuasiStaticProblem<dim>::pcout()
  {
    return progress;
  }



  template <int dim>
  TimerOutput &
  QuasiStaticProblem<dim>::timer()
  {
    return timer_output;
  }



  template class QuasiStaticProblem<2>;
  template class QuasiStaticProblem<3>;
} // namespace qsmpm
