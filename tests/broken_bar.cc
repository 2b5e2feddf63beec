// A bar that breaks completely and whose two pieces then move apart by most
// of a cell and back (doc/references.md#broken-bar): the far tail of a
// fracture test, where the points of the failed band have no stiffness
// across the crack and the intact points beside them cross cells.
//
// The bar of decohesion_bar (E = 1000, nu = 0, tau_nf = 1, G_f = 0.005,
// u0 = 2 G_f / tau_nf = 0.01, one point per cell, the band cell [2, 3]
// cracks with normal x), 5 cells of h = 1 on a grid of 8 (room to move):
// the left end held in x, every node in y, the nodes at x = 5 moved by
//   u(t) = t           for t <= 0.8  (out to 0.8 h),
//   u(t) = 1.6 - t     for t >  0.8  (back to 0.2 h at t = 1.4).
// Beyond u = h/2 the right piece's first point leaves the cell [3, 4], and
// the node x = 3 is left with the failed band point alone: no stiffness in
// x. Such a dof must be held (Material points/Minimum nodal stiffness),
// or the step's Jacobian is singular.
//
// Exact answers: the peak tau_nf A; the work of the load up to complete
// failure G_f A; after failure no load at all, pulling (the crack is open)
// and pushing back (a completely failed crack closes without traction, down
// to the opening u0, far below the 0.2 h where the test stops).
//
// Tolerances: energy 2 % (as decohesion_bar: load-step sampling < 0.1 %);
// load after failure 1e-6 of the peak (the Newton tolerance is 1e-9 of the
// residual's scale; a crack that locked when closing would push back with
// the band's full stiffness, E A / h times 1e-3 h per step = the peak, and
// a node held while a point still gives it stiffness would show as a load).
// The run without the hold (fraction 0) is reported as a control: it must
// stop at the first step with a dof without stiffness.
//
// 1400 load steps of exactly 0.001: the right piece's first point ends
// step 1100 on the way back on the cell face x = 4 (to a few ulps). There
// every dof has stiffness, yet the step's Jacobian is singular: the point,
// at xi = 1 of its cell, stiffens the nodes x = 3 only against their common
// motion, and the opposite motion of the top and bottom node, with the
// band point failed, has none. The direct factorization then returned
// infinities. The hold finds that motion as the null vector of the 2 x 2
// block of the two dofs in K and holds it (NullModeHold); the test checks
// that it did so in at least one step.
#include "tests.h"

#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/fracture/load_displacement_curve.h>
#include <qsmpm/materials/decohesion.h>

using namespace qsmpm;

namespace
{
  const double E = 1000., tau = 1., G_f = 0.005, h = 1.;
  const double u0 = 2. * G_f / tau, A = h, t_turn = 0.8, t_end = 1.4;

  class OutAndBack : public Function<2>
  {
  public:
    OutAndBack()
      : Function<2>(2)
    {
    }
    double
    value(const Point<2> &, const unsigned int c) const override
    {
      const double t = get_time();
      return c == 0 ? (t <= t_turn ? t : 2. * t_turn - t) : 0.;
    }
  };

  struct Result
  {
    bool                  finished              = false;
    unsigned int          steps_with_held_modes = 0;
    std::string           message;
    LoadDisplacementCurve curve;
  };

  Result
  run(const double min_nodal_stiffness)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    problem.pcout().set_condition(false);
    problem.grid().make_box(Point<2>(), Point<2>(8. * h, h), {{8, 1}});
    Tensor<1, 2> x_normal;
    x_normal[0] = 1.;
    auto model =
      std::make_unique<Decohesion<2>>(E, 0., true, tau, G_f, x_normal, h);
    model->set_crack_region(
      [](const Point<2> &x) { return x[0] > 2. * h && x[0] < 3. * h; });
    // The shear stiffness of the crack falls to zero with the normal one,
    // so that a failed point has none against the x motion of its nodes.
    model->set_shear_retention(Decohesion<2>::ShearRetention::linear);
    problem.set_model(std::move(model));
    problem.points().fill([](const Point<2> &x) { return x[0] < 5. * h; },
                          1,
                          MaterialPointSet<2>::Placement::regular);

    auto               &bcs = problem.boundary_conditions();
    std::array<bool, 2> x_only{{true, false}}, y_only{{false, true}};
    const auto          zero = std::make_shared<Functions::ZeroFunction<2>>(2);
    bcs.add_dirichlet_boundary(0, x_only, zero);
    bcs.add_dirichlet_nodes(
      "all y", [](const Point<2> &) { return true; }, y_only, zero);
    const unsigned int right = bcs.dirichlet_conditions().size();
    bcs.add_dirichlet_nodes(
      "pulled",
      [](const Point<2> &x) { return std::abs(x[0] - 5. * h) < 1e-9; },
      x_only,
      std::make_shared<OutAndBack>());

    auto &prm                                        = problem.parameters();
    prm.nonlinear_solver.tolerance                   = 1e-9;
    prm.nonlinear_solver.residual_floor              = 0.;
    prm.nonlinear_solver.linear_tolerance            = 1e-10;
    prm.nonlinear_solver.max_line_search_steps       = 4;
    prm.nonlinear_solver.preconditioner              = "direct";
    prm.load_stepping.n_steps                        = 1400;
    prm.load_stepping.final_load_factor              = t_end;
    prm.load_stepping.max_cut_backs                  = 2;
    prm.material_points.update_volumes               = false;
    prm.material_points.min_nodal_stiffness_fraction = min_nodal_stiffness;
    prm.output.directory                             = "results";
    prm.output.interval                              = 0;

    Result result;
    problem.set_step_callback(
      [&](const QuasiStaticProblem<2>::StepReport &report) {
        result.curve.add(report.step,
                         report.load_factor,
                         problem.reactions()[right][0]);
        if (report.null_modes_held > 0)
          ++result.steps_with_held_modes;
        return true;
      });
    try
      {
        problem.run();
        result.finished = true;
      }
    catch (const std::exception &e)
      {
        result.message = e.what();
      }
    return result;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  const Result held = run(1e-8);
  deallog << "with the hold: run " << (held.finished ? "finished" : "stopped")
          << std::endl;
  if (!held.finished)
    deallog << held.message << std::endl;
  const auto  &points = held.curve.points();
  const double P_max  = held.curve.peak_force();
  check("peak load: |P_max / (tau_nf A) - 1|", P_max / (tau * A) - 1., 0.01);

  // Work of the load up to the turn (the trapezoidal rule over the steps).
  // (from the unloaded start, which the curve does not list)
  double work            = 0.5 * points[0].force * points[0].displacement;
  double largest_pulling = 0., largest_pushing = 0.;
  for (unsigned int i = 1; i < points.size(); ++i)
    {
      const double t = points[i].displacement;
      if (t <= t_turn + 1e-12)
        work += 0.5 * (points[i].force + points[i - 1].force) *
                (t - points[i - 1].displacement);
      if (t > 1.5 * u0 && t <= t_turn + 1e-12)
        largest_pulling = std::max(largest_pulling, std::abs(points[i].force));
      if (t > t_turn + 1e-12)
        largest_pushing = std::max(largest_pushing, std::abs(points[i].force));
    }
  check("dissipated energy: |int P du / (G_f A) - 1|",
        work / (G_f * A) - 1.,
        0.02);
  check("no load pulled apart (1.5 u0 < u <= 0.8 h): max |P| / P_max",
        largest_pulling / P_max,
        1e-6);
  check("no load pushed back (0.8 h > u >= 0.2 h): max |P| / P_max",
        largest_pushing / P_max,
        1e-6);
  check("reached u = 0.2 h on the way back: |t_last - 1.4|",
        points.back().displacement - t_end,
        1e-9);

  check_at_least("steps in which a pair's motion without stiffness was held",
                 held.steps_with_held_modes,
                 1);

  const Result free = run(0.);
  deallog << "control without the hold (Minimum nodal stiffness = 0): run "
          << (free.finished ? "finished" : "stopped")
          << " at u = " << std::setprecision(2)
          << free.curve.points().back().displacement << std::endl;
  check_at_least("control: 1 - t_last / 1.4 (it stops before the end)",
                 1. - free.curve.points().back().displacement / t_end,
                 1e-3);
}
