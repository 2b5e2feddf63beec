// The column of examples/consolidation/terzaghi.prm (10 m, 32 cells,
// drained top) with a Modified Cam Clay skeleton, for the tests of its
// consolidation.
#ifndef qsmpm_tests_cam_clay_column_h
#define qsmpm_tests_cam_clay_column_h

#include "prm_text.h"

#include <string>
#include <utility>
#include <vector>

namespace qsmpm_tests
{
  /// The edit (for run_column()) that replaces terzaghi.prm's linear
  /// elastic skeleton by Modified Cam Clay at p0 = 20 kPa with the
  /// overconsolidation ratio @p ocr: kappa = 0.02 and G = 6e5 Pa, so that
  /// at p0 its bulk modulus p0 / kappa and its shear modulus are the linear
  /// column's (E_oed = 1.8 MPa); lambda = 0.1, M = 1.2.
  inline std::pair<std::string, std::string>
  cam_clay_skeleton(const std::string &ocr)
  {
    return {"  set Model = linear elastic\n",
            "  set Model = Modified Cam Clay\n"
            "  subsection Modified Cam Clay\n"
            "    set Shear modulus = 6e5\n"
            "    set Swelling index = 0.02\n"
            "    set Compression index = 0.1\n"
            "    set Critical state slope = 1.2\n"
            "    set Initial pressure = 2e4\n"
            "    set Overconsolidation ratio = " +
              ocr +
              "\n"
              "  end\n"};
  }

  /// terzaghi.prm with @p edits (a text of the file and its replacement),
  /// run with its output into @p directory; returns probes.csv. Terzaghi's
  /// theory is geometrically linear: the points keep their volumes (with
  /// the default update, an initial stress p0 times the volume change adds
  /// forces of p0 dq / E_oed, 1.1 % of a surcharge dq at p0 = 20 kPa).
  inline std::string
  run_column(const std::vector<std::pair<std::string, std::string>> &edits,
             const std::string                                      &directory)
  {
    const std::string text =
      edited_example("consolidation/terzaghi.prm", edits, directory) +
      "subsection Material points\n  set Update volumes = false\nend\n";
    run_from_text<2>(text);
    return directory + "/probes.csv";
  }
} // namespace qsmpm_tests

#endif
