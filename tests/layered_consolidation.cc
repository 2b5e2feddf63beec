// Layered soil: a mobility per material id (`Pore fluid/Mobility by
// material id`). A column 0 <= y <= H = 10 m on rollers (E = 1.5 MPa,
// nu = 0.25, b = 1, 1/M = 0: E_oed = 1.8 MPa), its lower half material id
// 0, its upper half id 1, 1 x 32 cells (the layers meet on a grid line),
// 2 x 2 points per cell.
//
// 1. Steady seepage through two layers in series: p = p0 = 100 Pa at the
//    base, 0 at the top, no load, kappa_0 = 1e-6 and kappa_1 = 4e-6
//    m^2 / (Pa s), run to t = 1000 s (T_v = 18 for the slower layer over
//    the whole height) in steps growing by 30 %. The flux is the same in
//    both layers, kappa_0 (p0 - p_i) / (H/2) = kappa_1 p_i / (H/2), so
//    the pressure is linear in each layer with p_i = p0 kappa_0 / (kappa_0
//    + kappa_1) = 20 Pa at y = H/2; Q1 holds that exactly. Checked: L2
//    over the points below 1e-4 of p0 (terzaghi_consolidation's steady
//    seepage; the fixed-stress iteration stops at 1e-5). With one mobility
//    for both layers p_i would be 50 Pa.
// 2. A clay under a sand: kappa_0 = 1e-6 (clay, below), kappa_1 = 1e-2
//    (sand, above), q = 10 kPa on the drained top, T_v = c t / (H/2)^2 =
//    0.5 for the clay (c = kappa_0 E_oed) in 32 steps. The sand drains
//    within the first step (its T_v then exceeds 100), so the clay is
//    Terzaghi's column of height H/2 drained at the sand: its pressure
//    against that solution, L2 over the clay's points below 1.5 % of q
//    (Terzaghi's column of one material on the same 16 cells and steps:
//    0.90 %, contact_bodies_consolidation); the sand's largest pressure
//    below 1 % of q. With the clay's mobility everywhere the sand would
//    hold the pressure as the clay does.
#include "consolidation_solutions.h"
#include "prm_text.h"
#include "tests.h"
#include "two_layer_column.h"

using namespace qsmpm;

namespace
{
  using namespace two_layer_column;
  constexpr double   q     = 1e4;
  constexpr unsigned cells = 32;

  /// Run the column; @p exact(Y) is the pressure at the initial height Y
  /// (NaN where no comparison is made). Returns the L2 error over the
  /// compared points relative to @p scale, and the largest |p| of the
  /// others.
  template <typename Exact>
  std::pair<double, double>
  run(const std::string &text, const Exact &exact, const double scale)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    try
      {
        initialize_from_text(problem, text);
        problem.run();
      }
    catch (const std::exception &exc)
      {
        deallog << "  run stopped: " << exc.what() << std::endl;
        return {1e300, 1e300};
      }
    const auto        &points   = problem.points();
    const auto        &offsets  = points.get_offsets();
    const unsigned int p_offset = pressure_offset(points);
    double             sum = 0., volume = 0., others = 0.;
    for (const auto &particle : points.get_particle_handler())
      {
        const auto   data = particle.get_properties();
        const double Y =
          particle.get_location()[1] - data[offsets.displacement + 1];
        const double p     = data[p_offset];
        const double p_ref = exact(Y);
        if (std::isnan(p_ref))
          others = std::max(others, std::abs(p));
        else
          {
            const double V = data[offsets.initial_volume];
            sum += V * (p - p_ref) * (p - p_ref);
            volume += V;
          }
      }
    const MPI_Comm comm = MPI_COMM_WORLD;
    return {std::sqrt(Utilities::MPI::sum(sum, comm) /
                      Utilities::MPI::sum(volume, comm)) /
              scale,
            Utilities::MPI::max(others, comm) / scale};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  deallog << "1. Steady seepage through two layers, kappa_1 = 4 kappa_0"
          << std::endl;
  {
    constexpr double p0 = 100., p_i = 20.;
    const auto       exact = [&](const double Y) {
      return Y < H / 2 ? p0 - (p0 - p_i) * Y / (H / 2) :
                               p_i * (H - Y) / (H / 2);
    };
    const auto [l2, unused] =
      run(prm_text(cells,
                   0.,
                   "  set Mobility = 1e-6\n"
                   "  set Mobility by material id = 1: 4e-6\n"
                   "  set Drained boundaries = 2, 3\n"
                   "  set Boundary pore pressure = 100 * (y < 5)\n",
                   1000.,
                   1000,
                   1.3),
          exact,
          p0);
    (void)unused;
    check("  L2 error of p / p0", l2, 1e-4);
  }

  deallog << "2. A clay under a sand (kappa_1 = 1e4 kappa_0), loaded on "
             "the drained top, clay T_v = 0.5 in 32 steps"
          << std::endl;
  {
    constexpr double kappa_clay = 1e-6, Tv = 0.5;
    const double     t_end = Tv * (H / 2) * (H / 2) / (kappa_clay * E_oed);
    const auto       exact = [&](const double Y) {
      return Y < H / 2 ?
                     Consolidation::terzaghi_pressure(H / 2 - Y, H / 2, Tv, q) :
                     std::nan("");
    };
    const auto [l2, sand] =
      run(prm_text(cells,
                   q,
                   "  set Mobility = 1e-6\n"
                   "  set Mobility by material id = 1: 1e-2\n"
                   "  set Drained boundaries = 3\n",
                   t_end,
                   32,
                   1.),
          exact,
          q);
    check("  clay: L2 error of p against Terzaghi (H/2) / q", l2, 0.015);
    check("  sand: largest |p| / q", sand, 0.01);
  }
  return 0;
}
