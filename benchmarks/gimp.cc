// gimp: what GIMP shape functions cost and how the solver behaves with them
// (issue 10, items 4 and 6), measured against linear shape functions in the
// same run.
//
//  1. residual cost: wall time of one residual evaluation R(du) of the
//     block problem of benchmark_problem.h (2^dim points per cell, Hencky
//     elasticity: at small strain the linear-elastic update, at finite
//     strain the Hencky update), cpGIMP over linear, 2D 256^2 and 3D 32^3
//     cells, with the domains in their cells and with every domain crossing
//     faces;
//  2. GMRES iterations per Newton iteration with AMG on the block, one load
//     step, under refinement (2D 32^2 ... 256^2, 3D 8^3 ... 32^3);
//  3. small cut cells: the self-weight column (finite strain, Hencky,
//     E = 1 MPa, 16 cells, 20 steps), one cell wide with nu = 0 and 16
//     cells wide (a block on rollers) with nu = 0.3, whose top row of cells is
//     filled to a fraction f = 1, 0.5, 0.1, 0.01 of its height: Newton and
//     GMRES iterations and the stress error.
//
// Usage: gimp. Writes "key,value" lines to standard output.
#include "benchmark_problem.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <iostream>
#include <qsmpm/assembly/quasi_static_residual.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/materials/hencky.h>
#include <sstream>

namespace
{
  using namespace dealii;
  using VectorType = TrilinosWrappers::MPI::Vector;

  using Benchmarks::print;

  std::string
  name(const qsmpm::ShapeFunctions s)
  {
    return s == qsmpm::ShapeFunctions::linear ? "linear" : "cpgimp";
  }

  // 1. Seconds per residual evaluation at a smooth increment.
  template <int dim>
  double
  residual_seconds(const unsigned int          n,
                   const qsmpm::ShapeFunctions shape,
                   const bool                  crossing      = false,
                   const bool                  finite_strain = false)
  {
    qsmpm::BackgroundGrid<dim> grid(MPI_COMM_WORLD);
    Benchmarks::make_unit_box(grid, n);
    const qsmpm::Hencky<dim> model(1e3, 0.3);
    qsmpm::Formulation       formulation;
    formulation.shape_functions = shape;
    if (finite_strain)
      formulation.kinematics = qsmpm::Kinematics::finite_strain;
    qsmpm::MaterialPointSet<dim> points(grid, model, formulation);
    points.fill([](const Point<dim> &) { return true; },
                2,
                qsmpm::MaterialPointSet<dim>::Placement::regular);
    // Domains widened to 0.45 h in every direction: every point reaches
    // 3^dim nodes (the most expensive GIMP state).
    if (crossing)
      for (auto &particle : points.get_particle_handler())
        for (unsigned int d = 0; d < dim; ++d)
          particle
            .get_properties()[points.get_offsets().initial_half_length + d] =
            0.45 / n;
    qsmpm::ShapeCache<dim>          cache;
    qsmpm::QuasiStaticResidual<dim> residual(grid, points, cache, true);
    cache.reinit(grid, points, residual.ghosted_layout());
    VectorType du(grid.locally_owned_dofs(), MPI_COMM_WORLD), R(du);
    for (const auto i : grid.locally_owned_dofs())
      du[i] = 1e-4 * std::sin(0.001 * i);
    du.compress(VectorOperation::insert);
    residual.evaluate(du, R); // warm-up
    const unsigned int repetitions = 10;
    Timer              timer;
    for (unsigned int r = 0; r < repetitions; ++r)
      residual.evaluate(du, R);
    timer.stop();
    return timer.wall_time() / repetitions;
  }

  // 2. One load step of the block: GMRES iterations per Newton iteration.
  template <int dim>
  void
  block_step(const unsigned int n, const qsmpm::ShapeFunctions shape)
  {
    qsmpm::QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
    problem.return_large_blocks_to_system();
    problem.parameters().material_points.formulation.shape_functions = shape;
    Benchmarks::setup_block(problem, n, "amg");
    Timer timer;
    problem.run();
    timer.stop();
    const auto       &r = problem.step_reports().back().newton;
    const std::string tag =
      std::to_string(dim) + "d_" + std::to_string(n) + "_" + name(shape);
    print(tag + "_newton_iterations", r.newton_iterations);
    print(tag + "_gmres_per_newton",
          double(r.linear_iterations) / r.newton_iterations);
    print(tag + "_seconds", timer.wall_time());
  }

  // 3. The column with its top cell filled to the fraction f.
  class Weight : public Function<2>
  {
  public:
    Weight()
      : Function<2>(2)
    {
    }
    double
    value(const Point<2> &, const unsigned int c) const override
    {
      return c == 1 ? -800. * get_time() : 0.;
    }
  };

  void
  cut_column(const double                f,
             const qsmpm::ShapeFunctions shape,
             const unsigned int          width,
             const double                nu)
  {
    const unsigned int           n = 16;
    const double                 h = 50. / n, l0 = (n - 1 + f) * h;
    qsmpm::QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    problem.return_large_blocks_to_system();
    problem.pcout().set_condition(false);
    auto &prm = problem.parameters();
    prm.material_points.formulation.kinematics =
      qsmpm::Kinematics::finite_strain;
    prm.material_points.formulation.shape_functions = shape;
    prm.output.interval                             = 0;
    prm.output.directory                            = "benchmark_output";
    prm.load_stepping.n_steps                       = 20;
    problem.grid().make_box(Point<2>(),
                            Point<2>(width * h, n * h),
                            {{width, n}});
    problem.set_model(std::make_unique<qsmpm::Hencky<2>>(1e6, nu));

    // Full cells with 2 x 2 points; the top cell with 2 x 2 points in its
    // lowest fraction f, whose volumes and domains are scaled by f.
    auto &points = problem.points();
    points.fill([&](const Point<2> &x) { return x[1] < (n - 1) * h; },
                2,
                qsmpm::MaterialPointSet<2>::Placement::regular);
    std::vector<Point<2>> top;
    for (const double y : {0.25 * f, 0.75 * f})
      for (const double x : {0.25, 0.75})
        top.emplace_back(x, y);
    points.fill([&](const Point<2> &x) { return x[1] > (n - 1) * h; },
                Quadrature<2>(top, std::vector<double>(4, 0.25)));
    const auto &o = points.get_offsets();
    for (auto &particle : points.get_particle_handler())
      if (particle.get_location()[1] > (n - 1) * h)
        {
          auto data = particle.get_properties();
          data[o.initial_volume] *= f;
          data[o.volume] *= f;
          if (o.initial_half_length != numbers::invalid_unsigned_int)
            data[o.initial_half_length + 1] *= f;
        }

    auto      &bcs  = problem.boundary_conditions();
    const auto zero = std::make_shared<Functions::ZeroFunction<2>>(2);
    bcs.add_dirichlet_boundary(0, {}, zero, true);
    bcs.add_dirichlet_boundary(1, {}, zero, true);
    bcs.add_dirichlet_boundary(2, {}, zero, true);
    bcs.set_body_force(std::make_shared<Weight>());
    problem.run();

    unsigned int newton_max = 0, gmres_max = 0;
    double       gmres_per_newton = 0;
    for (const auto &s : problem.step_reports())
      {
        newton_max = std::max(newton_max, s.newton.newton_iterations);
        gmres_max  = std::max(gmres_max, s.newton.linear_iterations);
        gmres_per_newton += double(s.newton.linear_iterations) /
                            s.newton.newton_iterations /
                            problem.step_reports().size();
      }
    double sum = 0, volume = 0;
    for (const auto &particle : points.get_particle_handler())
      {
        const auto   data = particle.get_properties();
        const double Y = particle.get_location()[1] - data[o.displacement + 1];
        SymmetricTensor<2, 2> e =
          qsmpm::Utils::read_symmetric<2>(&data[o.stress]);
        e[1][1] += 800. * (l0 - Y);
        sum += data[o.initial_volume] * e.norm() * e.norm();
        volume += data[o.initial_volume];
      }
    sum    = Utilities::MPI::sum(sum, MPI_COMM_WORLD);
    volume = Utilities::MPI::sum(volume, MPI_COMM_WORLD);
    std::ostringstream fraction;
    fraction << f;
    const std::string tag = "cut_w" + std::to_string(width) + "_nu" +
                            (nu > 0 ? "03_" : "0_") + fraction.str() + "_" +
                            name(shape);
    print(tag + "_steps", problem.step_reports().size());
    print(tag + "_newton_max", newton_max);
    print(tag + "_gmres_per_newton_mean", gmres_per_newton);
    print(tag + "_gmres_per_step_max", gmres_max);
    if (nu == 0.) // the exact solution has sigma_xx = 0 only for nu = 0
      print(tag + "_l2_stress_error", std::sqrt(sum / volume) / (800. * l0));
  }
} // namespace

int
main(int argc, char *argv[])
{
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      using S = qsmpm::ShapeFunctions;
      if (argc > 1 && std::string(argv[1]) == "--cut-cells-only")
        {
          for (const auto &[width, nu] :
               std::vector<std::pair<unsigned int, double>>{{1, 0.}, {16, 0.3}})
            for (const S s : {S::linear, S::cpgimp})
              for (const double f : {1., 0.5, 0.1, 0.01})
                cut_column(f, s, width, nu);
          return 0;
        }
      for (const S s : {S::linear, S::cpgimp})
        {
          print("residual_seconds_2d_256_" + name(s),
                residual_seconds<2>(256, s));
          print("residual_seconds_3d_32_" + name(s),
                residual_seconds<3>(32, s));
        }
      print("residual_ratio_2d_256_cpgimp_over_linear",
            residual_seconds<2>(256, S::cpgimp) /
              residual_seconds<2>(256, S::linear));
      print("residual_ratio_3d_32_cpgimp_over_linear",
            residual_seconds<3>(32, S::cpgimp) /
              residual_seconds<3>(32, S::linear));
      for (const bool crossing : {false, true})
        {
          const std::string what = crossing ? "_all_crossing" : "";
          print("residual_ratio_finite_strain_2d_256_cpgimp" + what +
                  "_over_linear",
                residual_seconds<2>(256, S::cpgimp, crossing, true) /
                  residual_seconds<2>(256, S::linear, false, true));
          print("residual_ratio_finite_strain_3d_32_cpgimp" + what +
                  "_over_linear",
                residual_seconds<3>(32, S::cpgimp, crossing, true) /
                  residual_seconds<3>(32, S::linear, false, true));
        }
      print("residual_ratio_2d_256_cpgimp_all_crossing_over_linear",
            residual_seconds<2>(256, S::cpgimp, true) /
              residual_seconds<2>(256, S::linear));
      print("residual_ratio_3d_32_cpgimp_all_crossing_over_linear",
            residual_seconds<3>(32, S::cpgimp, true) /
              residual_seconds<3>(32, S::linear));
      for (const S s : {S::linear, S::cpgimp})
        {
          for (const unsigned int n : {32u, 64u, 128u, 256u})
            block_step<2>(n, s);
          for (const unsigned int n : {8u, 16u, 32u})
            block_step<3>(n, s);
        }
      for (const auto &[width, nu] :
           std::vector<std::pair<unsigned int, double>>{{1, 0.}, {16, 0.3}})
        for (const S s : {S::linear, S::cpgimp})
          for (const double f : {1., 0.5, 0.1, 0.01})
            cut_column(f, s, width, nu);
    }
  catch (std::exception &exc)
    {
      std::cerr << "gimp: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
