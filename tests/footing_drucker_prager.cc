// Prandtl's smooth rigid strip footing on a weightless c-phi soil (issue
// 31): Drucker-Prager with the plane-strain Mohr-Coulomb matching and
// associated flow (psi = phi), c = 100, E = 1e6, nu = 0.3, plane strain,
// small strain, on a coarse grid (a/h = 4, 24 x 16 cells over 6a x 4a,
// 2 x 2 points per cell, settlement 0.02 a in 20 steps). The reference is
// the exact limit pressure of a Mohr-Coulomb soil (Prandtl-Reissner), which
// the plane-strain matching with associated flow reproduces:
//
//   q_u = c N_c,  N_c = (N_q - 1) cot phi,
//   N_q = exp(pi tan phi) tan^2(pi/4 + phi/2)
//
// (phi = 20 degrees: N_c = 14.835; phi = 10 degrees: N_c = 8.345).
//
// 1. phi = 20 degrees with F-bar: the 20 steps converge (before the fix of
//    issue 31 Newton stalled after the first yield: the internal forces
//    paired the pressures of the points, which differ within a cell once
//    the flow dilates, with each point's own volume change, to which the
//    F-bar kinematics gives no stiffness), q/c at the end is within 7 % of
//    c N_c and the curve has a plateau (the last fifth of the settlement
//    adds < 2 %). The tolerance is the discretization error of this grid:
//    measured +3.9 % here; the examples/footing file
//    footing-drucker-prager.prm (domain 8a x 5a) measures +0.08 % at
//    a/h = 8 and +1.5 % at a/h = 16 (doc/example_footing.md). F-bar that
//    gives every point of a cell the cell's volume change, while
//    associated flow ties each point's plastic volume change to its own
//    shear, locks (dilatancy locking): +11.7 % here, which fails.
// 2. phi = 20 degrees without F-bar: the grid locks; the pressure at the same
//    settlement is at least 5 % higher than with F-bar (measured +20 %,
//    +24 % above c N_c).
// 3. phi = 10 degrees with F-bar: converged, q/c within 7 % of c N_c (the
//    same allowance; measured +4.8 %, +10.6 % with dilatancy locking).
// 4. The same F-bar curve (phi = 20 degrees) on one rank and on all ranks,
//    to 1e-6 relative (the Newton tolerance is 1e-9).
// 5. The same soil as the default model of a material map (Material/Models
//    by material id; no point has the map's other id): the same pressure to
//    1e-6. The split of the volume change (case 1) reaches a model through
//    ConstitutiveModel::elastic_volume_strains(), which the map passes on;
//    without it the mapped soil got plain F-bar and locked (measured
//    +7.5 %, the +11.7 % of case 1's dilatancy locking).
// 6. The same soil saturated (Pore fluid, Biot, incompressible
//    constituents) with a mobility that drains it within every step
//    (c_v dt / (4 a)^2 = 4e3): the drained limit, the dry soil's pressure
//    within 1e-3, the fixed-stress coupling's tolerance (measured 5.9e-5;
//    with the skeleton's strain split hidden from the residual +7.5 %).
// 7. The same soil as the ring r in [R, R + 6 a] of an axisymmetric problem
//    with R = 1e4 a, the footing the ring r <= R + a: far from the axis
//    the hoop strain u_r / r is a / R = 1e-4 of the in-plane strains, and
//    the ring is in plane strain. Its pressure (force per radian over
//    a (R + a / 2)) is case 1's within 1e-2: without F-bar the ring and
//    the plane strip agree to 1.5e-5, but axisymmetric F-bar shares its
//    correction of the volume change with the hoop strain, where plane
//    strain F-bar keeps eps_zz = 0, and the two discretizations differ by
//    0.36 % at phi = 0 (isochoric flow, nothing to split) and 0.46 % here.
//    The split of the volume change shares the hoop strain too (the third
//    normal strain); without it the ring got plain F-bar and locked.
#include "c_phi_footing.h"

using namespace c_phi_footing;

namespace
{
  enum class Soil
  {
    dry,
    /// The soil the default model of a material map (the points all have
    /// id 0, the map's other entry is an elastic id 1).
    in_map,
    /// Saturated, draining through the surface within each step.
    saturated,
    /// A ring far from the axis of an axisymmetric problem.
    axisymmetric_ring
  };

  Result
  run(const MPI_Comm     comm,
      const std::string &locking,
      const double       phi,
      const Soil         soil = Soil::dry)
  {
    const bool  ring = soil == Soil::axisymmetric_ring;
    std::string text =
      drucker_prager_text(locking,
                          phi,
                          "footing-dp-out",
                          ring ? "  set Axisymmetric = true\n" : "");
    if (soil == Soil::in_map)
      {
        const std::string model = "  set Model = Drucker-Prager\n";
        text.insert(text.find(model) + model.size(),
                    "  set Models by material id = 1: linear elastic\n");
      }
    // Mobility 1: c_v = kappa M_c = 1.3e6 per unit time, a step of 0.05
    // and a drainage path of at most 4 a give c_v dt / (4 a)^2 = 4e3.
    if (soil == Soil::saturated)
      text += "subsection Pore fluid\n  set Enabled = true\n"
              "  set Mobility = 1\n  set Drained boundaries = 3\nend\n";
    return c_phi_footing::run(comm, text, {}, ring ? 1e4 * a : 0.);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  const double Nc20 = bearing_factor(20.), Nc10 = bearing_factor(10.);
  deallog << "N_c(20 deg) = " << std::setprecision(5) << Nc20
          << ", N_c(10 deg) = " << Nc10 << std::endl;

  deallog << "1. phi = 20 deg, F-bar (a/h = 4)" << std::endl;
  const Result fbar = run(MPI_COMM_WORLD, "F-bar", 20.);
  check_that("  20 steps converged", fbar.completed);
  if (!fbar.completed && root)
    std::cout << fbar.message << std::endl;
  const double q_fbar = last(fbar);
  check("  |q/c - N_c| / N_c", (q_fbar - Nc20) / Nc20, 0.07);
  check("  change of q over the last 20 % of the settlement",
        fbar.pressure_over_c.size() == 20 ?
          q_fbar / fbar.pressure_over_c[15] - 1. :
          std::numeric_limits<double>::quiet_NaN(),
        0.02);

  deallog << "2. phi = 20 deg, no treatment (locking)" << std::endl;
  const Result none = run(MPI_COMM_WORLD, "none", 20.);
  check_that("  20 steps converged", none.completed);
  check_at_least("  q_none / q_F-bar - 1", last(none) / q_fbar - 1., 0.05);

  deallog << "3. phi = 10 deg, F-bar" << std::endl;
  const Result fbar10 = run(MPI_COMM_WORLD, "F-bar", 10.);
  check_that("  20 steps converged", fbar10.completed);
  check("  |q/c - N_c| / N_c", (last(fbar10) - Nc10) / Nc10, 0.07);

  deallog << "4. The same curve on one rank and on all ranks" << std::endl;
  const Result serial = run(MPI_COMM_SELF, "F-bar", 20.);
  check_that("  serial run converged", serial.completed);
  check("  max relative difference of q over the curve",
        curve_difference(serial, fbar),
        1e-6);

  // Cases 5 and 6: the soil of case 1 in another setting, its pressure at
  // the end against case 1's.
  const auto check_same_soil =
    [&](const Soil soil, const std::string &name, const double tolerance) {
      const Result result = run(MPI_COMM_WORLD, "F-bar", 20., soil);
      check_that("  20 steps converged", result.completed);
      if (!result.completed && root)
        std::cout << result.message << std::endl;
      check("  |q_" + name + " / q_F-bar - 1| at the end",
            result.completed ? last(result) / q_fbar - 1. :
                               std::numeric_limits<double>::quiet_NaN(),
            tolerance);
    };
  deallog << "5. The same soil as a member of a material map" << std::endl;
  check_same_soil(Soil::in_map, "map", 1e-6);
  deallog << "6. The same soil saturated, drained within each step"
          << std::endl;
  check_same_soil(Soil::saturated, "saturated", 1e-3);
  deallog << "7. The same soil as a ring far from the axis (axisymmetric)"
          << std::endl;
  check_same_soil(Soil::axisymmetric_ring, "ring", 1e-2);
  if (root)
    std::cout << "q/c: F-bar(20) " << q_fbar << " (N_c " << Nc20
              << "), none(20) " << last(none) << ", F-bar(10) " << last(fbar10)
              << " (N_c " << Nc10 << ")" << std::endl;
}
