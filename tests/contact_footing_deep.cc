// A smooth rigid footing pushed in by its half-width at finite strain (issue
// 30, "no load lost"; doc/example_footing.md, deep penetration with the rigid
// footing): the points under the footing's edge are flattened and sheared, and
// their faces slide over the edge of its base.
//
// Prandtl's smooth strip footing (half-width a = 1) as a rigid box on a
// weightless von Mises soil (c = 100, E = 1e5, nu = 0.3), plane strain,
// finite strain, cpGIMP, F-bar, Ghost penalty 1e-4, 2 x 2 points per cell,
// a/h = 4 (the grid and supports of contact_footing_penetration). The
// footing is pushed in by s = a = 4 h in 200 steps.
//
// Checks against what the mechanics requires, not against a stored curve:
// 1. Under monotonic penetration of a perfectly plastic, weightless soil
//    the pressure does not fall abruptly: from s = 0.05 a on, no step
//    lowers q by more than 2 % of (2 + pi) c. With each step's contact
//    points recomputed from the points' deformed boxes (the contact before
//    it followed the contact points the grid moved) q fell by 25 % of
//    (2 + pi) c in one step at s = 0.505 a (measured). With the contact
//    point at the middle of the point's face, a point whose face's middle
//    passed the base's edge while half of its face still lay under the
//    base was let go carrying 12 % of the footing's force: a fall of 8.3 %
//    at 0.79 a (measured). Now such a point is measured at the middle of
//    the share of its face under the base and the rest of its face is
//    pressed by the edge: the largest fall is 0.52 % (at 0.5 a).
// 2. The embedment only raises the limit load of a weightless soil: q at
//    s = a is at least q at s = 0.05 a (5.66 c).
// 3. No load lost: the footing's force equals the vertical reactions of
//    the supports to 1e-4 of it in every step.
// 4. On several ranks, the same curve as on one (to 1e-4 of (2 + pi) c:
//    the steps are solved to the Newton tolerance, 1e-6 relative).
#include "rigid_footing.h"

using namespace qsmpm;
using namespace rigid_footing;

namespace
{
  const double       settlement = a;
  const unsigned int steps      = 200;
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  deallog << "Rigid footing pushed in by a at finite strain (cpGIMP, "
             "F-bar, a/h = 4)"
          << std::endl;
  const Result r = run_finite_strain_gimp(MPI_COMM_WORLD, settlement, steps);
  if (!check_completed(r))
    return 0;
  // 1.-3.
  check_deep_penetration(r, settlement);

  // 4. Several ranks against one.
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    check_same_on_one_rank(
      r, run_finite_strain_gimp(MPI_COMM_SELF, settlement, steps));
}
