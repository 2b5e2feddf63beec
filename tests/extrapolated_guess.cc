// The extrapolated initial guess of an elastic model at small strain
// (Initial guess = auto or extrapolation): each step's first iterate
// extrapolates the rate du / dt of the last two converged steps linearly
// (QuasiStaticProblem::extrapolated_guess()).
//
// A strip on rollers, 16 x 16 cells, linear elastic (E = 1e6, nu = 0.3),
// points that neither move nor change their volume: the residual is then
// linear in du with the same stiffness K in every step, R(du) = K du -
// df_n, and the step's solution is K^-1 df_n. The traction on the left
// half of the top follows a load history p(t); 5 equal load steps. The
// measure is the first iterate's residual relative to that of the paper's
// du_0 = 0, rho_n = ||R(guess)|| / ||R(0)|| (Newton's residual history).
// Analysis, with df_n = p(t_n) - p(t_{n-1}):
//
// 1. p = t^2 (df_n proportional to 2n - 1): in step 2 the last step's rate
//    alone, guess K^-1 df_1, rho_2 = (df_2 - df_1) / df_2 = 2/3; from step
//    3 on the rate is linear in t and its extrapolation exact: rho_n = 0
//    up to what Newton left in the last two steps (tolerance 1e-10; checked
//    <= 1e-6). Extrapolating only the last step's increment would leave
//    rho_n = 2 / (2n - 1) (0.4, 0.29, 0.22).
// 2. p = t up to t = 0.6, then back (df = 0.2, 0.2, 0.2, -0.2, -0.2):
//    step 4, where the load turns, rho_4 = |df_3 - df_4| / |df_4| = 2;
//    in step 5 the last two rates point opposite ways, and their change
//    says nothing about this step's: the last step's rate alone, exact,
//    rho_5 = 0 (<= 1e-6). Extrapolating the change of rate would give
//    rho_5 = 2.
// 3. The displacements of case 1 agree with those of the linear
//    predictor (Initial guess = linear predictor) to 1e-8 of the largest
//    (both solved to a Newton tolerance of 1e-10).
#include "prm_text.h"
#include "tests.h"

#include <qsmpm/core/quasi_static_problem.h>

using namespace qsmpm;

namespace
{
  std::string
  strip(const std::string &pressure, const std::string &initial_guess)
  {
    return "set Dimension = 2\n"
           "subsection Geometry\n  set Subdivisions = 16,16\nend\n"
           "subsection Material points\n"
           "  set Move points = false\n"
           "  set Update volumes = false\n"
           "end\n"
           "subsection Material\n  set Model = linear elastic\n"
           "  subsection linear elastic\n"
           "    set Young's modulus = 1e6\n"
           "    set Poisson's ratio = 0.3\n"
           "  end\nend\n"
           "subsection Boundary conditions\n"
           "  set Dirichlet boundaries = 0:x, 1:x, 2:y\n"
           "  set Traction boundaries = 3\n"
           "  subsection Traction\n"
           "    set Function expression = 0; -1e3*(" +
           pressure +
           ")*(x<0.5 ? 1 : 0)\n"
           "  end\nend\n"
           "subsection Load stepping\n  set Number of steps = 5\nend\n"
           "subsection Nonlinear solver\n"
           "  set Tolerance = 1e-10\n"
           "  set Initial guess = " +
           initial_guess +
           "\n"
           "end\n"
           "subsection Output\n  set Interval = 0\n"
           "  set Directory = extrapolated-guess-out\nend\n";
  }

  struct Run
  {
    /// rho_n of steps 1-5.
    std::vector<double>                           rho;
    std::map<types::particle_index, Tensor<1, 2>> displacement;
  };

  Run
  run(const std::string &pressure, const std::string &initial_guess)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    initialize_from_text(problem, strip(pressure, initial_guess));
    Run result;
    problem.set_step_callback(
      [&](const QuasiStaticProblem<2>::StepReport &report) {
        const auto &newton = report.newton;
        result.rho.push_back(newton.residual_history.front() /
                             newton.initial_residual);
        return true;
      });
    problem.run();
    result.displacement = point_displacements(problem);
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  deallog << "1. p = t^2" << std::endl;
  const Run quadratic = run("t*t", "auto");
  check("step 2: |rho_2 - 2/3|", quadratic.rho[1] - 2. / 3., 1e-6);
  for (unsigned int n = 3; n <= 5; ++n)
    check("step " + std::to_string(n) + ": rho_" + std::to_string(n),
          quadratic.rho[n - 1],
          1e-6);

  deallog << "2. p = t, turning at t = 0.6" << std::endl;
  const Run turning = run("t < 0.6 + 1e-9 ? t : 1.2 - t", "extrapolation");
  check("step 4: |rho_4 - 2|", turning.rho[3] - 2., 1e-6);
  check("step 5: rho_5", turning.rho[4], 1e-6);

  deallog << "3. p = t^2: against the linear predictor" << std::endl;
  const Run predictor = run("t*t", "linear predictor");
  check("max |u_extrapolated - u_predictor| / max |u|",
        max_relative_difference(predictor.displacement, quadratic.displacement),
        1e-8);
}
