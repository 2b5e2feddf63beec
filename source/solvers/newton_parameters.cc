#include <qsmpm/solvers/newton_parameters.h>

namespace qsmpm
{
  void
  NewtonParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlinear solver");
    {
      prm.add_parameter("Tolerance",
                        tolerance,
                        "gamma of the Newton stopping test ||R(du_n)|| <= "
                        "gamma max(floor, ||R(du_0)||, 1e-6 F) (paper A.1, "
                        "step 2), F the forces in the body (||R(du_0)|| on "
                        "all rows, the supports' reactions included), and "
                        "at most <Equilibrium check/Lost load tolerance> "
                        "times the largest force the body carried in the "
                        "steps before. A "
                        "Newton iteration that does not halve a residual "
                        "already below 1e-6 F ends the step (or, with a "
                        "pore fluid, the solve of a fixed-stress "
                        "iteration) as converged (\"stagnated at 1e-6 of "
                        "the forces\" in its progress line): under a load "
                        "held constant a step starts in equilibrium up to "
                        "the points' motion, and the kinks of contact and "
                        "plasticity keep Newton from reaching the target "
                        "relative to that tiny first residual.",
                        Patterns::Double(0., 1.));
      prm.add_parameter("Residual floor",
                        residual_floor,
                        "An absolute floor of the stopping test, in the "
                        "units of the forces: the paper uses 1. 0 (the "
                        "default) makes the test relative, to ||R(du_0)|| "
                        "and to 1e-6 of the forces in the body, so that it "
                        "does not depend on the units.",
                        Patterns::Double(0.));
      prm.add_parameter("Maximum Newton iterations",
                        max_iterations,
                        "A step that has not converged after this many "
                        "iterations is rejected (and cut back).",
                        Patterns::Integer(1));
      prm.add_parameter("Linear tolerance",
                        linear_tolerance,
                        "Relative tolerance of GMRES on the Newton "
                        "correction.",
                        Patterns::Double(0., 1.));
      prm.add_parameter("Maximum linear iterations",
                        max_linear_iterations,
                        "GMRES iterations per Newton step at most. A "
                        "Newton solve in which GMRES reaches this limit "
                        "twice in a row having removed less than a tenth "
                        "of its residual fails at once (the step is then "
                        "cut back, or first retried, see <Direct retry>) "
                        "instead of going on with corrections that hardly "
                        "lower the residual.",
                        Patterns::Integer(1));
      prm.add_parameter("GMRES restart",
                        gmres_restart,
                        "Number of Krylov vectors before GMRES restarts.",
                        Patterns::Integer(2));
      prm.add_parameter("Finite difference parameter",
                        sqrt_eps_prec,
                        "sqrt(eps_prec) of Kelley's difference step h "
                        "(paper A.4); about 1e-7 for double precision.",
                        Patterns::Double(0., 1.));
      prm.add_parameter("Preconditioner",
                        preconditioner,
                        "Preconditioner of GMRES, built once per load step "
                        "from the stiffness at the points: none (the "
                        "paper's solver), jacobi, amg (algebraic "
                        "multigrid with the rigid-body near-null space), or "
                        "direct (a sparse LU factorization by Amesos KLU on "
                        "one rank: for small problems, up to a few 10^4 "
                        "dofs), or auto (direct up to <Direct solver "
                        "threshold> dofs, amg above). The factorization "
                        "serves where AMG fails on a nearly singular "
                        "plastic stiffness (a rigid footing on von Mises "
                        "soil at its limit load, a/h = 16, 1 rank: with "
                        "amg alone five steps were cut back, with direct "
                        "none; <Direct retry> takes it for the steps AMG "
                        "fails), but each of its applications costs more "
                        "than an AMG cycle (at 13,122 dofs in 2D 3.4 ms "
                        "more), which dominates where the Jacobian is far "
                        "from the stiffness and GMRES needs many "
                        "iterations either way (perfect plasticity).",
                        Patterns::Selection("none|jacobi|amg|direct|auto"));
      prm.add_parameter(
        "AMG near null space",
        amg_null_space,
        "The modes AMG's coarse levels represent exactly: rigid body modes "
        "(the dim translations and the rotations, the near-null space of "
        "elasticity: few GMRES iterations for any body, also a slender one "
        "in bending) or translations (the dim translations only: in 3D "
        "half the coarse unknowns, so about half the memory and set-up "
        "time of AMG, which suits compact 3D bodies; a slender body in "
        "bending then needs many more GMRES iterations).",
        Patterns::Selection("rigid body modes|translations"));
      prm.add_parameter(
        "AMG anisotropy threshold",
        amg_anisotropy_threshold,
        "With AMG: the nodes are grouped into AMG's aggregates by the "
        "distances between them instead of by the stiffness alone (ML's "
        "auxiliary matrix, weights 1/|x_i - x_j|^2): a connection whose "
        "weight is below this fraction of its nodes' (the scaled weight "
        "|a_ij| / sqrt(a_ii a_jj)) does not join two nodes into one "
        "aggregate. On a grid of stretched cells the aggregates then "
        "follow the short directions, along which the stiffness couples "
        "the nodes strongly (the polycrystal's 96 x 96 x 4 grid, cells 24 "
        "times longer in z than across: 140 GMRES iterations for its six "
        "tests instead of 601, half the run time); on cells up to about "
        "3:1 nothing is dropped at 0.01. On cells of equal sides (squares, "
        "cubes) the distances have no direction, and on a periodic grid "
        "they would drop the couplings across the period (the "
        "polycrystal's periodic tests: 103-168 GMRES iterations instead of "
        "37-94): there the aggregation is by the stiffness whatever this "
        "value. 0: aggregation by the "
        "stiffness only (ML's default). At most 0.5: an interior node of "
        "a grid of boxes has two nearest neighbours, so none of its "
        "connections weighs more than half, and a larger value would "
        "drop them all.",
        Patterns::Double(0., 0.5));
      prm.add_parameter("Direct solver threshold",
                        direct_threshold,
                        "With <Preconditioner> = auto: the largest number of "
                        "degrees of freedom for which the direct "
                        "factorization is used instead of AMG. 0 (the "
                        "default): 20000 in 2D, 1500 in 3D, about where a "
                        "factorization becomes dearer than AMG's set-up "
                        "(KLU's factors of a 3D stiffness fill in much "
                        "faster).",
                        Patterns::Integer(0));
      prm.add_parameter(
        "Direct retry",
        direct_retry,
        "With <Preconditioner> = amg: a load step that fails is tried "
        "again with the direct factorization before its increment is cut "
        "back, if the problem has at most <Direct solver threshold> "
        "degrees of freedom (0: 20000 in 2D, 1500 in 3D); the step after "
        "it goes back to AMG. It pays where the factorization solves what "
        "AMG cannot: at the knee of the load curve of a smooth rigid "
        "footing on von Mises soil (a/h = 16, 1 rank) Newton with AMG "
        "failed in three steps that the factorization solved in 7-8 "
        "iterations, 40 steps in 96 s with the two-rank answer against "
        "114 s, five cut-backs and a pressure 0.2 % higher without. It "
        "costs where the factorization fails as well or is the slower "
        "preconditioner (the prescribed-node footing of examples/footing "
        "with F-bar: a/h = 16 224-267 s against 132 s, a/h = 8 about "
        "twice the time), hence false by default. (A cut-back changes the path "
        "of the "
        "plastic points, and so the answer, within the error of the "
        "steps.)",
        Patterns::Bool());
      prm.add_parameter(
        "Preconditioner reuse steps",
        preconditioner_reuse_steps,
        "The preconditioner (AMG hierarchy or LU factors) may serve up to "
        "this many load steps before it is built anew from the stiffness of "
        "the current step. 1: a new one every step (the paper). "
        "Larger values save the set-up where the stiffness changes slowly; "
        "a preconditioner is always rebuilt after a failed step and when "
        "GMRES slows down (Preconditioner reuse growth) and when the "
        "constrained degrees of freedom change. Measured: a converged "
        "answer within the Newton tolerance of a rebuilt one in elastic "
        "and softening runs; with perfect plasticity (the footing with "
        "F-bar) more Newton iterations and cut-backs. 0 (the default): "
        "auto, 10 for elastic models, 1 for all others.",
        Patterns::Integer(0));
      prm.add_parameter(
        "Preconditioner update",
        preconditioner_update,
        "When the preconditioner's matrix is built: once per load step "
        "from the tangents of the committed state (load step, the paper), "
        "or in every Newton iteration from the consistent tangent of each "
        "point at the iterate (Newton iteration; at finite strain with "
        "the iterate's stress and geometry). A plastic model's committed "
        "tangent is elastic, and where the iterate yields GMRES has to "
        "make up the difference in "
        "every Newton iteration; the tangent at the iterate is the "
        "Jacobian (with F-bar too), so that with the direct factorization "
        "GMRES needs one or two iterations per Newton iteration. It costs "
        "an assembly and a factorization (or AMG set-up) per Newton "
        "iteration instead of per step: it pays where residuals are dear "
        "(the Mohr-Coulomb footing of examples/footing: half the time) "
        "or where AMG needs many GMRES iterations (its rigid footing at "
        "finite strain on 1 rank: two thirds of the time), not for a cheap "
        "von Mises return on a small grid (doc/benchmarks.md).",
        Patterns::Selection("load step|Newton iteration"));
      prm.add_parameter(
        "Preconditioner reuse growth",
        preconditioner_reuse_growth,
        "With reuse: the preconditioner is rebuilt before the next step "
        "once a step needed more than this factor times the GMRES "
        "iterations per Newton iteration of the first step after the last "
        "rebuild.",
        Patterns::Double(1.));
      Utils::add_selection<Forcing>(
        prm,
        "Forcing term",
        forcing,
        {{"constant", Forcing::constant},
         {"eisenstat-walker", Forcing::eisenstat_walker},
         {"auto", Forcing::automatic}},
        "constant: GMRES always solves to <Linear tolerance> (the paper); "
        "eisenstat-walker: adapt it to the Newton convergence (Eisenstat "
        "and Walker's choice 2), starting from <Linear tolerance>: loose "
        "where Newton is far from the solution, tight near it, and no "
        "solve (the linear predictor's included) further than the Newton "
        "target asks. The "
        "stopping test is on the nonlinear residual either way. auto: "
        "eisenstat-walker for elastic models, constant for all others.");
      prm.add_parameter("Line search steps",
                        max_line_search_steps,
                        "Backtracking: halve the Newton correction at most "
                        "this many times while ||R|| does not decrease. 0 "
                        "gives the paper's full Newton steps.",
                        Patterns::Integer(0, 30));
      Utils::add_selection<InitialGuess>(
        prm,
        "Initial guess",
        initial_guess,
        {{"boundary values", InitialGuess::boundary_values},
         {"linear predictor", InitialGuess::linear_predictor},
         {"extrapolation", InitialGuess::extrapolation},
         {"auto", InitialGuess::automatic}},
        "boundary values: the paper's du_0, the prescribed "
        "increments on constrained degrees of freedom and "
        "zero elsewhere; linear predictor: the solution of "
        "the problem linearized about zero free increments "
        "with the prescribed increments as data (one extra "
        "linear solve that makes the first Newton iterate "
        "independent of the cell size; a linear problem "
        "then converges in one iteration); extrapolation: "
        "the increment of the last converged load step, "
        "scaled to this step's load increment, with the "
        "prescribed increments on constrained degrees of "
        "freedom (no extra solve; under proportional "
        "loading it is close to the solution; the linear "
        "predictor serves in the first step, after a step "
        "that failed and after a restart; path following "
        "(Load stepping/Control) does not use it). Under "
        "proportional loading extrapolation often meets the "
        "stopping test without a Newton iteration. auto: "
        "extrapolation for elastic models with small-strain kinematics, "
        "the linear predictor for all others (with finite strain a "
        "rotating body's last increment points the wrong way: the "
        "cantilever example needed up to 20 Newton iterations and "
        "cut-backs with extrapolation, 3-8 with the predictor; with "
        "perfect plasticity the footing needed cut-backs).");
      prm.add_parameter("Verbose",
                        verbose,
                        "Print one line per Newton iteration: ||R||, GMRES "
                        "iterations and residual reached, line-search "
                        "step length.",
                        Patterns::Bool());
    }
    prm.leave_subsection();
  }



  NewtonParameters
  NewtonParameters::resolve(const bool elastic, const bool finite_strain) const
  {
    NewtonParameters resolved = *this;
    if (resolved.preconditioner_reuse_steps == 0)
      resolved.preconditioner_reuse_steps = elastic ? 10 : 1;
    if (resolved.forcing == Forcing::automatic)
      resolved.forcing =
        elastic ? Forcing::eisenstat_walker : Forcing::constant;
    if (resolved.initial_guess == InitialGuess::automatic)
      resolved.initial_guess = elastic && !finite_strain ?
                                 InitialGuess::extrapolation :
                                 InitialGuess::linear_predictor;
    return resolved;
  }



  unsigned int
  NewtonParameters::direct_threshold_for(const unsigned int dim) const
  {
    if (direct_threshold > 0)
      return direct_threshold;
    return dim < 3 ? 20000 : 1500;
  }
} // namespace qsmpm
