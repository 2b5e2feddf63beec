#include <qsmpm/solvers/newton_parameters.h>

namespace qsmpm
{
  void
  NewtonParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlinear solver");
    {
      prm.declare_entry("Tolerance",
                        "1e-6",
                        Patterns::Double(0., 1.),
                        "gamma of the Newton stopping test ||R(du_n)|| <= "
                        "gamma max(floor, ||R(du_0)||) (paper A.1, step 2).");
      prm.declare_entry("Residual floor",
                        "1.0",
                        Patterns::Double(0.),
                        "The absolute floor of the stopping test; the "
                        "paper uses 1 (in the units of the forces).");
      prm.declare_entry("Maximum Newton iterations",
                        "20",
                        Patterns::Integer(1),
                        "A step that has not converged after this many "
                        "iterations is rejected (and cut back).");
      prm.declare_entry("Linear tolerance",
                        "1e-3",
                        Patterns::Double(0., 1.),
                        "Relative tolerance of GMRES on the Newton "
                        "correction.");
      prm.declare_entry("Maximum linear iterations",
                        "1000",
                        Patterns::Integer(1),
                        "GMRES iterations per Newton step at most.");
      prm.declare_entry("GMRES restart",
                        "50",
                        Patterns::Integer(2),
                        "Number of Krylov vectors before GMRES restarts.");
      prm.declare_entry("Finite difference parameter",
                        "1e-7",
                        Patterns::Double(0., 1.),
                        "sqrt(eps_prec) of Kelley's difference step h "
                        "(paper A.4); about 1e-7 for double precision.");
      prm.declare_entry("Preconditioner",
                        "amg",
                        Patterns::Selection("none|jacobi|amg|direct"),
                        "Preconditioner of GMRES, built once per load step "
                        "from the stiffness at the points: none (the "
                        "paper's solver), jacobi, amg (algebraic "
                        "multigrid with the rigid-body near-null space), or "
                        "direct (a sparse LU factorization by Amesos KLU on "
                        "one rank: for small problems, up to a few 10^4 "
                        "dofs).");
      prm.declare_entry(
        "Preconditioner reuse steps",
        "1",
        Patterns::Integer(1),
        "The preconditioner (AMG hierarchy or LU factors) may serve up to "
        "this many load steps before it is built anew from the stiffness of "
        "the current step. 1: a new one every step (the default). Larger "
        "values save the set-up where the stiffness changes slowly; a "
        "preconditioner is always rebuilt after a failed step and when "
        "GMRES slows down (Preconditioner reuse growth).");
      prm.declare_entry(
        "Preconditioner reuse growth",
        "2",
        Patterns::Double(1.),
        "With reuse: the preconditioner is rebuilt before the next step "
        "once a step needed more than this factor times the GMRES "
        "iterations per Newton iteration of the first step after the last "
        "rebuild.");
      prm.declare_entry("Forcing term",
                        "constant",
                        Patterns::Selection("constant|eisenstat-walker"),
                        "constant: GMRES always solves to <Linear "
                        "tolerance> (the paper); eisenstat-walker: adapt it "
                        "to the Newton convergence (Eisenstat and Walker's "
                        "choice 2), starting from <Linear tolerance>.");
      prm.declare_entry("Line search steps",
                        "0",
                        Patterns::Integer(0, 30),
                        "Backtracking: halve the Newton correction at most "
                        "this many times while ||R|| does not decrease. 0 "
                        "gives the paper's full Newton steps.");
      prm.declare_entry("Initial guess",
                        "linear predictor",
                        Patterns::Selection("boundary values|linear predictor"),
                        "boundary values: the paper's du_0, the prescribed "
                        "increments on constrained degrees of freedom and "
                        "zero elsewhere; linear predictor: the solution of "
                        "the problem linearized about zero free increments "
                        "with the prescribed increments as data (one extra "
                        "linear solve that makes the first Newton iterate "
                        "independent of the cell size; a linear problem "
                        "then converges in one iteration).");
      prm.declare_entry("Verbose",
                        "false",
                        Patterns::Bool(),
                        "Print one line per Newton iteration: ||R||, GMRES "
                        "iterations and residual reached, line-search "
                        "step length.");
    }
    prm.leave_subsection();
  }



  void
  NewtonParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlinear solver");
    {
      tolerance             = prm.get_double("Tolerance");
      residual_floor        = prm.get_double("Residual floor");
      max_iterations        = prm.get_integer("Maximum Newton iterations");
      linear_tolerance      = prm.get_double("Linear tolerance");
      max_linear_iterations = prm.get_integer("Maximum linear iterations");
      gmres_restart         = prm.get_integer("GMRES restart");
      sqrt_eps_prec         = prm.get_double("Finite difference parameter");
      max_line_search_steps = prm.get_integer("Line search steps");
      preconditioner        = prm.get("Preconditioner");
      preconditioner_reuse_steps =
        prm.get_integer("Preconditioner reuse steps");
      preconditioner_reuse_growth =
        prm.get_double("Preconditioner reuse growth");
      eisenstat_walker = prm.get("Forcing term") == "eisenstat-walker";
      verbose          = prm.get_bool("Verbose");
      linear_predictor = prm.get("Initial guess") == "linear predictor";
    }
    prm.leave_subsection();
  }
} // namespace qsmpm
