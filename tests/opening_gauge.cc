// The clip gauge of Load stepping/Control = opening (OpeningGauge) on an
// affine motion, with linear and cpGIMP shape functions, in 2D and 3D: a
// block [-0.5, 0.5]^dim in the grid [-1, 1]^dim (8 cells per direction,
// 2^dim points per cell) whose grid nodes all move by u = t G x, G a fixed
// matrix (stretch and shear). Path following must choose the load factor
// increment that opens the gauge by the prescribed Delta w in every step.
//
// Reference (closed form): both kinds of shape functions reproduce affine
// fields, so a point at x moves by Delta t G x in a step, and the gauge's
// points, at d = x_b - x_a, open by Delta t (G d) . e, e = d_0/|d_0| the
// gauge's fixed direction: Delta t = Delta w / ((G d) . e), with d carried
// from step to step by d <- (I + Delta t G) d from d_0 = x_b - x_a (the two
// positions are point positions). Checked: every step's Delta t against
// that value, and the gauge's opening (u_b - u_a) . e read from the points
// against k Delta w after k steps.
//
// Tolerance 1e-9 relative: every increment is prescribed and the
// constraint is linear, so only round-off remains; a gauge built on the
// wrong points, with a wrong sign or a wrong stencil is off by 1e-2 or more
// (the gauge's points are 0.125 apart from their neighbours, G d changes by
// 10 % across the block).
#include "tests.h"

#include <deal.II/base/function.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>

using namespace qsmpm;

namespace
{
  template <int dim>
  Tensor<2, dim>
  gradient()
  {
    Tensor<2, dim> G;
    G[0][0] = 0.1;
    G[0][1] = 0.05;
    G[1][0] = 0.02;
    G[1][1] = -0.03;
    if (dim == 3)
      {
        G[2][2]       = 0.04;
        G[0][dim - 1] = 0.01;
      }
    return G;
  }

  /// u = t G x.
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
      return this->get_time() * (gradient<dim>() * x)[c];
    }
  };

  template <int dim>
  void
  test(const ShapeFunctions shape_functions, const std::string &name)
  {
    deallog << dim << "D, " << name << std::endl;
    QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
    problem.pcout().set_condition(false);
    std::array<unsigned int, dim> n;
    n.fill(8);
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = -1.;
        upper[d] = 1.;
      }
    problem.grid().make_box(lower, upper, n);

    // The gauge: two point positions (points at +-0.0625, +-0.1875, ...).
    Point<dim> x_a, x_b;
    x_a[0] = -0.3125;
    x_a[1] = -0.1875;
    x_b[0] = 0.3125;
    x_b[1] = 0.1875;
    if (dim == 3)
      x_b[dim - 1] = 0.0625, x_a[dim - 1] = -0.0625;
    std::ostringstream gauge;
    for (unsigned int d = 0; d < dim; ++d)
      gauge << (d > 0 ? "," : "") << x_a[d];
    gauge << ";";
    for (unsigned int d = 0; d < dim; ++d)
      gauge << (d > 0 ? "," : "") << x_b[d];

    const double opening                            = 1e-3;
    auto        &prm                                = problem.parameters();
    prm.material_points.formulation.shape_functions = shape_functions;
    prm.material_points.update_volumes              = false;
    prm.load_stepping.control                       = "opening";
    prm.load_stepping.opening_increment             = opening;
    prm.load_stepping.opening_gauge                 = gauge.str();
    prm.load_stepping.max_increment                 = 1.;
    prm.load_stepping.n_steps                       = 1;
    prm.load_stepping.final_load_factor             = 0.2;
    prm.nonlinear_solver.tolerance                  = 1e-12;
    prm.nonlinear_solver.residual_floor             = 0.;
    // Every increment is prescribed: nothing for a preconditioner to do.
    prm.nonlinear_solver.preconditioner = "none";
    prm.output.directory                = "results";
    prm.output.interval                 = 0;

    problem.set_model(std::make_unique<LinearElastic<dim>>(100., 0.3));
    problem.points().fill(
      [](const Point<dim> &x) {
        for (unsigned int d = 0; d < dim; ++d)
          if (std::abs(x[d]) > 0.5)
            return false;
        return true;
      },
      2,
      MaterialPointSet<dim>::Placement::regular);
    std::array<bool, dim> all;
    all.fill(true);
    problem.boundary_conditions().add_dirichlet_nodes(
      "all nodes",
      [](const Point<dim> &) { return true; },
      all,
      std::make_shared<Affine<dim>>());

    const Tensor<2, dim> G = gradient<dim>();
    const Tensor<1, dim> e = (x_b - x_a) / x_b.distance(x_a);
    Tensor<1, dim>       d = x_b - x_a;
    double               t = 0., increment_error = 0., opening_error = 0.;
    unsigned int         steps = 0;
    problem.set_step_callback(
      [&](const typename QuasiStaticProblem<dim>::StepReport &report) {
        const double expected = opening / ((G * d) * e);
        increment_error =
          std::max(increment_error,
                   std::abs((report.load_factor - t) / expected - 1.));
        d += (report.load_factor - t) * (G * d);
        t = report.load_factor;
        ++steps;
        // The gauge's opening from the points' displacements.
        const unsigned int u = problem.points().get_offsets().displacement;
        double             w = 0.;
        for (const auto &particle : problem.points().get_particle_handler())
          {
            Point<dim> X = particle.get_location();
            for (unsigned int c = 0; c < dim; ++c)
              X[c] -= particle.get_properties()[u + c];
            const double sign = X.distance(x_b) < 1e-3 ? 1. :
                                X.distance(x_a) < 1e-3 ? -1. :
                                                         0.;
            for (unsigned int c = 0; c < dim; ++c)
              w += sign * particle.get_properties()[u + c] * e[c];
          }
        w = Utilities::MPI::sum(w, MPI_COMM_WORLD);
        opening_error =
          std::max(opening_error, std::abs(w / (steps * opening) - 1.));
        return true;
      });
    problem.run();

    check_that("  at least 10 steps", steps >= 10);
    check("  max |Delta t / (Delta w / ((G d) . e)) - 1|",
          increment_error,
          1e-9);
    check("  max |(u_b - u_a) . e / (k Delta w) - 1|", opening_error, 1e-9);
  }
} // namespace



int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  test<2>(ShapeFunctions::linear, "linear");
  test<2>(ShapeFunctions::cpgimp, "cpGIMP");
  test<3>(ShapeFunctions::linear, "linear");
  test<3>(ShapeFunctions::cpgimp, "cpGIMP");
}
