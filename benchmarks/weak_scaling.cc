// weak_scaling: one linear-elastic load step of a 3D block whose size grows
// with the number of ranks p (n x n x n p cells, 2 x 2 x 2 points per cell,
// AMG), and what a model of weak scaling needs from it: per rank the owned
// and ghost degrees of freedom and the number of neighbours it exchanges
// ghost values with (the messages of one vector update), and the times of
// the step's sections (doc/benchmarks.md, "Weak scaling").
//
//   mpirun -np p build/benchmarks/weak_scaling [n]      (default n = 24)
//
// Prints, from rank 0, one line for the step and one per rank:
//   step: ranks, cells, dofs, points, newton, gmres, amg_levels?,
//         setup_s, preconditioner_s, solve_s, step_s
//   rank r: owned_dofs, ghost_dofs, ghost_neighbours, import_dofs,
//           import_neighbours, points
#include "benchmark_problem.h"

#include <cstdlib>
#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/base/timer.h>
#include <iostream>

int
main(int argc, char *argv[])
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  constexpr int                    dim = 3;
  const unsigned int               n   = argc > 1 ? std::atoi(argv[1]) : 24;
  const unsigned int ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);

  qsmpm::QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
  problem.return_large_blocks_to_system();
  // The block n x n x n p: p4est's space-filling curve splits it along z
  // into slabs of about n^3 cells per rank.
  Benchmarks::setup_block<dim>(problem,
                               Point<dim>(1., 1., static_cast<double>(ranks)),
                               {{n, n, n * ranks}},
                               "amg");
  problem.run();

  const auto                       &grid = problem.grid();
  const Utilities::MPI::Partitioner partitioner(grid.locally_owned_dofs(),
                                                grid.locally_relevant_dofs(),
                                                MPI_COMM_WORLD);
  const std::vector<double>         mine = {
            static_cast<double>(grid.locally_owned_dofs().n_elements()),
            static_cast<double>(partitioner.n_ghost_indices()),
            static_cast<double>(partitioner.ghost_targets().size()),
            static_cast<double>(partitioner.n_import_indices()),
            static_cast<double>(partitioner.import_targets().size()),
            static_cast<double>(
      problem.points().get_particle_handler().n_locally_owned_particles())};
  const auto all = Utilities::MPI::gather(MPI_COMM_WORLD, mine, 0);

  const auto &report = problem.step_reports().at(0);
  const auto  times =
    problem.timer().get_summary_data(TimerOutput::OutputData::total_wall_time);
  const auto time = [&](const std::string &section) {
    const auto it = times.find(section);
    return it == times.end() ? 0. : it->second;
  };
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    return 0;
  std::cout << "step: ranks " << ranks << ", cells "
            << grid.get_triangulation().n_global_active_cells() << ", dofs "
            << grid.get_dof_handler().n_dofs() << ", points "
            << problem.points().n_global_points() << ", newton "
            << report.newton.newton_iterations << ", gmres "
            << report.newton.linear_iterations << ", sparsity set-up "
            << time("set-up (sparsity pattern)") << " s, tangent "
            << time("tangent assembly") << " s, AMG set-up "
            << time("preconditioner setup") << " s, Newton-Krylov "
            << time("Newton-Krylov solve") << " s, step " << report.wall_time
            << " s" << std::endl;
  for (unsigned int r = 0; r < all.size(); ++r)
    std::cout << "rank " << r << ": owned dofs " << all[r][0] << ", ghost dofs "
              << all[r][1] << " from " << all[r][2] << " ranks, sends "
              << all[r][3] << " to " << all[r][4] << " ranks, points "
              << all[r][5] << std::endl;
}
