// Manufactured solution for linear elasticity in 2D (plane strain) and 3D:
//
//   u_c(x) = A alpha_c prod_d sin(pi x_d) + B x_{c+1}
//
// on the unit square/cube, with the body force b = -div sigma(u) computed
// analytically and u prescribed on the whole boundary. The L2 error of the
// point displacements, sqrt(sum_p Omega_p |u_p - u(X_p)|^2), must converge
// at rate >= 1.8 (Q1: 2) over successive refinements, for points at the
// Gauss points and for regularly placed points (2 x 2 per cell).
//
// The problem is run geometrically linear ("Update volumes = false") in one
// load step, so that the only error is the discretization error.
#include "tests.h"

#include <deal.II/base/function.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>

constexpr double A        = 1e-2;
constexpr double B        = 2e-3;
constexpr double E        = 100.;
constexpr double nu       = 0.3;
const double     lambda   = E * nu / ((1 + nu) * (1 - 2 * nu));
const double     mu       = E / (2 * (1 + nu));
const double     alpha[3] = {1., 0.5, 0.25};

template <int dim>
class ExactDisplacement : public Function<dim>
{
public:
  ExactDisplacement()
    : Function<dim>(dim)
  {
  }
  double
  value(const Point<dim> &x, const unsigned int c) const override
  {
    double phi = 1;
    for (unsigned int d = 0; d < dim; ++d)
      phi *= std::sin(numbers::PI * x[d]);
    return this->get_time() * (A * alpha[c] * phi + B * x[(c + 1) % dim]);
  }
};

template <int dim>
class BodyForce : public Function<dim>
{
public:
  BodyForce()
    : Function<dim>(dim)
  {
  }
  // b_i = -(mu Laplace u_i + (lambda + mu) d_i div u), with
  // d_i d_j phi = -pi^2 phi (i = j), pi^2 cos cos prod sin (i != j).
  double
  value(const Point<dim> &x, const unsigned int i) const override
  {
    const double pi     = numbers::PI;
    auto         second = [&](const unsigned int a, const unsigned int b) {
      double r = 1;
      for (unsigned int d = 0; d < dim; ++d)
        r *= (d == a || d == b) ?
                       (a == b ? -std::sin(pi * x[d]) : std::cos(pi * x[d])) :
                       std::sin(pi * x[d]);
      return pi * pi * r;
    };
    double laplace_u_i = 0, grad_div_i = 0;
    for (unsigned int d = 0; d < dim; ++d)
      laplace_u_i += A * alpha[i] * second(d, d);
    for (unsigned int j = 0; j < dim; ++j)
      grad_div_i += A * alpha[j] * second(i, j);
    return -this->get_time() * (mu * laplace_u_i + (lambda + mu) * grad_div_i);
  }
};

template <int dim>
double
l2_error(const unsigned int n_cells, const bool gauss)
{
  qsmpm::QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
  problem.pcout().set_condition(false);
  std::array<unsigned int, dim> subdivisions;
  subdivisions.fill(n_cells);
  Point<dim> one;
  for (unsigned int d = 0; d < dim; ++d)
    one[d] = 1.;
  problem.grid().make_box(Point<dim>(), one, subdivisions);
  problem.set_model(std::make_unique<qsmpm::LinearElastic<dim>>(E, nu));
  using Placement = typename qsmpm::MaterialPointSet<dim>::Placement;
  problem.points().fill([](const Point<dim> &) { return true; },
                        2,
                        gauss ? Placement::gauss : Placement::regular);

  auto                  exact = std::make_shared<ExactDisplacement<dim>>();
  std::array<bool, dim> all;
  all.fill(true);
  for (unsigned int id = 0; id < 2 * dim; ++id)
    problem.boundary_conditions().add_dirichlet_boundary(id, all, exact);
  problem.boundary_conditions().set_body_force(
    std::make_shared<BodyForce<dim>>());

  auto &prm                                  = problem.parameters();
  prm.material_points.update_volumes         = false;
  prm.nonlinear_solver.tolerance             = 1e-10;
  prm.nonlinear_solver.residual_floor        = 0;
  prm.nonlinear_solver.linear_tolerance      = 1e-8;
  prm.nonlinear_solver.max_linear_iterations = 5000;
  prm.nonlinear_solver.gmres_restart         = 200;
  prm.output.directory                       = "results";
  prm.output.interval                        = 0;
  prm.load_stepping.n_steps                  = 1;
  problem.run();

  const auto &offsets = problem.points().get_offsets();
  double      error2  = 0;
  exact->set_time(1.);
  for (const auto &particle : problem.points().get_particle_handler())
    {
      const auto data = particle.get_properties();
      Point<dim> X    = particle.get_location();
      for (unsigned int d = 0; d < dim; ++d)
        X[d] -= data[offsets.displacement + d];
      for (unsigned int d = 0; d < dim; ++d)
        error2 +=
          data[offsets.volume] *
          std::pow(data[offsets.displacement + d] - exact->value(X, d), 2);
    }
  return std::sqrt(Utilities::MPI::sum(error2, MPI_COMM_WORLD));
}

template <int dim>
void
convergence(const std::vector<unsigned int> &sizes)
{
  for (const bool gauss : {true, false})
    {
      deallog << dim << "D, points " << (gauss ? "at Gauss points" : "regular")
              << std::endl;
      double previous = 0, last_rate = 0;
      for (const unsigned int n : sizes)
        {
          const double error = l2_error<dim>(n, gauss);
          deallog << "  h = 1/" << n << "  L2 error " << std::scientific
                  << std::setprecision(2) << error << std::defaultfloat;
          if (previous > 0)
            {
              last_rate = std::log2(previous / error);
              deallog << "  rate " << std::fixed << std::setprecision(1)
                      << last_rate << std::defaultfloat;
            }
          deallog << std::endl;
          previous = error;
        }
      // Q1 elements converge at O(h^2) in L2; 1.8 allows for pre-asymptotic
      // behaviour on the coarsest grids.
      check_at_least("  observed rate on the finest grids", last_rate, 1.8);
    }
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  convergence<2>({4, 8, 16, 32});
  convergence<3>({4, 8, 16});
}
