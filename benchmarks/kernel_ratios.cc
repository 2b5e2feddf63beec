// kernel_ratios: what Jacobian-free Newton-Krylov costs against the classical
// assembled-matrix Newton method, measured in the same run on the same block
// problem as solver_scaling (2^dim points per cell):
//
//  - one residual evaluation R(du) (all points, constitutive update, forces)
//    against one SparseMatrix::vmult of the assembled stiffness on the same
//    degrees of freedom;
//  - one JFNK linear load step (AMG-preconditioned GMRES on finite-difference
//    products) against one assembled-matrix Newton step (GMRES with the
//    assembled stiffness and the same AMG), both including the assembly of
//    the stiffness and the AMG setup;
//  - memory: resident bytes per material point (points, their properties,
//    the cached shape data) and the peak resident memory.
//
// Usage: kernel_ratios [n2d n3d] (cells across; default 256 and 32).
// Writes "key,value" lines to standard output.
#include "benchmark_problem.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <iostream>
#include <limits>
#include <qsmpm/assembly/quasi_static_residual.h>
#include <qsmpm/assembly/tangent_assembler.h>
#include <qsmpm/core/step_operator.h>
#include <qsmpm/loading/boundary_descriptor.h>
#include <qsmpm/loading/displacement_constraints.h>
#include <qsmpm/materials/linear_elastic.h>
#include <qsmpm/solvers/newton_krylov.h>
#include <qsmpm/solvers/preconditioner.h>

namespace
{
  using namespace dealii;
  using VectorType = TrilinosWrappers::MPI::Vector;

  using Benchmarks::print;

  template <int dim>
  void
  run(const unsigned int n)
  {
    const std::string tag  = std::to_string(dim) + "d_" + std::to_string(n);
    const MPI_Comm    comm = MPI_COMM_WORLD;

    qsmpm::BackgroundGrid<dim> grid(comm);
    Benchmarks::make_unit_box(grid, n);
    const qsmpm::LinearElastic<dim> model(1e3, 0.3);

    const double                 rss_before = Benchmarks::resident_memory();
    qsmpm::MaterialPointSet<dim> points(grid, model);
    points.fill([](const Point<dim> &) { return true; },
                2,
                qsmpm::MaterialPointSet<dim>::Placement::regular);
    qsmpm::ShapeCache<dim>          cache;
    qsmpm::QuasiStaticResidual<dim> residual(grid, points, cache, true);
    cache.reinit(grid, points, residual.ghosted_layout());
    const double rss_points = Benchmarks::resident_memory();
    const double n_points   = points.n_global_points();
    print(tag + "_points", n_points);
    print(tag + "_dofs", grid.get_dof_handler().n_dofs());
    print(tag + "_bytes_per_point",
          Utilities::MPI::sum(rss_points - rss_before, comm) / n_points);

    qsmpm::BoundaryDescriptor<dim> bcs;
    std::array<bool, dim>          all;
    all.fill(true);
    bcs.add_dirichlet_boundary(
      2, all, std::make_shared<Functions::ZeroFunction<dim>>(dim));
    bcs.add_dirichlet_boundary(
      3, all, std::make_shared<Benchmarks::TopDisplacement<dim>>());
    AffineConstraints<double> step_lines;
    qsmpm::DisplacementConstraints<dim>(bcs).make(grid, 0., 1., step_lines);
    for (const auto dof : cache.dofs_without_points(grid))
      if (!step_lines.is_constrained(dof))
        step_lines.add_line(dof);
    step_lines.close();
    qsmpm::StepConstraints step_constraints;
    step_constraints.reinit(std::move(step_lines),
                            grid.locally_owned_dofs(),
                            comm);
    const AffineConstraints<double> &constraints = step_constraints.get();
    VectorType                       f_ext(grid.locally_owned_dofs(), comm);
    residual.set_external_force(f_ext);

    // Kernels: residual evaluation against sparse matrix-vector product.
    qsmpm::TangentAssembler<dim> tangent;
    tangent.reinit(grid);
    tangent.assemble(grid, points, cache, constraints);
    VectorType du(f_ext), R(f_ext), y(f_ext);
    du = 0.;
    constraints.distribute(du);
    // The fastest of 5 blocks of 10 evaluations each: robust against
    // other load on the machine.
    const auto seconds_per_call = [](const auto &kernel) {
      double best = std::numeric_limits<double>::max();
      for (unsigned int block = 0; block < 5; ++block)
        {
          Timer timer;
          for (unsigned int i = 0; i < 10; ++i)
            kernel();
          best = std::min(best, timer.wall_time() / 10);
        }
      return best;
    };
    const double t_residual =
      seconds_per_call([&]() { residual.evaluate(du, R); });
    const double t_vmult =
      seconds_per_call([&]() { tangent.matrix().vmult(y, du); });
    print(tag + "_residual_seconds", t_residual);
    print(tag + "_vmult_seconds", t_vmult);
    print(tag + "_residual_over_vmult", t_residual / t_vmult);

    qsmpm::NewtonParameters parameters;
    parameters.tolerance             = 1e-6;
    parameters.linear_tolerance      = 1e-3;
    parameters.gmres_restart         = 200;
    parameters.max_linear_iterations = 20000;

    // One JFNK load step: stiffness, AMG, Newton-Krylov.
    qsmpm::Preconditioner<dim> amg(qsmpm::Preconditioner<dim>::Type::amg);
    Timer                      timer;
    tangent.assemble(grid, points, cache, constraints);
    amg.setup(tangent.matrix(), grid);
    du = 0.;
    constraints.distribute(du);
    const qsmpm::StepOperator<dim> op(residual, step_constraints, amg);
    const auto                     report =
      qsmpm::NewtonKrylov<qsmpm::StepOperator<dim>, VectorType>(parameters)
        .solve(op, du, R);
    const double t_jfnk = timer.wall_time();
    AssertThrow(report.converged, ExcMessage("JFNK step did not converge"));

    // One assembled-matrix Newton step: the same stiffness and AMG, and the
    // assembled matrix as the Jacobian (exact here up to volume updates).
    timer.restart();
    tangent.assemble(grid, points, cache, constraints);
    amg.setup(tangent.matrix(), grid);
    du = 0.;
    constraints.distribute(du);
    residual.evaluate(du, R);
    VectorType rhs(R), s(R);
    rhs = R;
    constraints.set_zero(rhs);
    const double target = parameters.tolerance * std::max(1., rhs.l2_norm());
    unsigned int newton = 0, gmres = 0;
    for (; rhs.l2_norm() > target && newton < 20; ++newton)
      {
        // K s = R  <=>  J s = -R with J = -K.
        SolverControl           control(parameters.max_linear_iterations,
                              parameters.linear_tolerance * rhs.l2_norm());
        SolverGMRES<VectorType> solver(control,
                                       SolverGMRES<VectorType>::AdditionalData(
                                         parameters.gmres_restart + 2, true));
        s = 0.;
        struct Positive
        {
          const qsmpm::Preconditioner<dim> &p;
          void
          vmult(VectorType &dst, const VectorType &src) const
          {
            p.vmult(dst, src);
            dst *= -1.;
          }
        } positive{amg};
        solver.solve(tangent.matrix(), s, rhs, positive);
        gmres += control.last_step();
        constraints.set_zero(s);
        du += s;
        residual.evaluate(du, R);
        rhs = R;
        constraints.set_zero(rhs);
      }
    const double t_assembled = timer.wall_time();
    print(tag + "_jfnk_step_seconds", t_jfnk);
    print(tag + "_jfnk_newton_iterations", report.newton_iterations);
    print(tag + "_jfnk_gmres_iterations", report.linear_iterations);
    print(tag + "_assembled_step_seconds", t_assembled);
    print(tag + "_assembled_newton_iterations", newton);
    print(tag + "_assembled_gmres_iterations", gmres);
    print(tag + "_jfnk_over_assembled", t_jfnk / t_assembled);
    print(tag + "_peak_memory_bytes",
          Utilities::MPI::sum(Benchmarks::peak_memory(), comm));
  }
} // namespace

int
main(int argc, char *argv[])
{
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const unsigned int n2d = argc > 2 ? std::stoi(argv[1]) : 256;
      const unsigned int n3d = argc > 2 ? std::stoi(argv[2]) : 32;
      if (n2d > 0)
        run<2>(n2d);
      if (n3d > 0)
        run<3>(n3d);
    }
  catch (std::exception &exc)
    {
      std::cerr << "kernel_ratios stopped: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
