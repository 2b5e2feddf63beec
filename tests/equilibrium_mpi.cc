// A body smaller than the background grid (so that some nodes carry no
// points and must be constrained), clamped on its left edge (a node set
// selected by position), loaded by its weight and a point load, in several
// load steps. Run on 1 and 2 MPI ranks (equilibrium_mpi.mpirun=1/2.output):
// the printed results must agree to the printed digits.
//
// Checks against independent references:
//  - global equilibrium: the reactions balance the applied loads
//    (sum of Omega_p b over the points, computed here from the points'
//    volumes, plus the point load), to 1e-8 relative with tight tolerances;
//  - the problem is linear (Update volumes = false), so with the paper's
//    tolerances (1e-3 for Newton and GMRES) every step needs 1 or 2 Newton
//    iterations.
#include "tests.h"

#include <deal.II/base/function.h>
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
  problem.set_model(std::make_unique<qsmpm::LinearElastic<dim>>(1000., 0.3));
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
  problem.run();

  unsigned int min_newton = 100, max_newton = 0;
  for (const auto &report : problem.step_reports())
    {
      min_newton = std::min(min_newton, report.newton.newton_iterations);
      max_newton = std::max(max_newton, report.newton.newton_iterations);
    }

  // Independent reference: the applied load at t = 1.
  Tensor<1, dim> applied = load;
  const auto    &offsets = problem.points().get_offsets();
  double         volume  = 0;
  for (const auto &particle : problem.points().get_particle_handler())
    volume += particle.get_properties()[offsets.volume];
  volume = Utilities::MPI::sum(volume, MPI_COMM_WORLD);
  applied[1] += -2. * volume;

  const Tensor<1, dim> reaction = problem.reactions()[0];
  deallog << dim << "D, tolerances " << format(tolerance) << ", "
          << problem.points().n_global_points() << " points, "
          << problem.step_reports().size() << " steps" << std::endl;
  if (tolerance > 1e-6)
    {
      check_that("  linear problem: 1 or 2 Newton iterations per step",
                 min_newton >= 1 && max_newton <= 2);
      return;
    }

  // Converged tightly: these digits do not depend on the number of ranks.
  deallog << "  reaction on the clamp:" << std::fixed << std::setprecision(6);
  for (unsigned int d = 0; d < dim; ++d)
    deallog << ' ' << (std::abs(reaction[d]) < 1e-9 ? 0. : reaction[d]);
  deallog << std::defaultfloat << std::endl;
  check("  |reaction + applied load| / |applied load|",
        (reaction + applied).norm() / applied.norm(),
        1e-8);
  double u2 = 0;
  for (const auto &particle : problem.points().get_particle_handler())
    for (unsigned int d = 0; d < dim; ++d)
      u2 += particle.get_properties()[offsets.volume] *
            std::pow(particle.get_properties()[offsets.displacement + d], 2);
  deallog << "  ||u||_L2(points) = " << std::setprecision(6)
          << std::sqrt(Utilities::MPI::sum(u2, MPI_COMM_WORLD)) << std::endl;
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
