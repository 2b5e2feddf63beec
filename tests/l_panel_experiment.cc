// The mixed-mode fracture experiment of issue 29: the L-shaped concrete
// panel of Winkler, Hofstetter and Niederwanger (2001), the example
// examples/l_panel with its shipped l_panel.prm (E = 25.85 GPa, nu = 0.18,
// tau_nf = 2.7 MPa, G_f = 65 J/m^2, Petersson's bilinear softening, h = 10
// mm, 2 x 2 points per cell, cracking anywhere but next to the loading
// plate, 800 steps to a deflection of 1 mm), on all ranks of
// MPI_COMM_WORLD. The references are not the code's:
//
// 1. The set-up: with the points at the Gauss points (Placement = gauss)
//    and their volumes kept (Update volumes = false: geometrically linear)
//    the first step is the finite element solution on the same grid, and
//    the elastic stiffness (load over deflection) must be that of an
//    independent finite element computation,
//    examples/l_panel/elastic_stiffness.py (numpy; bilinear quadrilaterals,
//    2 x 2 Gauss points): 65.19900443 kN/mm, to 1e-8 (with Newton's
//    tolerance 1e-12 for this step; measured 1.6e-11; with the shipped
//    1e-6 the difference is 5.6e-5). A wrong support, load position, plate
//    width, thickness or plane strain instead of plane stress is off by a
//    per cent or more.
// 2. The experiment (series A of Winkler's thesis, Fig. 7.12; the measured
//    curve is examples/l_panel/winkler_series_a.csv): its peak load, 7.219
//    kN, within 20 %. Two independent models with the same material data
//    reach 8.11 kN (embedded discontinuities) and 8.12 kN (phase field),
//    12 % above the measurement (github.com/PSAAPGroupLinder/
//    lShapedPanelBenchmark); a peak beyond 20 % is wrong by more than such
//    models are. Measured: -4.5 %.
// 3. The crack: it starts at the re-entrant corner (the crack of the
//    column of cells left of the corner within 2 h of the corner's height),
//    crosses the leg (a crack in every column of cells from the corner to
//    within 2 h of the left edge: at 1 mm the panel still carries 18 % of
//    the peak, the crack's last cells are still opening), and rises as it runs
//    (mixed mode: its height at the left edge above the corner's by more than
//    h, as in the tests, where it ends between the corner's height and the
//    middle of the upper leg). Measured: 0.2725 m against the corner's 0.25 m.
// 4. The panel breaks: the load at 1 mm is below 25 % of the peak (the
//    measured curve: 14 %; computed: 18 %).
#include "l_panel.h"
#include "tests.h"

using namespace LPanel;

namespace
{
  void
  shipped(ParameterHandler &prm)
  {
    prm.enter_subsection("L panel");
    prm.set("Experiment file", "");
    prm.set("Output directory", "output-l-panel");
    prm.leave_subsection();
    prm.enter_subsection("Output");
    prm.set("Interval", "0");
    prm.leave_subsection();
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  const std::string prm_file = QSMPM_EXAMPLES_DIR "/l_panel/l_panel.prm";

  deallog << "1. Elastic stiffness, points at the Gauss points" << std::endl;
  {
    LShapedPanel<2> elastic(prm_file, [](ParameterHandler &prm) {
      shipped(prm);
      prm.enter_subsection("L panel");
      prm.set("Final deflection", "2.5e-6");
      prm.leave_subsection();
      prm.enter_subsection("Load stepping");
      prm.set("Number of steps", "1");
      prm.leave_subsection();
      prm.enter_subsection("Material points");
      prm.set("Placement", "gauss");
      prm.set("Update volumes", "false");
      prm.leave_subsection();
      prm.enter_subsection("Nonlinear solver");
      prm.set("Tolerance", "1e-12");
      prm.leave_subsection();
    });
    const auto      r         = elastic.run();
    const double    reference = 65.19900443e6; // N/m, elastic_stiffness.py
    check("  |stiffness / FE stiffness - 1|",
          r.initial_stiffness / reference - 1.,
          1e-8);
  }

  deallog << "2.-4. The shipped run" << std::endl;
  LShapedPanel<2> panel(prm_file, shipped);
  const auto      r        = panel.run();
  const double    measured = 7219.1; // N, winkler_series_a.csv
  const double    h        = 0.01;
  check("  |peak / measured peak - 1|", r.peak / measured - 1., 0.2);

  // The crack's columns: from the corner (x < 0.25) to 2 h from the left
  // edge.
  bool   every_column = true;
  double at_corner    = 0.;
  for (const auto &[x, y] : r.crack_path)
    if (x < 0.25 && x > 2. * h)
      {
        every_column = every_column && std::isfinite(y);
        if (x > 0.25 - h)
          at_corner = y;
      }
  check_that("  a crack in every column of cells of the leg but the two at "
             "its left edge",
             every_column);
  check("  |crack height beside the corner - 0.25 m| / h",
        (at_corner - 0.25) / h,
        2.);
  check_that("  the crack rises by more than h: height at the left edge > "
             "0.25 m + h",
             r.crack_height_at_left_edge > 0.25 + h);
  check_that("  and stays in the lower half of the upper leg: < 0.375 m",
             r.crack_height_at_left_edge < 0.375);
  check_that("  the load at 1 mm is below 25 % of the peak",
             r.curve.back()[1] < 0.25 * r.peak);
}
