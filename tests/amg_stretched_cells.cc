// AMG on stretched cells (Nonlinear solver/AMG anisotropy threshold): a 3D
// slab of 32 x 32 x 2 cells, each 16 times longer in z than across (like the
// polycrystal's 96 x 96 x 4 grid of columnar grains), clamped at x = 0 and
// bent in its plane by its own weight. Aggregated by the stiffness alone
// (threshold 0, ML's default) AMG's aggregates span the weak z direction and
// GMRES needs many iterations; aggregated by the nodes' distances (the
// default threshold 0.01) the aggregates follow the plane and GMRES needs at
// most half as many (measured: about a quarter). The two solves must give
// the same increment to the linear tolerance (1e-8; checked at 1e-6, since
// GMRES's own estimate of the residual and the true one differ by the
// conditioning). On cells twice as long in z as across the distance graph
// drops no connection at 0.01: the iteration counts must agree within 25 %
// (the aggregates are those of the distance graph instead of the matrix
// graph). (On cells of equal sides the stiffness aggregates, see
// Preconditioner.) Iteration counts are printed
// only with QSMPM_VERBOSE (they depend on round-off in GMRES's residual
// estimate).
#include "tests.h"

#include <deal.II/base/function.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>

struct Result
{
  double                        gmres_per_newton;
  TrilinosWrappers::MPI::Vector increment;
};

Result
solve(const std::array<unsigned int, 3> &cells, const double threshold)
{
  constexpr int                dim = 3;
  qsmpm::QuasiStaticProblem<3> problem(MPI_COMM_WORLD);
  problem.pcout().set_condition(false);
  problem.grid().make_box(Point<dim>(), Point<dim>(1., 1., 1.), cells);
  problem.set_model(std::make_unique<qsmpm::LinearElastic<dim>>(100., 0.3));
  problem.points().fill([](const Point<dim> &) { return true; },
                        2,
                        qsmpm::MaterialPointSet<dim>::Placement::regular);
  problem.boundary_conditions().add_dirichlet_boundary(
    0,
    {{true, true, true}},
    std::make_shared<Functions::ZeroFunction<dim>>(dim));
  problem.boundary_conditions().set_body_force(
    std::make_shared<Functions::ConstantFunction<dim>>(
      std::vector<double>{0., -1e-3, 0.}));

  auto &prm                                     = problem.parameters();
  prm.material_points.update_volumes            = false;
  prm.nonlinear_solver.preconditioner           = "amg";
  prm.nonlinear_solver.amg_anisotropy_threshold = threshold;
  prm.nonlinear_solver.tolerance                = 1e-10;
  prm.nonlinear_solver.residual_floor           = 0.;
  prm.nonlinear_solver.linear_tolerance         = 1e-8;
  prm.nonlinear_solver.max_linear_iterations    = 5000;
  prm.nonlinear_solver.gmres_restart            = 500;
  prm.output.directory                          = "results";
  prm.output.interval                           = 0;
  problem.run();
  const auto  &report = problem.step_reports()[0].newton;
  const double gmres_per_newton =
    double(report.linear_iterations) / report.newton_iterations;
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 &&
      std::getenv("QSMPM_VERBOSE"))
    std::cout << "threshold " << threshold << ": GMRES per Newton step "
              << gmres_per_newton << std::endl;
  return {gmres_per_newton, problem.increment()};
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  deallog << "slab of 32 x 32 x 2 cells, 16:1" << std::endl;
  const Result by_stiffness = solve({{32, 32, 2}}, 0.);
  const Result by_distance  = solve({{32, 32, 2}}, 0.01);
  check_at_least("  GMRES iterations, by stiffness / by distance",
                 by_stiffness.gmres_per_newton / by_distance.gmres_per_newton,
                 2.);
  TrilinosWrappers::MPI::Vector difference = by_distance.increment;
  difference -= by_stiffness.increment;
  check("  increment, |by distance - by stiffness| / |by stiffness|",
        difference.l2_norm() / by_stiffness.increment.l2_norm(),
        1e-6);

  deallog << "block of 16 x 16 x 8 cells, 2:1" << std::endl;
  const Result mild_stiffness = solve({{16, 16, 8}}, 0.);
  const Result mild_distance  = solve({{16, 16, 8}}, 0.01);
  check("  GMRES iterations, |by distance / by stiffness - 1|",
        mild_distance.gmres_per_newton / mild_stiffness.gmres_per_newton - 1.,
        0.25);
}
