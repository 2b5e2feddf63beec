// solver_scaling: linear-elastic quasi-static load steps on a block with 2^dim
// points per cell over a sequence of grids, for the preconditioners none (the
// paper's GMRES) and amg. Writes CSV to standard output:
//
//   dim,cells,dofs,points,preconditioner,newton_iterations,gmres_iterations,seconds
//
// gmres_iterations is summed over the Newton iterations of the step; seconds
// is the wall time of the load step (shape functions, constraints,
// preconditioner setup, Newton-Krylov solve, commit and point motion).
//
// Options: --dim 2|3 (default both), --min-2d/--max-2d N (default 32 and
// 512 cells across), --min-3d/--max-3d N (default 8 and 64), --max-none-2d N
// (default 256) and --max-none-3d N (default 32): unpreconditioned cases above
// these sizes are skipped, since their GMRES iteration count, and so their
// cost, grows with the grid.
#include "benchmark_problem.h"

#include <deal.II/base/mpi.h>
#include <iostream>
#include <map>

namespace
{
  template <int dim>
  void
  run(const unsigned int n, const std::string &preconditioner)
  {
    qsmpm::QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
    problem.return_large_blocks_to_system();
    Benchmarks::setup_block(problem, n, preconditioner);
    problem.run();
    const auto &report = problem.step_reports().at(0);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << dim << ','
                << problem.grid().get_triangulation().n_global_active_cells()
                << ',' << problem.grid().get_dof_handler().n_dofs() << ','
                << problem.points().n_global_points() << ',' << preconditioner
                << ',' << report.newton.newton_iterations << ','
                << report.newton.linear_iterations << ',' << report.wall_time
                << std::endl;
  }
} // namespace

int
main(int argc, char *argv[])
{
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      std::map<std::string, unsigned int>      option{{"--dim", 0},
                                                 {"--max-2d", 512},
                                                 {"--max-3d", 64},
                                                 {"--min-2d", 32},
                                                 {"--min-3d", 8},
                                                 {"--max-none-2d", 256},
                                                 {"--max-none-3d", 32}};
      for (int i = 1; i + 1 < argc; i += 2)
        {
          AssertThrow(option.count(argv[i]) == 1,
                      dealii::ExcMessage(std::string("Unknown option ") +
                                         argv[i]));
          option[argv[i]] = std::stoi(argv[i + 1]);
        }
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cout << "dim,cells,dofs,points,preconditioner,newton_iterations,"
                     "gmres_iterations,seconds"
                  << std::endl;
      if (option["--dim"] != 3)
        for (unsigned int n = option["--min-2d"]; n <= option["--max-2d"];
             n *= 2)
          for (const std::string p : {"none", "amg"})
            if (p == "amg" || n <= option["--max-none-2d"])
              run<2>(n, p);
      if (option["--dim"] != 2)
        for (unsigned int n = option["--min-3d"]; n <= option["--max-3d"];
             n *= 2)
          for (const std::string p : {"none", "amg"})
            if (p == "amg" || n <= option["--max-none-3d"])
              run<3>(n, p);
    }
  catch (std::exception &exc)
    {
      std::cerr << "solver_scaling stopped: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
