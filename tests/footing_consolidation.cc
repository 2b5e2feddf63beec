// A footing on saturated clay through the driver's path (issue 31): the
// shipped examples/consolidation/footing-undrained.prm and
// footing-consolidation.prm, run as a user runs them, each against a
// reference that does not come from the pore-fluid code.
//
// 1. footing-consolidation.prm: a strip load q = 257.1 Pa on |x| <= 1 m of a
//    5 m x 5 m elastic half-layer (E = 1e6 Pa, nu = 0.3, below yield),
//    applied in 1e-5 s and held for 200 s (c_v t / H^2 = 10.8).
//    - At the end the water has drained (the average degree of
//      consolidation 1 within 1e-3), and the settlement below the load's
//      centre is the drained one: the same file without the pore fluid,
//      loaded in one step. Both solve the same drained equations at the
//      end, so only the fixed-stress coupling tolerance (1e-5) separates
//      them: 1e-3 relative is checked (measured 4e-5).
//    - The first step is undrained: an elastic skeleton with incompressible
//      water deforms as an incompressible solid of the skeleton's shear
//      modulus, nu_u = 1/2. The reference is the displacement-only
//      formulation with nu_u = 0.4999 and E_u = 2 G (1 + nu_u), F-bar
//      against locking. The two discretizations (stabilized equal-order
//      u-p and F-bar) differ at h = 0.125 m, and the u-p run has drained a
//      little through the surface within its first step: the settlement
//      within 2 % (measured 0.9 %; 0.05 % at h / 2), the pore pressure 1 m
//      below the centre (Skempton: the change of mean total stress,
//      -(1 + nu_u)(sigma_xx + sigma_yy) / 3 in plane strain) within 5 %.
//      The reference's mean stress is the less accurate of the two: from
//      the F-bar run 127.4 Pa at h, 129.8 Pa at h / 2; the u-p pressure
//      132.2 and 132.1 Pa (measured 3.8 % apart at h, 1.8 % at h / 2).
//      Without the coupling the pressure would be 0, with b = 1/2 half.
//    - The settlement never decreases while the load is held.
// 2. footing-undrained.prm: the smooth rigid footing pressed 0.02 a into
//    the von Mises soil (c = 100 Pa) in 1 ms. Plastic flow of a Tresca soil
//    is isochoric, so the undrained limit is Prandtl's (2 + pi) c; at
//    a / h = 8 within 3 % (the footing example's tolerance; measured
//    +2.3 %), and within 0.5 % of the same footing on the dry soil (the
//    same grid's drained limit; measured 0.06 %).
#include "prm_text.h"
#include "tests.h"

#include <qsmpm/core/quasi_static_problem.h>

using namespace qsmpm;

namespace
{
  /// The shipped file examples/consolidation/@p name with the replacements
  /// @p edits (each: a line's text and what replaces it; the line must be
  /// there), run with its output into @p directory.
  void
  run(const std::string                                      &name,
      const std::vector<std::pair<std::string, std::string>> &edits,
      const std::string                                      &directory)
  {
    const std::string text =
      edited_example("consolidation/" + name, edits, directory);
    run_from_text<2>(text);
  }

  const std::pair<std::string, std::string> dry{"set Enabled = true",
                                                "set Enabled = false"};
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::MPILogInitAll       log;

  deallog << "1. footing-consolidation.prm" << std::endl;
  {
    run("footing-consolidation.prm", {}, "consolidation-out");
    const auto u = csv_values("consolidation-out/probes.csv", "probe0_u_y");
    const auto p =
      csv_values("consolidation-out/probes.csv", "probe1_pore_pressure");
    const auto U =
      csv_values("consolidation-out/reactions.csv", "consolidation_degree");

    // Loaded in one step: the load's time is 1e-5 s.
    const std::vector<std::pair<std::string, std::string>> one_step = {
      {"set Final load factor = 200", "set Final load factor = 1e-5"},
      {"set Number of steps = 20000000", "set Number of steps = 1"}};
    auto drained = one_step;
    drained.push_back(dry);
    run("footing-consolidation.prm", drained, "drained-out");
    const double s_drained =
      -csv_values("drained-out/probes.csv", "probe0_u_y").back();

    const double nu_u      = 0.4999;
    auto         undrained = drained;
    for (const auto &edit : same_shear_modulus("1e6", "0.3", nu_u))
      undrained.push_back(edit);
    undrained.push_back({"set Points per cell per direction = 2",
                         "set Points per cell per direction = 2\n"
                         "  set Volumetric locking = F-bar"});
    run("footing-consolidation.prm", undrained, "undrained-out");
    const double s_undrained =
      -csv_values("undrained-out/probes.csv", "probe0_u_y").back();
    const double p_undrained =
      -(1. + nu_u) / 3. *
      (csv_values("undrained-out/probes.csv", "probe1_stress_xx").back() +
       csv_values("undrained-out/probes.csv", "probe1_stress_yy").back());

    bool monotone = true;
    for (unsigned int i = 1; i < u.size(); ++i)
      monotone = monotone && u[i] <= u[i - 1] + 1e-12;
    check_that("  more than 20 steps, the settlement never decreasing",
               u.size() > 20 && monotone);
    check("  1 - degree of consolidation at the end", 1. - U.back(), 1e-3);
    check("  settlement at the end against the drained one, relative",
          (-u.back() - s_drained) / s_drained,
          1e-3);
    check("  first step: settlement against the undrained one, relative",
          (-u.front() - s_undrained) / s_undrained,
          0.02);
    check("  first step: pore pressure 1 m deep against the mean total "
          "stress, relative",
          (p.front() - p_undrained) / p_undrained,
          0.05);
    check_that("  the undrained settlement below 0.6 of the drained one",
               s_undrained < 0.6 * s_drained);
  }

  deallog << "2. footing-undrained.prm" << std::endl;
  {
    // The pressure on the footing of half-width a = 1 at the end, over c.
    const auto q_end = [](const std::string &directory) {
      return csv_values(directory + "/reactions.csv", "footing_Fy").back() /
             100.;
    };
    run("footing-undrained.prm", {}, "undrained-footing-out");
    const double q_undrained = q_end("undrained-footing-out");
    run("footing-undrained.prm", {dry}, "dry-footing-out");
    const double q_dry = q_end("dry-footing-out");
    check("  q / c at the end against 2 + pi, relative",
          (q_undrained - (2. + numbers::PI)) / (2. + numbers::PI),
          0.03);
    check("  against the dry soil's limit on the same grid, relative",
          (q_undrained - q_dry) / q_dry,
          5e-3);
  }
}
