// The finite-difference Jacobian-vector product of paper eqs. (A.3)-(A.4)
// against the exact product -K s, with K the stiffness assembled from the
// model's tangent (exact for linear elasticity without volume updates), in
// 2D and 3D, at du = 0 and at du != 0 (both branches of Kelley's h).
// Directions s are arbitrary (deterministic pseudo-random) with zero
// constrained components. The finite-difference error is O(h) relative,
// h ~ 1e-7: tolerance 1e-5.
#include "tests.h"

#include <deal.II/base/function.h>
#include <qsmpm/assembly/quasi_static_residual.h>
#include <qsmpm/assembly/tangent_assembler.h>
#include <qsmpm/loading/boundary_conditions.h>
#include <qsmpm/materials/linear_elastic.h>
#include <qsmpm/solvers/jacobian_free_operator.h>

template <int dim>
struct Operator
{
  const qsmpm::QuasiStaticResidual<dim> &residual_evaluator;
  const AffineConstraints<double>       &constraints;
  void
  residual(const TrilinosWrappers::MPI::Vector &du,
           TrilinosWrappers::MPI::Vector       &R) const
  {
    residual_evaluator.evaluate(du, R);
  }
  void
  set_constrained_to_zero(TrilinosWrappers::MPI::Vector &v) const
  {
    constraints.set_zero(v);
  }
  double
  typical_increment_norm() const
  {
    return residual_evaluator.typical_increment_norm();
  }
};

template <int dim>
void
test()
{
  qsmpm::BackgroundGrid<dim>    grid(MPI_COMM_WORLD);
  Point<dim>                    upper;
  std::array<unsigned int, dim> n;
  for (unsigned int d = 0; d < dim; ++d)
    {
      upper[d] = 1. + d;
      n[d]     = 4 + d;
    }
  grid.make_box(Point<dim>(), upper, n);
  const qsmpm::LinearElastic<dim> model(50., 0.3);
  qsmpm::MaterialPointSet<dim>    points(grid, model);
  // The body does not fill the grid: inactive nodes are constrained.
  points.fill([](const Point<dim> &x) { return x[0] < 0.8; },
              2,
              qsmpm::MaterialPointSet<dim>::Placement::regular);

  qsmpm::ShapeCache<dim>          cache;
  qsmpm::QuasiStaticResidual<dim> residual(grid, points, cache, false);
  cache.reinit(grid, points, residual.ghosted_layout());

  qsmpm::BoundaryConditions<dim> bcs;
  std::array<bool, dim>          all;
  all.fill(true);
  bcs.add_dirichlet_boundary(
    0, all, std::make_shared<Functions::ZeroFunction<dim>>(dim));
  AffineConstraints<double> constraints;
  bcs.make_constraints(
    grid, cache.dofs_without_points(grid), 0., 1., constraints);

  TrilinosWrappers::MPI::Vector f_ext(grid.locally_owned_dofs(),
                                      MPI_COMM_WORLD);
  residual.set_external_force(f_ext);
  qsmpm::TangentAssembler<dim> tangent;
  tangent.reinit(grid);
  tangent.assemble(grid, points, cache, constraints);

  TrilinosWrappers::MPI::Vector s(f_ext), du(f_ext), R(f_ext), Js(f_ext),
    Ks(f_ext);
  for (const auto i : grid.locally_owned_dofs())
    {
      s(i)  = std::sin(1. + 3.7 * i);
      du(i) = 1e-3 * std::cos(0.3 + 1.3 * i);
    }
  s.compress(VectorOperation::insert);
  du.compress(VectorOperation::insert);
  constraints.set_zero(s);
  constraints.set_zero(du);

  const Operator<dim> op{residual, constraints};
  for (const bool zero_du : {true, false})
    {
      if (zero_du)
        du = 0.;
      residual.evaluate(du, R);
      const qsmpm::JacobianFreeOperator<Operator<dim>,
                                        TrilinosWrappers::MPI::Vector>
        J(op, du, R, 1e-7);
      J.vmult(Js, s);
      tangent.matrix().vmult(Ks, s);
      constraints.set_zero(Ks);
      Js += Ks; // J s = -K s
      deallog << dim << "D, du " << (zero_du ? "= 0" : "!= 0") << std::endl;
      check("  ||J_fd s - (-K s)|| / ||K s||",
            Js.l2_norm() / Ks.l2_norm(),
            1e-5);
    }
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  test<2>();
  test<3>();
}
