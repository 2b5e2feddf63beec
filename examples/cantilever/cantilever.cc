/* ---------------------------------------------------------------------
 *
 * qsmpm example: cantilever
 *
 * A cantilever bent by its own weight until its tip has rotated by more
 * than 60 degrees: the standard large-deformation verification of implicit
 * MPM (Coombs & Augarde 2020, AMPLE; Sinaie et al. 2017). The program runs
 * the beam with linear, uGIMP and cpGIMP shape functions on a sequence of
 * grids, compares the tip's deflection and rotation with Reissner's
 * geometrically exact beam (solved here by shooting), checks a small load
 * against Timoshenko's beam, audits the equilibrium of every step, and
 * writes summary.txt and tip.csv.
 *
 * Usage:
 *   ./cantilever [cantilever.prm]
 *   mpirun -np 2 ./cantilever cantilever.prm
 *
 * ---------------------------------------------------------------------
 */

// @sect3{Include files}
#include "reissner_beam.h"

#include <algorithm>
#include <array>
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
#include <qsmpm/base/parameter_file.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <sstream>
#include <string>
#include <vector>

namespace Cantilever
{
  using namespace dealii;
  using namespace qsmpm;

  // @sect3{The problem}
  //
  // A beam of length $L$ and height $H$ (plane strain, Hencky elasticity
  // with $E$ and $\nu$) is clamped at $x = 0$: every grid node on the face
  // $x = 0$ is fixed. Its weight $q$ per unit initial volume grows with the
  // load factor, $q(t) = t\,q_{max}$, a dead load. The grid reaches below
  // and beyond the beam, so that the bent beam stays inside it.
  //
  // The reference is Reissner's beam (reissner_beam.h) with the plane-strain
  // stiffnesses $EA = E' H$, $EI = E' H^3/12$, $\kappa G A = \frac56 G H$,
  // $E' = E / (1 - \nu^2)$, under the load $w = q H$ per unit length. It
  // follows the axis of the beam and the rotation of its cross-sections;
  // from the material points we take the two points of the cross-section
  // nearest the tip, at the top and at the bottom of the beam: their
  // midpoint follows the axis, the line between them the cross-section.
  //
  // For a small load the same comparison is made with Timoshenko's linear
  // beam, whose deflection at $s$ is
  // @f[
  //   v(s) = \frac{w}{24 EI}(s^4 - 4 L s^3 + 6 L^2 s^2)
  //        + \frac{w}{\kappa G A}(L s - s^2/2).
  // @f]

  // @sect3{Parameters}
  //
  // The example's own subsection; the library's subsections (material
  // points, material, load stepping, nonlinear solver) are read by
  // QuasiStaticProblem for each run, with the shape functions and the grid
  // set by the study.
  struct Parameters
  {
    double                    length           = 10.;
    double                    height           = 1.;
    double                    large_load       = 100.;
    double                    small_load       = 0.3;
    unsigned int              small_load_cells = 8;
    std::vector<unsigned int> cells            = {4, 8};
    std::vector<std::string>  shape_functions  = {"cpGIMP", "uGIMP", "linear"};
    std::vector<std::string>  verified         = {"cpGIMP", "uGIMP"};
    double                    margin_below     = 9.;
    double                    tolerance        = 0.02;
    double                    small_tolerance  = 0.01;
    std::string               directory        = "output-cantilever";

    void
    add_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Cantilever");
      prm.add_parameter("Length", length, "L, along x from the clamp.");
      prm.add_parameter("Height", height, "H, along y.");
      prm.add_parameter("Large load",
                        large_load,
                        "q_max, the weight per unit initial volume at the "
                        "end of the large-deformation runs.");
      prm.add_parameter("Small load",
                        small_load,
                        "The weight of the run compared with Timoshenko's "
                        "linear beam (in one load step).");
      prm.add_parameter("Cells over the height for the small load",
                        small_load_cells);
      prm.add_parameter("Cells over the height",
                        cells,
                        "The grids of the large-deformation study.");
      prm.add_parameter("Shape functions list",
                        shape_functions,
                        "linear, uGIMP, cpGIMP.");
      prm.add_parameter("Shape functions held to the tolerance",
                        verified,
                        "Of the list above, those whose error on the "
                        "finest grid must be within the tolerance (linear "
                        "shape functions keep a cell-crossing error that "
                        "does not vanish under refinement: they are "
                        "reported only). The first of them gives "
                        "tip_deflection_error and tip_rotation_error.");
      prm.add_parameter("Room below",
                        margin_below,
                        "How far the grid reaches below the beam.");
      prm.add_parameter("Tolerance",
                        tolerance,
                        "Largest relative error of the tip's deflection and "
                        "rotation on the finest grid at the largest load.");
      prm.add_parameter("Small load tolerance",
                        small_tolerance,
                        "Largest relative error of the deflection against "
                        "Timoshenko's beam.");
      prm.add_parameter("Output directory", directory);
      prm.leave_subsection();
    }
  };



  // @sect3{The weight}
  class Weight : public Function<2>
  {
  public:
    explicit Weight(const double q)
      : Function<2>(2)
      , q(q)
    {
    }

    double
    value(const Point<2> &, const unsigned int component) const override
    {
      return component == 1 ? -q * get_time() : 0.;
    }

  private:
    const double q;
  };



  // @sect3{What one run measures}
  //
  // Per accepted step: the load q, the tip's deflection (downward
  // displacement of the midpoint of the tip section's points) and its
  // rotation (clockwise, in degrees), and the step's lost load.
  struct TipRecord
  {
    double q, deflection, rotation, imbalance;
  };

  struct Run
  {
    std::string            shape_functions;
    unsigned int           cells = 0;
    std::vector<TipRecord> records;
    double                 s_tip = 0.; // arc length of the tip section
    unsigned int newton_min      = std::numeric_limits<unsigned int>::max(),
                 newton_max = 0, gmres = 0, newton = 0;
    double wall_time = 0.;
  };



  // @sect3{The cantilever class}
  //
  // One beam on one grid with one kind of shape functions, set up from
  // the parameter file like a driver run, then driven by QuasiStaticProblem.
  class CantileverBeam
  {
  public:
    CantileverBeam(const Parameters  &parameters,
                   ParameterHandler  &prm,
                   const std::string &shape_functions,
                   const unsigned int cells,
                   const double       load,
                   const unsigned int n_steps);

    /// Run all load steps; the tip after each.
    Run
    run();

  private:
    /// The ids of the points of the tip section, found once.
    void
    find_tip_points();

    /// The tip's deflection and rotation now.
    std::pair<double, double>
    tip() const;

    const Parameters     &parameters;
    const double          h;
    const double          load;
    QuasiStaticProblem<2> problem;
    types::particle_index top_id = 0, bottom_id = 0;
    Run                   result;
  };



  CantileverBeam::CantileverBeam(const Parameters  &parameters,
                                 ParameterHandler  &prm,
                                 const std::string &shape_functions,
                                 const unsigned int cells,
                                 const double       load,
                                 const unsigned int n_steps)
    : parameters(parameters)
    , h(parameters.height / cells)
    , load(load)
    , problem(MPI_COMM_WORLD)
  {
    problem.parameters().parse_parameters(prm);
    auto &mp                       = problem.parameters().material_points;
    mp.formulation.shape_functions = parse_shape_functions(shape_functions);
    if (n_steps > 0)
      problem.parameters().load_stepping.n_steps = n_steps;
    problem.parameters().output.interval = 0;
    problem.pcout().set_condition(false);
    result.shape_functions = shape_functions;
    result.cells           = cells;

    // The grid: from two cells behind the clamp to two cells (at least
    // half a unit) beyond the tip, and from the room below the beam to half
    // a unit above it, in square cells of size h. The cells behind the
    // clamp hold the part of the GIMP domains of the points next to it
    // that reaches behind x = 0 (without them, their weights would not sum
    // to one, and the equilibrium check would stop the run).
    const double   beyond = std::max(2. * h, 0.5);
    const Point<2> lower(-2. * h, -parameters.margin_below);
    const Point<2> upper(parameters.length + beyond, parameters.height + 0.5);
    const std::array<unsigned int, 2> subdivisions = {
      {static_cast<unsigned int>(std::round((upper[0] - lower[0]) / h)),
       static_cast<unsigned int>(std::ceil((upper[1] - lower[1]) / h))}};
    problem.grid().make_box(lower,
                            Point<2>(lower[0] + subdivisions[0] * h,
                                     lower[1] + subdivisions[1] * h),
                            subdivisions);
    problem.set_model(ConstitutiveModelFactory<2>::create(prm));
    const double L = parameters.length, H = parameters.height;
    problem.points().fill(
      [L, H](const Point<2> &x) {
        return x[0] > 0. && x[0] < L && x[1] > 0. && x[1] < H;
      },
      mp.points_per_direction,
      mp.placement);

    // The clamp: every node at or behind x = 0.
    auto        &bcs       = problem.boundary_conditions();
    const double tolerance = 1e-9 * h;
    bcs.add_dirichlet_nodes(
      "clamp",
      [tolerance](const Point<2> &x) { return x[0] <= tolerance; },
      {{true, true}},
      std::make_shared<Functions::ZeroFunction<2>>(2));
    bcs.set_body_force(std::make_shared<Weight>(load));
    find_tip_points();
  }



  // @sect4{CantileverBeam::find_tip_points}
  //
  // The points of the section nearest the tip: the largest x, and there
  // the smallest and the largest y (the same on every number of ranks: ties
  // go to the smaller id).
  void
  CantileverBeam::find_tip_points()
  {
    const auto &handler = problem.points().get_particle_handler();
    double      x_max   = -std::numeric_limits<double>::max();
    for (const auto &particle : handler)
      x_max = std::max(x_max, particle.get_location()[0]);
    x_max           = Utilities::MPI::max(x_max, MPI_COMM_WORLD);
    const auto pick = [&](const double sign) {
      std::pair<double, types::particle_index> best{
        std::numeric_limits<double>::max(), 0};
      for (const auto &particle : handler)
        if (particle.get_location()[0] > x_max - 1e-9 * h)
          best =
            std::min(best,
                     {sign * particle.get_location()[1], particle.get_id()});
      const double y = Utilities::MPI::min(best.first, MPI_COMM_WORLD);
      return Utilities::MPI::min(
        best.first == y ? best.second :
                          std::numeric_limits<types::particle_index>::max(),
        MPI_COMM_WORLD);
    };
    bottom_id    = pick(1.);
    top_id       = pick(-1.);
    result.s_tip = x_max;
  }



  // @sect4{CantileverBeam::tip}
  //
  // The positions of the two tip points (gathered from the ranks that own
  // them): the deflection of their midpoint from its initial height H/2,
  // and the rotation of the line between them from the vertical.
  std::pair<double, double>
  CantileverBeam::tip() const
  {
    std::vector<double> xy(4, 0.);
    for (const auto &particle : problem.points().get_particle_handler())
      {
        const auto id = particle.get_id();
        if (id == bottom_id || id == top_id)
          {
            const unsigned int k = (id == top_id) ? 2 : 0;
            xy[k]                = particle.get_location()[0];
            xy[k + 1]            = particle.get_location()[1];
          }
      }
    Utilities::MPI::sum(xy, MPI_COMM_WORLD, xy);
    const double deflection = parameters.height / 2. - 0.5 * (xy[1] + xy[3]);
    const double rotation =
      std::atan2(xy[2] - xy[0], xy[3] - xy[1]) * 180. / numbers::PI;
    return {deflection, rotation};
  }



  // @sect4{CantileverBeam::run}
  Run
  CantileverBeam::run()
  {
    problem.set_step_callback([&](const auto &report) {
      const auto [deflection, rotation] = tip();
      result.records.push_back({report.load_factor * load,
                                deflection,
                                rotation,
                                problem.equilibrium().imbalance()});
      result.newton_min =
        std::min(result.newton_min, report.newton.newton_iterations);
      result.newton_max =
        std::max(result.newton_max, report.newton.newton_iterations);
      result.newton += report.newton.newton_iterations;
      result.gmres += report.newton.linear_iterations;
      return true;
    });
    Timer timer;
    problem.run();
    result.wall_time = timer.wall_time();
    return result;
  }



  // @sect3{The study}
  //
  // The small-load run against Timoshenko, then the large-deformation runs
  // against Reissner's beam, a line per run on the screen, tip.csv with
  // every step of every run, and summary.txt with the figures the
  // verification reads.
  class CantileverStudy
  {
  public:
    explicit CantileverStudy(const std::string &parameter_file);

    void
    run();

  private:
    ParameterHandler   prm;
    Parameters         parameters;
    double             E = 0., nu = 0.;
    ConditionalOStream pcout;
  };



  CantileverStudy::CantileverStudy(const std::string &parameter_file)
    : pcout(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
  {
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 2), "");
    QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
    parameters.add_parameters(prm);
    prm.parse_input(parameter_file);
    prm.enter_subsection("Material");
    AssertThrow(prm.get("Model") == "hencky",
                ExcMessage("cantilever: the reference beam is elastic; use "
                           "Material/Model = hencky."));
    prm.enter_subsection("hencky");
    E  = prm.get_double("Young's modulus");
    nu = prm.get_double("Poisson's ratio");
    prm.leave_subsection();
    prm.leave_subsection();
    AssertThrow(!parameters.cells.empty() &&
                  !parameters.shape_functions.empty(),
                ExcMessage("cantilever: Cells over the height and Shape "
                           "functions list must not be empty."));
  }



  void
  CantileverStudy::run()
  {
    const double L = parameters.length, H = parameters.height;
    const double E_plane = E / (1. - nu * nu), G = E / (2. * (1. + nu));
    const double EA = E_plane * H, EI = E_plane * H * H * H / 12.,
                 kGA = 5. / 6. * G * H;
    const bool root  = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    if (root)
      std::filesystem::create_directories(parameters.directory);
    std::ofstream csv;
    if (root)
      {
        csv.open(parameters.directory + "/tip.csv");
        csv << "shape_functions,cells,q,deflection,rotation_deg,"
               "reference_deflection,reference_rotation_deg,imbalance\n";
      }
    double largest_imbalance = 0.;

    // Small load, one step, against Timoshenko's beam at the tip section.
    CantileverBeam small(parameters,
                         prm,
                         "linear",
                         parameters.small_load_cells,
                         parameters.small_load,
                         1);
    const Run      s_run = small.run();
    const double   w = parameters.small_load * H, s = s_run.s_tip;
    const double   timoshenko =
      w / (24. * EI) *
        (s * s * s * s - 4. * L * s * s * s + 6. * L * L * s * s) +
      w / kGA * (L * s - s * s / 2.);
    const double small_error =
      std::abs(s_run.records.back().deflection / timoshenko - 1.);
    for (const auto &r : s_run.records)
      largest_imbalance = std::max(largest_imbalance, r.imbalance);
    pcout << "small load q = " << parameters.small_load << ", "
          << parameters.small_load_cells
          << " cells over the height, linear: tip deflection "
          << std::setprecision(6) << s_run.records.back().deflection
          << ", Timoshenko " << timoshenko << ", error " << std::setprecision(3)
          << 100. * small_error << " %" << std::endl;

    // Large deformation.
    const ReissnerBeam beam(L, EA, kGA, EI, parameters.large_load * H);
    std::vector<Run>   runs;
    for (const auto &shape_functions : parameters.shape_functions)
      for (const unsigned int cells : parameters.cells)
        {
          CantileverBeam beam_run(
            parameters, prm, shape_functions, cells, parameters.large_load, 0);
          runs.push_back(beam_run.run());
          const Run &r = runs.back();
          for (const auto &record : r.records)
            {
              largest_imbalance = std::max(largest_imbalance, record.imbalance);
              const ReissnerBeam at_q(L, EA, kGA, EI, record.q * H);
              const auto         z = at_q.at(r.s_tip);
              if (root)
                csv << shape_functions << ',' << cells << ','
                    << std::setprecision(8) << record.q << ','
                    << record.deflection << ',' << record.rotation << ','
                    << -z[1] + 0. << ',' << -z[2] * 180. / numbers::PI << ','
                    << record.imbalance << '\n';
            }
          const auto   z          = beam.at(r.s_tip);
          const double deflection = -z[1],
                       rotation   = -z[2] * 180. / numbers::PI;
          pcout << std::setw(7) << shape_functions << "  cells over H "
                << std::setw(2) << cells << "  q " << r.records.back().q
                << "  tip deflection " << std::setprecision(5)
                << r.records.back().deflection << " (beam " << deflection
                << ", error " << std::setprecision(3)
                << 100. * (r.records.back().deflection / deflection - 1.)
                << " %)  rotation " << std::setprecision(4)
                << r.records.back().rotation << " deg (beam " << rotation
                << ", error " << std::setprecision(3)
                << 100. * (r.records.back().rotation / rotation - 1.)
                << " %)  steps " << r.records.size() << "  newton "
                << r.newton_min << "-" << r.newton_max << "  gmres/newton "
                << (r.newton > 0 ? r.gmres / r.newton : 0) << "  " << std::fixed
                << std::setprecision(1) << r.wall_time << " s"
                << std::defaultfloat << std::endl;
        }

    // The figures of the finest grid: for every kind of shape functions
    // in summary.txt, and those held to the tolerance decide whether the
    // study passes.
    const unsigned int finest =
      *std::max_element(parameters.cells.begin(), parameters.cells.end());
    double deflection_error = -1., rotation_error = -1., max_rotation = 0.;
    bool   pass = small_error <= parameters.small_tolerance;
    std::ostringstream per_kind;
    for (const Run &r : runs)
      if (r.cells == finest)
        {
          const auto   z = beam.at(r.s_tip);
          const double d_error =
            std::abs(r.records.back().deflection / -z[1] - 1.);
          const double r_error = std::abs(
            r.records.back().rotation / (-z[2] * 180. / numbers::PI) - 1.);
          per_kind << "tip_deflection_error_" << r.shape_functions << ' '
                   << d_error << '\n'
                   << "tip_rotation_error_" << r.shape_functions << ' '
                   << r_error << '\n';
          if (std::find(parameters.verified.begin(),
                        parameters.verified.end(),
                        r.shape_functions) == parameters.verified.end())
            continue;
          pass = pass && d_error <= parameters.tolerance &&
                 r_error <= parameters.tolerance &&
                 r.records.back().rotation > 60.;
          if (deflection_error < 0.)
            {
              deflection_error = d_error;
              rotation_error   = r_error;
              max_rotation     = r.records.back().rotation;
            }
        }
    AssertThrow(deflection_error >= 0.,
                ExcMessage("cantilever: none of the Shape functions held to "
                           "the tolerance was run."));
    if (root)
      {
        std::ofstream summary(parameters.directory + "/summary.txt");
        summary << std::setprecision(6) << "max_tip_rotation_deg "
                << max_rotation << '\n'
                << "tip_deflection_error " << deflection_error << '\n'
                << "tip_rotation_error " << rotation_error << '\n'
                << "small_load_error " << small_error << '\n'
                << "largest_load_imbalance " << largest_imbalance << '\n'
                << per_kind.str() << "pass " << (pass ? "yes" : "no") << '\n';
        summary.close();
        std::filesystem::copy_file(
          parameters.directory + "/summary.txt",
          "summary.txt",
          std::filesystem::copy_options::overwrite_existing);
      }
    pcout << "finest grid (" << finest
          << " cells over H), q = " << parameters.large_load << ", "
          << parameters.verified[0] << ": tip rotation " << std::setprecision(4)
          << max_rotation << " deg, deflection error " << std::setprecision(3)
          << 100. * deflection_error << " %, rotation error "
          << 100. * rotation_error << " % (tolerance "
          << 100. * parameters.tolerance << " %); largest lost load "
          << largest_imbalance << std::endl;
    AssertThrow(pass,
                ExcMessage("the cantilever misses its reference (see "
                           "summary.txt)."));
  }
} // namespace Cantilever



// @sect3{The main function}
int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      const std::string parameter_file =
        argc > 1 ?
          std::string(argv[1]) :
          (std::filesystem::path(argv[0]).parent_path() / "cantilever.prm")
            .string();
      qsmpm::Utils::check_parameter_file(parameter_file);
      Cantilever::CantileverStudy study(parameter_file);
      study.run();
    }
  catch (std::exception &exc)
    {
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cerr << "cantilever stopped: " + qsmpm::Utils::error_message(exc) +
                       "\n"
                  << std::flush;
      return 1;
    }
  return 0;
}
