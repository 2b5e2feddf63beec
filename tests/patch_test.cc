// Patch test in 2D and 3D: a box of non-square cells filled with 3^dim
// regularly placed points per cell, affine displacement g(x, t) = t (H x + c)
// prescribed on the whole boundary, with a general (non-symmetric) H. The
// exact solution is homogeneous: every point must carry the strain sym(H) and
// the stress C : sym(H), and the displacement H X + c, to round-off
// (1e-10 relative, far above round-off and far below any discretization
// error, which would be O(h^2 |H|)).
//
// One load step: after the points move, they no longer sit symmetrically in
// their cells and MPM's point quadrature of grad N_i is no longer exact, so
// later steps are not patch tests.
#include "tests.h"

#include <deal.II/base/function.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>

template <int dim>
Tensor<2, dim>
gradient()
{
  Tensor<2, dim> H;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      H[i][j] = 1e-3 * (1. + i + 2. * j) * (i == j ? 1. : (i < j ? 0.5 : -0.3));
  return H;
}

template <int dim>
class Affine : public Function<dim>
{
public:
  Affine()
    : Function<dim>(dim)
  {
  }
  double
  value(const Point<dim> &x, const unsigned int c) const override
  {
    return this->get_time() * ((gradient<dim>() * x)[c] + 1e-4 * (c + 1));
  }
};

template <int dim>
void
test(const bool plane_stress)
{
  qsmpm::QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
  problem.pcout().set_condition(false);
  Point<dim>                    upper;
  std::array<unsigned int, dim> n;
  for (unsigned int d = 0; d < dim; ++d)
    {
      upper[d] = 2. - 0.5 * d;
      n[d]     = 5 - d;
    }
  problem.grid().make_box(Point<dim>(), upper, n);
  auto model =
    std::make_unique<qsmpm::LinearElastic<dim>>(200., 0.3, plane_stress);
  const SymmetricTensor<4, dim> C = model->stiffness();
  problem.set_model(std::move(model));
  problem.points().fill([](const Point<dim> &) { return true; },
                        3,
                        qsmpm::MaterialPointSet<dim>::Placement::regular);
  std::array<bool, dim> all;
  all.fill(true);
  auto g = std::make_shared<Affine<dim>>();
  for (unsigned int id = 0; id < 2 * dim; ++id)
    problem.boundary_conditions().add_dirichlet_boundary(id, all, g);

  auto &prm                             = problem.parameters();
  prm.nonlinear_solver.tolerance        = 1e-14;
  prm.nonlinear_solver.residual_floor   = 0.;
  prm.nonlinear_solver.linear_tolerance = 1e-10;
  prm.output.directory                  = "results";
  prm.output.interval                   = 0;
  problem.run();

  const SymmetricTensor<2, dim> strain  = symmetrize(gradient<dim>());
  const SymmetricTensor<2, dim> stress  = C * strain;
  const auto                   &offsets = problem.points().get_offsets();
  double strain_error = 0, stress_error = 0, displacement_error = 0;
  g->set_time(1.);
  for (const auto &particle : problem.points().get_particle_handler())
    {
      const double *data = particle.get_properties().data();
      strain_error =
        std::max(strain_error,
                 (qsmpm::Utils::read_symmetric<dim>(data + offsets.strain) -
                  strain)
                     .norm() /
                   strain.norm());
      stress_error =
        std::max(stress_error,
                 (qsmpm::Utils::read_symmetric<dim>(data + offsets.stress) -
                  stress)
                     .norm() /
                   stress.norm());
      Tensor<1, dim> u, u_exact;
      Point<dim>     X = particle.get_location();
      for (unsigned int d = 0; d < dim; ++d)
        {
          u[d] = data[offsets.displacement + d];
          X[d] -= u[d];
        }
      for (unsigned int d = 0; d < dim; ++d)
        u_exact[d] = g->value(X, d);
      displacement_error =
        std::max(displacement_error, (u - u_exact).norm() / u_exact.norm());
    }
  deallog << dim << "D"
          << (dim == 2 ? (plane_stress ? ", plane stress" : ", plane strain") :
                         "")
          << ", " << problem.points().n_global_points() << " points"
          << std::endl;
  check("  max relative point strain error", strain_error, 1e-10);
  check("  max relative point stress error", stress_error, 1e-10);
  check("  max relative point displacement error", displacement_error, 1e-10);
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  test<2>(false);
  test<2>(true);
  test<3>(false);
}
