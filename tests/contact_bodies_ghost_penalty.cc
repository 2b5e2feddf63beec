// The ghost penalty (Material points/Ghost penalty) with contact between
// deformable bodies: each body has its own field on the grid, and the faces
// are chosen in each field by that body's material alone
// (GhostPenalty::reinit()). Cells of h = 0.125, 2 x 2 points per cell,
// E = 1000, nu = 0.3, plane strain, small strain (two_blocks.h), material
// id 0 (A) below x = 1 and 1 (B) beyond, gamma = 1 (10^4 times the
// footing examples' factor, so that the penalty changes the answer by far
// more than the tolerances below).
//
// 1. Two cantilevers apart: A over [0, 6.5 h] held at x = 0, B over
//    [11.5 h, 18 h] held at x = 18 h, under their weight (0, -10 t) per
//    unit volume, one load step. Each ends in the middle of a cell, whose
//    far nodes the material barely reaches (an eighth of a cell's volume):
//    cut cells. Known answer: bodies that do not share a cell are each
//    their own problem, so the two bodies on their own fields give the
//    stresses of the same points as one body on one field with the same
//    penalty (1e-8 of the largest stress; Newton to 1e-10). The penalty
//    must matter: one field with and without it differ by more than 1e-3
//    of the largest stress. Chosen over all fields at once, every cell has
//    dofs of the other body without material, and nothing was penalized.
// 2. Two blocks in contact across the middle of a cell: A over
//    [x0, 1), B over [1, x0 + 9 h], x0 = 1 - 4.5 h, the cell at x = 1 shared
//    (A's points in its left half, B's in its right: each body cuts it),
//    frictionless; rollers at x = x0 and y = 0, the traction (-p t, 0),
//    p = 10, on x = x0 + 9 h, one load step, volumes that do not change
//    (with them the stress is p / J). Known answer: the uniform uniaxial
//    state sigma_xx = -p, sigma_yy = sigma_xy = 0 at every point (the
//    penalty vanishes for it), checked to 1e-8 of p. A penalty applied in a
//    field on a face chosen by the other body's material ties that field's
//    barely reached node to dofs without material, held at zero.
//
// Before, a run with both stopped at once ("The ghost penalty cannot be
// used with several bodies yet").
#include "tests.h"
#include "two_blocks.h"

using namespace qsmpm;
using namespace two_blocks;

namespace
{
  using Friction = BodyContact<2>::Parameters::Friction;
  const double p = 10., weight = 10.;

  struct Run
  {
    Stresses stress;
    bool     converged = false;
  };

  /// two_blocks::set_up() for one frictionless load step, linear
  /// functions, and the ghost penalty @p gamma.
  void
  set_up(QuasiStaticProblem<2> &problem,
         const bool             two_bodies,
         const double           gamma)
  {
    two_blocks::set_up(problem,
                       two_bodies,
                       Friction::frictionless,
                       ShapeFunctions::linear,
                       1,
                       "bodies-ghost-out");
    problem.parameters().material_points.ghost_penalty = gamma;
  }

  /// Run @p problem: whether its one step converged, and the stresses.
  Run
  run_one_step(QuasiStaticProblem<2> &problem)
  {
    Run result;
    result.converged = run_counting_steps(problem) == 1;
    result.stress    = point_stresses(problem);
    return result;
  }

  /// Part 1: the two cantilevers, on @p two_bodies fields, penalty
  /// @p gamma.
  Run
  cantilevers(const bool two_bodies, const double gamma)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    set_up(problem, two_bodies, gamma);
    problem.grid().make_box(Point<2>(), Point<2>(18. * h, 4. * h), {{18, 4}});
    auto      &bcs  = problem.boundary_conditions();
    const auto zero = std::make_shared<Functions::ZeroFunction<2>>(2);
    bcs.add_dirichlet_boundary(0, {{true, true}}, zero);
    bcs.add_dirichlet_boundary(1, {{true, true}}, zero);
    auto gravity = std::make_shared<FunctionParser<2>>(2);
    gravity->initialize("x,y,t", "0; -w*t", {{"w", weight}}, true);
    bcs.set_body_force(gravity);
    make_points(
      problem,
      [](const Point<2> &x) { return x[0] < 6.5 * h || x[0] > 11.5 * h; },
      two_bodies);
    return run_one_step(problem);
  }

  /// Part 2: the blocks in contact across the middle of a cell, on
  /// @p two_bodies fields, penalty @p gamma.
  Run
  blocks_in_contact(const bool two_bodies, const double gamma)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    set_up(problem, two_bodies, gamma);
    problem.parameters().material_points.update_volumes = false;
    const double x0                                     = 1. - 4.5 * h;
    problem.grid().make_box(Point<2>(x0, 0.),
                            Point<2>(x0 + 9. * h, 4. * h),
                            {{9, 4}});
    auto      &bcs  = problem.boundary_conditions();
    const auto zero = std::make_shared<Functions::ZeroFunction<2>>(2);
    bcs.add_dirichlet_boundary(0, {{true, false}}, zero);
    bcs.add_dirichlet_boundary(2, {{false, true}}, zero);
    auto traction = std::make_shared<FunctionParser<2>>(2);
    traction->initialize("x,y,t", "-p*t; 0", {{"p", p}}, true);
    bcs.add_traction(1, traction);
    make_points(
      problem, [](const Point<2> &) { return true; }, two_bodies);
    return run_one_step(problem);
  }

  /// The largest stress component of @p r (all ranks).
  double
  largest_stress(const Run &r)
  {
    double largest = 0.;
    for (const auto &[id, s] : r.stress)
      for (const double component : s)
        largest = std::max(largest, std::abs(component));
    return Utilities::MPI::max(largest, MPI_COMM_WORLD);
  }

  /// max over the points of |sigma - (-p, 0, 0)| (all ranks).
  double
  uniaxial_error(const Run &r)
  {
    double error = 0.;
    for (const auto &[id, s] : r.stress)
      error =
        std::max({error, std::abs(s[0] + p), std::abs(s[1]), std::abs(s[2])});
    return Utilities::MPI::max(error, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  const Run    one     = cantilevers(false, 1.);
  const Run    two     = cantilevers(true, 1.);
  const Run    free    = cantilevers(false, 0.);
  const double largest = largest_stress(one);
  check_that("cantilevers: 1 step each",
             one.converged && two.converged && free.converged);
  check("cantilevers, two fields against one: max |d sigma| / max |sigma|",
        largest_stress_difference(two.stress, one.stress) / largest,
        1e-8);
  check_at_least(
    "cantilevers, one field with the penalty and without: max |d sigma| / "
    "max |sigma|",
    largest_stress_difference(free.stress, one.stress) / largest,
    1e-3);

  const Run blocks = blocks_in_contact(true, 1.);
  check_that("blocks in contact: 1 step", blocks.converged);
  check("blocks in contact: max |sigma - uniaxial state| / p",
        uniaxial_error(blocks) / p,
        1e-8);
}
