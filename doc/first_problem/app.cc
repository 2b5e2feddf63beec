// A first qsmpm program (doc/first_problem.md), adapted from
// examples/block_compression: a 1 x 1 elastic block (plane strain) between a
// frictionless floor and a frictionless top plate that moves down by 1 %,
// in a 1.5 x 1 background grid whose right third holds no material points.
// It prints the plate force and the analytical value E/(1-nu^2) delta/H W.
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <iostream>
#include <memory>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>

using namespace dealii;

int
main(int argc, char *argv[])
{
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

      // Solver, load stepping and output settings from app.prm.
      ParameterHandler prm;
      qsmpm::QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
      prm.parse_input(argc > 1 ? argv[1] : "app.prm");

      qsmpm::QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
      problem.parameters().parse_parameters(prm);

      // The background grid: 12 x 8 square cells of size 1/8.
      problem.grid().make_box(Point<2>(0, 0), Point<2>(1.5, 1), {{12, 8}});

      // The material, then the body: points only where x < 1.
      const double E = 1e4, nu = 0.3, delta = 0.01;
      problem.set_model(std::make_unique<qsmpm::LinearElastic<2>>(E, nu));
      problem.points().fill([](const Point<2> &x) { return x[0] < 1; },
                            2,
                            qsmpm::MaterialPointSet<2>::Placement::regular);

      // Boundary ids: 0/1 = x min/max, 2/3 = y min/max. The left side (a
      // symmetry plane) and the floor fix the normal displacement only; the
      // plate prescribes u_y = -delta t, t = load factor (0 -> 1).
      auto      &bcs  = problem.boundary_conditions();
      const auto zero = std::make_shared<Functions::ZeroFunction<2>>(2);
      bcs.add_dirichlet_boundary(0, {}, zero, /*normal_only=*/true);
      bcs.add_dirichlet_boundary(2, {}, zero, /*normal_only=*/true);
      auto plate = std::make_shared<FunctionParser<2>>(2);
      plate->initialize("x,y,t",
                        "0; -delta*t",
                        {{"delta", delta}},
                        /*time_dependent=*/true);
      bcs.add_dirichlet_boundary(3, {{false, true}}, plate);

      problem.run();

      // reactions()[i]: the force the i-th displacement condition exerts on
      // the body after the last step (the same numbers as the last row of
      // output/reactions.csv). The plate pushes down.
      const double F = -problem.reactions()[2][1];
      problem.pcout() << "plate force " << F << ", analytical "
                      << E / (1 - nu * nu) * delta << std::endl;
    }
  catch (std::exception &exc)
    {
      std::cerr << "app stopped: " << qsmpm::Utils::error_message(exc)
                << std::endl;
      return 1;
    }
  return 0;
}
