// A rigid footing pushed into von Mises (Tresca) soil by a force that rises
// and is then held constant: the case of a footing loaded by a building,
// and the first stage of consolidation under a constant load.
//
// The soil of the footing example: c = 100, E = 1e6, nu = 0.3, weightless,
// plane strain, 5 a x 5 a with a = 1 the footing's half-width, h = a/4,
// 2 x 2 points per cell, F-bar. The footing is a smooth rigid box over
// |x| <= a driven by the force 400 min(t, 1) per unit length (0.78 of
// Prandtl's (2 + pi) c a = 514): ten steps up to t = 1, then ten steps
// with the force held.
//
// Checks, each against what a rate-independent soil under a constant load
// must do:
// - Every step converges, without a cut-back, the held ones in at most 8
//   Newton iterations. (Before, the held steps' Newton target, relative to
//   their tiny first residual, lay below what the kinks of contact and
//   plasticity let Newton reach: a held step failed in 20 Newton
//   iterations, at every cut-back.)
// - The footing's force balances its load in every step (1e-9: the root
//   of the footing's equation is found to round-off).
// - The settlement stays where the ramp left it while the force is held:
//   within 1e-3 of it (the soil does not creep; what moves it at all is
//   that the points are moved after each step, and equilibrium on the
//   moved points differs from the last one by a little).
// - The first held step starts close to equilibrium: its first residual
//   is below 0.1 of that of a step of the ramp, because only the points'
//   motion in the last step changed, not the load. (Before, the contact
//   point of each point touching the footing was made anew every step from
//   the point's strain, which F-bar replaces in part by its cell's: the
//   footing's force jumped by up to 10 % between two steps at the same
//   position, and the first held step's residual was 2.2 times a ramp
//   step's.)
//
// Output from rank 0; the results do not depend on the number of ranks.
#include "prm_text.h"
#include "tests.h"

#include <algorithm>
#include <cmath>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>

using namespace qsmpm;

namespace
{
  std::string
  footing_prm()
  {
    return "set Dimension = 2\n"
           "subsection Geometry\n"
           "  set Lower corner = 0, 0\n"
           "  set Upper corner = 5, 5\n"
           "  set Subdivisions = 20, 20\n"
           "end\n"
           "subsection Material points\n"
           "  set Points per cell per direction = 2\n"
           "  set Volumetric locking = F-bar\n"
           "end\n"
           "subsection Material\n"
           "  set Model = von Mises\n"
           "  subsection von Mises\n"
           "    set Young's modulus = 1e6\n"
           "    set Poisson's ratio = 0.3\n"
           "    set Yield stress = 173.20508075688772\n"
           "    set Hardening modulus = 0\n"
           "  end\n"
           "end\n"
           "subsection Boundary conditions\n"
           "  set Dirichlet boundaries = 0:x, 1:x, 2:xy\n"
           "  subsection Rigid body\n"
           "    set Shape = box\n"
           "    set Name = footing\n"
           "    set Point = -1, 5\n"
           "    set Upper corner = 1, 6\n"
           "    set Friction = frictionless\n"
           "    set Penalty factor = 10\n"
           "    set Load direction = 0, -1\n"
           "    subsection Load\n"
           "      set Function expression = 400*min(t, 1)\n"
           "    end\n"
           "  end\n"
           "end\n"
           "subsection Load stepping\n"
           "  set Final load factor = 2\n"
           "  set Number of steps = 20\n"
           "  set Maximum cut-backs = 2\n"
           "end\n"
           "subsection Nonlinear solver\n"
           "  set Line search steps = 8\n"
           "end\n"
           "subsection Output\n"
           "  set Interval = 0\n"
           "  set Directory = contact-held-out\n"
           "end\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::MPILogInitAll       log;

  deallog << "A rigid footing on von Mises soil, its force raised in 10 "
             "steps, then held for 10"
          << std::endl;
  QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
  initialize_from_text(problem, footing_prm());
  std::vector<StepReport> steps;
  std::vector<double>     settlements, balances;
  problem.set_step_callback([&](const StepReport &report) {
    steps.push_back(report);
    settlements.push_back(problem.rigid_body_load_displacements().at(0));
    const double load = 400. * std::min(report.load_factor, 1.);
    balances.push_back(
      std::abs(problem.rigid_body_loads().at(0).force[1] / load - 1.));
    return true;
  });
  std::string message;
  try
    {
      problem.run();
    }
  catch (const std::exception &exc)
    {
      message = qsmpm::Utils::error_message(exc);
    }
  deallog << "  run " << (message.empty() ? "completed" : "stopped")
          << std::endl;
  if (!message.empty() && Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << message << std::endl;

  unsigned int cut_backs = 0, held_newton = 0;
  double       ramp_residual = 0.;
  for (const StepReport &step : steps)
    {
      cut_backs += step.cut_backs;
      if (step.load_factor <= 1. + 1e-12)
        ramp_residual = std::max(ramp_residual, step.newton.initial_residual);
      else
        held_newton = std::max(held_newton, step.newton.newton_iterations);
    }
  check_that("  20 steps, none cut back", steps.size() == 20 && cut_backs == 0);
  check_that("  at most 8 Newton iterations in each held step",
             held_newton <= 8);
  check("  footing's force against its load, every step: max |F / L - 1|",
        balances.empty() ? 1. :
                           *std::max_element(balances.begin(), balances.end()),
        1e-9);
  const bool held = settlements.size() == 20;
  check("  settlement while the force is held: |u(t = 2) / u(t = 1) - 1|",
        held ? settlements[19] / settlements[9] - 1. : 1.,
        1e-3);
  check("  first held step's first residual / a ramp step's largest",
        steps.size() > 10 ? steps[10].newton.initial_residual / ramp_residual :
                            1.,
        0.1);
}
