// strip: the "strip" problem of issue 14. A unit block of N x N cells with
// 2 x 2 regularly placed points per cell, linear elastic, clamped at the
// bottom, rollers on the sides, and a uniform pressure on the left half of
// the top (a flexible strip footing), applied in 5 equal load steps. For a
// linear model and points that barely move, the stiffness and so the AMG
// hierarchy of step 1 serve the later steps as well: the option --reuse K
// (Nonlinear solver/Preconditioner reuse steps) rebuilds them only every K
// steps or when GMRES slows down by the reuse growth factor (default 2).
//
// Output: CSV "key,value" lines on standard output, per step
// (step_k_seconds, step_k_newton, step_k_gmres) and in total (seconds per
// step, the share of the preconditioner setup, the number of builds, peak
// memory, bytes per point, and where the memory goes: points, grid and
// degrees of freedom, stiffness matrix). Run each configuration in its own
// process: the peak memory is that of the process.
//
//   strip [--cells N] [--reuse K] [--extrapolate 0|1]
//                                     (defaults 256, 1 and 0)
#include "benchmark_problem.h"

#include <deal.II/base/timer.h>
#include <map>

namespace
{
  using namespace dealii;

  /// The pressure q t on x < 1/2 of the top, zero elsewhere.
  class StripPressure : public Function<2>
  {
  public:
    StripPressure()
      : Function<2>(2)
    {
    }
    double
    value(const Point<2> &x, const unsigned int c) const override
    {
      return (c == 1 && x[0] < 0.5) ? -this->get_time() : 0.;
    }
  };
} // namespace

int
main(int argc, char *argv[])
{
  try
    {
      Utilities::MPI::MPI_InitFinalize    mpi(argc, argv, 1);
      std::map<std::string, unsigned int> option{{"--cells", 256},
                                                 {"--reuse", 1},
                                                 {"--extrapolate", 0}};
      for (int i = 1; i + 1 < argc; i += 2)
        {
          AssertThrow(option.count(argv[i]) == 1,
                      ExcMessage(std::string("Unknown option ") + argv[i]));
          option[argv[i]] = std::stoi(argv[i + 1]);
        }
      const unsigned int n_steps = 5;

      qsmpm::QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
      problem.return_large_blocks_to_system();
      problem.pcout().set_condition(false);
      const double rss_start = Benchmarks::resident_memory();
      Benchmarks::make_unit_box(problem.grid(), option["--cells"]);
      const double rss_grid = Benchmarks::resident_memory();
      // E = 1e4, nu = 0.3, final pressure 10: strains of about 1e-3.
      problem.set_model(std::make_unique<qsmpm::LinearElastic<2>>(1e4, 0.3));
      problem.points().fill([](const Point<2> &) { return true; },
                            2,
                            qsmpm::MaterialPointSet<2>::Placement::regular);
      const double rss_points = Benchmarks::resident_memory();
      auto        &bcs        = problem.boundary_conditions();
      const auto   zero       = std::make_shared<Functions::ZeroFunction<2>>(2);
      bcs.add_dirichlet_boundary(2, {{true, true}}, zero);
      bcs.add_dirichlet_boundary(0, {{true, false}}, zero);
      bcs.add_dirichlet_boundary(1, {{true, false}}, zero);
      bcs.add_traction(3, std::make_shared<StripPressure>());

      auto &prm                                       = problem.parameters();
      prm.nonlinear_solver.preconditioner             = "amg";
      prm.nonlinear_solver.tolerance                  = 1e-6;
      prm.nonlinear_solver.linear_tolerance           = 1e-3;
      prm.nonlinear_solver.max_linear_iterations      = 2000;
      prm.nonlinear_solver.preconditioner_reuse_steps = option["--reuse"];
      // --extrapolate 1: each step starts from the last step's increment
      // scaled to its load increment, with Eisenstat-Walker forcing (the
      // settings of the polycrystal .prm files, for a load that grows in
      // proportion).
      if (option["--extrapolate"] != 0)
        {
          prm.nonlinear_solver.initial_guess =
            qsmpm::NewtonParameters::InitialGuess::extrapolation;
          prm.nonlinear_solver.forcing =
            qsmpm::NewtonParameters::Forcing::eisenstat_walker;
        }
      else
        {
          prm.nonlinear_solver.initial_guess =
            qsmpm::NewtonParameters::InitialGuess::linear_predictor;
          prm.nonlinear_solver.forcing =
            qsmpm::NewtonParameters::Forcing::constant;
        }
      prm.load_stepping.n_steps           = n_steps;
      prm.load_stepping.final_load_factor = 10.;
      prm.output.directory                = "benchmark_output";
      prm.output.interval                 = 0;

      Timer timer;
      problem.run();
      timer.stop();

      Benchmarks::print("cells", option["--cells"]);
      Benchmarks::print("reuse_steps", option["--reuse"]);
      Benchmarks::print("extrapolate", option["--extrapolate"]);
      Benchmarks::print("points", problem.points().n_global_points());
      Benchmarks::print("dofs", problem.grid().get_dof_handler().n_dofs());
      for (const auto &report : problem.step_reports())
        {
          const std::string step = "step_" + std::to_string(report.step);
          Benchmarks::print(step + "_seconds", report.wall_time);
          Benchmarks::print(step + "_newton", report.newton.newton_iterations);
          Benchmarks::print(step + "_gmres", report.newton.linear_iterations);
        }
      const auto sections =
        problem.timer().get_summary_data(TimerOutput::total_wall_time);
      const double setup = sections.count("preconditioner setup") > 0 ?
                             sections.at("preconditioner setup") :
                             0.;
      // Where the time goes: every section of the problem's timer.
      for (const auto &[name, seconds] : sections)
        {
          std::string key = "seconds_" + name;
          for (char &c : key)
            if (c == ' ' || c == '(' || c == ')')
              c = '_';
          Benchmarks::print(key, seconds);
        }
      Benchmarks::print("seconds_per_step", timer.wall_time() / n_steps);
      Benchmarks::print("preconditioner_setup_share",
                        setup / timer.wall_time());
      Benchmarks::print("preconditioner_builds",
                        problem.n_preconditioner_builds());

      // Where the memory goes (rank 0): resident memory before and after
      // making the grid and filling the points, and what the stiffness
      // matrix reports; the rest of the peak is the solver's (vectors,
      // AMG hierarchy, GMRES basis, shape-function cache).
      const double n_points = problem.points().n_global_points();
      Benchmarks::print("memory_start_MB", rss_start / 1e6);
      Benchmarks::print("memory_grid_MB", (rss_grid - rss_start) / 1e6);
      Benchmarks::print("memory_points_MB", (rss_points - rss_grid) / 1e6);
      Benchmarks::print("memory_stiffness_MB",
                        problem.stiffness().memory_consumption() / 1e6);
      Benchmarks::print("peak_memory_MB", Benchmarks::peak_memory() / 1e6);
      Benchmarks::print("peak_bytes_per_point",
                        Benchmarks::peak_memory() / n_points);
    }
  catch (std::exception &exc)
    {
      std::cerr << "strip stopped: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
