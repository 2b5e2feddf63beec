// With points at the 2^dim Gauss points of every cell and volumes equal to
// the Gauss weights times the cell volume (JxW), and without volume updates,
// the first MPM load step is exactly the Q1 finite element method with
// 2-point Gauss quadrature. Compare the grid displacement with a deal.II
// finite element solve (direct solver) of the same problem on the same mesh:
// a box fixed on the left, pulled down with a prescribed u_y on the bottom,
// a traction on the right and a body force. Tolerance 1e-8 relative: the
// JFNK solve is converged to 1e-12, so only round-off and the
// finite-difference Jacobian limit the agreement.
//
// Then the same loads in four steps (all proportional to t): with <Move
// points = false> every step is that FEM's step, so the points' accumulated
// displacements are the FEM field at the points to the same 1e-8; the
// material-point method (points moving, the default) departs from it by
// the change of its quadrature and geometry (of the order of the strain,
// 1e-3), which the second check asks to exceed 1e-6: it shows that the
// first would fail if the points moved. Last, a formulation changed after
// set_model() (which made the points) must stop run() with a message.
#include "fem_reference.h"
#include "tests.h"

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>
#include <iostream>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>

template <int dim>
class BottomDisplacement : public Function<dim>
{
public:
  BottomDisplacement()
    : Function<dim>(dim)
  {
  }
  double
  value(const Point<dim> &x, const unsigned int c) const override
  {
    return c == 1 ? -2e-3 * x[0] * this->get_time() : 0.;
  }
};

template <int dim>
Tensor<1, dim>
traction()
{
  Tensor<1, dim> t;
  t[0] = 0.2;
  t[1] = -0.1;
  return t;
}

template <int dim>
Tensor<1, dim>
body_force()
{
  Tensor<1, dim> b;
  b[1] = -1.;
  return b;
}

// The reference: textbook Q1 linear elasticity, assembled with FEValues.
template <int dim>
Vector<double>
fem_solution(const DoFHandler<dim>         &dof_handler,
             const SymmetricTensor<4, dim> &C)
{
  const auto                      &fe = dof_handler.get_fe();
  AffineConstraints<double>        constraints;
  const FEValuesExtractors::Vector u(0);
  VectorTools::interpolate_boundary_values(dof_handler,
                                           0,
                                           Functions::ZeroFunction<dim>(dim),
                                           constraints);
  BottomDisplacement<dim> bottom;
  bottom.set_time(1.);
  ComponentMask y_only(dim, false);
  y_only.set(1, true);
  VectorTools::interpolate_boundary_values(
    dof_handler, 2, bottom, constraints, y_only);
  constraints.close();

  DynamicSparsityPattern dsp(dof_handler.n_dofs());
  DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
  SparsityPattern sparsity;
  sparsity.copy_from(dsp);
  SparseMatrix<double> K(sparsity);
  Vector<double>       f(dof_handler.n_dofs()), solution(dof_handler.n_dofs());

  const QGauss<dim>     quadrature(2);
  const QGauss<dim - 1> face_quadrature(2);
  FEFaceValues<dim>     fe_face(fe,
                            face_quadrature,
                            update_values | update_JxW_values);
  // The traction on boundary 1.
  const auto tractions = [&](const auto &cell, Vector<double> &f_cell) {
    for (const unsigned int face : cell->face_indices())
      if (cell->face(face)->at_boundary() &&
          cell->face(face)->boundary_id() == 1)
        {
          fe_face.reinit(cell, face);
          for (const unsigned int q : fe_face.quadrature_point_indices())
            for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
              f_cell(i) +=
                fe_face[u].value(i, q) * traction<dim>() * fe_face.JxW(q);
        }
  };
  FEM::assemble_elasticity<dim>(dof_handler,
                                quadrature,
                                C,
                                body_force<dim>(),
                                constraints,
                                K,
                                f,
                                tractions);
  SparseDirectUMFPACK direct;
  direct.initialize(K);
  direct.vmult(solution, f);
  constraints.distribute(solution);
  return solution;
}

// The box, its points at the Gauss points and its loads; @p ramped: the
// traction and body force grow with t (for several steps), else constant.
template <int dim>
void
set_up(qsmpm::QuasiStaticProblem<dim> &problem,
       const bool                      ramped,
       const bool                      move_points = true)
{
  // Before set_model(), which makes the points with it.
  problem.parameters().material_points.formulation.move_points = move_points;
  problem.pcout().set_condition(false);
  Point<dim>                    upper;
  std::array<unsigned int, dim> n;
  for (unsigned int d = 0; d < dim; ++d)
    {
      upper[d] = d == 0 ? 3. : 1.;
      n[d]     = d == 0 ? 9 : 3;
    }
  problem.grid().make_box(Point<dim>(), upper, n);
  problem.set_model(std::make_unique<qsmpm::LinearElastic<dim>>(100., 0.25));
  problem.points().fill([](const Point<dim> &) { return true; },
                        2,
                        qsmpm::MaterialPointSet<dim>::Placement::gauss);

  auto                 &bcs = problem.boundary_conditions();
  std::array<bool, dim> all, y_only;
  all.fill(true);
  y_only.fill(false);
  y_only[1] = true;
  bcs.add_dirichlet_boundary(
    0, all, std::make_shared<Functions::ZeroFunction<dim>>(dim));
  bcs.add_dirichlet_boundary(2,
                             y_only,
                             std::make_shared<BottomDisplacement<dim>>());
  // One load step: constant loads are the loads at t = 1.
  auto constant = [](const Tensor<1, dim> &value) {
    std::vector<double> values(value.begin_raw(), value.begin_raw() + dim);
    return std::make_shared<Functions::ConstantFunction<dim>>(values);
  };
  // value * t, with deal.II's parser (its last variable the time).
  auto ramp = [](const Tensor<1, dim> &value) {
    std::vector<std::string> expressions;
    for (unsigned int d = 0; d < dim; ++d)
      expressions.push_back(std::to_string(value[d]) + " * t");
    auto function = std::make_shared<FunctionParser<dim>>(dim);
    function->initialize(FunctionParser<dim>::default_variable_names() + ",t",
                         expressions,
                         {},
                         true);
    return function;
  };
  if (ramped)
    {
      bcs.add_traction(1, ramp(traction<dim>()));
      bcs.set_body_force(ramp(body_force<dim>()));
    }
  else
    {
      bcs.add_traction(1, constant(traction<dim>()));
      bcs.set_body_force(constant(body_force<dim>()));
    }

  auto &prm                             = problem.parameters();
  prm.material_points.update_volumes    = false;
  prm.nonlinear_solver.tolerance        = 1e-12;
  prm.nonlinear_solver.residual_floor   = 0.;
  prm.nonlinear_solver.linear_tolerance = 1e-10;
  prm.output.directory                  = "results";
  prm.output.interval                   = 0;
}

template <int dim>
void
test()
{
  qsmpm::QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
  set_up(problem, false);
  problem.run();

  const SymmetricTensor<4, dim> C =
    qsmpm::LinearElastic<dim>(100., 0.25).stiffness();
  const Vector<double> u_fem =
    fem_solution(problem.grid().get_dof_handler(), C);
  Vector<double> u_mpm(u_fem.size());
  for (unsigned int i = 0; i < u_fem.size(); ++i)
    u_mpm[i] = problem.increment()(i);
  Vector<double> difference = u_mpm;
  difference -= u_fem;

  // 9 x 3 (x 3) cells: dim (10 x 4 (x 4)) dofs, 2^dim points per cell.
  const unsigned int cells = dim == 2 ? 27 : 81, nodes = dim == 2 ? 40 : 160;
  const unsigned int newton =
    problem.step_reports()[0].newton.newton_iterations;
  std::cout << dim << "D: " << u_fem.size() << " dofs, "
            << problem.points().n_global_points() << " points, " << newton
            << " Newton iterations" << std::endl;
  deallog << dim << "D" << std::endl;
  check_that("  dim x nodes dofs, 2^dim points per cell",
             u_fem.size() == dim * nodes &&
               problem.points().n_global_points() == (1u << dim) * cells);
  check("  ||u_MPM - u_FEM|| / ||u_FEM||",
        difference.l2_norm() / u_fem.l2_norm(),
        1e-8);
  // A linear problem: the first Newton step solves it up to GMRES's 1e-10
  // and the finite-difference Jacobian's relative error (~1e-7), the
  // second to ~1e-14 < 1e-12; 3 allows one step more for round-off in the
  // residual norm near the tolerance.
  check_that("  Newton iterations: 1 to 3 (linear problem)",
             newton >= 1 && newton <= 3);

  // Four steps; the points' displacements against the FEM field at their
  // initial places (where they stay with Move points = false).
  const auto departure = [&](const bool move) {
    qsmpm::QuasiStaticProblem<dim> steps(MPI_COMM_WORLD);
    set_up(steps, true, move);
    steps.parameters().load_stepping.n_steps = 4;
    steps.run();
    const auto &offsets = steps.points().get_offsets();
    double      error = 0., norm = 0.;
    for (const auto &particle : steps.points().get_particle_handler())
      {
        // Where the point was created: x_p - u_p if it moved.
        const double *u_p =
          particle.get_properties().data() + offsets.displacement;
        Point<dim> x = particle.get_location();
        if (move)
          for (unsigned int d = 0; d < dim; ++d)
            x[d] -= u_p[d];
        Vector<double> u(dim);
        VectorTools::point_value(problem.grid().get_dof_handler(), u_fem, x, u);
        for (unsigned int d = 0; d < dim; ++d)
          {
            error += (u_p[d] - u[d]) * (u_p[d] - u[d]);
            norm += u[d] * u[d];
          }
      }
    return std::sqrt(error / norm);
  };
  check("  4 steps, Move points = false: |u_p - u_FEM(x_p)| / |u_FEM|",
        departure(false),
        1e-8);
  check_that("  4 steps, points moving (MPM): the same above 1e-6",
             departure(true) > 1e-6);

  // The points are made by set_model(): a formulation changed after it
  // would be ignored, so run() stops and says so.
  qsmpm::QuasiStaticProblem<dim> late(MPI_COMM_WORLD);
  set_up(late, true);
  late.parameters().material_points.formulation.move_points = false;
  std::string message;
  try
    {
      late.run();
    }
  catch (const std::exception &exc)
    {
      message = exc.what();
    }
  check_that("  Move points changed after set_model(): run() stops, names "
             "set_model()",
             message.find("set_model()") != std::string::npos);
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  test<2>();
  test<3>();
}
