// A pore fluid with contact between bodies (issue 30): the bodies of a
// multi-field grid share one pore pressure field, so that the fluid flows
// across the faces where they touch.
//
// Terzaghi's column (as in terzaghi_consolidation: H = 10 m, E = 1.5 MPa,
// nu = 0.25, kappa = 1e-6 m^2 / (Pa s), b = 1, 1/M = 0, q = 10 kPa on the
// drained top, impermeable base, rollers on the sides; 1 x 16 cells, 2 x 2
// points per cell, T_v = 0.5 in 32 steps) made of two bodies: the lower
// half (material id 0) and the upper half (id 1), `Contact between
// bodies/Bodies = 0; 1`, frictionless. The upper body presses on the lower
// one across the grid line y = H / 2, and the lower half drains through
// the upper one to the top. Known answers:
//  - the column is one body in all but the name: pressure and displacement
//    of every point equal to those of the same column on one field (a
//    different path through the code: no contact), to 1e-6 of q and of
//    the settlement q H / E_oed (the fixed-stress iteration stops at 1e-5
//    of the largest pressure, the same in both runs; monolithic: Newton's
//    tolerance);
//  - the pressure against Terzaghi's solution: L2 over the points below
//    1.5 % of q (the error of the grid and the steps: 0.90 % for one body
//    on this grid, 0.59 % with the drained surface).
// Were the interface impermeable (a pressure field per body), the lower
// half could not drain: its pressure would stay at q (undrained, with
// incompressible constituents) while Terzaghi's falls to 0.37 q at the
// base. With the upper body's nodes leading to the pressure of the node
// above (checked by editing the code), the pressures differ from one
// body's by 0.72 q.
// The same with `Coupling = monolithic`, and with the top drained through
// `Drained surface region` (the upper body's own top face, a penalty)
// instead of the grid's boundary: equal to one body with the same entries.
#include "consolidation_solutions.h"
#include "prm_text.h"
#include "tests.h"
#include "two_layer_column.h"

#include <map>

using namespace qsmpm;

namespace
{
  using namespace two_layer_column;
  constexpr double   kappa = 1e-6, q = 1e4, Tv = 0.5;
  constexpr unsigned cells = 16, steps = 32;

  struct Result
  {
    bool completed = false;
    /// Per point (by its id): pore pressure and vertical displacement.
    std::map<types::particle_index, std::pair<double, double>> points;
    /// L2 of p - Terzaghi's over the points, relative to q.
    double l2 = 0.;
  };

  Result
  run(const bool two_bodies, const std::string &pore_fluid)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    Result                result;
    try
      {
        initialize_from_text(
          problem,
          prm_text(cells,
                   q,
                   "  set Mobility = " + std::to_string(kappa) + "\n" +
                     pore_fluid,
                   Tv * H * H / (kappa * E_oed),
                   steps,
                   1.,
                   two_bodies ? "subsection Contact between bodies\n"
                                "  set Bodies = 0; 1\nend\n" :
                                ""));
        problem.run();
        result.completed = true;
      }
    catch (const std::exception &exc)
      {
        deallog << "  run stopped: " << exc.what() << std::endl;
      }
    const auto        &points   = problem.points();
    const auto        &offsets  = points.get_offsets();
    const unsigned int p_offset = pressure_offset(points);
    double             sum = 0., volume = 0.;
    for (const auto &particle : points.get_particle_handler())
      {
        const auto   data = particle.get_properties();
        const double u    = data[offsets.displacement + 1];
        const double Y    = particle.get_location()[1] - u;
        const double V    = data[offsets.initial_volume];
        const double p    = data[p_offset];
        const double e = p - Consolidation::terzaghi_pressure(H - Y, H, Tv, q);
        sum += V * e * e;
        volume += V;
        result.points[particle.get_id()] = {p, u};
      }
    result.l2 = std::sqrt(Utilities::MPI::sum(sum, MPI_COMM_WORLD) /
                          Utilities::MPI::sum(volume, MPI_COMM_WORLD)) /
                q;
    return result;
  }

  /// The largest difference of pressure (over q) and of displacement (over
  /// q H / E_oed) between two runs, point by point (both runs make the same
  /// points with the same ids on the same ranks).
  std::pair<double, double>
  difference(const Result &a, const Result &b)
  {
    double dp = (a.points.size() == b.points.size()) ? 0. : 1e300, du = 0.;
    for (const auto &[id, values] : a.points)
      {
        const auto found = b.points.find(id);
        if (found == b.points.end())
          {
            dp = 1e300;
            continue;
          }
        dp = std::max(dp, std::abs(values.first - found->second.first) / q);
        du = std::max(du,
                      std::abs(values.second - found->second.second) /
                        (q * H / E_oed));
      }
    return {Utilities::MPI::max(dp, MPI_COMM_WORLD),
            Utilities::MPI::max(du, MPI_COMM_WORLD)};
  }

  void
  compare(const std::string &label, const std::string &pore_fluid)
  {
    deallog << label << std::endl;
    const Result one = run(false, pore_fluid);
    const Result two = run(true, pore_fluid);
    check_that("  both runs completed", one.completed && two.completed);
    const auto [dp, du] = difference(one, two);
    check("  two bodies against one: largest pressure difference / q",
          dp,
          1e-6);
    check("  two bodies against one: largest displacement difference / "
          "(q H / E_oed)",
          du,
          1e-6);
    check("  two bodies: L2 error of p against Terzaghi / q", two.l2, 0.015);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  compare("1. Drained top boundary, fixed-stress split",
          "  set Drained boundaries = 3\n");
  compare("2. Drained top boundary, monolithic",
          "  set Drained boundaries = 3\n  set Coupling = monolithic\n");
  compare("3. The upper body's top face drained (Drained surface region)",
          "  set Drained surface region = y > " + std::to_string(H - 0.1) +
            "\n");
  return 0;
}
