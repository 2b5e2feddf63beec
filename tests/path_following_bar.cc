// Path following (Load stepping/Control = dissipation) through a snap-back:
// the 1-D bar of decohesion_bar, but long, L = 20 > E u0 / tau_nf = 10, so
// that the softening branch bends back
// (doc/references.md#one-dimensional-bar):
//   before the peak       P = E A u / L,
//   peak                  P = tau_nf A at u = tau_nf L / E = 2 u0,
//   after the peak        u = sigma L / E + u0 (1 - sigma / tau_nf),
//                         which here decreases from 2 u0 to u0,
//   complete failure      at u = u0, then P = 0,
//   dissipated energy     integral P du = G_f A.
// Displacement control jumps from the peak to complete failure (the step
// past 2 u0 has no solution on the softening branch); path following must
// trace the branch with decreasing u. The run stops once the stress has
// fallen below tau_nf / 10 (u = 1.1 u0 on the branch; the last step, with
// the remaining energy, may reach complete failure at u0). Checked: peak, the
// distance of every step from the analytical curve, how far u came back,
// the number of steps on the branch, the work of the load against the
// dissipated plus the elastic energy at the end,
//   W = G_f A (1 - s^2) + sigma^2 A L / (2 E),   s = sigma / tau_nf,
// and that every step dissipated about the prescribed increment.
//
// Tolerances. As in decohesion_bar the discrete bar is exact (uniform
// strain per region), so only the Newton tolerance 1e-9 remains (measured
// errors <= 1e-10 with QSMPM_VERBOSE):
// - peak 1 %: the elastic steps are u0 / 20 = 2.5 % of u_peak = 2 u0, and
//   the peak falls on one of them;
// - distance from the branch 1e-3 u0 and work of the load 1e-3 relative:
//   the relative accuracy asked of the dissipation per step (1e-3), far
//   above the Newton tolerance and far below the branch's extent u0 (the
//   trapezoidal rule is exact on the piecewise-linear curve);
// - snap-back >= 0.85 u0: on the branch u = u0 (1 + s), s = sigma/tau_nf,
//   and the run stops at s <= 0.1, so u comes back by at least 0.9 u0;
//   less the peak displacement's tolerance (1 % of 2 u0) and the branch
//   tolerance, rounded down;
// - 15 to 25 steps on the branch: 20 increments of G_f A / 20 dissipate
//   the branch's G_f A (1 - s^2) >= 0.99 G_f A; +-5 allows partial
//   increments at the peak and at complete failure and cut-back steps.
#include "tests.h"

#include <deal.II/base/function.h>
#include <iostream>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/fracture/load_displacement_curve.h>
#include <qsmpm/materials/decohesion.h>

using namespace qsmpm;

namespace
{
  const double E = 1000., tau = 1., G_f = 0.005, L = 20.;
  const double u0 = 2. * G_f / tau;

  /// u_x = t.
  class Pull : public Function<2>
  {
  public:
    Pull()
      : Function<2>(2)
    {
    }
    double
    value(const Point<2> &, const unsigned int c) const override
    {
      return c == 0 ? get_time() : 0.;
    }
  };
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  const unsigned int    n_cells = 20;
  const double          h = L / n_cells, A = h;
  QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
  problem.pcout().set_condition(false);
  problem.grid().make_box(Point<2>(), Point<2>(L, h), {{n_cells, 1}});
  Tensor<1, 2> x_normal;
  x_normal[0] = 1.;
  auto model =
    std::make_unique<Decohesion<2>>(E, 0., true, tau, G_f, x_normal, h);
  const double x_band = (n_cells / 2 + 0.5) * h;
  model->set_crack_region(
    [=](const Point<2> &x) { return std::abs(x[0] - x_band) < 0.5 * h; });
  problem.set_model(std::move(model));
  problem.points().fill([](const Point<2> &) { return true; },
                        1,
                        MaterialPointSet<2>::Placement::regular);

  auto               &bcs = problem.boundary_conditions();
  std::array<bool, 2> x_only{{true, false}}, y_only{{false, true}};
  const auto          zero = std::make_shared<Functions::ZeroFunction<2>>(2);
  bcs.add_dirichlet_boundary(0, x_only, zero);
  bcs.add_dirichlet_nodes(
    "all y", [](const Point<2> &) { return true; }, y_only, zero);
  const unsigned int right = bcs.dirichlet_conditions().size();
  bcs.add_dirichlet_boundary(1, x_only, std::make_shared<Pull>());

  // 20 steps of G_f A / 20 on the softening branch; elastic steps (and
  // those after complete failure) of u0 / 20.
  const double dissipation                   = G_f * A / 20.;
  auto        &prm                           = problem.parameters();
  prm.nonlinear_solver.tolerance             = 1e-9;
  prm.nonlinear_solver.residual_floor        = 0.;
  prm.nonlinear_solver.linear_tolerance      = 1e-10;
  prm.nonlinear_solver.max_line_search_steps = 4;
  prm.load_stepping.control                  = "dissipation";
  prm.load_stepping.dissipation_increment    = dissipation;
  prm.load_stepping.n_steps                  = 60;
  prm.load_stepping.final_load_factor        = 3. * u0;
  prm.material_points.update_volumes         = false;
  prm.output.directory                       = "results";
  prm.output.interval                        = 0;

  LoadDisplacementCurve curve;
  unsigned int          newton_max = 0;
  problem.set_step_callback(
    [&](const QuasiStaticProblem<2>::StepReport &report) {
      curve.add(report.step, report.load_factor, problem.reactions()[right][0]);
      newton_max = std::max(newton_max, report.newton.newton_iterations);
      return !curve.fallen_below(0.1);
    });
  problem.run();

  check("peak load: |P_max / (tau_nf A) - 1|",
        curve.peak_force() / (tau * A) - 1.,
        0.01);
  check("peak displacement: |u_peak / (tau_nf L / E) - 1|",
        curve.peak_displacement() / (tau * L / E) - 1.,
        0.01);

  // Every step after the peak on the analytical curve, u(sigma), as long as
  // the bar carries load; the smallest u and the steps on the branch.
  const auto &points = curve.points();
  check_that("stopped below a tenth of the peak", curve.fallen_below(0.1));
  double       largest_distance = 0., u_min = curve.peak_displacement();
  unsigned int on_branch = 0, dissipation_exceeded = 0, full_increments = 0;
  bool         past_peak = false;
  for (unsigned int i = 0; i < points.size(); ++i)
    {
      const auto &p = points[i];
      if (i > 0 && past_peak)
        {
          // The energy dissipated in the step: the work of the load less
          // the change of the elastic energy P^2 L / (2 E A) (the model
          // unloads with the elastic stiffness, and the bar is statically
          // determinate).
          const auto  &q = points[i - 1];
          const double D =
            0.5 * (q.force + p.force) * (p.displacement - q.displacement) -
            0.5 * (p.force * p.force - q.force * q.force) * L / (E * A);
          dissipation_exceeded += D > (1. + 1e-3) * dissipation;
          full_increments += std::abs(D - dissipation) <= 1e-3 * dissipation;
        }
      past_peak = past_peak || p.force == curve.peak_force();
      if (!past_peak || p.force == curve.peak_force())
        continue;
      u_min = std::min(u_min, p.displacement);
      if (p.force > 1e-6 * tau * A)
        {
          ++on_branch;
          const double sigma = p.force / A;
          const double u     = sigma * L / E + u0 * (1. - sigma / tau);
          largest_distance =
            std::max(largest_distance, std::abs(p.displacement - u) / u0);
        }
    }
  check("softening branch: max |u - (sigma L/E + u0 (1 - sigma/tau_nf))| / u0",
        largest_distance,
        1e-3);
  check_at_least("snap-back traced: (u_peak - min u after the peak) / u0",
                 (curve.peak_displacement() - u_min) / u0,
                 0.85);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << "steps on the branch " << on_branch << ", full increments "
              << full_increments << ", u_min / u0 " << u_min / u0
              << ", Newton at most " << newton_max << std::endl;
  check_that("steps on the softening branch: 15 to 25",
             on_branch >= 15 && on_branch <= 25);
  check_that("no step past the peak dissipates more than the increment",
             dissipation_exceeded == 0);
  check_that("at least 15 steps past the peak dissipate the increment "
             "within 1e-3",
             full_increments >= 15);
  const double s_end = points.back().force / (tau * A);
  check("work of the load: |int P du / (G_f A (1 - s^2) + sigma^2 A L/(2E)) "
        "- 1|",
        curve.work() / (G_f * A * (1. - s_end * s_end) +
                        0.5 * s_end * s_end * tau * tau * A * L / E) -
          1.,
        1e-3);
  check_that("Newton iterations per step: at most 20",
             newton_max >= 1 && newton_max <= 20);
}
