// Rigid plates pressed by a force (Boundary conditions/Rigid plate
// boundaries, RigidPlates), and Mandel's problem with them (issue 31).
//
// 1. Two elastic columns side by side (E = 1000 and 3000, nu = 0, plane
//    strain, each 0.5 wide and 1 high, their interface on a grid line) on
//    rollers, under one rigid, frictionless plate loaded by F = 10 (a
//    traction of 10 on the top's width 1). Exact: the plate settles by
//    delta = F H / ((E_1 + E_2) W / 2) = 5e-3, every point has
//    u_y = -delta Y / H and sigma_yy = -E_i delta / H (the stiff column
//    carries 3/4 of F). Without the plate the same traction would give
//    the columns settlements 3 : 1. Small strain with the points' volumes
//    kept (Update volumes = false), so the discrete solution is exact:
//    checked to 1e-6 (the Newton tolerance 1e-8), in one step (in more,
//    the points' motion in the first would add a relative error of the
//    order of the strain, 5e-3, to the displacement of the second).
// 2. Mandel's problem: the quarter a x b = 1 m x 1 m of a saturated
//    specimen under a rigid plate loaded by F = 10 kN/m, drained at x = a
//    (E = 1.5 MPa, nu = 0.25, kappa = 1e-6 m^2/(Pa s), incompressible
//    grains and fluid), against the exact solution (Mandel 1953;
//    Abousleiman et al. 1996; examples/consolidation/
//    consolidation_solutions.h): the centre pressure first rises above
//    p_0 = F / (2 a) by 9.2 % at c t / a^2 = 0.07 (the Mandel-Cryer
//    effect), the plate's settlement follows u_y / y of the solution. On
//    8 x 8 cells (100 steps) and 16 x 16 (200 steps) to c t / a^2 = 0.5.
//    Measured (doc/example_consolidation.md): peak error 0.60 % and
//    0.22 %, settlement error at most 0.52 % and 0.094 %.

#include "consolidation_solutions.h"
#include "tests.h"

#include <deal.II/base/function.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>
#include <qsmpm/materials/material_map.h>
#include <qsmpm/porous/poroelastic_model.h>

using namespace qsmpm;

namespace
{
  void
  check(const std::string &what, const bool passed)
  {
    deallog << what << ": " << (passed ? "PASS" : "FAIL") << std::endl;
  }

  bool
  verbose()
  {
    return std::getenv("QSMPM_VERBOSE") != nullptr &&
           Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }

  double
  global_max(const double value)
  {
    return Utilities::MPI::max(value, MPI_COMM_WORLD);
  }

  // The settings both parts share: small strain, volumes kept, 2 x 2
  // points per cell, no output.
  void
  configure(QuasiStaticProblem<2> &problem,
            const double           final_time,
            const unsigned int     steps)
  {
    problem.pcout().set_condition(false);
    auto &p                               = problem.parameters();
    p.material_points.update_volumes      = false;
    p.load_stepping.final_load_factor     = final_time;
    p.load_stepping.n_steps               = steps;
    p.output.interval                     = 0;
    p.output.directory                    = "mandel-out";
    p.equilibrium_check.stop_on_lost_load = true;
  }



  // A traction (0, -q t) on the top: the load grows with the load factor.
  class RampedTraction : public Function<2>
  {
  public:
    explicit RampedTraction(const double q)
      : Function<2>(2)
      , q(q)
    {
    }

    void
    vector_value(const Point<2> &, Vector<double> &values) const override
    {
      values    = 0.;
      values[1] = -q * this->get_time();
    }

  private:
    const double q;
  };



  constexpr double E1 = 1000, E2 = 3000, F = 10, W = 1, H = 1;

  // The two columns under their plate, loaded in @p steps steps.
  void
  make_two_columns(QuasiStaticProblem<2> &problem, const unsigned int steps)
  {
    configure(problem, 1., steps);
    problem.parameters().nonlinear_solver.tolerance = 1e-8;
    problem.grid().make_box(Point<2>(), Point<2>(W, H), {{8, 8}});
    auto map = std::make_unique<MaterialMap<2>>();
    map->add(0, std::make_unique<LinearElastic<2>>(E1, 0.));
    map->add(1, std::make_unique<LinearElastic<2>>(E2, 0.));
    problem.set_model(std::move(map));
    problem.points().fill([](const Point<2> &) { return true; },
                          MaterialPointSet<2>::reference_rule(
                            MaterialPointSet<2>::Placement::regular, {{2, 2}}),
                          [W](const Point<2> &x) {
                            return x[0] < W / 2 ? 0u : 1u;
                          });
    auto      &bcs  = problem.boundary_conditions();
    const auto zero = std::make_shared<Functions::ZeroFunction<2>>(2);
    bcs.add_dirichlet_boundary(0, {}, zero, /*normal_only=*/true);
    bcs.add_dirichlet_boundary(2, {}, zero, /*normal_only=*/true);
    bcs.add_traction(3, std::make_shared<RampedTraction>(F / W));
    bcs.add_rigid_plate(3);
  }



  void
  two_columns()
  {
    deallog << "1. Two columns (E = 1000 and 3000) under one rigid plate "
               "loaded by F = 10"
            << std::endl;
    const double delta = F * H / ((E1 + E2) * W / 2);

    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    make_two_columns(problem, 1);
    problem.run();

    const auto &offsets = problem.points().get_offsets();
    double      u_error = 0, stress_error = 0;
    for (const auto &particle : problem.points().get_particle_handler())
      {
        const auto   data = particle.get_properties();
        const double u_y  = data[offsets.displacement + 1];
        const double Y    = particle.get_location()[1] - u_y;
        const double E    = particle.get_location()[0] < W / 2 ? E1 : E2;
        u_error = std::max(u_error, std::abs(u_y + delta * Y / H) / delta);
        stress_error =
          std::max(stress_error,
                   std::abs(data[offsets.stress + 1] + E * delta / H) /
                     (E * delta / H));
      }
    u_error      = global_max(u_error);
    stress_error = global_max(stress_error);
    const double plate_error =
      std::abs(problem.rigid_plate_displacements()[0] + delta) / delta;
    if (verbose())
      std::cout << "two columns: u error " << u_error << ", stress error "
                << stress_error << ", plate error " << plate_error << std::endl;
    check("  the plate's displacement (reactions.csv plate_3_u) = -delta "
          "within 1e-6 delta",
          plate_error < 1e-6);
    check("  every point's u_y = -delta Y / H within 1e-6 delta",
          u_error < 1e-6);
    check("  every point's sigma_yy = -E_i delta / H within 1e-6",
          stress_error < 1e-6);

    // Checkpoints hold the plate's displacement: 4 steps at once, and
    // stopped after step 2 with a checkpoint after step 1, resumed from
    // it.
    std::array<double, 2> plate{};
    for (unsigned int run = 0; run < 3; ++run)
      {
        QuasiStaticProblem<2> again(MPI_COMM_WORLD);
        make_two_columns(again, 4);
        again.parameters().output.checkpoint_interval = run == 1 ? 1 : 0;
        if (run == 1)
          again.set_step_callback(
            [](const StepReport &report) { return report.step < 2; });
        if (run == 2)
          again.resume();
        again.run();
        if (run != 1)
          plate[run / 2] = again.rigid_plate_displacements()[0];
      }
    if (verbose())
      std::cout << "restart: plate " << plate[0] << " / " << plate[1]
                << std::endl;
    // The resumed step starts from the linear predictor instead of the
    // extrapolated increment: equal within the Newton tolerance 1e-8.
    check("  resumed from a checkpoint: the plate's displacement equals the "
          "uninterrupted run's within 1e-6",
          std::abs(plate[1] - plate[0]) < 1e-6 * std::abs(plate[0]));
  }



  struct MandelResult
  {
    double peak = 0, exact_peak = 0, p0 = 0;
    double settlement_error = 0;
    /// The same from the plate's displacement, u_y(b) = b s(t).
    double       plate_error  = 0;
    double       late_error   = 0;
    unsigned int min_coupling = 1000, max_coupling = 0, cut_backs = 0;
  };

  MandelResult
  mandel(const unsigned int cells, const unsigned int steps)
  {
    constexpr double    a = 1, b = 1, F = 1e4, tau_end = 0.5;
    Consolidation::Soil soil;
    soil.E     = 1.5e6;
    soil.nu    = 0.25;
    soil.kappa = 1e-6;
    const Consolidation::MandelSolution exact(soil, a, F);
    const double                        h = a / cells;
    const double t_end = tau_end * a * a / soil.consolidation_coefficient();

    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    configure(problem, t_end, steps);
    auto &fluid              = problem.parameters().pore_fluid;
    fluid.enabled            = true;
    fluid.mobility           = soil.kappa;
    fluid.drained_boundaries = {1};
    problem.grid().make_box(Point<2>(), Point<2>(a, b), {{cells, cells}});
    problem.set_model(std::make_unique<LinearElastic<2>>(soil.E, soil.nu));
    problem.points().fill([](const Point<2> &) { return true; },
                          2,
                          MaterialPointSet<2>::Placement::regular);
    auto      &bcs  = problem.boundary_conditions();
    const auto zero = std::make_shared<Functions::ZeroFunction<2>>(2);
    bcs.add_dirichlet_boundary(0, {}, zero, /*normal_only=*/true);
    bcs.add_dirichlet_boundary(2, {}, zero, /*normal_only=*/true);
    bcs.add_traction(3,
                     std::make_shared<Functions::ConstantFunction<2>>(
                       std::vector<double>{0., -F / a}));
    bcs.add_rigid_plate(3);

    MandelResult result;
    result.p0     = exact.initial_pressure();
    double X_mean = 0;
    problem.set_step_callback([&](const StepReport &report) {
      const auto &points  = problem.points();
      const auto &offsets = points.get_offsets();
      const auto &model =
        dynamic_cast<const PoroelasticModel<2> &>(points.get_model());
      const unsigned int p_offset = offsets.state + model.pressure_offset();
      // Centre column: p, exact p, volume, V X; all points: V u_y Y, V Y^2.
      std::vector<double> sums(6, 0.);
      for (const auto &particle : points.get_particle_handler())
        {
          const auto   data = particle.get_properties();
          const double V    = data[offsets.initial_volume];
          const double u_y  = data[offsets.displacement + 1];
          const double X =
            particle.get_location()[0] - data[offsets.displacement];
          const double Y = particle.get_location()[1] - u_y;
          if (X < h)
            {
              sums[0] += V * data[p_offset];
              sums[1] += V * exact.pressure(X, report.load_factor);
              sums[2] += V;
              sums[3] += V * X;
            }
          sums[4] += V * u_y * Y;
          sums[5] += V * Y * Y;
        }
      MPI_Allreduce(MPI_IN_PLACE,
                    sums.data(),
                    sums.size(),
                    MPI_DOUBLE,
                    MPI_SUM,
                    MPI_COMM_WORLD);
      result.peak               = std::max(result.peak, sums[0] / sums[2]);
      X_mean                    = sums[3] / sums[2];
      const double strain       = sums[4] / sums[5];
      const double exact_strain = exact.vertical_strain(report.load_factor);
      result.settlement_error =
        std::max(result.settlement_error,
                 std::abs(strain - exact_strain) / std::abs(exact_strain));
      result.plate_error =
        std::max(result.plate_error,
                 std::abs(problem.rigid_plate_displacements()[0] / b -
                          exact_strain) /
                   std::abs(exact_strain));
      if (exact.dimensionless_time(report.load_factor) > 0.25)
        result.late_error =
          std::max(result.late_error,
                   std::abs(sums[0] - sums[1]) / sums[2] / result.p0);
      return true;
    });
    try
      {
        problem.run();
      }
    catch (const std::exception &exc)
      {
        deallog << "  run stopped: " << qsmpm::Utils::error_message(exc)
                << std::endl;
        return result;
      }
    result.exact_peak = exact.peak_pressure(X_mean, t_end);
    for (const auto &report : problem.step_reports())
      {
        result.min_coupling =
          std::min(result.min_coupling, report.coupling_iterations);
        result.max_coupling =
          std::max(result.max_coupling, report.coupling_iterations);
        result.cut_backs += report.cut_backs;
      }
    if (verbose())
      std::cout << "Mandel " << cells << " cells: peak/p0 "
                << result.peak / result.p0 << " exact "
                << result.exact_peak / result.p0 << ", settlement error "
                << result.settlement_error << ", plate error "
                << result.plate_error << ", late error " << result.late_error
                << ", coupling " << result.min_coupling << "-"
                << result.max_coupling << std::endl;
    return result;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::MPILogInitAll       log;

  two_columns();

  deallog << "2. Mandel's problem under a rigid plate, 8 x 8 and 16 x 16 "
             "cells"
          << std::endl;
  const MandelResult coarse = mandel(8, 100);
  const MandelResult fine   = mandel(16, 200);
  const double       error_coarse =
    std::abs(coarse.peak - coarse.exact_peak) / coarse.exact_peak;
  const double error_fine =
    std::abs(fine.peak - fine.exact_peak) / fine.exact_peak;
  check("  peak centre pressure within 1 % of the exact peak (16 x 16)",
        error_fine < 0.01);
  check("  its error falls from 8 x 8 to 16 x 16", error_fine < error_coarse);
  // The effect itself: the rise above p_0, 9.2 % of p_0 here.
  const double rise       = fine.peak / fine.p0 - 1;
  const double exact_rise = fine.exact_peak / fine.p0 - 1;
  check("  Mandel-Cryer rise above p_0 within 10 % of the exact rise",
        std::abs(rise - exact_rise) < 0.1 * exact_rise);
  check("  settlement (u_y = s y fitted over the points) within 0.5 % of "
        "the exact at every step (16 x 16)",
        fine.settlement_error < 0.005);
  check("  the plate's own displacement within 0.5 % of the exact at every "
        "step (16 x 16)",
        fine.plate_error < 0.005);
  check("  centre pressure within 1 % of p_0 of the exact for "
        "c t / a^2 > 0.25 (16 x 16)",
        fine.late_error < 0.01);
  check("  no cut-back; fixed-stress iterations per step in [2, 15]",
        fine.cut_backs == 0 && coarse.cut_backs == 0 &&
          fine.min_coupling >= 2 && fine.max_coupling <= 15);
  return 0;
}
