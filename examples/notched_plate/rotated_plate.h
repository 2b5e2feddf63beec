/* ---------------------------------------------------------------------
 *
 * qsmpm example: notched_plate -- one run of the study: the notched plate
 * at one angle to the grid (header-only; the test notched_plate_objectivity
 * includes it from here).
 *
 * ---------------------------------------------------------------------
 */
#ifndef qsmpm_examples_notched_plate_rotated_plate_h
#define qsmpm_examples_notched_plate_rotated_plate_h

#include <array>
#include <cmath>
#include <cstdlib>
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
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/smeared_cracks.h>
#include <sstream>
#include <string>
#include <vector>

namespace NotchedPlate
{
  using namespace dealii;
  using namespace qsmpm;

  // @sect3{The problem}
  //
  // A plate of length $L$ (along its load axis $e$) and width $W$, with a
  // notch of depth $a_0$ and width $2.5 h$ cut into one long edge at
  // mid-length, in plane stress. The notch must be wider than two cells: a
  // slot that removes only the points in the middle of the cells beside
  // the centre line leaves the grid nodes on it with material on both
  // sides, and the grid bridges it (a slot of 1.5 h made the plate at 0
  // degrees 14 % stiffer than at 15, 30 and 45 degrees; with 2.5 h the
  // four agree within 1.5 %). Its two ends are held by grips of length
  // $g$: the grid nodes in the grip zones (in the plate's frame, $\xi <
  // -L/2 + g$ and $\xi > L/2 - g$, across the whole grid) follow $u = 0$
  // and $u = \delta e$. The crack starts at the notch and runs across the
  // ligament $W - a_0$, normal to $e$; the work of the grips up to
  // complete failure is $G_f (W - a_0)$ per unit thickness, and the crack
  // normal is $e$. The plate's axis makes the angle $\theta$ with the
  // grid's x axis: the material points fill the rotated plate, the grid
  // stays Cartesian.
  //
  // The load is followed through the snap-back by the opening of a gauge
  // across the notch's mouth (Load stepping/Control = opening; the program
  // places the gauge).
  struct Parameters
  {
    double              length           = 2.;
    double              width            = 1.;
    double              notch_depth      = 0.3;
    unsigned int        cells_across     = 24;
    double              grip_length      = 0.25;
    std::vector<double> angles           = {0., 15., 30., 45.};
    std::string         output_file      = "objectivity.csv";
    double              stop_fraction    = 0.02;
    std::string         output_directory = "output-notched-plate";
    bool                verbose          = false;

    void
    add_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Notched plate");
      prm.add_parameter("Length", length, "L: along the load axis.");
      prm.add_parameter("Width", width, "W: across the load axis.");
      prm.add_parameter("Notch depth", notch_depth, "a0, from one long edge.");
      prm.add_parameter("Cells across the width",
                        cells_across,
                        "W / h: the grid's cell size h.");
      prm.add_parameter("Grip length",
                        grip_length,
                        "g: the length of each end held by a grip.");
      prm.add_parameter("Grid angles",
                        angles,
                        "The angles (degrees) between the plate's load axis "
                        "and the grid's x axis, one run each.");
      prm.add_parameter("Output file",
                        output_file,
                        "The table angle_deg, peak_N, work_over_Gf_area, "
                        "crack_normal_deg.");
      prm.add_parameter("Stop below fraction of peak",
                        stop_fraction,
                        "A run ends once the load has fallen below this "
                        "fraction of its peak.");
      prm.add_parameter("Verbose",
                        verbose,
                        "Print the step lines of every run.");
      prm.add_parameter("Output directory",
                        output_directory,
                        "Fields of each run go to <directory>/angle-<a>.");
      prm.leave_subsection();
    }
  };



  // @sect3{The grips' motion}
  //
  // $u = t\, e$ on the moving grip: the load factor $t$ is the grip's
  // displacement.
  template <int dim>
  class GripMotion : public Function<dim>
  {
  public:
    explicit GripMotion(const Tensor<1, dim> &axis)
      : Function<dim>(dim)
      , axis(axis)
    {
    }

    double
    value(const Point<dim> &, const unsigned int component) const override
    {
      return this->get_time() * axis[component];
    }

  private:
    const Tensor<1, dim> axis;
  };



  // @sect3{One run: the plate at one angle}
  template <int dim>
  class RotatedPlate
  {
  public:
    struct Result
    {
      double       peak      = 0.;
      double       work      = 0.;
      double       normal    = 0.;
      unsigned int steps     = 0;
      double       wall_time = 0.;
      bool         failed    = false;
      /// The energy the points' cracks dissipated (per unit thickness).
      double crack_energy = 0.;
      /// The energy the points hold at the end, sum of sigma : eps / 2 times
      /// the volume: what unloading to zero strain would give back along
      /// the cracks' secants (the unfinished cracks of the band hold most
      /// of it). The work less this and crack_energy is what the points
      /// released when they broke apart (see Failed points) and the error
      /// of the energy balance of the time integration.
      double stored_energy = 0.;
      /// The angle (degrees) between the main crack's path and the
      /// ligament's line xi = 0: the least-squares line xi = a + b eta
      /// through the points whose cracks dissipated at least half of G_f.
      double path_angle = 0.;
      /// The grip's displacement and the load P of each accepted step.
      std::vector<std::array<double, 2>> curve;
    };

    RotatedPlate(const Parameters &plate,
                 ParameterHandler &prm,
                 const double      angle_deg);

    Result
    run();

  private:
    /// The position in the plate's frame: (xi along e, eta across).
    std::array<double, 2>
    plate_frame(const Point<dim> &x) const
    {
      const Tensor<1, dim> r = x - centre;
      return {{r * axis, r * across}};
    }

    /// The grid position of plate coordinates (xi, eta).
    Point<dim>
    at(const double xi, const double eta) const
    {
      return centre + xi * axis + eta * across;
    }

    bool
    inside(const Point<dim> &x) const;

    void
    make_grid();

    void
    setup_loads();

    /**
     * From the points' cracks: Result::normal, the mean crack normal's
     * angle to x (degrees), weighted by the energy each crack dissipated;
     * Result::crack_energy and Result::path_angle.
     */
    void
    measure_cracks(Result &result) const;

    /// The cracks for a picture: each point's position in the plate's
    /// frame (xi, eta), the energy its cracks dissipated over G_f (0 to
    /// 1 per crack), and that energy in the point's volume over G_f (a
    /// length: sum_k D_k / L_k Omega_p / G_f, per unit thickness; summed
    /// over the points, the crack_energy of Result over G_f), gathered on
    /// rank 0 into @p file.
    void
    write_cracks(const std::string &file) const;

    const Parameters       &plate;
    const double            theta;
    const double            h;
    Tensor<1, dim>          axis, across;
    Point<dim>              centre;
    QuasiStaticProblem<dim> problem;
  };



  template <int dim>
  RotatedPlate<dim>::RotatedPlate(const Parameters &plate,
                                  ParameterHandler &prm,
                                  const double      angle_deg)
    : plate(plate)
    , theta(angle_deg * M_PI / 180.)
    , h(plate.width / plate.cells_across)
    , problem(MPI_COMM_WORLD)
  {
    axis[0]   = std::cos(theta);
    axis[1]   = std::sin(theta);
    across[0] = -std::sin(theta);
    across[1] = std::cos(theta);
    problem.return_large_blocks_to_system();
    problem.parameters().parse_parameters(prm);
    problem.pcout().set_condition(
      plate.verbose && Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
    std::ostringstream directory;
    directory << plate.output_directory << "/angle-" << angle_deg;
    problem.parameters().output.directory = directory.str();

    make_grid();
    // The gauge across the notch's mouth: the points a cell beside the
    // notch, half a cell below the edge.
    const double       mouth = 0.5 * plate.width - 0.25 * h;
    const double       side  = 1.25 * h + 0.5 * h;
    std::ostringstream gauge;
    gauge << std::setprecision(12);
    const Point<dim> a = at(-side, mouth), b = at(side, mouth);
    gauge << a[0] << "," << a[1] << "; " << b[0] << "," << b[1];
    problem.parameters().load_stepping.opening_gauge = gauge.str();

    // The crack band is one cell wide: its width is the cell size.
    prm.enter_subsection("Material");
    prm.enter_subsection(prm.get("Model"));
    prm.set("Crack band width", h);
    prm.leave_subsection();
    prm.leave_subsection();
    auto model = ConstitutiveModelFactory<dim>::create(prm);
    // Cracks may start anywhere in the plate but in the grips and the two
    // cells next to them: the grips hold grid nodes in a staircase across
    // the cells, whose corners concentrate stress as no real grip does.
    if (auto *cracks = dynamic_cast<SmearedCracks<dim> *>(model.get()))
      {
        const double free = 0.5 * plate.length - plate.grip_length - 2. * h;
        cracks->set_crack_region([this, free](const Point<dim> &x) {
          return std::abs(plate_frame(x)[0]) < free;
        });
      }
    problem.set_model(std::move(model));
    setup_loads();
    const auto &mp = problem.parameters().material_points;
    problem.points().fill([this](const Point<dim> &x) { return inside(x); },
                          mp.points_per_direction,
                          mp.placement);
  }



  // The plate minus the notch (a slot of width 2.5 h from the edge eta =
  // W/2, at xi = 0).
  template <int dim>
  bool
  RotatedPlate<dim>::inside(const Point<dim> &x) const
  {
    const auto [xi, eta] = plate_frame(x);
    if (std::abs(xi) > 0.5 * plate.length || std::abs(eta) > 0.5 * plate.width)
      return false;
    return !(std::abs(xi) < 1.25 * h &&
             eta > 0.5 * plate.width - plate.notch_depth);
  }



  // A square grid around the rotated plate with two empty cells of margin.
  template <int dim>
  void
  RotatedPlate<dim>::make_grid()
  {
    const double extent_x = std::abs(plate.length * std::cos(theta)) +
                            std::abs(plate.width * std::sin(theta));
    const double extent_y = std::abs(plate.length * std::sin(theta)) +
                            std::abs(plate.width * std::cos(theta));
    const unsigned int nx =
                         static_cast<unsigned int>(std::ceil(extent_x / h)) + 4,
                       ny =
                         static_cast<unsigned int>(std::ceil(extent_y / h)) + 4;
    centre[0] = 0.5 * nx * h;
    centre[1] = 0.5 * ny * h;
    problem.grid().make_box(Point<dim>(),
                            Point<dim>(nx * h, ny * h),
                            {{nx, ny}});
  }



  template <int dim>
  void
  RotatedPlate<dim>::setup_loads()
  {
    auto        &bcs = problem.boundary_conditions();
    const double end = 0.5 * plate.length - plate.grip_length;
    bcs.add_dirichlet_nodes(
      "fixed_grip",
      [this, end](const Point<dim> &x) { return plate_frame(x)[0] < -end; },
      {{true, true}},
      std::make_shared<Functions::ZeroFunction<dim>>(dim));
    bcs.add_dirichlet_nodes(
      "moving_grip",
      [this, end](const Point<dim> &x) { return plate_frame(x)[0] > end; },
      {{true, true}},
      std::make_shared<GripMotion<dim>>(axis));
  }



  template <int dim>
  typename RotatedPlate<dim>::Result
  RotatedPlate<dim>::run()
  {
    Result result;
    Timer  timer;
    double last_t = 0., last_P = 0.;
    // The load P is the moving grip's force on the body along the axis
    // (positive in tension); the work is
    // int P d delta by the trapezoidal rule over the accepted steps.
    problem.set_step_callback([&](const StepReport &report) {
      const double P = problem.reactions()[1] * axis;
      result.work += 0.5 * (P + last_P) * (report.load_factor - last_t);
      last_t      = report.load_factor;
      last_P      = P;
      result.peak = std::max(result.peak, P);
      result.curve.push_back({{report.load_factor, P}});
      return !(result.peak > 0. && P < plate.stop_fraction * result.peak &&
               report.load_factor > 0.);
    });
    try
      {
        problem.run();
      }
    catch (const std::exception &exc)
      {
        result.failed = true;
        if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          std::cout << "  the run at " << theta * 180. / M_PI
                    << " degrees stopped: " << Utils::error_message(exc)
                    << std::endl;
      }
    timer.stop();
    result.wall_time = timer.wall_time();
    result.steps     = problem.step_reports().size();
    measure_cracks(result);
    write_cracks(problem.parameters().output.directory + "/cracks.csv");
    return result;
  }



  template <int dim>
  void
  RotatedPlate<dim>::write_cracks(const std::string &file) const
  {
    const auto &model =
      dynamic_cast<const SmearedCracks<dim> &>(problem.points().get_model());
    const auto &offsets = problem.points().get_offsets();
    std::array<typename SmearedCracks<dim>::CrackSummary, dim> cracks;
    std::vector<double>                                        local;
    for (const auto &particle : problem.points().get_particle_handler())
      {
        const auto                    data = particle.get_properties();
        const ArrayView<const double> state(data.data() + offsets.state,
                                            model.n_state_components());
        const double D = model.dissipated_over_fracture_energy(state);
        if (D > 0.)
          {
            double             energy = 0.;
            const unsigned int count  = model.crack_summaries(state, cracks);
            for (unsigned int k = 0; k < count; ++k)
              energy += cracks[k].dissipated / cracks[k].length *
                        data[offsets.initial_volume];
            const auto [xi, eta] =
              plate_frame(problem.points().initial_location(particle));
            local.insert(local.end(),
                         {xi, eta, D, energy / model.fracture_energy()});
          }
      }
    const auto all = Utilities::MPI::gather(MPI_COMM_WORLD, local, 0);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    std::filesystem::create_directories(
      std::filesystem::path(file).parent_path());
    std::ofstream out(file);
    AssertThrow(out, ExcMessage("Cannot write <" + file + ">."));
    out << "xi,eta,dissipated_over_Gf,energy_over_Gf_m\n"
        << std::setprecision(6);
    for (const auto &part : all)
      for (unsigned int i = 0; i + 3 < part.size(); i += 4)
        out << part[i] << ',' << part[i + 1] << ',' << part[i + 2] << ','
            << part[i + 3] << '\n';
  }



  // The normals n and -n are the same crack: average the doubled angles
  // (cos 2 phi, sin 2 phi), weighted by the energy dissipated. The path is
  // the least-squares line xi = a + b eta through the points of the main
  // crack.
  template <int dim>
  void
  RotatedPlate<dim>::measure_cracks(Result &result) const
  {
    const auto *cracks_model =
      dynamic_cast<const SmearedCracks<dim> *>(&problem.points().get_model());
    if (cracks_model == nullptr)
      {
        result.normal = std::numeric_limits<double>::quiet_NaN();
        return;
      }
    const auto &model   = *cracks_model;
    const auto &offsets = problem.points().get_offsets();
    std::array<typename SmearedCracks<dim>::CrackSummary, dim> cracks;
    // Sums over the ranks: the energy, cos 2 phi and sin 2 phi weighted by
    // it, n, eta, xi, eta^2, eta xi of the main crack's points, and the
    // stored energy.
    std::array<double, 9> sums{};
    for (const auto &particle : problem.points().get_particle_handler())
      {
        const auto data = particle.get_properties();
        sums[8] += 0.5 *
                   scalar_product(
                     Utils::read_symmetric<dim>(data.data() + offsets.stress),
                     Utils::read_symmetric<dim>(data.data() + offsets.strain)) *
                   data[offsets.initial_volume];
        const ArrayView<const double> state(data.data() + offsets.state,
                                            model.n_state_components());
        const unsigned int count = model.crack_summaries(state, cracks);
        for (unsigned int k = 0; k < count; ++k)
          {
            // The energy the crack dissipated in the point's volume.
            const double energy = cracks[k].dissipated / cracks[k].length *
                                  data[offsets.initial_volume];
            const double phi =
              std::atan2(cracks[k].normal[1], cracks[k].normal[0]);
            sums[0] += energy;
            sums[1] += energy * std::cos(2. * phi);
            sums[2] += energy * std::sin(2. * phi);
          }
        if (model.dissipated_over_fracture_energy(state) >= 0.5)
          {
            const auto [xi, eta] =
              plate_frame(problem.points().initial_location(particle));
            const std::array<double, 5> terms = {
              {1., eta, xi, eta * eta, eta * xi}};
            for (unsigned int i = 0; i < terms.size(); ++i)
              sums[3 + i] += terms[i];
          }
      }
    for (double &sum : sums)
      sum = Utilities::MPI::sum(sum, MPI_COMM_WORLD);
    const auto [energy, c, sn, n, e, x, ee, ex, stored] = sums;
    result.crack_energy                                 = energy;
    result.stored_energy                                = stored;
    result.path_angle =
      std::atan((n * ex - e * x) / (n * ee - e * e)) * 180. / M_PI;
    double angle = 0.5 * std::atan2(sn, c) * 180. / M_PI;
    // In [theta - 90, theta + 90), the frame of the load axis.
    const double theta_deg = theta * 180. / M_PI;
    while (angle < theta_deg - 90.)
      angle += 180.;
    while (angle >= theta_deg + 90.)
      angle -= 180.;
    result.normal = angle;
  }



} // namespace NotchedPlate

#endif
