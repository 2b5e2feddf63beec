// Elastoplasticity on a boundary-value problem (issue 11): Prandtl's smooth
// rigid strip footing on a weightless von Mises soil in plane strain, small
// strain, on a coarse grid (a/h = 4, 16 x 16 cells, 2 x 2 points per cell;
// the example examples/footing runs the fine grids).
//
// 1. With F-bar the limit pressure q/c at the end of the curve is within 8 %
//    of Prandtl's (2 + pi) = 5.1416 (an exact limit-analysis result). The
//    tolerance allows for the coarse grid: on it a bilinear grid carries
//    the footing's edge singularity over a quarter of the footing, and the
//    example measures 2-3 % at a/h = 16 (doc/example_footing.md).
//    Without F-bar (volumetric locking) the pressure at the same settlement
//    is at least 10 % higher than with F-bar: the test fails if the F-bar
//    treatment is not active or does not remove the excess constraints.
// 2. The same load-displacement curve on 1 and on all ranks: the curve is
//    computed once on MPI_COMM_SELF (every rank alone) and once on
//    MPI_COMM_WORLD and compared point by point to 1e-6 relative (the
//    Newton tolerance is 1e-9).
// 3. Newton converges quadratically in a plastic step: the footing on a
//    hardening soil (H = E/10, F-bar), 10 steps, exact linear solves; the
//    relative residuals r_k satisfy r_{k+1} <= 100 r_k^2 from r_k <= 1e-2
//    until the round-off floor, and the step takes 2 to 12 iterations.
//    (With perfect plasticity the plastic zone still changes during the
//    first iterations of a step; the asymptotic rate is the same, but it
//    sets in later.) The residuals are printed to stdout only.
#include "nodal_footing.h"

using namespace qsmpm;

namespace
{
  const double sigma_y = 173.20508075688772;
  const double c = sigma_y / std::sqrt(3.), prandtl = 2. + numbers::PI;

  struct Result : nodal_footing::Result
  {
    std::vector<double> history; // Newton residuals of the last step
  };

  Result
  run(const MPI_Comm     comm,
      const std::string &locking,
      const unsigned int steps,
      const std::string &solver,
      const double       hardening = 0.)
  {
    std::ostringstream text;
    text << "set Dimension = 2\n"
         << "subsection Material points\n"
         << "  set Points per cell per direction = 2\n"
         << "  set Volumetric locking = " << locking << "\nend\n"
         << "subsection Material\n  set Model = von Mises\n"
         << "  subsection von Mises\n"
         << "    set Young's modulus = 1e6\n    set Poisson's ratio = 0.3\n"
         << "    set Yield stress = " << std::setprecision(17) << sigma_y
         << "\n    set Hardening modulus = " << hardening << "\n  end\nend\n"
         << "subsection Load stepping\n  set Number of steps = " << steps
         << "\nend\n"
         << "subsection Nonlinear solver\n"
         << solver << "end\n"
         << "subsection Output\n  set Interval = 0\n"
         << "  set Directory = footing-out\nend\n";
    Result result;
    static_cast<nodal_footing::Result &>(result) = nodal_footing::run(
      comm, text.str(), 4., c, [&result](QuasiStaticProblem<2> &problem) {
        result.history = problem.step_reports().back().newton.residual_history;
      });
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  // Line search: where the plastic zone grows, full Newton steps may
  // overshoot (the paper's default is no line search).
  const std::string solver =
    "  set Tolerance = 1e-9\n  set Line search steps = 8\n";

  deallog << "1. Limit pressure with and without F-bar (a/h = 4)" << std::endl;
  const Result fbar = run(MPI_COMM_WORLD, "F-bar", 20, solver);
  const Result none = run(MPI_COMM_WORLD, "none", 20, solver);
  check_that("  F-bar: 20 steps converged", fbar.completed);
  check_that("  none: 20 steps converged", none.completed);
  if (!fbar.completed || !none.completed)
    deallog << fbar.message << none.message << std::endl;
  const double q_fbar = fbar.pressure_over_c.back();
  const double q_none = none.pressure_over_c.back();
  check("  F-bar: |q/c - (2 + pi)| / (2 + pi)",
        (q_fbar - prandtl) / prandtl,
        0.08);
  check_at_least("  none: q_none / q_F-bar - 1", q_none / q_fbar - 1., 0.10);
  // The curve has a plateau: the last fifth of the settlement adds < 2 %.
  check("  F-bar: change of q over the last 20 % of the settlement",
        q_fbar / fbar.pressure_over_c[15] - 1.,
        0.02);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << "q/c: F-bar " << q_fbar << ", none " << q_none << ", Prandtl "
              << prandtl << std::endl;

  deallog << "2. The same curve on one rank and on all ranks" << std::endl;
  const Result serial     = run(MPI_COMM_SELF, "F-bar", 20, solver);
  double       difference = 0.;
  for (unsigned int i = 0; i < serial.pressure_over_c.size(); ++i)
    difference =
      std::max(difference,
               std::abs(serial.pressure_over_c[i] / fbar.pressure_over_c.at(i) -
                        1.));
  check_that("  serial run converged", serial.completed);
  check("  max relative difference of q over the curve", difference, 1e-6);

  deallog << "3. Quadratic Newton convergence in a plastic step" << std::endl;
  const Result exact =
    run(MPI_COMM_WORLD,
        "F-bar",
        10,
        "  set Tolerance = 1e-13\n  set Linear tolerance = 1e-12\n"
        "  set Forcing term = constant\n"
        "  set Initial guess = linear predictor\n"
        "  set Maximum linear iterations = 400\n"
        "  set Maximum Newton iterations = 30\n",
        /*hardening=*/1e5);
  check_that("  completed", exact.completed);
  // Quadratic convergence: r_{k+1} <= C r_k^2 with a bounded C. Linear
  // convergence (rate rho) gives C = rho / r_k, superlinear convergence of
  // order p < 2 gives C ~ r_k^(p-2): both grow without bound as r_k -> 0,
  // and exceed C = 100 for r_k below 1e-3 unless the rate is tiny.
  bool         quadratic = true;
  unsigned int n_checked = 0;
  const auto  &h         = exact.history;
  for (unsigned int k = 0; k + 1 < h.size(); ++k)
    {
      const double r = h[k] / h[0], r_next = h[k + 1] / h[0];
      if (r <= 1e-2 && r_next > 1e-12)
        {
          ++n_checked;
          quadratic = quadratic && r_next <= 100. * r * r;
        }
    }
  check_that("  r_{k+1} <= 100 r_k^2 in every iteration from r_k <= 1e-2 "
             "to the floor (at least two)",
             quadratic && n_checked >= 2);
  // The number of iterations as a range: at least 2 (a plastic step is
  // nonlinear: the plastic zone and the return mapping change in it), at
  // most 12: Newton that has lost quadratic convergence, e.g. linear at
  // rate 0.1, would need 13 iterations from r = 1 to the tolerance 1e-13.
  const unsigned int iterations = h.empty() ? 0 : h.size() - 1;
  check_that("  Newton iterations of the last step: 2 to 12",
             iterations >= 2 && iterations <= 12);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::cout << "Newton residuals of the last step (relative):";
      for (const double r : h)
        std::cout << ' ' << std::scientific << std::setprecision(1) << r / h[0];
      std::cout << std::endl;
    }
}
