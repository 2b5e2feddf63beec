// Path following (Load stepping/Control = dissipation) with contact between
// deformable bodies: the softening bar of path_following_bar (L = 20 > E
// u0 / tau_nf, so that its softening branch bends back) as body A (material
// id 0, the cells 0 <= y <= h) and an elastic bar B of the same section on
// top of it (id 1, h <= y <= 2 h), frictionless contact between them, each
// on its own field. Both ends: the left held in x, the right pulled by
// u = t; every node held in y; nu = 0, so that the bars do not press on
// each other: their contact ties only what the supports hold.
//
// Known answer: B carries P_B = E A u / L at every step (elastic, uniform),
// so A carries P_A = P - P_B, P the pulled end's reaction, and A's
// analytical curve (doc/references.md#one-dimensional-bar): peak
// P_A = tau_nf A at u = 2 u0; after it, on the branch
// u = sigma L / E + u0 (1 - sigma / tau_nf), sigma = P_A / A, along which u
// decreases from 2 u0 to u0 (a snap-back of the whole structure, which
// displacement control would jump over). Checked as in path_following_bar:
// the peak of P_A within 1 %, every step on the branch within 1e-3 u0 (the
// accuracy asked of the dissipation per step), u back by at least 0.85 u0,
// 15 to 25 steps on the branch (20 increments of G_f A / 20). Before, such
// a run stopped at once ("path following cannot be used with several
// bodies yet").
#include "softening_bar.h"
#include "tests.h"

#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/fracture/load_displacement_curve.h>
#include <qsmpm/materials/decohesion.h>

using namespace qsmpm;

namespace
{
  const double E = 1000., tau = 1., G_f = 0.005, L = 20.;
  const double u0 = 2. * G_f / tau;
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  const unsigned int    n_cells = 20;
  const double          h = L / n_cells, A = h;
  const double          x_band = (n_cells / 2 + 0.5) * h;
  QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
  problem.pcout().set_condition(false);
  BodyContact<2>::Parameters contact;
  contact.bodies   = "0; 1";
  contact.friction = BodyContact<2>::Parameters::Friction::frictionless;
  problem.set_body_contact(contact);
  problem.grid().make_box(Point<2>(), Point<2>(L, 2. * h), {{n_cells, 2}});
  Tensor<1, 2> x_normal;
  x_normal[0] = 1.;
  auto model =
    std::make_unique<Decohesion<2>>(E, 0., true, tau, G_f, x_normal, h);
  // Only A's band cell may crack.
  model->set_crack_region([=](const Point<2> &x) {
    return std::abs(x[0] - x_band) < 0.5 * h && x[1] < h;
  });
  problem.set_model(std::move(model));
  problem.points().fill([](const Point<2> &) { return true; },
                        MaterialPointSet<2>::reference_rule(
                          MaterialPointSet<2>::Placement::regular, {{1, 1}}),
                        [h](const Point<2> &x) { return x[1] > h ? 1u : 0u; });
  auto               &bcs = problem.boundary_conditions();
  std::array<bool, 2> x_only{{true, false}}, y_only{{false, true}};
  const auto          zero = std::make_shared<Functions::ZeroFunction<2>>(2);
  bcs.add_dirichlet_boundary(0, x_only, zero);
  bcs.add_dirichlet_nodes(
    "all y", [](const Point<2> &) { return true; }, y_only, zero);
  const unsigned int right = bcs.dirichlet_conditions().size();
  bcs.add_dirichlet_boundary(1, x_only, std::make_shared<Pull>());

  auto &prm                                  = problem.parameters();
  prm.nonlinear_solver.tolerance             = 1e-9;
  prm.nonlinear_solver.residual_floor        = 0.;
  prm.nonlinear_solver.linear_tolerance      = 1e-10;
  prm.nonlinear_solver.max_line_search_steps = 4;
  prm.load_stepping.control                  = "dissipation";
  prm.load_stepping.dissipation_increment    = G_f * A / 20.;
  prm.load_stepping.n_steps                  = 60;
  prm.load_stepping.final_load_factor        = 3. * u0;
  prm.material_points.update_volumes         = false;
  prm.output.directory                       = "results";
  prm.output.interval                        = 0;

  // A's load at each step; the run stops once it has fallen below a tenth
  // of its peak.
  std::vector<std::pair<double, double>> curve; // (u, P_A)
  double                                 peak = 0., u_peak = 0.;
  problem.set_step_callback(
    [&](const QuasiStaticProblem<2>::StepReport &report) {
      const double u   = report.load_factor;
      const double P_A = problem.reactions()[right][0] - E * A * u / L;
      curve.emplace_back(u, P_A);
      if (P_A > peak)
        {
          peak   = P_A;
          u_peak = u;
        }
      return !(peak > 0.9 * tau * A && P_A < 0.1 * peak);
    });
  problem.run();

  check("peak of A: |P_A,max / (tau_nf A) - 1|", peak / (tau * A) - 1., 0.01);
  check("peak displacement: |u_peak / (tau_nf L / E) - 1|",
        u_peak / (tau * L / E) - 1.,
        0.01);
  double       largest_distance = 0., u_min = u_peak;
  unsigned int on_branch = 0;
  bool         past_peak = false;
  for (const auto &[u, P_A] : curve)
    {
      if (!past_peak)
        {
          past_peak = P_A == peak;
          continue;
        }
      u_min = std::min(u_min, u);
      if (P_A > 1e-6 * tau * A)
        {
          ++on_branch;
          const double sigma = P_A / A;
          largest_distance =
            std::max(largest_distance,
                     std::abs(u - (sigma * L / E + u0 * (1. - sigma / tau))) /
                       u0);
        }
    }
  check_that("stopped below a tenth of the peak",
             curve.back().second < 0.1 * peak);
  check("largest distance of a step from A's branch / u0",
        largest_distance,
        1e-3);
  check_at_least("snap-back (u_peak - u_min) / u0",
                 (u_peak - u_min) / u0,
                 0.85);
  check_that("15 to 25 steps on the branch",
             on_branch >= 15 && on_branch <= 25);
}
