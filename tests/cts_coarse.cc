// A coarse compact-tension specimen (b = 15 cm with h = 2.5 cm, i.e. six
// cells across the ligament, one point per cell; the paper's concrete) run
// until the load has fallen below 0.2 % of its peak, on all ranks of
// MPI_COMM_WORLD and, for comparison, serially on MPI_COMM_SELF:
//
// - energy balance of a work-of-fracture test: the work of the load,
//   integral P d(delta), is the energy dissipated in the crack band. With
//   one point per cell the last cell of the ligament never breaks: the two
//   halves rotate about its point, which is an hourglass (zero-energy) mode
//   of one-point quadrature, so the broken ligament is b - h and the work
//   must be G_f (b - h) d (within 5 %), and never more than G_f b d;
// - every band point but the last one has (nearly) failed, w >= 0.95 u0
//   (the one next to the last cell is still opening when P is 0.2 % of
//   the peak);
// - the curve on 1 and 2 ranks is the same within the solver tolerance.
//
// The Newton tolerance is 1e-5 with GMRES at 1e-3: asking GMRES for 1e-6
// with finite-difference Jacobian products (sqrt(eps) = 1e-7) breaks down.
#include "tests.h"

#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/fracture/compact_tension_geometry.h>
#include <qsmpm/fracture/load_displacement_curve.h>
#include <qsmpm/materials/decohesion.h>

using namespace qsmpm;

namespace
{
  const double E = 34.9e9, nu = 0.18, tau_nf = 2.77e6, G_f = 122.7;

  struct Result
  {
    LoadDisplacementCurve curve;
    /// Smallest w / u0 of the band points above the lowest cell.
    double       smallest_opening;
    unsigned int max_newton;
  };

  Result
  run(const MPI_Comm communicator, const CompactTensionGeometry<2> &geometry)
  {
    QuasiStaticProblem<2> problem(communicator);
    problem.pcout().set_condition(false);
    Tensor<1, 2> x_normal;
    x_normal[0]              = 1.;
    const unsigned int right = geometry.setup(
      problem,
      std::make_unique<Decohesion<2>>(
        E, nu, true, tau_nf, G_f, x_normal, geometry.cell_size()),
      1,
      MaterialPointSet<2>::Placement::regular);

    auto &prm                                  = problem.parameters();
    prm.nonlinear_solver.tolerance             = 1e-5;
    prm.nonlinear_solver.linear_tolerance      = 1e-3;
    prm.nonlinear_solver.max_line_search_steps = 4;
    prm.load_stepping.n_steps                  = 400;
    prm.load_stepping.final_load_factor        = 2e-3;
    prm.load_stepping.max_cut_backs            = 6;
    prm.output.directory                       = "results";
    prm.output.interval                        = 0;

    Result result;
    result.max_newton = 0;
    problem.set_step_callback(
      [&](const QuasiStaticProblem<2>::StepReport &report) {
        result.curve.add(report.step,
                         report.load_factor,
                         geometry.load(problem.reactions(), right));
        result.max_newton =
          std::max(result.max_newton, report.newton.newton_iterations);
        return !result.curve.fallen_below(0.002);
      });
    problem.run();

    const auto &layout   = problem.points().get_layout();
    const auto  w        = layout.offset(Decohesion<2>::opening_ratio_name);
    double      smallest = 1e10;
    for (const auto &particle : problem.points().get_particle_handler())
      if (geometry.in_crack_band(particle.get_location()) &&
          particle.get_location()[1] > geometry.cell_size())
        smallest = std::min(smallest, particle.get_properties()[w]);
    result.smallest_opening = Utilities::MPI::min(smallest, communicator);
    return result;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  CompactTensionGeometry<2>::Parameters parameters;
  parameters.ligament  = 0.15;
  parameters.cell_size = 0.025;
  const CompactTensionGeometry<2> geometry(parameters);

  const Result parallel = run(MPI_COMM_WORLD, geometry);
  const auto  &curve    = parallel.curve;
  const double b = geometry.ligament(), d = geometry.depth(),
               h = geometry.cell_size();
  deallog << "Coarse CTS: b = " << b << " m, h = " << h << " m, "
          << "one point per cell" << std::endl;
  check_that("load fell below 0.2 % of the peak", curve.fallen_below(0.002));
  check_that("Newton iterations per step within 1 to 20",
             parallel.max_newton >= 1 && parallel.max_newton <= 20);
  check("|integral P d(delta) / (G_f (b - h) d) - 1|",
        curve.work() / (G_f * (b - h) * d) - 1.,
        0.05);
  check_that("integral P d(delta) <= G_f b d", curve.work() <= G_f * b * d);
  check_at_least("band points above the last cell: min w / u0",
                 parallel.smallest_opening,
                 0.95);

  // The same on one rank.
  const Result serial             = run(MPI_COMM_SELF, geometry);
  double       largest_difference = 0.;
  const auto  &p = curve.points(), &q = serial.curve.points();
  for (unsigned int i = 0; i < std::min(p.size(), q.size()); ++i)
    largest_difference =
      std::max(largest_difference, std::abs(p[i].force - q[i].force));
  check_that("same number of steps on this communicator and on one rank",
             p.size() == q.size());
  // The partitioned AMG gives other (equally converged) iterates on 2
  // ranks; each step's solution differs within the Newton tolerance (1e-5
  // of the step's initial residual) and a softening, path-dependent
  // material carries these differences over some 300 steps and through the
  // discrete events of crack initiation. 1e-3 of the peak (the paper's
  // tolerance) is 50 times below the energy check above.
  check("max |P - P_serial| / P_max",
        largest_difference / curve.peak_force(),
        1e-3);
}
