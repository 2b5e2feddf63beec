// A smooth rigid footing on soil whose points do not move (Move points =
// false: small displacements) pushed in by three quarters of a cell
// (issue 30; doc/example_footing.md, "The footing as a rigid body").
//
// Prandtl's smooth strip footing (half-width a = 1) as a rigid box on a
// weightless von Mises soil (c = 100, E = 1e6, nu = 0.3), plane strain,
// small strain, linear shape functions, F-bar, 2 x 2 points per cell,
// a/h = 4: the half domain 4 a x 3 a with empty cells (a) above the
// surface. The footing is pushed in by s = 0.75 h in 48 steps. Under it
// the soil flows outwards: at its edge u_x = 0.9 s, more than the half
// width h / 4 of a point's box by s = 0.3 h.
//
// Checks against what the mechanics requires, not against a stored curve:
// 1. The limit: q/c at s = h/4 within 8 % of Prandtl's 2 + pi (an exact
//    limit-analysis result; the node footing of footing_plasticity is
//    within 8 % at a/h = 4).
// 2. At small displacements the limit load of a perfectly plastic,
//    weightless soil is a plateau: from s = h/4 on, q never falls below
//    its largest value so far by more than 0.2 % of (2 + pi) c (the
//    tolerance allows Newton's tolerance and a plateau that rounds off;
//    it is a tenth of what the contact measured at x_p + u_p lost, where
//    the points at the footing's edge slid over it: with that code the
//    plateau fell by 4.2 % at a/h = 8 between s = 0.31 h and 0.49 h, and
//    by 2.2 % at a/h = 16).
// 3. No load lost: the footing's force equals the vertical reactions of
//    the supports to 1e-4 of it in every step.
// 4. The same curve on 1 and on all ranks (to 1e-4 of q: the steps are
//    solved to the Newton tolerance, 1e-6 relative).
#include "rigid_footing.h"

using namespace qsmpm;
using namespace rigid_footing;

namespace
{
  const double       h = 0.25, settlement = 0.75 * h;
  const unsigned int steps = 48;

  Result
  run(const MPI_Comm comm)
  {
    return rigid_footing::run(
      comm,
      "  set Move points = false\n"
      "  set Update volumes = false\n",
      1e6,
      settlement,
      steps,
      [](QuasiStaticProblem<2> &problem) {
        // x in [0, 4 a], y in [0, depth + a]: 16 x 16 cells.
        problem.grid().make_box(Point<2>(0., 0.),
                                Point<2>(4. * a, depth + a),
                                {{16, 16}});
        auto      &bcs  = problem.boundary_conditions();
        const auto zero = std::make_shared<Functions::ZeroFunction<2>>(2);
        bcs.add_dirichlet_boundary(0, {}, zero, /*normal_only=*/true);
        bcs.add_dirichlet_boundary(1, {}, zero, /*normal_only=*/true);
        bcs.add_dirichlet_boundary(2, {{true, true}}, zero);
      });
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  deallog << "Smooth rigid footing on points that do not move, pushed in by "
             "0.75 h (small strain, F-bar, a/h = 4)"
          << std::endl;
  const Result r = run(MPI_COMM_WORLD);
  if (!check_completed(r))
    return 0;

  // 1. The limit.
  double limit = 0.;
  for (unsigned int k = 0; k < r.s.size(); ++k)
    if (std::abs(r.s[k] - 0.25 * h) < 1e-9)
      limit = r.q_over_c[k];
  check("|q(s = h/4) / ((2 + pi) c) - 1|", limit / prandtl - 1., 0.08);

  // 2. A plateau.
  double largest = 0., largest_fall = 0.;
  for (unsigned int k = 0; k < r.s.size(); ++k)
    if (r.s[k] > 0.25 * h - 1e-9)
      {
        largest = std::max(largest, r.q_over_c[k]);
        largest_fall =
          std::max(largest_fall, (largest - r.q_over_c[k]) / prandtl);
      }
  check("largest fall of q below its largest value, s >= h/4, "
        "/ ((2 + pi) c)",
        largest_fall,
        2e-3);
  check_that("the footing reached s = 0.75 h",
             std::abs(r.s.back() - settlement) < 1e-12);

  // 3. The supports carry the footing's force.
  check("largest |supports - footing force| / footing force",
        r.largest_imbalance,
        1e-4);

  // 4. 1 rank against all ranks.
  check_same_on_one_rank(r, run(MPI_COMM_SELF));
}
