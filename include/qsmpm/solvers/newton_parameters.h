#ifndef qsmpm_solvers_newton_parameters_h
#define qsmpm_solvers_newton_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <qsmpm/base/parameter_struct.h>
#include <string>

namespace qsmpm
{
  using namespace dealii;

  /**
   * The subsection "Nonlinear solver": Newton's method of paper Appendix A.1
   * with GMRES (A.2) on the finite-difference Jacobian (A.3-A.4). The
   * initializers are the defaults of the entries.
   */
  struct NewtonParameters : ParameterStruct<NewtonParameters>
  {
    /// gamma of the stopping test ||R_n|| <= gamma max(floor, ||R_0||)
    /// (see internal::stopping_target()).
    double tolerance = 1e-6;
    /// An absolute floor of that test, in the units of the forces (the
    /// paper's 1); 0, the default, makes the test independent of the units.
    double residual_floor = 0.;
    /// Whether the stopping test is relative to ||R_0||, the residual of
    /// the step's prescribed increments (true, the paper), or to the
    /// residual of the solve's first iterate (false). The fixed-stress
    /// iterations of a pore fluid set it false after their first solve:
    /// each later solve restarts from a converged increment after a small
    /// change of the pore pressure, and must resolve the forces of that
    /// change, whatever their size against the step's load (a test
    /// relative to the load, or to a fixed floor, lets the solve return at
    /// once when they are small, and the pressure then changes by the same
    /// amount in every iteration).
    bool relative_to_load = true;
    /// An upper bound on the stopping target and on the residual at which
    /// a stagnating iteration is accepted, in the units of the forces; 0
    /// (the default): none. QuasiStaticProblem sets it to
    /// <Equilibrium check/Lost load tolerance> times the largest force the
    /// body has carried in the converged steps, so that a first residual made
    /// large by something other than the load (the overlap of a penalty contact
    /// in the first guess, where a rigid body moves in a step and the
    /// points do not) cannot end a step far from equilibrium.
    double       residual_ceiling = 0.;
    unsigned int max_iterations   = 20;
    /// GMRES stops at ||J s + R|| <= linear_tolerance ||R||.
    double       linear_tolerance      = 1e-3;
    unsigned int max_linear_iterations = 1000;
    unsigned int gmres_restart         = 50;
    /// sqrt(eps_prec) of Kelley's difference parameter (A.4).
    double sqrt_eps_prec = 1e-7;
    /// none, jacobi, amg, direct (see Preconditioner) or auto (direct up
    /// to direct_threshold_for(dim) dofs, amg above).
    std::string preconditioner = "amg";
    /// With preconditioner = auto: the largest number of dofs for direct;
    /// 0 = by the dimension (direct_threshold_for()).
    unsigned int direct_threshold = 0;
    /// With preconditioner = amg: a step that fails is tried again with
    /// the direct factorization before it is cut back, if the problem has
    /// at most direct_threshold_for() dofs (QuasiStaticProblem).
    bool direct_retry = false;
    /// AMG's near-null space: "rigid body modes" (translations and
    /// rotations) or "translations" (see Preconditioner).
    std::string amg_null_space = "rigid body modes";
    /// AMG aggregates nodes by their distances, dropping connections below
    /// this fraction (0: by the stiffness alone; see Preconditioner).
    double amg_anisotropy_threshold = 0.01;
    /// Load steps a preconditioner may serve before it is rebuilt (1 = a
    /// new one every step, as in the paper's runs; 0 = auto, see
    /// resolve()).
    unsigned int preconditioner_reuse_steps = 0;
    /// Rebuild early once GMRES needs this many times more iterations per
    /// Newton iteration than in the first step after the last rebuild.
    double preconditioner_reuse_growth = 2.;
    /// "load step": the preconditioner is built from the tangents of the
    /// committed state (the paper); "Newton iteration": in every Newton
    /// iteration from the consistent tangents at the iterate
    /// (QuasiStaticProblem, small strain in plane and 3D problems).
    std::string preconditioner_update = "load step";
    /// GMRES's tolerance in each Newton iteration.
    enum class Forcing
    {
      /// The fixed linear tolerance (the paper).
      constant,
      /// Eisenstat and Walker's forcing terms.
      eisenstat_walker,
      /// eisenstat_walker for elastic models, constant otherwise
      /// (resolve()).
      automatic
    };
    Forcing forcing = Forcing::automatic;
    /// Backtracking line search on ||R|| (halving, at most this many times).
    unsigned int max_line_search_steps = 0;
    /// Where Newton's first iterate of a load step comes from.
    enum class InitialGuess
    {
      /// The paper's du_0: the prescribed increments on constrained
      /// degrees of freedom, zero elsewhere.
      boundary_values,
      /// The solution of the problem linearized about zero free increments
      /// with the prescribed increments as data (see NewtonKrylov::solve()).
      linear_predictor,
      /// The increment of the last converged load step, scaled to this
      /// step's load increment, with the prescribed increments on the
      /// constrained degrees of freedom; the linear predictor where there is
      /// no such step (see QuasiStaticProblem).
      extrapolation,
      /// extrapolation for elastic models at small strain,
      /// linear_predictor otherwise (resolve()).
      automatic
    };
    InitialGuess initial_guess = InitialGuess::automatic;
    /// Print one line per Newton iteration (on the stream given to the
    /// solver).
    bool verbose = false;

    /// Declare the entries, bound to the members.
    void
    add_parameters(ParameterHandler &prm);

    /**
     * These parameters with every `auto` setting decided, for a model that
     * is elastic (@p elastic, ConstitutiveModel::is_elastic()) or not, at
     * finite strain or not (@p finite_strain):
     *  - elastic: a preconditioner serves up to 10 steps, Eisenstat-Walker
     *    forcing, the initial guess extrapolated from the last step (the
     *    linear predictor at finite strain, where a rotating body's last
     *    increment points the wrong way);
     *  - otherwise the paper's settings: a new preconditioner every step, a
     *    constant forcing term, the linear predictor (measured with the
     *    faster settings: the footing with perfect plasticity needed
     *    cut-backs or stopped, footing-large.prm gave q/c 5.80 instead of
     *    6.05).
     * Settings that are not `auto` are kept.
     */
    NewtonParameters
    resolve(const bool elastic, const bool finite_strain) const;

    /**
     * With preconditioner = auto, the largest number of dofs for which a
     * problem in @p dim dimensions gets the direct factorization:
     * direct_threshold, or with 0 (the default) 20000 in 2D and 1500 in
     * 3D, where KLU's factors fill in far faster and a factorization
     * costs more than AMG's set-up from about 1500 dofs on (measured with
     * benchmarks/cube-preconditioner.prm; doc/benchmarks.md, "Direct or
     * AMG by default").
     */
    unsigned int
    direct_threshold_for(const unsigned int dim) const;
  };
} // namespace qsmpm

#endif
