// Manufactured solution for linear elasticity in 2D (plane strain) and 3D:
//
//   u_c(x) = A alpha_c prod_d sin(pi x_d) + B x_{c+1}
//
// on the unit square/cube, with the body force b = -div sigma(u) computed
// analytically and u prescribed on the whole boundary, for points at the
// Gauss points and for regularly placed points (2 x 2 per cell). The problem
// is run geometrically linear ("Update volumes = false") in one load step,
// so that the only error is the discretization error. Checked against the
// theory of Q1 elements, not against earlier output:
//
// - the L2 error of the point displacements, sqrt(sum_p Omega_p |u_p -
//   u(X_p)|^2), converges at rate 2 and the energy-norm error of the grid
//   solution, a(u - u_h, u - u_h)^(1/2), at rate 1, on every refinement;
//   tolerance +-0.2 on the rate: the coarsest grid (h = 1/4) is not yet
//   asymptotic (the rates measured are within 0.05 of 2 and 1);
// - Cea's lemma: with points at the Gauss points the first step is Q1
//   Galerkin with exact stiffness on these affine cells (mpm_equals_fem),
//   and the Galerkin solution is the best approximation in the energy norm
//   among the Q1 functions with the same boundary values: its energy error
//   is at most that of the nodal interpolant I_h u, computed here from the
//   closed form. The only slack is the 2 x 2 Gauss quadrature of the body
//   force, an O(h^2) perturbation of an O(h) error: allowed 1 %;
// - regular points integrate the stiffness inexactly (a consistent but
//   different quadrature), so Cea's lemma does not apply; their energy
//   error must stay within twice the interpolant's (a method whose error
//   is not of the interpolation error's size is wrong, whatever its rate).
//
// The errors and rates are printed to stdout only.
#include "tests.h"

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>
#include <iostream>
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
  Tensor<1, dim>
  gradient(const Point<dim> &x, const unsigned int c) const override
  {
    Tensor<1, dim> g;
    for (unsigned int k = 0; k < dim; ++k)
      {
        double dphi = numbers::PI;
        for (unsigned int d = 0; d < dim; ++d)
          dphi *= d == k ? std::cos(numbers::PI * x[d]) :
                           std::sin(numbers::PI * x[d]);
        g[k] = A * alpha[c] * dphi + (k == (c + 1) % dim ? B : 0.);
      }
    return this->get_time() * g;
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

struct Errors
{
  double l2;                 // of the point displacements
  double energy;             // a(u - u_h, u - u_h)^(1/2), u_h the grid solution
  double energy_interpolant; // a(u - I_h u, u - I_h u)^(1/2)
};

// The energy norm a(e, e)^(1/2) = (int lambda (div e)^2 + 2 mu eps(e) :
// eps(e))^(1/2) of u - v_h, v_h the Q1 function with nodal values @p v,
// integrated with 4 x 4 (x 4) Gauss points per cell.
template <int dim>
double
energy_error(const DoFHandler<dim>        &dof_handler,
             const Vector<double>         &v,
             const ExactDisplacement<dim> &exact)
{
  const QGauss<dim>                    quadrature(4);
  FEValues<dim>                        fe_values(dof_handler.get_fe(),
                          quadrature,
                          update_gradients | update_quadrature_points |
                            update_JxW_values);
  const FEValuesExtractors::Vector     u(0);
  std::vector<SymmetricTensor<2, dim>> eps_h(quadrature.size());
  double                               sum = 0;
  for (const auto &cell : dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        fe_values.reinit(cell);
        fe_values[u].get_function_symmetric_gradients(v, eps_h);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            Tensor<2, dim> grad;
            for (unsigned int c = 0; c < dim; ++c)
              grad[c] = exact.gradient(fe_values.quadrature_point(q), c);
            const SymmetricTensor<2, dim> e = symmetrize(grad) - eps_h[q];
            sum += (lambda * trace(e) * trace(e) + 2 * mu * e * e) *
                   fe_values.JxW(q);
          }
      }
  return std::sqrt(Utilities::MPI::sum(sum, MPI_COMM_WORLD));
}

template <int dim>
Errors
errors(const unsigned int n_cells, const bool gauss)
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

  // The grid solution (one step: the increment) and the nodal interpolant
  // of the exact solution, as serial vectors (the test runs on one rank).
  const DoFHandler<dim> &dof_handler = problem.grid().get_dof_handler();
  Vector<double>         u_h(dof_handler.n_dofs()), u_I(dof_handler.n_dofs());
  for (unsigned int i = 0; i < u_h.size(); ++i)
    u_h[i] = problem.increment()(i);
  VectorTools::interpolate(dof_handler, *exact, u_I);
  return {std::sqrt(Utilities::MPI::sum(error2, MPI_COMM_WORLD)),
          energy_error(dof_handler, u_h, *exact),
          energy_error(dof_handler, u_I, *exact)};
}

template <int dim>
void
convergence(const std::vector<unsigned int> &sizes)
{
  for (const bool gauss : {true, false})
    {
      const std::string placement =
        gauss ? "at Gauss points" : "regular (2 x 2)";
      deallog << dim << "D, points " << placement << ", h = 1/" << sizes[0]
              << " ... 1/" << sizes.back() << std::endl;
      std::vector<Errors> e;
      double              worst_ratio = 0;
      for (const unsigned int n : sizes)
        {
          e.push_back(errors<dim>(n, gauss));
          worst_ratio = std::max(worst_ratio,
                                 e.back().energy / e.back().energy_interpolant);
          std::cout << dim << "D " << placement << " h = 1/" << n
                    << ": L2 error " << e.back().l2 << ", energy error "
                    << e.back().energy << ", interpolant's energy error "
                    << e.back().energy_interpolant << std::endl;
        }
      double l2_rate = 0, energy_rate = 0;
      for (unsigned int i = 1; i < e.size(); ++i)
        {
          const double r_l2 = std::log2(e[i - 1].l2 / e[i].l2),
                       r_e  = std::log2(e[i - 1].energy / e[i].energy);
          std::cout << "  rates h = 1/" << sizes[i - 1] << " -> 1/" << sizes[i]
                    << ": L2 " << r_l2 << ", energy " << r_e << std::endl;
          // The largest deviation from the theoretical order.
          if (std::abs(r_l2 - 2.) > std::abs(l2_rate - 2.) || i == 1)
            l2_rate = r_l2;
          if (std::abs(r_e - 1.) > std::abs(energy_rate - 1.) || i == 1)
            energy_rate = r_e;
        }
      check("  L2 error of the points, every refinement: |rate - 2|",
            l2_rate - 2.,
            0.2);
      check("  energy error, every refinement: |rate - 1|",
            energy_rate - 1.,
            0.2);
      if (gauss)
        check("  Cea: energy error / interpolant's energy error - 1, "
              "largest over the grids",
              std::max(0., worst_ratio - 1.),
              0.01);
      else
        check("  energy error / interpolant's energy error, largest over "
              "the grids",
              worst_ratio,
              2.);
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
