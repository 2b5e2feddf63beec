// A coarse compact-tension specimen (b = 15 cm with h = 2.5 cm, i.e. six
// cells across the ligament, one point per cell; the paper's concrete) run
// to complete failure, on all ranks of MPI_COMM_WORLD and, for comparison,
// serially on MPI_COMM_SELF. This is a work-of-fracture test: at complete
// failure the load is zero, nothing elastic is left, and the work of the
// load, integral P d(delta), is the energy dissipated in the crack band,
// which must be G_f b d (b the ligament, d the depth).
//
// Two effects make "complete failure" delicate, see
// CompactTensionGeometry::setup() and the example's documentation:
//
// - the hinge: once the crack has run through, the two halves rotate about
//   the lowest point of the band, whose strain vanishes (with one point per
//   cell this is the hourglass mode of one-point quadrature); that point
//   never breaks. With one point per cell its share is h of b, and the
//   work would be G_f (b - h) d = 5/6 G_f b d here: the check below would
//   fail. The back-face band cell therefore holds 1 x 8 points (Back-face
//   point refinement = 8), and the unbroken share is at most h / 8 = b / 48,
//   2.1 %;
// - the tail: the point next to the hinge, h / 8 above it, fails only when
//   the rotation has opened it by u0 = 2 G_f / tau_nf = 0.089 mm, i.e. at a
//   load-point displacement of several millimetres, against 0.07 mm at the
//   peak. The load steps (5e-3 mm, fine enough for the peak and the steep
//   softening branch) therefore grow by 5 % per step from delta = 0.5 mm on
//   (LoadStepper's increment growth), and the run stops once every band
//   point but the hinge has failed completely, w >= u0.
//
// Checks: complete failure reached, the load then below 1e-3 of the peak,
// |W / (G_f b d) - 1| <= 5 % (W <= G_f b d as well), and the curve on 1
// and 2 ranks the same within 1e-3 of the peak load (see the reason below).
//
// Then the same specimen with path following instead of growing steps
// (issue 12): Load stepping/Control = opening, every step opening a clip
// gauge across the notch mouth by 0.025 mm (the gauge joins the points of
// the top cells beside the notch), no increment growth, and the decohesion
// model's continuous shear release (Shear retention = linear). Opening
// control traces the snap-backs of the tail instead of jumping them, so
// the energy must lie between two bounds that follow from the model: the
// unbroken hinge keeps its share h/8 of b (2.1 %) out of W, and the shear
// energy that linear retention releases on top of G_f adds to W. Checked:
// 1 - h/(8b) - 0.005 <= W / (G_f b d) <= 1.02, where 0.005 allows for the
// points' volume changes (the crack area of a point is its volume over
// L_c) and the trapezoidal rule, and 1.02 is the 2 % (measured
// 0.9783 with this Newton tolerance; 0.982 with the paper's 1e-3 in the
// example on 1, 2 and 3 ranks). The same curve on
// 1 and 2 ranks within 1e-3 of the peak, compared step by step (each step
// opens the gauge by the same amount on any number of ranks; measured
// 3.4e-4 on 2 ranks, 4.4e-4 on 3).
//
// The Newton tolerance is 1e-5 with GMRES at 1e-3: asking GMRES for 1e-6
// with finite-difference Jacobian products (sqrt(eps) = 1e-7) breaks down.
#include "tests.h"

// The specimen of the example compact_tension (examples/compact_tension/,
// on the include path of the tests).
#include "compact_tension_geometry.h"

#include <iostream>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/fracture/load_displacement_curve.h>
#include <qsmpm/materials/decohesion.h>

using namespace qsmpm;
using CompactTension::CompactTensionGeometry;

namespace
{
  const double E = 34.9e9, nu = 0.18, tau_nf = 2.77e6, G_f = 122.7;

  struct Result
  {
    LoadDisplacementCurve curve;
    /// Whether every band point but the lowest (the hinge) has failed.
    bool         complete_failure;
    unsigned int max_newton;
  };

  // Whether every point of the crack band except the lowest one (the
  // hinge) has failed completely, w / u0 >= 1.
  bool
  band_failed(const QuasiStaticProblem<2>     &problem,
              const CompactTensionGeometry<2> &geometry,
              const MPI_Comm                   communicator)
  {
    const auto band = geometry.count_failed_band_points(problem, communicator);
    return band.first > 0 && band.second == band.first;
  }

  /// How the load is stepped.
  enum class Control
  {
    /// Displacement control with steps growing from delta = 0.5 mm on.
    growing_displacement,
    /// Crack-mouth opening control with constant steps, linear shear
    /// retention.
    opening
  };

  Result
  run(const MPI_Comm                   communicator,
      const CompactTensionGeometry<2> &geometry,
      const Control                    control)
  {
    QuasiStaticProblem<2> problem(communicator);
    problem.pcout().set_condition(false);
    Tensor<1, 2> x_normal;
    x_normal[0] = 1.;
    auto model  = std::make_unique<Decohesion<2>>(
      E, nu, true, tau_nf, G_f, x_normal, geometry.cell_size());
    if (control == Control::opening)
      model->set_shear_retention(Decohesion<2>::ShearRetention::linear);
    const unsigned int right = geometry.setup(
      problem, std::move(model), 1, MaterialPointSet<2>::Placement::regular);

    auto &prm                                  = problem.parameters();
    prm.nonlinear_solver.tolerance             = 1e-5;
    prm.nonlinear_solver.linear_tolerance      = 1e-3;
    prm.nonlinear_solver.max_line_search_steps = 4;
    prm.load_stepping.n_steps                  = 4000;
    prm.load_stepping.final_load_factor        = 2e-2;
    prm.load_stepping.max_cut_backs            = 6;
    if (control == Control::growing_displacement)
      {
        prm.load_stepping.growth_factor = 1.05;
        prm.load_stepping.growth_start  = 5e-4;
      }
    else
      {
        const double h = geometry.cell_size(), y = geometry.height() - 0.5 * h;
        prm.load_stepping.control           = "opening";
        prm.load_stepping.opening_increment = 2.5e-5;
        prm.load_stepping.opening_gauge =
          std::to_string(-h) + "," + std::to_string(y) + "; " +
          std::to_string(h) + "," + std::to_string(y);
        prm.load_stepping.max_increment = 1e-3;
        prm.load_stepping.n_steps       = 100000;
      }
    prm.output.directory = "results";
    prm.output.interval  = 0;

    Result result;
    result.max_newton       = 0;
    result.complete_failure = false;
    problem.set_step_callback(
      [&](const QuasiStaticProblem<2>::StepReport &report) {
        result.curve.add(report.step,
                         report.load_factor,
                         geometry.load(problem.reactions(), right));
        result.max_newton =
          std::max(result.max_newton, report.newton.newton_iterations);
        result.complete_failure = result.curve.fallen_below(0.5) &&
                                  band_failed(problem, geometry, communicator);
        return !result.complete_failure;
      });
    problem.run();
    return result;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  CompactTensionGeometry<2>::Parameters parameters;
  parameters.ligament             = 0.15;
  parameters.cell_size            = 0.025;
  parameters.back_face_refinement = 8;
  const CompactTensionGeometry<2> geometry(parameters);

  for (const Control control :
       {Control::growing_displacement, Control::opening})
    {
      const Result parallel = run(MPI_COMM_WORLD, geometry, control);
      const auto  &curve    = parallel.curve;
      const double b = geometry.ligament(), d = geometry.depth();
      deallog << "Coarse CTS: b = " << b << " m, h = " << geometry.cell_size()
              << " m, one point per cell, 1 x 8 in the back-face band cell, "
              << (control == Control::opening ?
                    "crack-mouth opening control, linear shear retention" :
                    "displacement control with growing steps")
              << std::endl;
      check_that("complete failure: every band point but the hinge has w >= u0",
                 parallel.complete_failure);
      check("load at complete failure / peak load",
            curve.points().back().force / curve.peak_force(),
            1e-3);
      check_that("Newton iterations per step within 1 to 20",
                 parallel.max_newton >= 1 && parallel.max_newton <= 20);
      const double energy_ratio = curve.work() / (G_f * b * d);
      if (control == Control::growing_displacement)
        {
          check("|integral P d(delta) / (G_f b d) - 1|",
                energy_ratio - 1.,
                0.05);
          check_that("integral P d(delta) <= G_f b d", energy_ratio <= 1.);
        }
      else
        {
          const double hinge_share = geometry.cell_size() / (8. * b);
          check_that("integral P d(delta) / (G_f b d) >= 1 - h/(8b) - 0.005 "
                     "(the unbroken hinge)",
                     energy_ratio >= 1. - hinge_share - 0.005);
          check_that("integral P d(delta) / (G_f b d) <= 1.02",
                     energy_ratio <= 1.02);
        }

      // The same on one rank.
      const Result serial             = run(MPI_COMM_SELF, geometry, control);
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
      // material carries these differences over hundreds of steps and through
      // the discrete events of crack initiation and failure. The tolerance,
      // 1e-3 of the peak load, is our choice (not the paper's: the paper's 1e-3
      // is its Newton and GMRES tolerance, a relative residual, not a
      // difference of loads): 50 times below the energy check above, so a
      // difference it lets pass cannot decide that check.
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cout << "max |P - P_serial| / P_max = "
                  << largest_difference / curve.peak_force()
                  << ", load at the end / peak = "
                  << curve.points().back().force / curve.peak_force()
                  << ", W / (G_f b d) = " << curve.work() / (G_f * b * d)
                  << std::endl;
      check("max |P - P_serial| / P_max",
            largest_difference / curve.peak_force(),
            1e-3);
    }
}
