/* ---------------------------------------------------------------------
 *
 * qsmpm example: l_panel -- the panel and one run of it (header-only; the
 * test l_panel_experiment includes it from here).
 *
 * ---------------------------------------------------------------------
 */
#ifndef qsmpm_examples_l_panel_l_panel_h
#define qsmpm_examples_l_panel_l_panel_h

// @sect3{Include files}
#include <array>
#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/smeared_cracks.h>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace LPanel
{
  using namespace dealii;
  using namespace qsmpm;

  // @sect3{The experiment}
  //
  // Winkler, Hofstetter and Niederwanger (2001): an L-shaped panel of
  // unreinforced concrete, 500 mm x 500 mm with a square of 250 mm x 250 mm
  // cut out, 100 mm thick. The lower edge of its leg is clamped; a steel
  // plate 30 mm from the end of the arm pushes the arm's lower face up
  // (displacement control). The panel breaks by one crack from the
  // re-entrant corner across the leg, which curves upwards as it runs: the
  // corner opens (mode I) while the arm's bending shears it. In the frame
  // here the leg is x in [0, 0.25] m, y in [0, 0.5] m, the arm x in [0.25,
  // 0.5] m, y in [0.25, 0.5] m, the corner at (0.25, 0.25) and the load at
  // (0.47, 0.25). Plane stress, per unit thickness; the load is reported
  // for the panel's thickness.
  struct Parameters
  {
    double       edge             = 0.5;
    double       cut              = 0.25;
    double       thickness        = 0.1;
    double       load_x           = 0.47;
    double       load_half_width  = 0.01;
    unsigned int cells_along_edge = 50;
    double       uncracked_radius = 0.05;
    std::string  experiment_file  = "winkler_series_a.csv";
    std::string  output_directory = "output-l-panel";
    double       stop_deflection  = 1e-3;

    void
    add_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("L panel");
      prm.add_parameter("Edge length", edge, "The panel's outer edge (m).");
      prm.add_parameter("Cut-out", cut, "The side of the square cut out (m).");
      prm.add_parameter("Thickness",
                        thickness,
                        "The panel's thickness (m): the computed load per "
                        "unit thickness is multiplied by it.");
      prm.add_parameter("Load position",
                        load_x,
                        "x of the centre of the loading plate on the arm's "
                        "lower face (m).");
      prm.add_parameter("Load plate half-width",
                        load_half_width,
                        "The grid nodes of the arm's lower face within this "
                        "distance of the load position move up with the "
                        "plate (m).");
      prm.add_parameter("Cells along the edge",
                        cells_along_edge,
                        "The grid's cells along the outer edge: h = edge / "
                        "cells.");
      prm.add_parameter("Uncracked radius",
                        uncracked_radius,
                        "No crack starts within this distance of the loading "
                        "plate (m): its nodes concentrate the load as the "
                        "steel plate of the test does not.");
      prm.add_parameter("Experiment file",
                        experiment_file,
                        "The measured load-deflection curve (deflection mm, "
                        "load N, comma separated, '#' comments), drawn with "
                        "the computed one and its peak compared; empty: "
                        "none.");
      prm.add_parameter("Output directory", output_directory, "");
      prm.add_parameter("Final deflection",
                        stop_deflection,
                        "The run ends at this displacement of the loading "
                        "plate (m); it is <Load stepping/Final load factor>.");
      prm.leave_subsection();
    }
  };



  // @sect3{The plate's motion}
  //
  // The load factor t is the plate's upward displacement.
  template <int dim>
  class PlateMotion : public Function<dim>
  {
  public:
    PlateMotion()
      : Function<dim>(dim)
    {
    }

    double
    value(const Point<dim> &, const unsigned int component) const override
    {
      return component == 1 ? this->get_time() : 0.;
    }
  };



  // @sect3{The measured curve}
  //
  // Reads "deflection (mm), load (N)" pairs; returns the peak load (N) and
  // its deflection (mm).
  std::array<double, 2>
  measured_peak(const std::string &file)
  {
    std::ifstream in(file);
    AssertThrow(in,
                ExcMessage("Cannot read the experiment file <" + file + ">."));
    std::array<double, 2> peak = {{0., 0.}};
    std::string           line;
    while (std::getline(in, line))
      {
        if (line.empty() || line[0] == '#')
          continue;
        std::istringstream row(line);
        double             u = 0., P = 0.;
        char               comma = 0;
        AssertThrow(row >> u >> comma >> P && comma == ',',
                    ExcMessage("<" + file + ">: cannot read the line <" + line +
                               "> as 'deflection, load'."));
        if (P > peak[1])
          peak = {{u, P}};
      }
    AssertThrow(peak[1] > 0.,
                ExcMessage("<" + file + "> has no positive load."));
    return peak;
  }



  // @sect3{The computation}
  template <int dim>
  class LShapedPanel
  {
  public:
    /// What a run measured.
    struct Result
    {
      /// The peak load (N, for the panel's thickness) and the plate's
      /// displacement there (m).
      double peak = 0., deflection_at_peak = 0.;
      /// The load over the displacement in the first step (N/m): the
      /// elastic stiffness of the set-up.
      double initial_stiffness = 0.;
      /// The measured peak load (N) and its displacement (m); 0 without an
      /// experiment file.
      double measured_peak = 0., measured_deflection = 0.;
      /// The crack's height (m) in the first column of cells from the
      /// leg's left edge that has one (NaN if none).
      double crack_height_at_left_edge = 0.;
      /// The crack's height in every column of cells (x, y), NaN where
      /// none.
      std::vector<std::array<double, 2>> crack_path;
      /// The plate's displacement (m) and the load (N) of every step.
      std::vector<std::array<double, 2>> curve;
      unsigned int                       steps     = 0;
      double                             wall_time = 0.;
    };

    /// Reads @p parameter_file; @p adjust, if given, may change entries
    /// of it before they are used.
    explicit LShapedPanel(
      const std::string                             &parameter_file,
      const std::function<void(ParameterHandler &)> &adjust = {});

    /// Runs the panel to <Final deflection> and writes the output
    /// directory's files: load_deflection.csv, crack_path.csv, cracks.csv,
    /// summary.txt and the pictures.
    Result
    run();

  private:
    bool
    inside(const Point<dim> &x) const
    {
      return !(x[0] > panel.cut && x[1] < panel.edge - panel.cut);
    }

    /// The points of this rank that have dissipated: x, y (initial
    /// positions) and the energy their cracks dissipated over G_f.
    std::vector<std::array<double, 3>>
    cracked_points() const;

    /// For each column of cells: the height of the crack (the mean y of
    /// the @p cracked points of the column, of all ranks, that dissipated
    /// at least half of G_f, weighted by their dissipation); NaN where none
    /// did.
    std::vector<std::array<double, 2>>
    crack_path(const std::vector<std::array<double, 3>> &cracked) const;

    /// The @p cracked points of all ranks into @p file (rank 0).
    void
    write_cracks(const std::vector<std::array<double, 3>> &cracked,
                 const std::string                        &file) const;

    void
    write_results(const Result &result) const;

    void
    write_plots(const std::string &experiment) const;

    ConditionalOStream      pcout;
    ParameterHandler        prm;
    Parameters              panel;
    double                  h = 0.;
    QuasiStaticProblem<dim> problem;
  };



  template <int dim>
  LShapedPanel<dim>::LShapedPanel(
    const std::string                             &parameter_file,
    const std::function<void(ParameterHandler &)> &adjust)
    : pcout(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    , problem(MPI_COMM_WORLD)
  {
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 2), "");
    QuasiStaticProblem<dim>::Parameters::declare_parameters(prm);
    panel.add_parameters(prm);
    prm.parse_input(parameter_file);
    if (adjust)
      adjust(prm);
    AssertThrow(panel.cut > 0. && panel.cut < panel.edge,
                ExcMessage("L panel/<Cut-out> must lie between 0 and "
                           "<Edge length>."));
    AssertThrow(panel.load_x > panel.cut && panel.load_x < panel.edge,
                ExcMessage("L panel/<Load position> must lie on the arm, "
                           "between <Cut-out> and <Edge length>."));
    h = panel.edge / panel.cells_along_edge;

    problem.return_large_blocks_to_system();
    problem.parameters().parse_parameters(prm);
    problem.parameters().output.directory = panel.output_directory;
    problem.parameters().load_stepping.final_load_factor =
      panel.stop_deflection;
    problem.pcout().set_condition(false);
    problem.grid().make_box(Point<dim>(),
                            Point<dim>(panel.edge, panel.edge),
                            {{panel.cells_along_edge, panel.cells_along_edge}});

    // The crack band is one cell wide.
    prm.enter_subsection("Material");
    const std::string model_name = prm.get("Model");
    AssertThrow(model_name == "smeared cracks",
                ExcMessage("l_panel: Material/<Model> must be <smeared "
                           "cracks>."));
    prm.enter_subsection(model_name);
    prm.set("Crack band width", h);
    prm.leave_subsection();
    prm.leave_subsection();
    auto             model  = ConstitutiveModelFactory<dim>::create(prm);
    auto            &cracks = dynamic_cast<SmearedCracks<dim> &>(*model);
    const Point<dim> load(panel.load_x, panel.edge - panel.cut);
    cracks.set_crack_region([this, load](const Point<dim> &x) {
      return x.distance(load) > panel.uncracked_radius;
    });
    problem.set_model(std::move(model));

    // The clamped lower edge of the leg, and the loading plate: the nodes
    // of the arm's lower face under it. (The nodes of the box's lower edge
    // beyond the leg have no points and are held anyway.)
    const double tol = 1e-6 * h;
    auto        &bcs = problem.boundary_conditions();
    bcs.add_dirichlet_nodes(
      "base",
      [tol](const Point<dim> &x) { return x[1] < tol; },
      {{true, true}},
      std::make_shared<Functions::ZeroFunction<dim>>(dim));
    bcs.add_dirichlet_nodes(
      "load",
      [this, load, tol](const Point<dim> &x) {
        return std::abs(x[1] - load[1]) < tol &&
               std::abs(x[0] - load[0]) < panel.load_half_width + tol;
      },
      {{false, true}},
      std::make_shared<PlateMotion<dim>>());

    const auto &mp = problem.parameters().material_points;
    problem.points().fill([this](const Point<dim> &x) { return inside(x); },
                          mp.points_per_direction,
                          mp.placement);
  }



  template <int dim>
  typename LShapedPanel<dim>::Result
  LShapedPanel<dim>::run()
  {
    pcout << "L-shaped panel, h = " << h * 1e3 << " mm, "
          << problem.points().n_global_points() << " material points"
          << std::endl;
    Result result;
    Timer  timer;
    // P: the plate's force on the panel (upward), for the whole thickness.
    problem.set_step_callback([&](const StepReport &report) {
      const double P = problem.reactions()[1][1] * panel.thickness;
      if (result.curve.empty())
        result.initial_stiffness = P / report.load_factor;
      result.curve.push_back({{report.load_factor, P}});
      if (P > result.peak)
        {
          result.peak               = P;
          result.deflection_at_peak = report.load_factor;
        }
      return true;
    });
    problem.run();
    timer.stop();
    result.wall_time                 = timer.wall_time();
    result.steps                     = problem.step_reports().size();
    const auto cracked               = cracked_points();
    result.crack_path                = crack_path(cracked);
    result.crack_height_at_left_edge = std::numeric_limits<double>::quiet_NaN();
    for (const auto &[x, y] : result.crack_path)
      if (std::isfinite(y))
        {
          result.crack_height_at_left_edge = y;
          break;
        }
    if (!panel.experiment_file.empty())
      {
        const auto measured        = measured_peak(panel.experiment_file);
        result.measured_deflection = 1e-3 * measured[0];
        result.measured_peak       = measured[1];
      }

    pcout << "  " << result.steps << " steps, " << std::setprecision(3)
          << result.wall_time << " s\n"
          << std::setprecision(5) << "  elastic stiffness "
          << 1e-6 * result.initial_stiffness << " kN/mm\n"
          << "  peak load " << 1e-3 * result.peak << " kN at a deflection of "
          << 1e3 * result.deflection_at_peak << " mm" << std::endl;
    if (result.measured_peak > 0.)
      pcout << "  measured (" << panel.experiment_file
            << "): " << 1e-3 * result.measured_peak << " kN at "
            << 1e3 * result.measured_deflection
            << " mm; computed / measured - 1 = "
            << result.peak / result.measured_peak - 1. << std::endl;
    pcout << "  the crack reaches the leg's left edge at y = "
          << result.crack_height_at_left_edge
          << " m (the corner is at y = " << panel.edge - panel.cut << " m)"
          << std::endl;
    write_cracks(cracked, panel.output_directory + "/cracks.csv");
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        write_results(result);
        write_plots(panel.experiment_file);
      }
    return result;
  }



  // The curve, the crack's path and summary.txt (one "name = value" line
  // each).
  template <int dim>
  void
  LShapedPanel<dim>::write_results(const Result &result) const
  {
    const std::string &dir = panel.output_directory;
    std::filesystem::create_directories(dir);
    std::ofstream out(dir + "/load_deflection.csv");
    AssertThrow(out, ExcMessage("Cannot write <" + dir + ">."));
    out << "deflection_mm,load_kN\n" << std::setprecision(8);
    for (const auto &[u, P] : result.curve)
      out << 1e3 * u << ',' << 1e-3 * P << '\n';
    std::ofstream path(dir + "/crack_path.csv");
    path << "x_m,y_m\n";
    for (const auto &[x, y] : result.crack_path)
      if (std::isfinite(y))
        path << x << ',' << y << '\n';
    std::ofstream summary(dir + "/summary.txt");
    summary << std::setprecision(6) << "peak_kN = " << 1e-3 * result.peak
            << "\ndeflection_at_peak_mm = " << 1e3 * result.deflection_at_peak
            << "\nelastic_stiffness_kN_per_mm = "
            << 1e-6 * result.initial_stiffness
            << "\ncrack_height_at_left_edge_m = "
            << result.crack_height_at_left_edge << '\n';
    if (result.measured_peak > 0.)
      summary << "measured_peak_kN = " << 1e-3 * result.measured_peak
              << "\npeak_over_measured = " << result.peak / result.measured_peak
              << '\n';
  }



  template <int dim>
  std::vector<std::array<double, 3>>
  LShapedPanel<dim>::cracked_points() const
  {
    const auto &model =
      dynamic_cast<const SmearedCracks<dim> &>(problem.points().get_model());
    const auto                        &offsets = problem.points().get_offsets();
    std::vector<std::array<double, 3>> cracked;
    for (const auto &particle : problem.points().get_particle_handler())
      {
        const double D = model.dissipated_over_fracture_energy(
          {particle.get_properties().data() + offsets.state,
           model.n_state_components()});
        if (D > 0.)
          {
            const Point<dim> x = problem.points().initial_location(particle);
            cracked.push_back({{x[0], x[1], D}});
          }
      }
    return cracked;
  }



  template <int dim>
  std::vector<std::array<double, 2>>
  LShapedPanel<dim>::crack_path(
    const std::vector<std::array<double, 3>> &cracked) const
  {
    const unsigned int  n = panel.cells_along_edge;
    std::vector<double> weight(n, 0.), moment(n, 0.);
    for (const auto &[x, y, D] : cracked)
      if (D >= 0.5)
        {
          const unsigned int column =
            std::min(n - 1, static_cast<unsigned int>(x / h));
          weight[column] += D;
          moment[column] += D * y;
        }
    Utilities::MPI::sum(make_array_view(std::as_const(weight)),
                        MPI_COMM_WORLD,
                        make_array_view(weight));
    Utilities::MPI::sum(make_array_view(std::as_const(moment)),
                        MPI_COMM_WORLD,
                        make_array_view(moment));
    std::vector<std::array<double, 2>> path(n);
    for (unsigned int i = 0; i < n; ++i)
      path[i] = {{(i + 0.5) * h,
                  weight[i] > 0. ? moment[i] / weight[i] :
                                   std::numeric_limits<double>::quiet_NaN()}};
    return path;
  }



  template <int dim>
  void
  LShapedPanel<dim>::write_cracks(
    const std::vector<std::array<double, 3>> &cracked,
    const std::string                        &file) const
  {
    const auto all = Utilities::MPI::gather(MPI_COMM_WORLD, cracked, 0);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    std::filesystem::create_directories(
      std::filesystem::path(file).parent_path());
    std::ofstream out(file);
    AssertThrow(out, ExcMessage("Cannot write <" + file + ">."));
    out << "x,y,dissipated_over_Gf\n" << std::setprecision(6);
    for (const auto &part : all)
      for (const auto &[x, y, D] : part)
        out << x << ',' << y << ',' << D << '\n';
  }



  // gnuplot scripts beside the data, and the pictures if gnuplot is
  // installed: the computed load-deflection curve over the measured one,
  // and the dissipated energy of the points with the crack's path.
  template <int dim>
  void
  LShapedPanel<dim>::write_plots(const std::string &experiment) const
  {
    const std::string &dir = panel.output_directory;
    std::ofstream      gp(dir + "/l_panel.gp");
    gp << "set terminal pngcairo size 800,560 noenhanced\n"
       << "set datafile separator ','\n"
       << "set output '" << dir << "/load_deflection.png'\n"
       << "set xlabel 'deflection of the loading plate (mm)'\n"
       << "set ylabel 'load (kN)'\nset grid\n"
       << "plot '" << dir
       << "/load_deflection.csv' every ::1 using 1:2 w l lw 2 t 'qsmpm, "
          "smeared cracks, h = "
       << h * 1e3 << " mm'";
    if (!experiment.empty())
      gp << ", \\\n     '" << experiment
         << "' using 1:($2/1e3) w p pt 6 t 'experiment (Winkler 2001, "
            "series A)'";
    gp << "\nset output '" << dir << "/cracks.png'\n"
       << "set terminal pngcairo size 700,640 noenhanced\n"
       << "set size ratio -1\nset cbrange [0:1]\n"
       << "set xlabel 'x (m)'\nset ylabel 'y (m)'\n"
       << "set cblabel 'dissipated energy / G_f'\n"
       << "set palette rgbformulae 33,13,10\n"
       << "set xrange [0:" << panel.edge << "]\nset yrange [0:" << panel.edge
       << "]\n"
       << "set object 1 rect from " << panel.cut << ",0 to " << panel.edge
       << "," << panel.edge - panel.cut << " fc rgb 'gray90' fs solid\n"
       << "plot '" << dir
       << "/cracks.csv' every ::1 using 1:2:($3 >= 0.02 ? $3 : 1/0) with "
          "points pt 5 ps 0.6 lc palette t '', \\\n     '"
       << dir
       << "/crack_path.csv' every ::1 using 1:2 w lp lw 2 pt 7 lc rgb "
          "'black' t 'crack path (points past G_f / 2)'\n";
    gp.close();
    if (Utils::run_gnuplot(dir + "/l_panel.gp"))
      pcout << "wrote " << dir << "/load_deflection.png and " << dir
            << "/cracks.png" << std::endl;
    else
      pcout << "wrote " << dir << "/l_panel.gp (gnuplot not found: no "
            << "pictures)" << std::endl;
  }
} // namespace LPanel

#endif
