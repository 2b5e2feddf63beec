// Contact between deformable bodies on a grid periodic in x: a laminate of
// two layers, A (material id 0) below y = 1 and B (id 1) above, each on its
// own field (a multi-field grid), in the periodic cell [0, 1] x [0, 2] of
// cells h = 0.125, 2 x 2 points per cell, E = 1000, nu = 0.3, plane
// strain, small strain (two_blocks.h), volumes that do not change. The
// bottom y = 0 is held, the top
// y = 2 carries the traction (tau t, -q t), tau = 2, q = 10, one load step;
// rough contact between the layers. Periodicity ties the nodes of x = 0 to
// those of x = 1 on every body's field.
//
// Known answers: the layers under a uniform traction in a cell periodic
// along them are in a uniform state, sigma_xy = tau and sigma_yy = -q at
// every point (equilibrium with the traction; from the points' regular
// places the discrete solution is this state exactly): checked to 1e-8 of
// q for one body on one field and for the two layers; and the two layers'
// stress is that of one body to 1e-8 of q. Before, such a run stopped at
// once ("A periodic grid (Geometry/Periodic) cannot be used with several
// bodies yet"); with only that check lifted, the periodicity's jumps
// (DisplacementConstraints) found no node for the second field's dofs and
// the run stopped ("a node tied across the period is not in the ghost
// layer").
#include "tests.h"
#include "two_blocks.h"

using namespace qsmpm;
using namespace two_blocks;

namespace
{
  using Friction   = BodyContact<2>::Parameters::Friction;
  const double tau = 2., q = 10.;

  struct Run
  {
    Stresses stress;
    bool     converged = false;
  };

  Run
  run(const bool two_bodies)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    set_up(problem,
           two_bodies,
           Friction::rough,
           ShapeFunctions::linear,
           1,
           "bodies-periodic-out");
    // Volumes that do not follow the strain: the residual's volume of a
    // point would be its volume times J = 1 + tr(eps) (0.9926 here), and
    // the stress that balances the traction q / J.
    problem.parameters().material_points.update_volumes = false;
    problem.grid().make_box(Point<2>(), Point<2>(1., 2.), {{8, 16}});
    problem.grid().make_periodic({0});
    auto      &bcs  = problem.boundary_conditions();
    const auto zero = std::make_shared<Functions::ZeroFunction<2>>(2);
    bcs.add_dirichlet_boundary(2, {{true, true}}, zero);
    auto traction = std::make_shared<FunctionParser<2>>(2);
    traction->initialize("x,y,t",
                         "tau*t; -q*t",
                         {{"tau", tau}, {"q", q}},
                         true);
    bcs.add_traction(3, traction);
    make_points(
      problem, [](const Point<2> &) { return true; }, two_bodies, 1);
    const unsigned int steps = run_counting_steps(problem);

    Run result;
    result.stress    = point_stresses(problem);
    result.converged = steps == 1;
    return result;
  }

  /// max over the points of |sigma_xy - tau| and |sigma_yy + q| (all
  /// ranks).
  double
  uniform_state_error(const Run &r)
  {
    double error = 0.;
    for (const auto &[id, s] : r.stress)
      error = std::max({error, std::abs(s[2] - tau), std::abs(s[1] + q)});
    return Utilities::MPI::max(error, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  const Run one = run(false);
  const Run two = run(true);
  check_that("one body and two layers: 1 step", one.converged && two.converged);
  check("one body: max |sigma - uniform state| / q",
        uniform_state_error(one) / q,
        1e-8);
  check("two layers: max |sigma - uniform state| / q",
        uniform_state_error(two) / q,
        1e-8);
  check("two layers: max |sigma - one body's| / q",
        largest_stress_difference(two.stress, one.stress) / q,
        1e-8);
}
