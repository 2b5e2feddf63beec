/* ---------------------------------------------------------------------
 *
 * qsmpm example: footing
 *
 * A smooth rigid strip footing pressed into a weightless elastic-perfectly
 * plastic soil in plane strain: Prandtl's bearing-capacity problem, the
 * standard verification of plasticity in (material-point and finite
 * element) codes for geomechanics. The program runs a study over grids and
 * over the treatment of volumetric locking (F-bar or none), compares the
 * limit pressure with Prandtl's q_u = (2 + pi) c and writes the
 * pressure-settlement curves, a summary and a picture of the plastic zone.
 * With Kinematics = finite strain and GIMP shape functions the same program
 * pushes the footing deep into the soil (footing-large.prm).
 *
 * Usage:
 *   ./footing [footing.prm]
 *   mpirun -np 2 ./footing footing.prm
 *
 * ---------------------------------------------------------------------
 */

// @sect3{Include files}
#include <algorithm>
#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <sstream>
#include <string>
#include <vector>

namespace Footing
{
  using namespace dealii;
  using namespace qsmpm;

  // The footing is a plane-strain or an axisymmetric problem (x = r).
  constexpr int dim = 2;

  // @sect3{The problem and its exact limit load}
  //
  // A rigid strip footing of width $B = 2a$ rests on the surface of a
  // weightless soil of Tresca cohesion $c$ (a von Mises material of yield
  // stress $\sigma_y$ has $c = \sigma_y/\sqrt{3}$ in plane strain). The
  // footing is smooth: it pushes the soil down but does not hold it
  // sideways. Prandtl (1920) found the collapse mechanism (a rigid wedge
  // under the footing, fans of radial shear and passive wedges beside it)
  // and the limit pressure
  // @f[
  //   q_u = (2 + \pi)\, c \approx 5.14\, c,
  // @f]
  // which is exact: the lower and upper bounds of limit analysis coincide.
  // For a Mohr-Coulomb soil with friction angle $\phi$ and associated flow
  // it is $q_u = c N_c$ with $N_c = (N_q - 1)\cot\phi$,
  // $N_q = e^{\pi\tan\phi}\tan^2(\pi/4 + \phi/2)$; the Drucker-Prager model
  // with the plane-strain matching reproduces Mohr-Coulomb in plane strain.
  //
  // The problem is symmetric about the footing's centre line: only the
  // half $x \geq 0$ is modelled, $x = 0$ is a plane of symmetry (rollers).
  // The footing is the set of grid nodes under it, $0 \le x \le a$ on the
  // soil surface, moved down by the settlement $s$ with their horizontal
  // displacement free (smooth) or held (rough, `Footing surface`). The mean
  // pressure is the vertical reaction of these nodes over $a$.
  //
  // With `Material points/Axisymmetric = true` the same grid is the
  // meridian plane (r, z) of a circular footing of radius $a$, $x = r$ and
  // the symmetry line the axis. The reactions are per radian, and the mean
  // pressure is $q = 2\pi F / (\pi a^2) = 2F/a^2$. For a Tresca soil
  // (Mohr-Coulomb with $\phi = 0$) the limit pressure of a circular punch
  // comes from the method of characteristics: $q_u = 5.69\,c$ for the
  // smooth footing (Shield 1955) and $6.05\,c$ for the rough one (Eason
  // and Shield 1960); a von Mises soil has no such solution in axisymmetry
  // (its surface is not Tresca's away from plane strain).
  //
  // Plastic flow of a von Mises material conserves volume. A bilinear cell
  // with 2x2 points has more volume constraints than it can satisfy, and the
  // computed limit pressure comes out too high or not at all ("volumetric
  // locking"). The F-bar treatment replaces each point's volume change by
  // the mean over its cell (Coombs et al. 2018), which removes the
  // excess constraints.

  // @sect3{Parameters}
  //
  // One struct per subsection, entries bound to members (step-68). The
  // library's subsections (material, material points, solver, load
  // stepping) are read by QuasiStaticProblem.
  struct Parameters
  {
    double                    half_width      = 1.;
    double                    width           = 5.;
    double                    depth           = 5.;
    double                    space_above     = 0.;
    double                    settlement      = 0.02;
    std::string               footing_model   = "grid nodes";
    std::string               footing_surface = "smooth";
    double                    penalty_factor  = 100.;
    std::vector<unsigned int> cells           = {8, 16};
    std::vector<std::string>  treatments      = {"F-bar", "none"};
    double                    tolerance       = 0.03;
    double                    umat_cohesion   = 0.;
    bool                      check           = true;
    std::string               directory       = ".";
    bool                      write_points    = false;
    bool                      verbose         = false;

    void
    add_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Footing");
      prm.add_parameter("Footing half-width",
                        half_width,
                        "a = B/2; the model is the half x >= 0.",
                        Patterns::Double(0.));
      prm.add_parameter("Domain width",
                        width,
                        "Width of the modelled half of the soil.",
                        Patterns::Double(0.));
      prm.add_parameter("Domain depth",
                        depth,
                        "Depth of the soil; its surface is at y = depth.",
                        Patterns::Double(0.));
      prm.add_parameter("Space above the surface",
                        space_above,
                        "Height of the grid above the soil surface, into "
                        "which the soil beside the footing may heave.",
                        Patterns::Double(0.));
      prm.add_parameter("Settlement",
                        settlement,
                        "Final settlement of the footing (reached at load "
                        "factor 1; the load stepping's Final load factor "
                        "scales it).",
                        Patterns::Double(0.));
      prm.add_parameter(
        "Footing model",
        footing_model,
        "grid nodes: the footing is the set of grid nodes under it, their "
        "vertical displacement prescribed (horizontally free). rigid body: "
        "a rigid box |x| <= a above the soil surface that the soil points "
        "cannot enter (contact by a penalty, Boundary conditions/Rigid "
        "body in the library), independent of the grid.",
        Patterns::Selection("grid nodes|rigid body"));
      prm.add_parameter("Footing surface",
                        footing_surface,
                        "smooth (frictionless) or rough (no slip). With "
                        "grid nodes, rough holds the footing's nodes "
                        "horizontally as well.",
                        Patterns::Selection("smooth|rough"));
      prm.add_parameter("Footing penalty factor",
                        penalty_factor,
                        "With Footing model = rigid body: gamma of the "
                        "contact penalty (Boundary conditions/Rigid body/"
                        "Penalty factor).",
                        Patterns::Double(0.));
      prm.add_parameter("Cells per half-width",
                        cells,
                        "The grids of the study (cells across a); the last "
                        "one is the one reported in summary.txt.");
      prm.add_parameter("Volumetric locking list",
                        treatments,
                        "The treatments to compare (F-bar, none); the first "
                        "one is the one reported in summary.txt.");
      prm.add_parameter("Tolerance",
                        tolerance,
                        "Relative tolerance of the check of the limit "
                        "pressure against the exact value.",
                        Patterns::Double(0.));
      prm.add_parameter("Check against Prandtl",
                        check,
                        "Whether the limit pressure is checked against "
                        "Prandtl's (a small-deformation result); false for "
                        "deep penetration, where the pressure keeps rising "
                        "with the embedment, and for a non-associated soil "
                        "(Dilatancy angle != Friction angle), for which "
                        "Prandtl's N_c is no limit load.");
      prm.add_parameter("UMAT cohesion",
                        umat_cohesion,
                        "With Material/Model = umat: the cohesion c of the "
                        "von Mises soil the UMAT models (sigma_y / sqrt(3)), "
                        "for Prandtl's (2 + pi) c.",
                        Patterns::Double(0.));
      prm.add_parameter("Output directory", directory);
      prm.add_parameter("Verbose",
                        verbose,
                        "Print every load step (Newton and GMRES counts).");
      prm.add_parameter("Write point fields",
                        write_points,
                        "Write the points' fields (PVTU) of the reported "
                        "run at its end.");
      prm.leave_subsection();
    }
  };



  // @sect3{The reference: Prandtl's limit pressure}
  //
  // The cohesion c and q_u / c of the soil model named in the .prm file.
  struct Reference
  {
    double      cohesion;
    double      bearing_factor;
    std::string description;
  };

  Reference
  prandtl_reference(ParameterHandler  &prm,
                    const std::string &surface,
                    const bool         check)
  {
    Reference reference;
    prm.enter_subsection("Material points");
    const bool axisymmetric = prm.get_bool("Axisymmetric");
    prm.leave_subsection();
    prm.enter_subsection("Material");
    const std::string model = prm.get("Model");
    if (axisymmetric)
      {
        // The circular footing on a Tresca soil: Mohr-Coulomb with phi = 0.
        AssertThrow(model == "Mohr-Coulomb",
                    ExcMessage("Footing: with Material points/Axisymmetric = "
                               "true the soil must be Mohr-Coulomb with "
                               "Friction angle = 0 (Tresca), whose circular "
                               "footing has a known limit pressure."));
        prm.enter_subsection(model);
        reference.cohesion = prm.get_double("Cohesion");
        AssertThrow(prm.get_double("Friction angle") == 0.,
                    ExcMessage("Footing: with Material points/Axisymmetric = "
                               "true, Friction angle must be 0 (Tresca)."));
        prm.leave_subsection();
        prm.leave_subsection();
        const bool rough         = surface == "rough";
        reference.bearing_factor = rough ? 6.05 : 5.69;
        reference.description =
          rough ? "circular, rough: Eason & Shield 1960, 6.05 c" :
                  "circular, smooth: Shield 1955, 5.69 c";
        return reference;
      }
    if (model == "von Mises")
      {
        prm.enter_subsection("von Mises");
        reference.cohesion = prm.get_double("Yield stress") / std::sqrt(3.);
        prm.leave_subsection();
        reference.bearing_factor = 2. + numbers::PI;
        reference.description    = "Prandtl, (2 + pi) c, c = sigma_y/sqrt(3)";
      }
    else if (model == "Drucker-Prager" || model == "Mohr-Coulomb")
      {
        prm.enter_subsection(model);
        reference.cohesion = prm.get_double("Cohesion");
        const double phi =
          prm.get_double("Friction angle") * numbers::PI / 180.;
        // Without the check (Check against Prandtl = false) N_c is only
        // the curve's yardstick, and a non-associated soil may be run.
        AssertThrow(!check ||
                      ((model == "Mohr-Coulomb" ||
                        prm.get("Mohr-Coulomb matching") == "plane strain") &&
                       prm.get_double("Dilatancy angle") ==
                         prm.get_double("Friction angle")),
                    ExcMessage("Footing: Prandtl's N_c holds for associated "
                               "flow (Dilatancy angle = Friction angle) and, "
                               "with Drucker-Prager, the plane-strain "
                               "Mohr-Coulomb matching; set Check against "
                               "Prandtl = false to run another soil."));
        prm.leave_subsection();
        if (phi == 0.)
          reference.bearing_factor = 2. + numbers::PI;
        else
          {
            const double Nq =
              std::exp(numbers::PI * std::tan(phi)) *
              std::pow(std::tan(numbers::PI / 4. + phi / 2.), 2);
            reference.bearing_factor = (Nq - 1.) / std::tan(phi);
          }
        reference.description = "Prandtl, c N_c(phi)";
      }
    else if (model == "umat")
      {
        // A UMAT is a black box: the cohesion of the von Mises (Tresca)
        // soil it models comes from the footing's own entry.
        prm.leave_subsection();
        prm.enter_subsection("Footing");
        reference.cohesion = prm.get_double("UMAT cohesion");
        AssertThrow(reference.cohesion > 0.,
                    ExcMessage("Footing/UMAT cohesion: with Material/Model = "
                               "umat, give the cohesion c of the UMAT's von "
                               "Mises soil (sigma_y / sqrt(3))."));
        reference.bearing_factor = 2. + numbers::PI;
        reference.description    = "Prandtl, (2 + pi) c, c = UMAT cohesion";
      }
    else
      AssertThrow(false,
                  ExcMessage("Footing: the soil model must be <von Mises>, "
                             "<Drucker-Prager>, <Mohr-Coulomb> or <umat>, not "
                             "<" +
                             model + ">."));
    prm.leave_subsection();
    return reference;
  }



  // @sect3{The footing's motion}
  //
  // The displacement (0, -s t) of the footing's nodes; the time of a
  // Function is the load factor t.
  class Settlement : public Function<dim>
  {
  public:
    explicit Settlement(const double settlement)
      : Function<dim>(dim)
      , settlement(settlement)
    {
    }

    double
    value(const Point<dim> &, const unsigned int component) const override
    {
      return component == 1 ? -settlement * this->get_time() : 0.;
    }

  private:
    const double settlement;
  };



  // @sect3{The footing class}
  //
  // One object per run of the study (grid, locking treatment): it builds
  // the problem, follows the pressure under the footing step by step and
  // measures the result, one method per stage, like step-44's Solid.
  class StripFooting
  {
  public:
    StripFooting(const Parameters  &footing,
                 ParameterHandler  &prm,
                 const Reference   &reference,
                 const unsigned int cells,
                 const std::string &treatment);

    struct Result
    {
      unsigned int                           cells;
      std::string                            treatment;
      std::vector<std::pair<double, double>> curve;
      double                                 limit_pressure_over_c;
      double                                 plateau_change;
      double                                 heave;
      unsigned int                           steps;
      unsigned int                           newton_min, newton_max;
      unsigned int                           gmres_min, gmres_max;
      double                                 wall_time;
    };

    Result
    run();

    /// The points' positions and equivalent plastic strain, on rank 0.
    void
    write_plastic_strain(const std::string &file) const;

  private:
    /// Whether the points have GIMP shape functions.
    bool
    gimp()
    {
      return problem.parameters().material_points.formulation.gimp();
    }
    void
    make_grid();
    void
    setup_points();
    void
    setup_boundary_conditions();
    bool
    observe_step(const QuasiStaticProblem<dim>::StepReport &report);
    Result
    summarize() const;

    const Parameters       &footing;
    const Reference         reference;
    const unsigned int      cells;
    const std::string       treatment;
    const double            h;
    QuasiStaticProblem<dim> problem;

    /// The settlement at the start of the current load step: it decides
    /// which grid nodes the footing holds.
    double                                 current_settlement = 0.;
    unsigned int                           footing_condition  = 0;
    std::vector<std::pair<double, double>> curve;
  };



  StripFooting::StripFooting(const Parameters  &footing,
                             ParameterHandler  &prm,
                             const Reference   &reference,
                             const unsigned int cells,
                             const std::string &treatment)
    : footing(footing)
    , reference(reference)
    , cells(cells)
    , treatment(treatment)
    , h(footing.half_width / cells)
    , problem(MPI_COMM_WORLD)
  {
    problem.return_large_blocks_to_system();
    problem.parameters().parse_parameters(prm);
    problem.parameters().material_points.formulation.volumetric =
      parse_volumetric_treatment(treatment);
    // Point fields only of the reported run, at its start and end.
    const bool reported =
      treatment == footing.treatments.front() && cells == footing.cells.back();
    problem.parameters().output.interval =
      (reported && footing.write_points) ? 1000000 : 0;
    problem.parameters().output.directory =
      footing.directory + "/points-" + std::to_string(cells) + "-" + treatment;
    problem.pcout().set_condition(
      footing.verbose && Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
    make_grid();
    // The conditions first: with a rigid footing every point carries its
    // contact traction.
    setup_boundary_conditions();
    problem.set_model(ConstitutiveModelFactory<dim>::create(prm));
    setup_points();
    problem.set_step_callback(
      [this](const QuasiStaticProblem<dim>::StepReport &report) {
        return observe_step(report);
      });
  }



  // @sect4{StripFooting::make_grid}
  //
  // A uniform grid of square cells of size h = a / cells over the soil and
  // the space above it. The domain must be a whole number of cells.
  void
  StripFooting::make_grid()
  {
    const auto n_cells = [&](const double length, const std::string &name) {
      const double n = length / h;
      AssertThrow(std::abs(n - std::round(n)) < 1e-8 * n && n >= 1,
                  ExcMessage("Footing: <" + name +
                             "> must be a whole number of cells of size "
                             "a / (Cells per half-width)."));
      return static_cast<unsigned int>(std::round(n));
    };
    const unsigned int nx = n_cells(footing.width, "Domain width");
    const unsigned int ny =
      n_cells(footing.depth, "Domain depth") +
      (footing.space_above > 0. ?
         n_cells(footing.space_above, "Space above the surface") :
         0);
    // With GIMP the domains of the points at the fixed base may stretch
    // across it (cpGIMP): a row of cells below the soil, whose nodes are
    // held with the base, keeps them whole (a grid that ended there would
    // cut them at its edge and so move their material inside). The same
    // holds at the symmetry line, where the soil under the footing is
    // squeezed sideways and its domains widen across x = 0 (with the rigid
    // footing 50 of them by s = 0.117 a): a column of cells at x < 0, whose
    // nodes are held in x with the symmetry line.
    const unsigned int beside = gimp() ? 1 : 0;
    problem.grid().make_box(Point<dim>(-(beside * h), -(beside * h)),
                            Point<dim>(footing.width, ny * h),
                            {{nx + beside, ny + beside}});
  }



  // @sect4{StripFooting::setup_points}
  //
  // The soil fills the grid up to its surface y = depth.
  void
  StripFooting::setup_points()
  {
    const auto  &mp      = problem.parameters().material_points;
    const double surface = footing.depth;
    problem.points().fill(
      [surface](const Point<dim> &x) {
        return x[0] > 0. && x[1] > 0. && x[1] < surface;
      },
      mp.points_per_direction,
      mp.placement);
  }



  // @sect4{StripFooting::setup_boundary_conditions}
  //
  // Rollers on the symmetry line x = 0 (with GIMP on all nodes x <= 0, see
  // make_grid()) and on the far side x = width, a fixed base, and the
  // footing: the nodes with x <= a at the level of the
  // footing's base, moved down by s t, horizontally free (smooth). At
  // finite strain the footing sinks through the cells of the fixed grid:
  // the nodes it holds are chosen anew in every load step, those at most
  // h/2 below its base at the start of the step and all above.
  void
  StripFooting::setup_boundary_conditions()
  {
    auto      &bcs  = problem.boundary_conditions();
    const auto zero = std::make_shared<Functions::ZeroFunction<dim>>(dim);
    if (gimp())
      bcs.add_dirichlet_nodes(
        "symmetry",
        [this](const Point<dim> &x) { return x[0] <= 1e-10 * h; },
        {{true, false}},
        zero);
    else
      bcs.add_dirichlet_boundary(0, {}, zero, /*normal_only=*/true);
    bcs.add_dirichlet_boundary(1, {}, zero, /*normal_only=*/true);
    if (gimp())
      bcs.add_dirichlet_nodes(
        "base",
        [this](const Point<dim> &x) { return x[1] <= 1e-10 * h; },
        {{true, true}},
        zero);
    else
      bcs.add_dirichlet_boundary(2, {{true, true}}, zero);
    footing_condition = bcs.dirichlet_conditions().size();

    const double a = footing.half_width, surface = footing.depth;
    if (footing.footing_model == "rigid body")
      {
        // A box from the symmetry line's mirror image to x = a, its base
        // on the soil surface, moved down by s t.
        RigidBody<dim> body;
        body.name           = "footing";
        body.shape          = RigidBody<dim>::Shape::box;
        body.point          = Point<dim>(-a, surface);
        body.upper_corner   = Point<dim>(a, surface + a);
        body.motion         = std::make_shared<Settlement>(footing.settlement);
        body.penalty_factor = footing.penalty_factor;
        body.friction       = footing.footing_surface == "rough" ?
                                RigidBody<dim>::Friction::rough :
                                RigidBody<dim>::Friction::frictionless;
        bcs.add_rigid_body(body);
        return;
      }
    bcs.add_dirichlet_nodes(
      "footing",
      [this, a, surface](const Point<dim> &x) {
        return x[0] <= a * (1. + 1e-10) &&
               x[1] >= surface - current_settlement - 0.5 * h;
      },
      {{footing.footing_surface == "rough", true}},
      std::make_shared<Settlement>(footing.settlement));
  }



  // @sect4{StripFooting::observe_step}
  //
  // After every accepted load step: the point of the pressure-settlement
  // curve, and the footing's new level for the next step.
  bool
  StripFooting::observe_step(const QuasiStaticProblem<dim>::StepReport &report)
  {
    current_settlement = footing.settlement * report.load_factor;
    const double force = footing.footing_model == "rigid body" ?
                           problem.rigid_body_loads().front().force[1] :
                           -problem.reactions()[footing_condition][1];
    // Axisymmetric: the force per radian of the circle of radius a.
    const double a = footing.half_width;
    curve.emplace_back(
      current_settlement,
      problem.parameters().material_points.formulation.axisymmetric ?
        2. * force / (a * a) :
        force / a);
    return true;
  }



  // @sect4{StripFooting::run}
  StripFooting::Result
  StripFooting::run()
  {
    Timer timer;
    problem.run();
    timer.stop();
    Result result    = summarize();
    result.wall_time = timer.wall_time();
    return result;
  }



  // @sect4{StripFooting::summarize}
  //
  // The limit pressure is the pressure at the end of the curve; how flat
  // the curve is there is measured by its relative change over the last
  // tenth of the settlement. Heave: the highest point beside the footing
  // above the initial surface.
  StripFooting::Result
  StripFooting::summarize() const
  {
    Result result;
    result.cells     = cells;
    result.treatment = treatment;
    result.curve     = curve;
    AssertThrow(!curve.empty(), ExcMessage("Footing: no load step converged."));
    const double q_end           = curve.back().second;
    result.limit_pressure_over_c = q_end / reference.cohesion;
    double q_before              = curve.front().second;
    for (const auto &[s, q] : curve)
      if (s <= 0.9 * curve.back().first)
        q_before = q;
    result.plateau_change = (q_end - q_before) / q_end;

    double top = -std::numeric_limits<double>::max();
    for (const auto &particle : problem.points().get_particle_handler())
      if (particle.get_location()[0] > footing.half_width)
        top = std::max(top, particle.get_location()[1]);
    result.heave = Utilities::MPI::max(top, MPI_COMM_WORLD) - footing.depth;

    result.steps      = problem.step_reports().size();
    result.newton_min = result.gmres_min = std::numeric_limits<unsigned>::max();
    result.newton_max = result.gmres_max = 0;
    for (const auto &report : problem.step_reports())
      {
        const auto &n     = report.newton;
        result.newton_min = std::min(result.newton_min, n.newton_iterations);
        result.newton_max = std::max(result.newton_max, n.newton_iterations);
        result.gmres_min  = std::min(result.gmres_min, n.linear_iterations);
        result.gmres_max  = std::max(result.gmres_max, n.linear_iterations);
      }
    return result;
  }



  // @sect4{StripFooting::write_plastic_strain}
  //
  // Position and equivalent plastic strain of every point, gathered on
  // rank 0 into a CSV file that gnuplot draws as the plastic zone. With a
  // UMAT it is STATEV(1), the equivalent plastic strain of the von Mises
  // UMAT of footing-umat.prm.
  void
  StripFooting::write_plastic_strain(const std::string &file) const
  {
    const auto        &points = problem.points();
    const auto        &layout = points.get_layout();
    const unsigned int alpha  = layout.offset(
      layout.has("equivalent_plastic_strain") ? "equivalent_plastic_strain" :
                                                "umat_statev");
    std::vector<double> local;
    for (const auto &particle : points.get_particle_handler())
      {
        local.push_back(particle.get_location()[0]);
        local.push_back(particle.get_location()[1]);
        local.push_back(particle.get_properties()[alpha]);
      }
    const auto all = Utilities::MPI::gather(MPI_COMM_WORLD, local, 0);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    std::ofstream out(file);
    AssertThrow(out, ExcMessage("Cannot write <" + file + ">."));
    out << "x,y,equivalent_plastic_strain\n" << std::setprecision(6);
    for (const auto &part : all)
      for (unsigned int i = 0; i + 2 < part.size(); i += 3)
        out << part[i] << ',' << part[i + 1] << ',' << part[i + 2] << '\n';
  }



  // @sect3{The FootingStudy class}
  //
  // The program itself is a class, like step-44's Solid: the constructor
  // reads the parameter file and the reference solution, run() does all
  // runs of the study -- one StripFooting per locking treatment and grid --
  // and writes their results, one method per stage.
  class FootingStudy
  {
  public:
    explicit FootingStudy(const std::string &parameter_file);

    void
    run();

  private:
    Reference
    parse_parameters(const std::string &parameter_file);
    void
    run_all();
    bool
    is_reported(const std::string &treatment, const unsigned int cells) const;
    void
    write_curves() const;
    void
    write_summary() const;
    void
    write_plots() const;

    // The parameter handler keeps the library's subsections, which every
    // StripFooting reads again; the entries of "Footing" are bound to the
    // members of footing (add_parameter()), which parsing the file fills.
    // Both are declared before reference, which parse_parameters() makes.
    ParameterHandler                  prm;
    Parameters                        footing;
    const Reference                   reference;
    const bool                        root;
    ConditionalOStream                pcout;
    std::vector<StripFooting::Result> results;
  };



  // @sect4{FootingStudy::FootingStudy}
  FootingStudy::FootingStudy(const std::string &parameter_file)
    : reference(parse_parameters(parameter_file))
    , root(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    , pcout(std::cout, root)
  {
    if (root)
      std::filesystem::create_directories(footing.directory);
  }



  // @sect4{FootingStudy::parse_parameters}
  //
  // The library's subsections and our "Footing" in one ParameterHandler,
  // so that a misspelt entry in any of them is reported with its name.
  // "Dimension" is declared so that the file may hold it (the footing is
  // always 2D). Returns Prandtl's limit pressure for the soil of the file.
  Reference
  FootingStudy::parse_parameters(const std::string &parameter_file)
  {
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 2), "");
    QuasiStaticProblem<dim>::Parameters::declare_parameters(prm);
    footing.add_parameters(prm);
    prm.parse_input(parameter_file);
    AssertThrow(!footing.cells.empty() && !footing.treatments.empty(),
                ExcMessage("Footing: give at least one grid and one "
                           "treatment."));
    return prandtl_reference(prm, footing.footing_surface, footing.check);
  }



  // @sect4{FootingStudy::run}
  //
  // All runs, a line per run, then on rank 0 the curves in
  // load_displacement.csv, the reported run's limit pressure and its check
  // against the reference in summary.txt, and the pictures.
  void
  FootingStudy::run()
  {
    pcout << "Footing: c = " << reference.cohesion
          << ", exact limit pressure q_u / c = " << std::setprecision(6)
          << reference.bearing_factor << " (" << reference.description << ")"
          << std::endl;
    run_all();
    if (!root)
      return;
    write_curves();
    write_summary();
    write_plots();
  }



  // @sect4{FootingStudy::is_reported}
  //
  // The reported run: the first treatment on the finest grid.
  bool
  FootingStudy::is_reported(const std::string &treatment,
                            const unsigned int cells) const
  {
    return treatment == footing.treatments.front() &&
           cells == footing.cells.back();
  }



  // @sect4{FootingStudy::run_all}
  //
  // Every treatment on every grid, a line per run.
  void
  FootingStudy::run_all()
  {
    for (const auto &treatment : footing.treatments)
      for (const unsigned int cells : footing.cells)
        {
          StripFooting run(footing, prm, reference, cells, treatment);
          results.push_back(run.run());
          const auto &r = results.back();
          pcout << std::setw(6) << treatment << "  a/h " << std::setw(3)
                << cells << "  q/c " << std::fixed << std::setprecision(4)
                << r.limit_pressure_over_c << "  error " << std::showpos
                << std::setprecision(2)
                << 100. *
                     (r.limit_pressure_over_c / reference.bearing_factor - 1.)
                << std::noshowpos
                << " %  last 10% of settlement: " << 100. * r.plateau_change
                << " %  heave/a " << std::setprecision(3)
                << r.heave / footing.half_width << std::defaultfloat
                << "  steps " << r.steps << "  newton " << r.newton_min << "-"
                << r.newton_max << "  gmres/step " << r.gmres_min << "-"
                << r.gmres_max << "  " << std::fixed << std::setprecision(1)
                << r.wall_time << " s" << std::defaultfloat << std::endl;
          if (is_reported(treatment, cells))
            run.write_plastic_strain(footing.directory + "/plastic_strain.csv");
        }
  }



  // @sect4{FootingStudy::write_curves}
  //
  // The pressure-settlement curves of all runs in one CSV file.
  void
  FootingStudy::write_curves() const
  {
    std::ofstream csv(footing.directory + "/load_displacement.csv");
    csv << "treatment,cells_per_half_width,settlement,pressure_over_c\n"
        << std::setprecision(8);
    for (const auto &r : results)
      for (const auto &[s, q] : r.curve)
        csv << r.treatment << ',' << r.cells << ',' << s << ','
            << q / reference.cohesion << '\n';
  }



  // @sect4{FootingStudy::write_summary}
  //
  // The reported run's limit pressure and its check against the reference,
  // in summary.txt and on the screen.
  void
  FootingStudy::write_summary() const
  {
    const auto &reported =
      *std::find_if(results.begin(),
                    results.end(),
                    [&](const StripFooting::Result &r) {
                      return is_reported(r.treatment, r.cells);
                    });
    const double error =
      reported.limit_pressure_over_c / reference.bearing_factor - 1.;
    std::ofstream summary(footing.directory + "/summary.txt");
    summary << std::setprecision(6)
            << "limit_pressure_over_c = " << reported.limit_pressure_over_c
            << "\nexact_over_c = " << reference.bearing_factor
            << "\nrelative_error = " << error
            << "\ntolerance = " << footing.tolerance << "\ncheck = "
            << (!footing.check ? "not applicable (large deformation)" :
                std::abs(error) <= footing.tolerance ? "PASS" :
                                                       "FAIL")
            << "\nreported_run = " << reported.treatment
            << ", cells per half-width " << reported.cells
            << "\nheave_over_half_width = "
            << reported.heave / footing.half_width << '\n';
    for (const auto &r : results)
      summary << "run " << r.treatment << " a/h=" << r.cells
              << ": limit_pressure_over_c = " << r.limit_pressure_over_c
              << ", change over the last 10% of settlement = "
              << r.plateau_change << '\n';
    summary.close();
    std::cout << std::setprecision(6)
              << "limit_pressure_over_c = " << reported.limit_pressure_over_c
              << " (exact " << reference.bearing_factor << ", difference "
              << std::setprecision(3) << 100. * error << " %";
    if (footing.check)
      std::cout << ", "
                << (std::abs(error) <= footing.tolerance ? "within" : "OUTSIDE")
                << " the tolerance " << 100. * footing.tolerance << " %";
    std::cout << ")" << std::endl;
  }



  // @sect4{FootingStudy::write_plots}
  //
  // gnuplot scripts next to the data, and the pictures if gnuplot is
  // installed: the pressure-settlement curves of all runs with the exact
  // limit pressure, and the plastic zone of the reported run.
  void
  FootingStudy::write_plots() const
  {
    const std::string &directory = footing.directory;
    std::ofstream      gp(directory + "/footing.gp");
    gp << "set terminal pngcairo size 800,560 noenhanced\n"
       << "set datafile separator ','\n"
       << "set output '" << directory << "/pressure_settlement.png'\n"
       << "set xlabel 'settlement / a'\nset ylabel 'mean pressure / c'\n"
       << "set key bottom right\nset grid\n"
       << "f = '" << directory << "/load_displacement.csv'\n"
       << "plot ";
    for (unsigned int r = 0; r < results.size(); ++r)
      gp << "f using (strcol(1) eq '" << results[r].treatment
         << "' && $2 == " << results[r].cells << " ? $3/" << footing.half_width
         << " : 1/0):4 w l lw 2 t '" << results[r].treatment
         << ", a/h = " << results[r].cells << "', \\\n     ";
    gp << reference.bearing_factor << " w l lc rgb 'black' dt 2 t '"
       << reference.description << "'\n";
    gp << "set output '" << directory << "/plastic_strain.png'\n"
       << "set size ratio -1\nset xlabel 'x'\nset ylabel 'y'\n"
       << "set cblabel 'equivalent plastic strain'\nunset key\n"
       << "set palette rgbformulae 33,13,10\n"
       << "plot '" << directory
       << "/plastic_strain.csv' every ::1 using 1:2:3 with points pt 5 "
          "ps 0.3 lc palette\n";
    gp.close();
    if (qsmpm::Utils::run_gnuplot(directory + "/footing.gp"))
      std::cout << "wrote " << directory << "/pressure_settlement.png and "
                << directory << "/plastic_strain.png" << std::endl;
    else
      std::cout << "wrote " << directory
                << "/footing.gp (gnuplot not found: no pictures)" << std::endl;
  }
} // namespace Footing



// @sect3{The main function}
int
main(int argc, char *argv[])
{
  // The rank of this process, for the catch blocks below: by the time they
  // run, the MPI_InitFinalize object of the try block is gone, and MPI with
  // it.
  unsigned int rank = 0;
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
      const std::string parameter_file =
        argc > 1 ?
          std::string(argv[1]) :
          (std::filesystem::path(argv[0]).parent_path() / "footing.prm")
            .string();
      AssertThrow(std::filesystem::exists(parameter_file),
                  dealii::ExcMessage("Cannot find the parameter file <" +
                                     parameter_file + ">."));
      Footing::FootingStudy study(parameter_file);
      study.run();
    }
  catch (std::exception &exc)
    {
      // The errors of qsmpm are collective: every rank reads the same
      // parameter file and checks the same values, and a load step that
      // fails, fails on every rank with the same message (the library
      // broadcasts it). So one rank, rank 0, prints it, as one line
      // written at once: lines written piece by piece by several ranks
      // interleave ("footing stopped: footing stopped: ...").
      if (rank == 0)
        std::cerr << "footing stopped: " + qsmpm::Utils::error_message(exc) +
                       "\n"
                  << std::flush;
      return 1;
    }
  catch (...)
    {
      if (rank == 0)
        std::cerr << "footing stopped: unknown exception" << std::endl;
      return 1;
    }
  return 0;
}
