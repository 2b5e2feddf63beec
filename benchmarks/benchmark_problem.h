// The block problem shared by the benchmarks: a box of 2^dim regularly placed
// points per cell, clamped at the bottom, its top pushed down and sideways by
// displacement control, isotropic linear elasticity, one load step.
#ifndef qsmpm_benchmarks_benchmark_problem_h
#define qsmpm_benchmarks_benchmark_problem_h

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <fstream>
#include <iostream>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>
#include <string>

namespace Benchmarks
{
  using namespace dealii;

  /// A "key,value" line on standard output, from rank 0.
  inline void
  print(const std::string &key, const double value)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << key << ',' << value << std::endl;
  }

  /// The unit box with n cells per direction.
  template <int dim>
  void
  make_unit_box(qsmpm::BackgroundGrid<dim> &grid, const unsigned int n)
  {
    Point<dim>                    upper;
    std::array<unsigned int, dim> subdivisions;
    for (unsigned int d = 0; d < dim; ++d)
      {
        upper[d]        = 1.;
        subdivisions[d] = n;
      }
    grid.make_box(Point<dim>(), upper, subdivisions);
  }

  /// Top plate: u = t (1e-4, -1e-3, 0); the sideways part is small enough
  /// that no point leaves the unit box on grids up to 512 cells across.
  template <int dim>
  class TopDisplacement : public Function<dim>
  {
  public:
    TopDisplacement()
      : Function<dim>(dim)
    {
    }
    double
    value(const Point<dim> &, const unsigned int c) const override
    {
      return this->get_time() * (c == 0 ? 1e-4 : (c == 1 ? -1e-3 : 0.));
    }
  };

  /// Set up the block [0, upper] with the given subdivisions: clamped at
  /// y = 0, the face y = upper[1] moved by TopDisplacement, linear elastic,
  /// 2^dim points per cell, one load step.
  template <int dim>
  void
  setup_block(qsmpm::QuasiStaticProblem<dim>      &problem,
              const Point<dim>                    &upper,
              const std::array<unsigned int, dim> &subdivisions,
              const std::string                   &preconditioner)
  {
    problem.pcout().set_condition(false);
    // No room is needed around the body: it is compressed, so its points
    // stay inside the box.
    problem.grid().make_box(Point<dim>(), upper, subdivisions);
    problem.set_model(std::make_unique<qsmpm::LinearElastic<dim>>(1e3, 0.3));
    problem.points().fill([](const Point<dim> &) { return true; },
                          2,
                          qsmpm::MaterialPointSet<dim>::Placement::regular);
    std::array<bool, dim> all;
    all.fill(true);
    problem.boundary_conditions().add_dirichlet_boundary(
      2, all, std::make_shared<Functions::ZeroFunction<dim>>(dim));
    problem.boundary_conditions().add_dirichlet_boundary(
      3, all, std::make_shared<TopDisplacement<dim>>());

    auto &prm                                  = problem.parameters();
    prm.nonlinear_solver.preconditioner        = preconditioner;
    prm.nonlinear_solver.tolerance             = 1e-6;
    prm.nonlinear_solver.linear_tolerance      = 1e-3;
    prm.nonlinear_solver.max_linear_iterations = 20000;
    prm.nonlinear_solver.gmres_restart         = 200;
    prm.output.directory                       = "benchmark_output";
    prm.output.interval                        = 0;
    prm.load_stepping.n_steps                  = 1;
  }

  /// Set up the unit block with n cells per direction.
  template <int dim>
  void
  setup_block(qsmpm::QuasiStaticProblem<dim> &problem,
              const unsigned int              n,
              const std::string              &preconditioner)
  {
    Point<dim>                    upper;
    std::array<unsigned int, dim> subdivisions;
    for (unsigned int d = 0; d < dim; ++d)
      {
        upper[d]        = 1.;
        subdivisions[d] = n;
      }
    setup_block<dim>(problem, upper, subdivisions, preconditioner);
  }

  /// Peak resident memory of this process in bytes (VmHWM).
  inline double
  peak_memory()
  {
    std::ifstream status("/proc/self/status");
    std::string   line;
    while (std::getline(status, line))
      if (line.rfind("VmHWM:", 0) == 0)
        return 1024. * std::stod(line.substr(6));
    return 0.;
  }

  /// Current resident memory of this process in bytes (VmRSS).
  inline double
  resident_memory()
  {
    std::ifstream status("/proc/self/status");
    std::string   line;
    while (std::getline(status, line))
      if (line.rfind("VmRSS:", 0) == 0)
        return 1024. * std::stod(line.substr(6));
    return 0.;
  }
} // namespace Benchmarks

#endif
