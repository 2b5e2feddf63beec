// The deep rigid footing of contact_footing_deep in 3D (issue 30, "no load
// lost"): the same plane-strain problem on a slab one cell thick, held in z
// on both of its faces, the footing a box that reaches a slab thickness
// beyond it on either side. The points' faces slide over the edge of the
// box's base, a line along z: where a point's face reaches past it, the
// share of the face under the base is measured at its middle and the rest
// of the face is pressed by the edge, as in 2D.
//
// Checks against what the mechanics requires (those of contact_footing_deep):
// 1. Under monotonic penetration of a perfectly plastic, weightless soil
//    the pressure does not fall abruptly: from s = 0.05 a on, no step
//    lowers q by more than 2 % of (2 + pi) c (measured 0.91 %, at s = a;
//    1.16 % with the rest of a face past the edge not pressed, as in 3D
//    before; 0.52 % in 2D).
// 2. The embedment only raises the limit load of a weightless soil: q at
//    s = a is at least q at s = 0.05 a.
// 3. No load lost: the footing's force equals the vertical reactions of
//    the supports to 1e-4 of it in every step.
// 4. Plane strain: the slab's q at s = 0.05 a, on the plateau after the
//    knee, within 1 % of the 2D problem's (5.6602 c from
//    run_finite_strain_gimp<2>, which contact_footing_deep checks; the
//    measured difference is 0.11 %: the penalty, scaled with the grid's
//    mean stiffness, differs between the slab and the plane grid, and so
//    does the footing's penetration at the knee).
#include "rigid_footing.h"

using namespace qsmpm;
using namespace rigid_footing;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  deallog << "Rigid footing pushed in by a at finite strain in 3D (a slab "
             "one cell thick, cpGIMP, F-bar, a/h = 4)"
          << std::endl;
  const double       settlement = a;
  const unsigned int steps      = 200;
  const Result r = run_finite_strain_gimp<3>(MPI_COMM_WORLD, settlement, steps);
  if (!check_completed(r))
    return 0;
  // 1.-3.
  check_deep_penetration(r, settlement);

  // 4. Plane strain: the 2D problem's q on the plateau.
  const Result plane = run_finite_strain_gimp<2>(MPI_COMM_WORLD, 0.05 * a, 10);
  const double first_limit = q_over_c_at(r, 0.05 * a);
  check("|q_3D - q_2D| / q_2D at s = 0.05 a",
        plane.completed ? std::abs(first_limit - plane.q_over_c.back()) /
                            plane.q_over_c.back() :
                          1.,
        0.01);
}
