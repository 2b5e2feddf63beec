// A body smaller than the background grid (so that some nodes carry no
// points and must be constrained), clamped on its left edge (a node set
// selected by position), loaded by its weight and a point load, in several
// load steps. Run on 1 and 2 MPI ranks (equilibrium_mpi.mpirun=1/2.output).
//
// Checks against independent references:
//  - global equilibrium: the reactions balance the applied loads
//    (sum of Omega_p b over the points, computed here from the points'
//    volumes, plus the point load), to 1e-8 relative with tight tolerances;
//  - after the first step, the displacement of every point equals that of
//    an independent finite element solve written here with deal.II's
//    FEValues and a direct solver, times the load factor: the body [0, 2]
//    x [0, 1] (x [0, 1]) fills whole cells (h = 0.25), the empty nodes are
//    constrained, and without volume updates the first step is linear
//    elasticity with the points at their initial positions, i.e. Q1 FEM on
//    the body's cells with the quadrature rule at those points (the
//    midpoint rule iterated n times per direction, weights = the points'
//    volume fractions). (Later steps evaluate the shape functions where
//    the points have moved, which is no longer this linear problem.)
//    Tolerance 1e-8 relative in the points' L2 norm:
//    MPM's Newton and GMRES are converged to 1e-10, and the error of the
//    displacement is at most the condition number of the stiffness (about
//    1e3 on these grids) times the residual's relative size; the FEM solve
//    is exact up to round-off;
//  - each step is linear (Update volumes = false), so with the paper's
//    tolerances (1e-3 for Newton and GMRES) every step needs 1 or 2 Newton
//    iterations.
// The reaction and the points' L2 norms are printed to stdout.
#include "fem_reference.h"
#include "tests.h"

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>
#include <iostream>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>

template <int dim>
class Weight : public Function<dim>
{
public:
  Weight()
    : Function<dim>(dim)
  {
  }
  double
  value(const Point<dim> &, const unsigned int c) const override
  {
    return c == 1 ? -2. * this->get_time() : 0.;
  }
};

// The reference: textbook Q1 linear elasticity on the body's cells, h =
// 0.25, clamped at x = 0, weight 2 per unit volume, the point load at the
// node (2, 0.5 (, 0)), assembled with FEValues at the points' positions
// (n x n regular points per cell: the iterated midpoint rule) and solved
// with UMFPACK. Serial on every rank.
template <int dim>
struct FEMReference
{
  Triangulation<dim> triangulation;
  DoFHandler<dim>    dof_handler;
  Vector<double>     solution;

  FEMReference(const SymmetricTensor<4, dim> &C,
               const Point<dim>              &load_point,
               const Tensor<1, dim>          &load,
               const unsigned int             points_per_direction)
  {
    Point<dim>                upper;
    std::vector<unsigned int> n(dim);
    for (unsigned int d = 0; d < dim; ++d)
      {
        upper[d] = d == 0 ? 2. : 1.;
        n[d]     = d == 0 ? 8 : 4;
      }
    GridGenerator::subdivided_hyper_rectangle(
      triangulation, n, Point<dim>(), upper, /*colorize=*/true);
    const FESystem<dim> fe(FE_Q<dim>(1), dim);
    dof_handler.reinit(triangulation);
    dof_handler.distribute_dofs(fe);

    AffineConstraints<double> constraints;
    VectorTools::interpolate_boundary_values(dof_handler,
                                             0,
                                             Functions::ZeroFunction<dim>(dim),
                                             constraints);
    constraints.close();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityPattern sparsity;
    sparsity.copy_from(dsp);
    SparseMatrix<double> K(sparsity);
    Vector<double>       f(dof_handler.n_dofs());
    solution.reinit(dof_handler.n_dofs());

    const QIterated<dim> quadrature(QMidpoint<1>(), points_per_direction);
    Tensor<1, dim>       weight;
    weight[1] = -2.;
    FEM::assemble_elasticity(
      dof_handler, quadrature, C, weight, constraints, K, f);
    // The point load on the dofs of its node (once).
    bool found = false;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (!found && cell->vertex(v).distance(load_point) < 1e-10)
          {
            found = true;
            for (unsigned int d = 0; d < dim; ++d)
              f(cell->vertex_dof_index(v, d)) += load[d];
          }
    AssertThrow(found, ExcInternalError());

    SparseDirectUMFPACK direct;
    direct.initialize(K);
    direct.vmult(solution, f);
    constraints.distribute(solution);
  }

  Tensor<1, dim>
  value(const Point<dim> &X) const
  {
    Vector<double> v(dim);
    VectorTools::point_value(dof_handler, solution, X, v);
    Tensor<1, dim> t;
    for (unsigned int d = 0; d < dim; ++d)
      t[d] = v[d];
    return t;
  }
};

template <int dim>
void
test(const double tolerance)
{
  qsmpm::QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
  problem.pcout().set_condition(false);
  // Grid [0, 2.5] x [-0.25, 1.25] (x [-0.25, 1.25]); body [0, 2] x [0,
  // 1]^(dim-1).
  Point<dim>                    lower, upper;
  std::array<unsigned int, dim> n;
  for (unsigned int d = 0; d < dim; ++d)
    {
      lower[d] = d == 0 ? 0. : -0.25;
      upper[d] = d == 0 ? 2.5 : 1.25;
      n[d]     = d == 0 ? 10 : 6;
    }
  problem.grid().make_box(lower, upper, n);
  auto model = std::make_unique<qsmpm::LinearElastic<dim>>(1000., 0.3);
  const SymmetricTensor<4, dim> C = model->stiffness();
  problem.set_model(std::move(model));
  problem.points().fill(
    [](const Point<dim> &x) {
      for (unsigned int d = 0; d < dim; ++d)
        if (x[d] < 0. || x[d] > (d == 0 ? 2. : 1.))
          return false;
      return true;
    },
    2,
    qsmpm::MaterialPointSet<dim>::Placement::regular);

  auto                 &bcs = problem.boundary_conditions();
  std::array<bool, dim> all;
  all.fill(true);
  bcs.add_dirichlet_nodes(
    "clamp",
    [](const Point<dim> &x) { return std::abs(x[0]) < 1e-12; },
    all,
    std::make_shared<Functions::ZeroFunction<dim>>(dim));
  bcs.set_body_force(std::make_shared<Weight<dim>>());
  Point<dim>     load_point;
  Tensor<1, dim> load;
  load_point[0] = 2.;
  load_point[1] = 0.5;
  load[0]       = 0.3;
  load[1]       = -0.5;
  bcs.add_point_load(load_point, load);

  auto &prm                             = problem.parameters();
  prm.material_points.update_volumes    = false;
  prm.nonlinear_solver.tolerance        = tolerance;
  prm.nonlinear_solver.residual_floor   = tolerance < 1e-6 ? 0. : 1.;
  prm.nonlinear_solver.linear_tolerance = tolerance < 1e-6 ? 1e-10 : 1e-3;
  prm.output.directory                  = "results";
  prm.output.interval                   = 0;
  prm.load_stepping.n_steps             = 3;
  // Every point after the first step against the independent FEM solution
  // (times the load factor) at its position. Only the first step is linear
  // FEM: from the second on the points sit where the first step moved them
  // (by up to 0.1 h) and the shape functions are evaluated there, which is
  // MPM's updated-Lagrangian geometry, not the linear problem (1 % apart
  // after 3 steps here).
  const FEMReference<dim> fem(C, load_point, load, 2);
  const auto             &offsets        = problem.points().get_offsets();
  double                  fem_difference = -1.;
  problem.set_step_callback(
    [&](const typename qsmpm::QuasiStaticProblem<dim>::StepReport &report) {
      if (report.step != 1)
        return true;
      double difference2 = 0, norm2 = 0;
      for (const auto &particle : problem.points().get_particle_handler())
        {
          const auto     data = particle.get_properties();
          Tensor<1, dim> u;
          Point<dim>     X = particle.get_location();
          for (unsigned int d = 0; d < dim; ++d)
            {
              u[d] = data[offsets.displacement + d];
              X[d] -= u[d];
            }
          const Tensor<1, dim> u_fem = report.load_factor * fem.value(X);
          difference2 += data[offsets.volume] * (u - u_fem).norm_square();
          norm2 += data[offsets.volume] * u_fem.norm_square();
        }
      difference2    = Utilities::MPI::sum(difference2, MPI_COMM_WORLD);
      norm2          = Utilities::MPI::sum(norm2, MPI_COMM_WORLD);
      fem_difference = std::sqrt(difference2 / norm2);
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cout << dim << "D step 1 (t = " << report.load_factor
                  << "): ||u_FEM||_L2(points) " << std::sqrt(norm2)
                  << ", ||u - u_FEM||_L2(points) / ||u_FEM|| " << fem_difference
                  << std::endl;
      return true;
    });
  problem.run();

  unsigned int min_newton = 100, max_newton = 0;
  for (const auto &report : problem.step_reports())
    {
      min_newton = std::min(min_newton, report.newton.newton_iterations);
      max_newton = std::max(max_newton, report.newton.newton_iterations);
    }

  // Independent reference: the applied load at t = 1.
  Tensor<1, dim> applied = load;
  double         volume  = 0;
  for (const auto &particle : problem.points().get_particle_handler())
    volume += particle.get_properties()[offsets.volume];
  volume = Utilities::MPI::sum(volume, MPI_COMM_WORLD);
  applied[1] += -2. * volume;

  const Tensor<1, dim> reaction = problem.reactions()[0];
  deallog << dim << "D, tolerances " << format(tolerance) << std::endl;
  // The body fills 8 x 4 (x 4) cells with 2^dim points each.
  check_that("  2^dim points in each of the body's cells, 3 steps",
             problem.points().n_global_points() ==
                 (dim == 2 ? 32u * 4u : 128u * 8u) &&
               problem.step_reports().size() == 3);
  if (tolerance > 1e-6)
    {
      check_that("  linear problem: 1 or 2 Newton iterations per step",
                 min_newton >= 1 && max_newton <= 2);
      return;
    }

  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << dim << "D reaction on the clamp " << reaction
              << ", applied load " << applied << std::endl;
  check("  |reaction + applied load| / |applied load|",
        (reaction + applied).norm() / applied.norm(),
        1e-8);

  check("  step 1: ||u - u_FEM||_L2(points) / ||u_FEM||_L2(points)",
        fem_difference,
        1e-8);
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  test<2>(1e-3);
  test<2>(1e-10);
  test<3>(1e-3);
  test<3>(1e-10);
}
