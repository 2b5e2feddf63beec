// Consolidation of a yielding Modified Cam Clay skeleton (issue 31): the
// shipped examples/consolidation/terzaghi.prm (a 10 m column, 32 cells,
// drained top) with the skeleton replaced by normally consolidated Cam Clay
// (OCR = 1) at p0 = 20 kPa (each point starts at -p0 I, which a top
// traction of -p0 balances), loaded by dq = 1 kPa beyond p0 in 4.34e-3 s
// and held for 1000 s. The points yield from the start; there is no closed
// form for the settlement over time, but both of its ends are known:
//
// - The first step is undrained. With incompressible water (b = 1,
//   1/M = 0) a column on rollers cannot change its volume, so it does not
//   strain at all, and the water carries the whole surcharge (Skempton,
//   B = 1): the pore pressure at the four probes (depths 2.5 to 10 m)
//   equals dq within 1e-4 of dq (measured 1e-6; the first step drains a
//   little through the top), the settlement of the probe 7.5 m above the
//   base is below 1e-4 of its final one (measured 1e-6).
// - At the end the water has drained (the average degree of consolidation
//   1 within 1e-3), and the column is in the drained state: the same file
//   on the dry skeleton, the surcharge raised in 400 steps. Every point's
//   strain path is the same in both (uniaxial compression, growing
//   monotonically: in 1D the consolidation does not unload any point), so
//   a rate-independent skeleton ends in the same state; only the return
//   mapping's integration error, first order in the strain increments,
//   separates them (the drained run with 25, 100, 400 steps: 8.0925,
//   8.0819, 8.0793 mm). The settlement of that probe within 0.5 % (measured
//   0.12 %), the horizontal stress there, the one that tells how the point
//   yielded (K0), within 1e-2 dq (measured 2.3e-4 dq).
// - The skeleton did yield: the settlement is more than 1.5 times that of
//   the elastic skeleton under the same surcharge, dq y / E_oed with E_oed
//   = K + 4 G / 3 = 1.8 MPa at p0 (measured 1.96 times).
#include "cam_clay_column.h"
#include "prm_text.h"
#include "tests.h"

#include <qsmpm/core/quasi_static_problem.h>

using namespace qsmpm;

namespace
{
  constexpr double dq = 1e3, E_oed = 1.8e6;

  /// The Cam Clay column, normally consolidated, with the replacements
  /// @p edits, run with its output into @p directory; returns probes.csv.
  std::string
  run(std::vector<std::pair<std::string, std::string>> edits,
      const std::string                               &directory)
  {
    edits.insert(edits.begin(), cam_clay_skeleton("1"));
    return run_column(edits, directory);
  }

  double
  value(const std::string         &csv,
        const std::vector<double> &row,
        const std::string         &name)
  {
    return row[csv_column(csv, name)];
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::MPILogInitAll       log;

  const std::string consolidating = run(
    {{"set Function expression = 0; -1e4",
      "set Function expression = 0; -2e4 - 1e3 * min(t / 4.34e-3, 1)"},
     {"set Final load factor = 55.5556", "set Final load factor = 1000"},
     {"set Number of steps = 12800",
      "set Number of steps = 230415\n  set Growth from load factor = 4.34e-3"},
     {"set Maximum increment = 0.434", "set Maximum increment = 20"}},
    "consolidating-out");
  const std::string drained =
    run({{"set Function expression = 0; -1e4",
          "set Function expression = 0; -2e4 - 1e3 * t"},
         {"set Enabled = true", "set Enabled = false"},
         {"set Final load factor = 55.5556", "set Final load factor = 1"},
         {"set Number of steps = 12800", "set Number of steps = 400"},
         {"set Increment growth factor = 1.1",
          "set Increment growth factor = 1"}},
        "drained-out");

  const auto  rows      = read_csv(consolidating);
  const auto  reference = read_csv(drained).back();
  const auto  reactions = read_csv("consolidating-out/reactions.csv");
  const auto &first = rows.front(), &last = rows.back();

  double pressure_error = 0.;
  for (unsigned int k = 0; k < 4; ++k)
    pressure_error =
      std::max(pressure_error,
               std::abs(value(consolidating,
                              first,
                              "probe" + std::to_string(k) + "_pore_pressure") -
                        dq));
  const double settlement = -value(consolidating, last, "probe0_u_y");
  const double s_drained  = -value(drained, reference, "probe0_u_y");
  const double y          = value(consolidating, last, "probe0_y") -
                   value(consolidating, last, "probe0_u_y");

  check("  first step: pore pressure at the probes against dq, / dq",
        pressure_error / dq,
        1e-4);
  check("  first step: settlement of the probe / its final one",
        -value(consolidating, first, "probe0_u_y") / settlement,
        1e-4);
  check("  1 - degree of consolidation at the end",
        1. - reactions.back()[csv_column("consolidating-out/reactions.csv",
                                         "consolidation_degree")],
        1e-3);
  check("  settlement at the end against the drained one, relative",
        settlement / s_drained - 1.,
        5e-3);
  check("  horizontal stress at the end against the drained one, / dq",
        (value(consolidating, last, "probe0_stress_xx") -
         value(drained, reference, "probe0_stress_xx")) /
          dq,
        1e-2);
  check_that("  the skeleton yields: settlement above 1.5 times the elastic "
             "one",
             settlement > 1.5 * dq * y / E_oed);
}
