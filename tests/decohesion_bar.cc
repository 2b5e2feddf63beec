// A 1-D bar with one softening cell under displacement control, against the
// analytical curve (doc/references.md#one-dimensional-bar): a strip of n
// cells, length L, section A = h (per unit thickness), nu = 0 and u_y = 0
// everywhere, the left end fixed in x and the right end pulled by u = t.
// Only the middle cell may crack (normal x). Then
//   before the peak       P = E A u / L,
//   peak                  P = tau_nf A at u = tau_nf L / E,
//   after the peak        u = sigma L / E + u0 (1 - sigma / tau_nf),
//                         i.e. dP/du = A / (L/E - u0/tau_nf),
//   complete failure      at u = u0 = 2 G_f / tau_nf,
//   dissipated energy     integral P du = G_f A.
// Checked for one point per cell at h and h/2 (mesh objectivity: the
// energies agree within 3 %) and for 2x2 points per cell (the smearing
// length is the band width h, not the point size h/2). u0 = 0.01 (h/10 with
// 10 cells, h/5 with 20): the right end moves at most 1.1 u0 = 0.011, less
// than the distance from the last point to the grid's edge (h/2 = 0.05 and
// 0.025 with one point per cell, h/4 = 0.025 with 2 x 2), so no point
// leaves the grid; L < E u0 / tau_nf = 10 (no snap-back).
//
// Tolerances. The discrete bar reproduces the closed form exactly (uniform
// strain in each region, the points' quadrature exact for it, the peak and
// complete failure on load steps: 1e-3 = 20 du, u0 = 200 du, du = 5e-5),
// so only the Newton tolerance remains (measured errors <= 2e-10 with
// QSMPM_VERBOSE). The tolerances are loose on purpose and sized against
// load-step sampling and against the errors the test is to catch:
// - peak load 1 %: one load step on the softening branch lowers P by
//   0.56 % of the peak, so a peak detected one step late still passes;
//   peak displacement 1 %: one step is 5 % of u_peak;
// - post-peak slope 2 %: a smearing length h/2 instead of h (2 x 2 points)
//   changes the slope by about 50 %;
// - opening at failure 2 %: one load step is 0.5 % of u0;
// - dissipated energy 2 %: the trapezoidal rule is exact on this
//   piecewise-linear curve, a step's sampling changes it by < 0.1 %, and a
//   wrong smearing length changes it by a factor 2;
// - energy per unit area, h/2 against h, 3 %: without crack-band scaling
//   the energy scales with h, 100 % apart; 2 x 2 against 1 point, 2 %: a
//   smearing length of the point size h/2 would halve it.
#include "softening_bar.h"
#include "tests.h"

#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/fracture/load_displacement_curve.h>
#include <qsmpm/materials/decohesion.h>

using namespace qsmpm;

namespace
{
  const double E = 1000., tau = 1., G_f = 0.005, L = 1.;
  const double u0 = 2. * G_f / tau;

  LoadDisplacementCurve
  run_bar(const unsigned int n_cells, const unsigned int points_per_direction)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    problem.pcout().set_condition(false);
    const unsigned int right = make_softening_bar(
      problem, E, tau, G_f, L, n_cells, points_per_direction);

    auto &prm                                  = problem.parameters();
    prm.nonlinear_solver.tolerance             = 1e-9;
    prm.nonlinear_solver.residual_floor        = 0.;
    prm.nonlinear_solver.linear_tolerance      = 1e-10;
    prm.nonlinear_solver.max_line_search_steps = 4;
    prm.load_stepping.n_steps                  = 220;
    prm.load_stepping.final_load_factor        = 1.1 * u0;
    prm.material_points.update_volumes         = false;
    prm.output.directory                       = "results";
    prm.output.interval                        = 0;

    LoadDisplacementCurve curve;
    problem.set_step_callback(
      [&](const QuasiStaticProblem<2>::StepReport &report) {
        curve.add(report.step,
                  report.load_factor,
                  problem.reactions()[right][0]);
        return true;
      });
    problem.run();
    return curve;
  }

  /// Check the curve of a bar of section A = L / n against the analytical
  /// one; returns the dissipated energy.
  double
  check_bar(const unsigned int n_cells, const unsigned int points_per_direction)
  {
    const double A     = L / n_cells;
    const auto   curve = run_bar(n_cells, points_per_direction);
    deallog << n_cells << " cells, " << points_per_direction << "x"
            << points_per_direction << " points per cell" << std::endl;

    check("  peak load: |P_max / (tau_nf A) - 1|",
          curve.peak_force() / (tau * A) - 1.,
          0.01);
    check("  peak displacement: |u_peak / (tau_nf L / E) - 1|",
          curve.peak_displacement() / (tau * L / E) - 1.,
          0.01);

    // Post-peak slope from two points well inside the softening branch.
    const auto &points = curve.points();
    const auto  at     = [&](const double u) {
      for (const auto &p : points)
        if (p.displacement >= u - 1e-12)
          return p;
      return points.back();
    };
    const auto   p1 = at(0.25 * u0), p2 = at(0.75 * u0);
    const double slope =
      (p2.force - p1.force) / (p2.displacement - p1.displacement);
    const double slope_exact = A / (L / E - u0 / tau);
    check("  post-peak slope: |dP/du / (A / (L/E - u0/tau_nf)) - 1|",
          slope / slope_exact - 1.,
          0.02);

    // Complete failure: the first step at which the force has vanished.
    double u_failure = points.back().displacement;
    for (const auto &p : points)
      if (p.displacement > curve.peak_displacement() &&
          p.force < 1e-6 * curve.peak_force())
        {
          u_failure = p.displacement;
          break;
        }
    check("  opening at complete failure: |u_f / u0 - 1|",
          u_failure / u0 - 1.,
          0.02);
    check("  traction free after failure: |P_last| / P_max",
          points.back().force / curve.peak_force(),
          1e-6);
    const double energy = curve.work();
    check("  dissipated energy: |int P du / (G_f A) - 1|",
          energy / (G_f * A) - 1.,
          0.02);
    return energy / A;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  const double                     g_h  = check_bar(10, 1);
  const double                     g_h2 = check_bar(20, 1);
  check("mesh objectivity: |G(h/2) / G(h) - 1| (energy per unit area)",
        g_h2 / g_h - 1.,
        0.03);
  const double g_22 = check_bar(10, 2);
  check("2x2 points per cell: |G(2x2) / G(1) - 1| (energy per unit area)",
        g_22 / g_h - 1.,
        0.02);
}
