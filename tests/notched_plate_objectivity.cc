// Grid-orientation objectivity of the multi-crack smeared model (issue 29),
// the example examples/notched_plate with its shipped objectivity.prm (read
// from the source tree: a plate 0.4 m x 0.2 m with a notch 0.06 m deep,
// E = 30 GPa, nu = 0.2, tau_nf = 3 MPa, G_f = 100 J/m^2, h = W/24, 2 x 2
// points per cell, cracking anywhere with crack tracking, slip softening
// with beta = 0.5, crack tracking localization 0.02, crack-parallel
// softening, opening control) at three of its four angles, the grid at 0,
// 15 and 30 degrees to the load axis, on all ranks of MPI_COMM_WORLD. The
// references are the problem's, not the code's:
//
// - every run breaks the plate (the load falls below 2 % of its peak);
// - the crack normal (the energy-weighted mean of the cracks' normals) is
//   the load axis, within 5 degrees (the tolerance; measured 0.1,
//   0.1 and 0.3 degrees);
// - the crack runs straight across the ligament: the least-squares line
//   through the points that dissipated at least G_f / 2 is within 3
//   degrees of the ligament (measured 0.0, 1.3, 0.7; without crack
//   tracking 15.1 degrees at 15: the band runs along the grid's lines);
// - the peak loads agree: each within 2 % of their mean (the issue's
//   tolerance; measured 0.1-1.1 %);
// - the energy the points' cracks dissipated, with what the unfinished
//   cracks of the band still hold at the stop (their points' elastic
//   energy: run on to 0.2 % of the peak, the band dissipates it), is the
//   fracture energy of the ligament, G_f (W - a0) = 14 J/m, within 4 %
//   (measured 0.984, 0.989, 1.007);
// - the work of the grips up to the end of the run (2 % of the peak) is
//   G_f (W - a0) within 2 % (the tolerance; measured 0.990, 1.008,
//   1.017). It fails if the band locks or widens again: without
//   crack-parallel softening the ratio is 1.026 at 30 degrees, without the
//   localization of crack tracking as well 1.054, without crack tracking
//   and slip softening 1.24; without tracking it is 0.86 at 15 degrees
//   (the band along the grid's lines).
#include "rotated_plate.h"
#include "tests.h"

#include <qsmpm/core/quasi_static_problem.h>

using namespace NotchedPlate;

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  ParameterHandler prm;
  prm.declare_entry("Dimension", "2", Patterns::Integer(2, 2), "");
  QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
  Parameters plate;
  plate.add_parameters(prm);
  // The shipped parameter file, as a user runs it; only the output of
  // fields is switched off.
  prm.parse_input(QSMPM_EXAMPLES_DIR "/notched_plate/objectivity.prm");
  prm.enter_subsection("Output");
  prm.set("Interval", "0");
  prm.leave_subsection();
  prm.enter_subsection("Material");
  prm.enter_subsection("smeared cracks");
  const double G_f_ligament =
    prm.get_double("Fracture energy") * (plate.width - plate.notch_depth);
  prm.leave_subsection();
  prm.leave_subsection();

  std::vector<double> peaks;
  for (const double angle : {0., 15., 30.})
    {
      RotatedPlate<2> run(plate, prm, angle);
      const auto      r  = run.run();
      const auto      at = "  " + std::to_string(int(angle)) + " degrees: ";
      deallog << int(angle) << " degrees to the grid" << std::endl;
      check_that(at + "the plate broke", !r.failed);
      check(at + "|crack normal - load axis| (degrees)", r.normal - angle, 5.);
      check(at + "|crack path - ligament| (degrees)", r.path_angle, 3.);
      check(at + "|(cracks' energy + held) / (G_f (W - a0)) - 1|",
            (r.crack_energy + r.stored_energy) / G_f_ligament - 1.,
            0.04);
      check(at + "|work / (G_f (W - a0)) - 1|",
            r.work / G_f_ligament - 1.,
            0.02);
      peaks.push_back(r.peak);
    }
  const double mean = (peaks[0] + peaks[1] + peaks[2]) / 3.;
  for (unsigned int i = 0; i < peaks.size(); ++i)
    check("|P_" + std::to_string(15 * i) + " / mean - 1|",
          peaks[i] / mean - 1.,
          0.02);
}
