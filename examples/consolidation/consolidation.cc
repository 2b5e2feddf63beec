/* ---------------------------------------------------------------------
 *
 * qsmpm example: consolidation
 *
 * Two classical problems of Biot's consolidation theory, solved with the
 * pore pressure of subsection "Pore fluid" and compared with their exact
 * solutions: Terzaghi's one-dimensional column and Mandel's specimen
 * between two rigid, frictionless plates (the Mandel-Cryer effect).
 *
 * Usage:
 *   ./consolidation [file.prm]
 *   mpirun -np 2 ./consolidation [file.prm]
 *
 * Without an argument, consolidation.prm next to the executable is read.
 * Writes summary.txt (in "Output directory") and mandel.csv, and exits
 * with 1 if an error exceeds its tolerance.
 *
 * ---------------------------------------------------------------------
 */

// @sect3{Include files}
#include "consolidation_solutions.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/base/parsed_region.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>
#include <qsmpm/porous/poroelastic_model.h>
#include <sstream>
#include <string>
#include <vector>

namespace Consolidation
{
  using namespace dealii;
  using namespace qsmpm;

  // @sect3{The example's own parameters}
  //
  // The soil (the skeleton's E and nu in "Material/linear elastic", the
  // mobility kappa = k / gamma_w in "Pore fluid") is the same for both
  // problems; this subsection gives their geometry, load and steps. The
  // library's subsections (material points, nonlinear solver, pore fluid
  // stabilization and coupling tolerance) apply to both as well.
  struct Parameters : ParameterStruct<Parameters>
  {
    double       column_height = 10.;
    unsigned int column_cells  = 32;
    double       column_load   = 1e4;
    unsigned int column_steps  = 320;

    double       specimen_width  = 1.;
    double       specimen_height = 1.;
    unsigned int specimen_cells  = 16;
    double       plate_force     = 1e4;
    double       final_time      = 0.5;
    unsigned int specimen_steps  = 200;

    double      terzaghi_tolerance = 0.01;
    double      mandel_tolerance   = 0.02;
    std::string directory          = ".";
    bool        progress           = false;

    void
    add_parameters(ParameterHandler &prm);
  };



  void
  Parameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Consolidation");
    {
      prm.add_parameter("Column height",
                        column_height,
                        "Terzaghi: H (m), the drained top at y = H.",
                        Patterns::Double(0.));
      prm.add_parameter("Column cells",
                        column_cells,
                        "Terzaghi: square cells over H.",
                        Patterns::Integer(1));
      prm.add_parameter("Column load",
                        column_load,
                        "Terzaghi: q (Pa), applied at t = 0 and held.",
                        Patterns::Double(0.));
      prm.add_parameter("Column steps",
                        column_steps,
                        "Terzaghi: equal time steps up to T_v = 1; a "
                        "multiple of 10, so that steps end at T_v = 0.1 "
                        "and 0.5.",
                        Patterns::Integer(10));
      prm.add_parameter("Specimen half-width",
                        specimen_width,
                        "Mandel: a (m); the quarter 0 < x < a, 0 < y < b "
                        "is modelled.",
                        Patterns::Double(0.));
      prm.add_parameter("Specimen half-height",
                        specimen_height,
                        "Mandel: b (m).",
                        Patterns::Double(0.));
      prm.add_parameter("Specimen cells",
                        specimen_cells,
                        "Mandel: cells over a (and as many over b).",
                        Patterns::Integer(1));
      prm.add_parameter("Plate force",
                        plate_force,
                        "Mandel: F (N per unit thickness), the force on "
                        "the quarter's plate (2F on the whole specimen), "
                        "applied at t = 0 and held.",
                        Patterns::Double(0.));
      prm.add_parameter("Specimen final time",
                        final_time,
                        "Mandel: the run ends at c t / a^2 = this.",
                        Patterns::Double(0.));
      prm.add_parameter("Specimen steps",
                        specimen_steps,
                        "Mandel: equal time steps up to the final time.",
                        Patterns::Integer(1));
      prm.add_parameter("Terzaghi tolerance",
                        terzaghi_tolerance,
                        "Largest accepted L2 error of p, as a fraction of "
                        "q, at T_v = 0.1, 0.5 and 1.",
                        Patterns::Double(0.));
      prm.add_parameter("Mandel tolerance",
                        mandel_tolerance,
                        "Largest accepted error of the peak centre "
                        "pressure and of the plate's settlement at every "
                        "step, as fractions of the exact ones.",
                        Patterns::Double(0.));
      prm.add_parameter("Output directory",
                        directory,
                        "summary.txt and mandel.csv go here; each "
                        "problem's fields into terzaghi/ and mandel/ below "
                        "it.",
                        Patterns::Anything());
      prm.add_parameter("Show progress",
                        progress,
                        "Print the library's line per load step (Newton, "
                        "GMRES and fixed-stress iterations).",
                        Patterns::Bool());
    }
    prm.leave_subsection();
  }



  // @sect3{The Consolidation class}
  //
  // One object runs both problems in turn on its own QuasiStaticProblem.
  // Each problem has its grid, points and boundary conditions made here in
  // C++; the library's subsections of the parameter file give the rest.
  class Consolidation
  {
  public:
    explicit Consolidation(const std::string &parameter_file);

    bool
    run();

  private:
    void
    setup_problem(QuasiStaticProblem<2>             &problem,
                  const std::string                 &name,
                  const Point<2>                    &body,
                  const double                       h,
                  const std::array<unsigned int, 2> &margin,
                  const std::string                 &drained_region,
                  const double                       final_time,
                  const unsigned int                 steps);

    /// The range of fixed-stress iterations per step (Newton iterations
    /// per step with Pore fluid/Coupling = monolithic), GMRES iterations
    /// per Newton iteration and the wall time @p seconds of a run, as a
    /// line.
    std::string
    iterations(const QuasiStaticProblem<2> &problem, const double seconds);

    /// The pressure of each point of @p problem, with its initial position
    /// and volume, as (X, Y, V, p).
    static std::vector<std::array<double, 4>>
    point_pressures(const QuasiStaticProblem<2> &problem);

    /// L2 errors of p / q at T_v = 0.1, 0.5, 1.
    std::array<double, 3>
    run_terzaghi();

    /// Error of the peak centre pressure (fraction of the exact peak) and
    /// the largest error of the plate's settlement (fraction of the exact).
    std::pair<double, double>
    run_mandel();

    ParameterHandler                  prm;
    Parameters                        parameters;
    QuasiStaticProblem<2>::Parameters library_parameters;
    Soil                              soil;
    ConditionalOStream                pcout;
  };



  // @sect4{Consolidation::Consolidation}
  //
  // The soil is read from the library's subsections; the exact solutions
  // hold for incompressible constituents only, so other values stop the
  // program with a message.
  Consolidation::Consolidation(const std::string &parameter_file)
    : pcout(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
  {
    QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
    Parameters::declare_parameters(prm);
    prm.parse_input(parameter_file);
    parameters.parse_parameters(prm);
    library_parameters.parse_parameters(prm);

    prm.enter_subsection("Material");
    AssertThrow(prm.get("Model") == "linear elastic",
                ExcMessage("consolidation compares with exact solutions of "
                           "linear elasticity: set Material/Model = linear "
                           "elastic."));
    prm.enter_subsection("linear elastic");
    soil.E  = prm.get_double("Young's modulus");
    soil.nu = prm.get_double("Poisson's ratio");
    AssertThrow(!prm.get_bool("Plane stress"),
                ExcMessage("consolidation: both problems are plane strain; "
                           "set Material/linear elastic/Plane stress = "
                           "false."));
    prm.leave_subsection();
    prm.leave_subsection();

    const auto &fluid = library_parameters.pore_fluid;
    soil.kappa        = fluid.mobility;
    AssertThrow(fluid.biot_coefficient == 1. && fluid.biot_modulus == 0. &&
                  fluid.initial_pressure == 0.,
                ExcMessage("consolidation compares with solutions for "
                           "incompressible grains and fluid and no initial "
                           "pressure: set Pore fluid/Biot coefficient = 1, "
                           "Biot modulus = 0, Initial pore pressure = 0."));
    std::filesystem::create_directories(parameters.directory);
  }



  // @sect4{Consolidation::setup_problem}
  //
  // Common to both problems: the body 0 < x < body[0], 0 < y < body[1],
  // filled with points, in a grid of square cells of size h with its lower
  // corner at the origin; rollers on the grid's left (id 0) and bottom
  // (id 2) sides, which are symmetry planes of Mandel's specimen and the
  // walls and base of Terzaghi's column; equal time steps.
  //
  // The grid reaches @p margin cells beyond the body's side that moves
  // (Mandel's free side swells, Terzaghi's top settles): points that move
  // out of the last cell of a grid that ends at the body would leave it
  // (Mandel's specimen on 64 x 64 cells did in its first step), and a
  // drained grid face would lose the material beside it (Terzaghi's column
  // on 128 cells at T_v = 0.84). The drained side is therefore the body's
  // own surface, `Drained surface region`, which follows the points; the
  // other surfaces are impermeable.
  void
  Consolidation::setup_problem(QuasiStaticProblem<2>             &problem,
                               const std::string                 &name,
                               const Point<2>                    &body,
                               const double                       h,
                               const std::array<unsigned int, 2> &margin,
                               const std::string &drained_region,
                               const double       final_time,
                               const unsigned int steps)
  {
    problem.pcout().set_condition(
      parameters.progress &&
      Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
    auto &p              = problem.parameters();
    p                    = library_parameters;
    p.pore_fluid.enabled = true;
    p.pore_fluid.drained_boundaries.clear();
    p.pore_fluid.drained_surface_region = drained_region;
    p.pore_fluid.flux_boundaries.clear();
    p.load_stepping.final_load_factor = final_time;
    p.load_stepping.n_steps           = steps;
    p.load_stepping.growth_factor     = 1.;
    p.output.directory                = parameters.directory + "/" + name;

    std::array<unsigned int, 2> cells;
    Point<2>                    upper;
    for (unsigned int d = 0; d < 2; ++d)
      {
        const double n = body[d] / h;
        AssertThrow(std::abs(n - std::round(n)) < 1e-9 * n,
                    ExcMessage("consolidation: the " + name +
                               " problem's sides must be multiples of its "
                               "cell size."));
        cells[d] = static_cast<unsigned int>(std::round(n)) + margin[d];
        upper[d] = cells[d] * h;
      }
    problem.grid().make_box(Point<2>(), upper, cells);
    problem.set_model(std::make_unique<LinearElastic<2>>(soil.E, soil.nu));
    problem.points().fill(
      [&](const Point<2> &x) { return x[0] < body[0] && x[1] < body[1]; },
      p.material_points.points_per_direction,
      p.material_points.placement);
    const auto zero = std::make_shared<Functions::ZeroFunction<2>>(2);
    auto      &bcs  = problem.boundary_conditions();
    bcs.add_dirichlet_boundary(0, {}, zero, /*normal_only=*/true);
    bcs.add_dirichlet_boundary(2, {}, zero, /*normal_only=*/true);
  }



  // @sect4{Consolidation::point_pressures}
  std::vector<std::array<double, 4>>
  Consolidation::point_pressures(const QuasiStaticProblem<2> &problem)
  {
    const auto &points  = problem.points();
    const auto &offsets = points.get_offsets();
    const auto &model =
      dynamic_cast<const PoroelasticModel<2> &>(points.get_model());
    const unsigned int p_offset = offsets.state + model.pressure_offset();
    std::vector<std::array<double, 4>> values;
    for (const auto &particle : points.get_particle_handler())
      {
        const auto data = particle.get_properties();
        values.push_back(
          {{particle.get_location()[0] - data[offsets.displacement],
            particle.get_location()[1] - data[offsets.displacement + 1],
            data[offsets.initial_volume],
            data[p_offset]}});
      }
    return values;
  }



  // @sect4{Consolidation::iterations}
  std::string
  Consolidation::iterations(const QuasiStaticProblem<2> &problem,
                            const double                 seconds)
  {
    prm.enter_subsection("Pore fluid");
    const bool monolithic = prm.get("Coupling") == "monolithic";
    prm.leave_subsection();
    unsigned int min_count = 1000, max_count = 0, newton = 0, gmres = 0;
    for (const auto &report : problem.step_reports())
      {
        const unsigned int count = monolithic ?
                                     report.newton.newton_iterations :
                                     report.coupling_iterations;
        min_count                = std::min(min_count, count);
        max_count                = std::max(max_count, count);
        newton += report.newton.newton_iterations;
        gmres += report.newton.linear_iterations;
      }
    std::ostringstream line;
    line << (monolithic ? "monolithic: Newton iterations per step " :
                          "fixed-stress iterations per step ")
         << min_count << "-" << max_count << ", GMRES per Newton " << std::fixed
         << std::setprecision(2) << static_cast<double>(gmres) / newton << ", "
         << std::setprecision(1) << seconds << " s";
    return line.str();
  }



  // @sect4{Consolidation::run_terzaghi}
  //
  // The column is one cell wide, with rollers on both sides (the right
  // side, id 1, too), the load q on its top, which drains. After each step
  // at T_v = 0.1, 0.5 or 1 the L2 error of the points' pressure is taken,
  // relative to q.
  std::array<double, 3>
  Consolidation::run_terzaghi()
  {
    const double       H     = parameters.column_height;
    const unsigned int cells = parameters.column_cells;
    const double       q     = parameters.column_load;
    const double t_end = H * H / soil.consolidation_coefficient(); // T_v = 1
    const unsigned int steps = parameters.column_steps;
    AssertThrow(steps % 10 == 0,
                ExcMessage("consolidation: Column steps must be a multiple "
                           "of 10."));

    // The load and the drainage are on the column's top, y = H, which
    // settles into the empty row of cells above it: a traction on the
    // body's surface (added before the points are made, which carry its
    // area), and the drained surface there.
    const double          h = H / cells;
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    problem.return_large_blocks_to_system();
    const std::string top = "y > " + Utilities::to_string(H - h / 4);
    problem.boundary_conditions().add_surface_traction(
      "column load",
      parse_region<2>(top, "consolidation: column top", "on the column's top"),
      std::make_shared<Functions::ConstantFunction<2>>(
        std::vector<double>{0., -q}));
    setup_problem(
      problem, "terzaghi", Point<2>(h, H), h, {{0, 1}}, top, t_end, steps);
    problem.boundary_conditions().add_dirichlet_boundary(
      1,
      {},
      std::make_shared<Functions::ZeroFunction<2>>(2),
      /*normal_only=*/true);

    // Each error is taken in the first step that reaches its T_v, against
    // the exact pressure at that step's own time: a step cut back on the
    // way need not end on T_v exactly. A time that no step reached keeps
    // its NaN, which fails the check.
    const std::array<double, 3> times = {{0.1, 0.5, 1.0}};
    std::array<double, 3>       errors;
    errors.fill(std::numeric_limits<double>::quiet_NaN());
    problem.set_step_callback([&](const StepReport &report) {
      const double Tv = report.load_factor / t_end;
      for (unsigned int k = 0; k < times.size(); ++k)
        if (std::isnan(errors[k]) && Tv > times[k] * (1. - 1e-9))
          {
            double sum = 0, volume = 0;
            for (const auto &[X, Y, V, p] : point_pressures(problem))
              {
                const double e = p - terzaghi_pressure(H - Y, H, Tv, q);
                sum += V * e * e;
                volume += V;
              }
            errors[k] = std::sqrt(Utilities::MPI::sum(sum, MPI_COMM_WORLD) /
                                  Utilities::MPI::sum(volume, MPI_COMM_WORLD)) /
                        q;
          }
      return true;
    });

    Timer timer;
    problem.run();
    timer.stop();
    pcout << "Terzaghi's column: H = " << H << " m, " << cells << " cells, "
          << steps << " steps to T_v = 1\n  "
          << iterations(problem, timer.wall_time()) << '\n'
          << std::setprecision(3);
    for (unsigned int k = 0; k < times.size(); ++k)
      pcout << "  T_v = " << times[k] << ": L2 error of p = " << 100 * errors[k]
            << " % of q\n";
    return errors;
  }



  // @sect4{Consolidation::run_mandel}
  //
  // The quarter 0 < x < a, 0 < y < b: rollers on the symmetry planes x = 0
  // and y = 0 (impermeable), the plate on top (id 3, impermeable), the
  // free side x = a drained. The centre pressure is the mean
  // pressure of the points of the first column of cells, compared with the
  // exact pressure at the same points: the exact centre pressure at x = 0
  // differs from it by O(h^2) only (dp/dx = 0 there).
  std::pair<double, double>
  Consolidation::run_mandel()
  {
    const double         a = parameters.specimen_width;
    const double         b = parameters.specimen_height;
    const double         F = parameters.plate_force;
    const MandelSolution exact(soil, a, F);
    const double         c     = soil.consolidation_coefficient();
    const double         t_end = parameters.final_time * a * a / c;
    const unsigned int   cells = parameters.specimen_cells;
    const double         h     = a / cells;

    // The free side x = a swells at first (the undrained response) and
    // drains: one empty column of cells beyond it, and the drained surface
    // on the body's side x = a.
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    problem.return_large_blocks_to_system();
    setup_problem(problem,
                  "mandel",
                  Point<2>(a, b),
                  h,
                  {{1, 0}},
                  "x > " + Utilities::to_string(a - h / 4),
                  t_end,
                  parameters.specimen_steps);

    // The plate: boundary 3 moves as one along y (RigidPlates; the nodes
    // of the empty column carry no material and are not part of it),
    // loaded by the traction F / a on 0 < x < a, whose resultant is F. Its
    // motion is not given: it is what the force does to the specimen.
    auto &bcs = problem.boundary_conditions();
    bcs.add_rigid_plate(3);
    bcs.add_traction(
      3,
      std::make_shared<VectorFunctionFromScalarFunctionObject<2>>(
        [=](const Point<2> &x) { return x[0] < a ? -F / a : 0.; }, 1, 2));

    // After each step: the centre pressure (computed, and exact at the same
    // points), and the plate's settlement over b, the vertical strain
    // u_y / y, which the exact solution makes uniform.
    struct Record
    {
      double tau, pressure, exact_pressure, strain, exact_strain;
    };
    std::vector<Record> history;
    // The free side's points move out by up to F nu_u / (2 G) (4.2 mm
    // here) at t = 0+. Where that is more than their distance to the grid
    // line x = a (h / 4 with 2 x 2 points per cell: finer than about 60
    // cells over a) they cross it, and with linear shape functions the
    // cell-crossing error makes the specimen too soft there (on 64 x 64
    // cells the settlement ends 10 % above the exact one). The largest x
    // of any point tells whether that happened.
    double largest_x = 0;
    problem.set_step_callback([&](const StepReport &report) {
      for (const auto &particle : problem.points().get_particle_handler())
        largest_x = std::max(largest_x, particle.get_location()[0]);
      std::vector<double> sums(3, 0.);
      for (const auto &[X, Y, V, p] : point_pressures(problem))
        if (X < h)
          {
            sums[0] += V * p;
            sums[1] += V * exact.pressure(X, report.load_factor);
            sums[2] += V;
          }
      MPI_Allreduce(MPI_IN_PLACE,
                    sums.data(),
                    sums.size(),
                    MPI_DOUBLE,
                    MPI_SUM,
                    MPI_COMM_WORLD);
      history.push_back({exact.dimensionless_time(report.load_factor),
                         sums[0] / sums[2],
                         sums[1] / sums[2],
                         problem.rigid_plate_displacements()[0] / b,
                         exact.vertical_strain(report.load_factor)});
      return true;
    });

    Timer timer;
    problem.run();
    timer.stop();

    // The exact peak of the centre column's mean pressure: the exact
    // pressure at the column's mean X (the points' X are those of the
    // start), its largest value in time.
    double X_mean = 0, volume = 0;
    for (const auto &[X, Y, V, p] : point_pressures(problem))
      if (X < h)
        {
          X_mean += V * X;
          volume += V;
        }
    X_mean = Utilities::MPI::sum(X_mean, MPI_COMM_WORLD) /
             Utilities::MPI::sum(volume, MPI_COMM_WORLD);
    double computed_peak = 0, strain_error = 0;
    for (const auto &record : history)
      {
        computed_peak = std::max(computed_peak, record.pressure);
        strain_error  = std::max(strain_error,
                                std::abs(record.strain - record.exact_strain) /
                                  std::abs(record.exact_strain));
      }
    const double exact_peak = exact.peak_pressure(X_mean, t_end);
    const double peak_error = std::abs(computed_peak - exact_peak) / exact_peak;
    const double p0         = exact.initial_pressure();

    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::ofstream csv(parameters.directory + "/mandel.csv");
        csv << "# c t / a^2, centre pressure / p0: computed, exact; "
               "vertical strain u_y / y: computed, exact\n"
            << std::setprecision(8);
        for (const auto &record : history)
          csv << record.tau << ' ' << record.pressure / p0 << ' '
              << record.exact_pressure / p0 << ' ' << record.strain << ' '
              << record.exact_strain << '\n';
      }
    pcout << "Mandel's problem: a = " << a << " m, b = " << b << " m, " << cells
          << " x " << std::lround(b / h) << " cells, "
          << problem.step_reports().size()
          << " steps to c t / a^2 = " << parameters.final_time << "\n  "
          << iterations(problem, timer.wall_time()) << '\n'
          << std::setprecision(5) << "  peak centre pressure / p0: computed "
          << computed_peak / p0 << ", exact " << exact_peak / p0
          << " (at x = " << X_mean
          << "; at x = 0: " << exact.peak_pressure(0., t_end) / p0 << ")\n"
          << std::setprecision(3) << "  error of the peak " << 100 * peak_error
          << " %, largest error of the plate's settlement "
          << 100 * strain_error << " %\n";
    largest_x = Utilities::MPI::max(largest_x, MPI_COMM_WORLD);
    if (largest_x > a && !library_parameters.material_points.formulation.gimp())
      pcout << "  Points of the free side crossed the grid line x = a (up "
               "to x = "
            << std::setprecision(4) << largest_x
            << "): with linear shape functions the cell-crossing error "
               "spoils the settlement; use Material points/Shape functions "
               "= cpGIMP on this grid.\n";
    return {peak_error, strain_error};
  }



  // @sect4{Consolidation::run}
  bool
  Consolidation::run()
  {
    const std::array<double, 3> terzaghi      = run_terzaghi();
    const auto [peak_error, settlement_error] = run_mandel();

    bool passed = peak_error <= parameters.mandel_tolerance &&
                  settlement_error <= parameters.mandel_tolerance;
    for (const double e : terzaghi)
      passed = passed && e <= parameters.terzaghi_tolerance;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::ofstream summary(parameters.directory + "/summary.txt");
        summary << std::setprecision(6)
                << "terzaghi_l2_error_tv_0.1 = " << terzaghi[0]
                << "\nterzaghi_l2_error_tv_0.5 = " << terzaghi[1]
                << "\nterzaghi_l2_error_tv_1.0 = " << terzaghi[2]
                << "\nmandel_peak_pressure_error = " << peak_error
                << "\nmandel_settlement_error = " << settlement_error
                << "\npass = " << (passed ? "yes" : "no") << '\n';
      }
    pcout << (passed ? "OK" : "FAILED")
          << ": Terzaghi L2 errors <= " << parameters.terzaghi_tolerance
          << " of q, Mandel peak and settlement errors <= "
          << parameters.mandel_tolerance << " (summary.txt in "
          << parameters.directory << ")" << std::endl;
    return passed;
  }
} // namespace Consolidation



// @sect3{The main function}
int
main(int argc, char *argv[])
{
  unsigned int rank = 0;
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
      const std::string parameter_file =
        argc > 1 ?
          std::string(argv[1]) :
          (std::filesystem::path(argv[0]).parent_path() / "consolidation.prm")
            .string();
      AssertThrow(std::filesystem::exists(parameter_file),
                  dealii::ExcMessage("Cannot find the parameter file <" +
                                     parameter_file + ">."));
      if (!Consolidation::Consolidation(parameter_file).run())
        return 1;
    }
  catch (std::exception &exc)
    {
      if (rank == 0)
        std::cerr << "consolidation stopped: " +
                       qsmpm::Utils::error_message(exc) + "\n"
                  << std::flush;
      return 1;
    }
  catch (...)
    {
      if (rank == 0)
        std::cerr << "consolidation stopped: unknown exception" << std::endl;
      return 1;
    }
  return 0;
}
