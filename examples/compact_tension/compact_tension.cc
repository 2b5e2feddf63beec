/* ---------------------------------------------------------------------
 *
 * qsmpm example: compact_tension
 *
 * Failure of a concrete compact-tension specimen (paper Section 3) with the
 * quasi-static material-point method of Sanchez, Schreyer, Sulsky and
 * Wallstedt, "Solving Quasi-Static Equations with the Material-Point
 * Method", and Schreyer's elastic-decohesive smeared-crack model.
 *
 * Usage:
 *   ./compact_tension b15.prm
 *   mpirun -np 2 ./compact_tension b30.prm
 *   ./compact_tension --resume b15.prm   (after a run with checkpoints)
 *   ./compact_tension size_effect.prm    (three sizes, one fracture energy)
 *
 * ---------------------------------------------------------------------
 */

// @sect3{Include files}
//
// Besides QuasiStaticProblem, which owns grid, points, loads and the load-step
// loop, we use two pieces of the library that exist for this problem: the
// decohesion model and a load-deflection curve that integrates the work of
// the load. The specimen geometry with its supports, CompactTensionGeometry,
// is this example's own: it lives next to this file, in
// compact_tension_geometry.h (the tests of the specimen include it from
// there).
#include "compact_tension_geometry.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <qsmpm/base/parameter_file.h>
#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/fracture/load_displacement_curve.h>
#include <qsmpm/io/checkpoint.h>
#include <qsmpm/materials/decohesion.h>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CompactTension
{
  using namespace dealii;
  using namespace qsmpm;

  // @sect3{The problem}
  //
  // A work-of-fracture test: the two appendages of a notched specimen are
  // pulled apart by a testing machine that controls the load-point
  // displacement $\delta$ and measures the force $P$. The area under
  // $P(\delta)$ up to complete failure is the energy needed to break the
  // ligament, $G_f\,b\,d$. Wittmann et al. measured it for specimens with
  // ligaments $b$ = 15, 30 and 60 cm; the paper reproduces their
  // load-deflection curves with the size-dependent $G_f$ they report.
  //
  // The specimen is modelled in 2D (plane stress by default) with one
  // material point per square cell of size $h$ = 1, 2 and 4 cm. Cracks may
  // only form in the column of cells that contains the centre line, with
  // their normal fixed to $x$ (the paper's restrictions; with the `smeared
  // cracks` model and `Cracking region = everywhere` they may form
  // anywhere, at any angle, see "The size effect" below); the notch is the
  // upper part of that column, left empty, so the two appendages share no
  // grid node. Everything about the geometry lives in
  // CompactTensionGeometry (compact_tension_geometry.h), whose
  // documentation also explains the outer dimensions we chose (they are not
  // given in the paper).
  //
  // The load factor $t$ of the library is the load-point displacement in
  // metres; the parameter files advance it by $10^{-3}$ mm per step as in
  // the paper. Rather than run to a fixed end, the program stops once the
  // load has fallen below a fraction (2 %) of its peak, as in the paper's
  // plots. What is left of the curve then is a long tail: the last cells
  // of the ligament fail only at several millimetres, and it holds some
  // 3 % of the energy. To measure the whole work of fracture, `set Run to
  // complete failure = true` runs on until the band has failed (every
  // point but the hinge, see below). Displacement control cannot follow the
  // snap-back near the back face (load steps that grow in the tail,
  // `Load stepping/Increment growth factor`, jump over it, and the tail
  // then depends on the number of MPI ranks); `b15-opening.prm` runs to
  // complete failure by path following on the crack-mouth opening
  // (`Load stepping/Control = opening`) instead.
  //
  // @sect3{Parameters}
  //
  // The library's subsections ("Material", "Material points", "Load
  // stepping", "Nonlinear solver", "Output") are read as by the general
  // driver; the specimen comes from "Compact tension" and the few things
  // this program adds from "Run".
  //
  // Both are parameter structs in the manner of the library's
  // (ParameterStruct, deal.II's step-68): a member's initializer is its
  // default, and add_parameters() declares the entry bound to it with
  // ParameterHandler::add_parameter(), so that each entry's name, default
  // and documentation are written once. The base ParameterStruct adds
  // declare_parameters() (the entries with their defaults) and
  // parse_parameters() (the values of a parsed file into an object).
  struct RunParameters : ParameterStruct<RunParameters>
  {
    double      stop_fraction            = 0.02;
    bool        to_complete_failure      = false;
    bool        end_at_final_load_factor = false;
    double      partial_failure_fraction = 0.5;
    std::string plot_label               = "";

    void
    add_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Run");
      prm.add_parameter("Stop below fraction of peak",
                        stop_fraction,
                        "The run ends after the first step past the peak at "
                        "which the load is below this fraction of the peak "
                        "load.",
                        Patterns::Double(0., 1.));
      prm.add_parameter("Run to complete failure",
                        to_complete_failure,
                        "true: ignore <Stop below fraction of peak> and end "
                        "the run once every crack-band point but the lowest "
                        "one (the hinge, which never breaks) has failed "
                        "completely, [[u_n]] >= u0. The work of the load is "
                        "then the whole work of fracture. The tail takes "
                        "load-point displacements of several mm: use "
                        "<Load stepping/Increment growth factor>.");
      prm.add_parameter("End at final load factor",
                        end_at_final_load_factor,
                        "true: a run that reaches <Load stepping/Final load "
                        "factor> before its end criterion (fraction of the "
                        "peak or complete failure) ends there normally, "
                        "with the energy balance at that load-point "
                        "displacement; false: that is an error (the curve is "
                        "incomplete).");
      prm.add_parameter("Partial failure at fraction of peak",
                        partial_failure_fraction,
                        "The point fields of 'partial failure' are written at "
                        "the first step past the peak at which the load is "
                        "below this fraction of the peak load.",
                        Patterns::Double(0., 1.));
      prm.add_parameter("Label",
                        plot_label,
                        "A name for the run in the summary (e.g. b = 15 cm).");
      prm.leave_subsection();
    }
  };



  // @sect3{The size effect}
  //
  // The paper's question of Section 3.3: Wittmann et al. measured a
  // fracture energy that grows with the size of the specimen (122.7,
  // 160.6 and 163.6 J/m^2 for b = 15, 30 and 60 cm), and the paper fits one
  // to each size. With `Size effect/Ligament lengths` set, the program runs
  // the specimen of the file once per ligament b, with the same material
  // (one $G_f$) and everything else scaled with b as in the paper's three
  // files: the cell size h (15 cells along the ligament for the paper's
  // h/b; or not, `Scale cell size = false`), the final load factor and the
  // number of load steps (the displacement increment per step stays the
  // same). Each run writes its
  // own output directory, `<Output/Directory>-b<b in cm>`, and the table
  // of all sizes goes to `Output file`: the peak load and the apparent
  // fracture energy an experimentalist would measure, the work of the load
  // over the ligament area $W/(b\,d)$, beside the $G_f$ of the model.
  struct SizeEffectParameters : ParameterStruct<SizeEffectParameters>
  {
    std::vector<double> ligaments;
    bool                scale_cell_size = true;
    std::string         output_file     = "size_effect.csv";

    void
    add_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Size effect");
      prm.add_parameter("Ligament lengths",
                        ligaments,
                        "Ligament lengths b (m), one run each, with h, the "
                        "final load factor and the number of steps scaled "
                        "by b over <Compact tension/Ligament length>. Empty: "
                        "one run of the specimen as given.",
                        Patterns::List(Patterns::Double(0.)));
      prm.add_parameter("Scale cell size",
                        scale_cell_size,
                        "true: h scales with b (the paper's three files, the "
                        "same grid in units of b); false: every size keeps "
                        "the cell size of the file (the crack band width a "
                        "property of the material, as in Bazant's crack "
                        "band model), and larger specimens have more cells.");
      prm.add_parameter("Output file",
                        output_file,
                        "The table of the sizes (b_cm, peak_N, "
                        "apparent_Gf_J_per_m2, Gf_J_per_m2), relative to the "
                        "working directory.");
      prm.leave_subsection();
    }
  };



  // @sect3{The CompactTensionTest class}
  //
  // One object per run: it reads the parameters, builds the specimen, follows
  // the load-deflection curve step by step and sums the run up, one method
  // per stage, like step-44's Solid. The sequence is that of every qsmpm
  // program: read the parameters, make the grid, choose the model, fill the
  // body with points, add supports, run. The model comes from the
  // library's factory, but its crack band width is set here to the cell
  // size, and its cracking region (the centre line, or everywhere but the
  // pins) follows this particular grid.
  //
  // What the object keeps between steps -- the curve so far, which of the
  // moments of the paper's Fig. 4 have passed, the log of the steps -- is
  // member data, which the per-step observer observe_step() updates and
  // which goes into checkpoints (save_state(), restore_state()).
  template <int dim>
  class CompactTensionTest
  {
  public:
    /// Reads @p parameter_file; with @p ligament > 0 the specimen is scaled
    /// to that ligament (see SizeEffectParameters).
    CompactTensionTest(const std::string &parameter_file,
                       const bool         resume,
                       const double       ligament = 0.);

    /// All entries of the program's parameter files.
    static void
    declare_parameters(ParameterHandler &prm);

    void
    run();

    /// After run(): the peak load (N), the work of the load (J), G_f and
    /// the ligament area b d.
    double
    peak_force() const;
    double
    work() const;
    double
    fracture_energy() const;
    double
    ligament_area() const;
    /// The output directory and the label of the run.
    const std::string &
    output_directory() const;
    const std::string &
    label() const;

  private:
    typename CompactTensionGeometry<dim>::Parameters
    parse_parameters(const std::string &parameter_file, const double ligament);
    std::unique_ptr<ConstitutiveModel<dim>>
    make_model();
    void
    setup_specimen();
    void
    setup_output();
    std::string
    save_state() const;
    void
    restore_state(const std::string &text);
    bool
    observe_step(const typename QuasiStaticProblem<dim>::StepReport &report);
    bool
    cracks_started() const;
    void
    write_point_csv(const std::string &filename) const;
    void
    write_results() const;
    void
    print_summary(const double wall_time);

    const MPI_Comm communicator;
    const bool     resume;

    ParameterHandler                  prm;
    RunParameters                     run_parameters;
    const CompactTensionGeometry<dim> geometry;
    QuasiStaticProblem<dim>           problem;

    // The material constants the summary refers to, the index of the pulled
    // pin among the displacement conditions, and the output directory.
    double       G_f = 0., tau_nf = 0., u0 = 0.;
    unsigned int right_pin = 0;
    std::string  directory;

    // The state between steps.
    LoadDisplacementCurve curve;
    std::ofstream         steps_log;
    bool initiated = false, partially_failed = false, complete = false;
  };



  // @sect4{CompactTensionTest::CompactTensionTest}
  //
  // The parameters are read first, by parse_parameters() called from the
  // initializer list (prm and run_parameters are declared before geometry,
  // so they exist by then): the specimen is a constant member made from
  // them, and a contradictory geometry stops the program before anything
  // else is built. The step observer and the program's checkpoint state are
  // handed to the library here; QuasiStaticProblem::run() calls them.
  template <int dim>
  CompactTensionTest<dim>::CompactTensionTest(const std::string &parameter_file,
                                              const bool         resume,
                                              const double       ligament)
    : communicator(MPI_COMM_WORLD)
    , resume(resume)
    , geometry(parse_parameters(parameter_file, ligament))
    , problem(communicator)
  {
    problem.return_large_blocks_to_system();
    problem.parameters().parse_parameters(prm);
    problem.set_checkpoint_state([this]() { return save_state(); },
                                 [this](const std::string &text) {
                                   restore_state(text);
                                 });
    problem.set_step_callback(
      [this](const typename QuasiStaticProblem<dim>::StepReport &report) {
        return observe_step(report);
      });
  }



  // @sect4{CompactTensionTest::parse_parameters}
  //
  // The library's subsections, the specimen's "Compact tension" and our
  // "Run" (and "Size effect", which run_program() reads) are declared in one
  // ParameterHandler, so that a misspelt entry in any of them is reported
  // with its name. A run of a size study scales the specimen here, before
  // anything is read from the entries. Returns the specimen's parameters,
  // from which the constructor makes the geometry.
  template <int dim>
  void
  CompactTensionTest<dim>::declare_parameters(ParameterHandler &prm)
  {
    QuasiStaticProblem<dim>::Parameters::declare_parameters(prm);
    CompactTensionGeometry<dim>::Parameters::declare_parameters(prm);
    RunParameters::declare_parameters(prm);
    SizeEffectParameters::declare_parameters(prm);
  }



  template <int dim>
  typename CompactTensionGeometry<dim>::Parameters
  CompactTensionTest<dim>::parse_parameters(const std::string &parameter_file,
                                            const double       ligament)
  {
    declare_parameters(prm);
    prm.parse_input(parameter_file);
    if (ligament > 0.)
      {
        prm.enter_subsection("Size effect");
        const bool scale_h = prm.get_bool("Scale cell size");
        prm.leave_subsection();
        prm.enter_subsection("Compact tension");
        const double factor = ligament / prm.get_double("Ligament length");
        prm.set("Ligament length", ligament);
        if (scale_h)
          prm.set("Cell size", prm.get_double("Cell size") * factor);
        prm.leave_subsection();
        prm.enter_subsection("Load stepping");
        prm.set("Final load factor",
                prm.get_double("Final load factor") * factor);
        prm.set("Number of steps",
                static_cast<long int>(
                  std::ceil(prm.get_integer("Number of steps") * factor)));
        prm.leave_subsection();
        std::ostringstream name;
        name << std::round(1e4 * ligament) / 100.;
        prm.enter_subsection("Output");
        prm.set("Directory", prm.get("Directory") + "-b" + name.str());
        prm.leave_subsection();
        prm.enter_subsection("Run");
        prm.set("Label", "b = " + name.str() + " cm");
        prm.leave_subsection();
      }

    typename CompactTensionGeometry<dim>::Parameters specimen;
    specimen.parse_parameters(prm);
    run_parameters.parse_parameters(prm);
    return specimen;
  }



  // @sect4{CompactTensionTest::make_model}
  //
  // The material: the paper's `decohesion` model, or `smeared cracks`
  // (several cracks per point at any angle, SmearedCracks), made by the
  // library's factory. The smearing length must follow the grid (see the
  // documentation of Decohesion: the crack band is one cell wide whatever
  // the number of points per cell), so we set "Crack band width" to h
  // here instead of asking for it twice in the parameter file. The
  // decohesion model checks the local stability limit L_c < M u0 / tau_nf
  // and stops with a message if h is too large.
  template <int dim>
  std::unique_ptr<ConstitutiveModel<dim>>
  CompactTensionTest<dim>::make_model()
  {
    prm.enter_subsection("Material");
    const std::string name = prm.get("Model");
    AssertThrow(name == "decohesion" || name == "smeared cracks",
                ExcMessage("compact_tension: set Material/Model = "
                           "decohesion or smeared cracks."));
    prm.enter_subsection(name);
    prm.set("Crack band width", geometry.cell_size());
    G_f    = prm.get_double("Fracture energy");
    tau_nf = prm.get_double("Tensile strength");
    u0     = 2. * G_f / tau_nf;
    prm.leave_subsection();
    prm.leave_subsection();
    return ConstitutiveModelFactory<dim>::create(prm);
  }



  // @sect4{CompactTensionTest::setup_specimen}
  //
  // Grid, points in every cell but those of the notch, cracks only in the
  // cells on the centre line as in the paper, and the two pins: all done
  // by CompactTensionGeometry::setup(), which the tests use as well. With
  // `Compact tension/Back-face point refinement` = k > 1 the band cell at
  // the back face gets k times as many points along the ligament: the
  // point about which the broken specimen finally rotates (the hinge,
  // which never breaks) then stands for h/k of the ligament instead of h.
  template <int dim>
  void
  CompactTensionTest<dim>::setup_specimen()
  {
    const auto &mp = problem.parameters().material_points;
    right_pin      = geometry.setup(problem,
                               make_model(),
                               mp.points_per_direction,
                               mp.placement);
  }



  // @sect4{CompactTensionTest::setup_output}
  //
  // The output directory, the heading of the run and the log of the steps.
  // A run with `Output/Checkpoint interval` > 0 can be continued with
  // `--resume` from its newest checkpoint: the library replaces the points
  // just made by those of the checkpoint, and restores what this program
  // keeps between steps (restore_state()) when run() starts.
  template <int dim>
  void
  CompactTensionTest<dim>::setup_output()
  {
    directory = problem.parameters().output.directory;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      std::filesystem::create_directories(directory);

    const unsigned int resumed_step = resume ? problem.resume() : 0;

    problem.pcout() << "Compact tension " << run_parameters.plot_label
                    << ": b = " << geometry.ligament()
                    << " m, d = " << geometry.depth()
                    << " m, W x H = " << geometry.width() << " x "
                    << geometry.height() << " m, h = " << geometry.cell_size()
                    << " m, load points at x = +-" << geometry.load_point_x()
                    << " m\n"
                    << "  tau_nf = " << tau_nf << " Pa, G_f = " << G_f
                    << " J/m^2, u0 = " << u0 << " m" << std::endl;

    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        if (resume && std::filesystem::exists(directory + "/steps.csv"))
          {
            // Rows past the checkpoint were written by the interrupted run
            // and come again.
            Checkpoint<dim>::truncate_csv(directory + "/steps.csv",
                                          resumed_step);
            steps_log.open(directory + "/steps.csv", std::ios::app);
          }
        else
          {
            steps_log.open(directory + "/steps.csv");
            steps_log << "step,displacement_m,force_N,newton_iterations,"
                         "gmres_iterations,line_search_steps,cut_backs,"
                         "wall_time_s\n";
          }
      }
  }



  // @sect4{CompactTensionTest::save_state}
  //
  // Our state between steps, for checkpoints: the curve so far (peak and
  // work follow from it) and which of the moments of Fig. 4 have passed.
  // The library calls this on rank 0 when it writes a checkpoint.
  template <int dim>
  std::string
  CompactTensionTest<dim>::save_state() const
  {
    std::ostringstream state;
    state << std::setprecision(17) << initiated << ' ' << partially_failed
          << ' ' << curve.points().size() << '\n';
    for (const auto &point : curve.points())
      state << point.step << ' ' << point.displacement << ' ' << point.force
            << '\n';
    return state.str();
  }



  // @sect4{CompactTensionTest::restore_state}
  //
  // The inverse, called on all ranks by QuasiStaticProblem::run() after
  // `--resume`.
  template <int dim>
  void
  CompactTensionTest<dim>::restore_state(const std::string &text)
  {
    std::istringstream state(text);
    std::size_t        n = 0;
    state >> initiated >> partially_failed >> n;
    curve = LoadDisplacementCurve();
    for (std::size_t i = 0; i < n; ++i)
      {
        LoadDisplacementCurve::Point point;
        state >> point.step >> point.displacement >> point.force;
        curve.add(point.step, point.displacement, point.force);
      }
    AssertThrow(state,
                ExcMessage("compact_tension: the checkpoint holds no "
                           "load-displacement curve."));
  }



  // @sect4{CompactTensionTest::run}
  template <int dim>
  void
  CompactTensionTest<dim>::run()
  {
    setup_specimen();
    setup_output();

    Timer timer;
    problem.run();
    timer.stop();

    write_results();
    print_summary(timer.wall_time());
  }



  // @sect4{CompactTensionTest::observe_step}
  //
  // After each accepted step the library calls this observer. We record the
  // point of the load-deflection curve, log what the solver did, write the
  // point pictures when one of the three moments of Fig. 4 is reached, and
  // tell the library to stop once the load has fallen far enough. All ranks
  // see the same (summed) reaction force, so they all take the same
  // decision.
  template <int dim>
  bool
  CompactTensionTest<dim>::observe_step(
    const typename QuasiStaticProblem<dim>::StepReport &report)
  {
    const double delta = report.load_factor;
    const double P     = geometry.load(problem.reactions(), right_pin);
    curve.add(report.step, delta, P);
    if (steps_log.is_open())
      steps_log << report.step << ',' << std::setprecision(10) << delta << ','
                << P << ',' << report.newton.newton_iterations << ','
                << report.newton.linear_iterations << ','
                << report.newton.line_search_steps << ',' << report.cut_backs
                << ',' << std::setprecision(4) << report.wall_time << std::endl;

    if (!initiated)
      {
        if (cracks_started())
          {
            initiated = true;
            problem.pcout()
              << "  crack initiation at step " << report.step
              << ", delta = " << delta << " m, P = " << P << " N" << std::endl;
            write_point_csv(directory + "/points_initiation.csv");
          }
      }
    if (!partially_failed &&
        curve.fallen_below(run_parameters.partial_failure_fraction))
      {
        partially_failed = true;
        write_point_csv(directory + "/points_partial.csv");
      }
    // The end: below the stop fraction of the peak, or, if asked for,
    // complete failure of the band (checked only once the load has fallen
    // below half the peak, to save the loop over the points). The band is
    // broken once every band point has failed completely, $[[u_n]] \geq
    // u_0$ -- all but the lowest one: after the crack has run through the
    // ligament, the two halves rotate about that point, which then has no
    // strain and never breaks (see CompactTensionGeometry::setup(), "The
    // hinge at the back face").
    bool done = false;
    if (run_parameters.to_complete_failure)
      {
        if (curve.fallen_below(0.5))
          {
            const auto band =
              geometry.count_failed_band_points(problem, communicator);
            done = band.first > 0 && band.second == band.first;
          }
      }
    else
      done = curve.fallen_below(run_parameters.stop_fraction);
    if (done)
      {
        complete = true;
        write_point_csv(directory + "/points_complete.csv");
        return false;
      }
    return true;
  }



  // @sect4{CompactTensionTest::cracks_started}
  //
  // Whether any point has a crack: an opening with `decohesion`, a crack
  // with `smeared cracks`.
  template <int dim>
  bool
  CompactTensionTest<dim>::cracks_started() const
  {
    const auto &layout     = problem.points().get_layout();
    const bool  decohesion = layout.has(Decohesion<dim>::crack_opening_name);
    const unsigned int offset =
      decohesion ? layout.offset(Decohesion<dim>::crack_opening_name) :
                   layout.offset(SmearedCracks<dim>::count_name);
    double largest = 0.;
    for (const auto &particle : problem.points().get_particle_handler())
      largest = std::max(largest, particle.get_properties()[offset]);
    return Utilities::MPI::max(largest, communicator) > 0.;
  }



  // @sect4{CompactTensionTest::write_point_csv}
  //
  // The PVTU output holds every point field, including those the model
  // computes as output fields from the committed state (not stored on the
  // points): with `decohesion` the normalized crack opening $[[u_n]]/u_0$
  // and stresses $\sigma_{xx}/\tau_{nf}$, $\sigma_{yy}/\tau_{nf}$; with
  // `smeared cracks` the number of cracks, the largest separation over
  // $\delta_0$ and the first crack's angle. For pictures without ParaView
  // we also write these fields of all points, after their position, into a
  // small CSV file at the three moments of the paper's Fig. 4. Each rank
  // sends its points to rank 0, which writes the file.
  template <int dim>
  void
  CompactTensionTest<dim>::write_point_csv(const std::string &filename) const
  {
    const auto               &points        = problem.points();
    const PropertyLayout      output_layout = points.output_layout();
    std::vector<unsigned int> columns;
    std::string               header = "x,y";
    for (const auto &field : points.get_model().output_fields())
      for (unsigned int c = 0; c < field.n_components; ++c)
        {
          columns.push_back(output_layout.offset(field.name) + c);
          header += ',' + field.name;
        }
    // With smeared cracks also the energy the point's cracks dissipated
    // per unit crack area, over G_f: the dissipation map.
    const auto *cracks_model =
      dynamic_cast<const SmearedCracks<dim> *>(&points.get_model());
    if (cracks_model != nullptr)
      header += ",dissipated_over_Gf";
    const unsigned int n_columns =
      2 + columns.size() + (cracks_model != nullptr ? 1 : 0);
    const auto &offsets = points.get_offsets();
    std::array<typename SmearedCracks<dim>::CrackSummary, dim> cracks;
    std::vector<double> local, values(output_layout.size());
    for (const auto &particle : points.get_particle_handler())
      {
        points.compute_output_fields(particle, ArrayView<double>(values));
        const auto x = particle.get_location();
        local.insert(local.end(), {x[0], x[1]});
        for (const unsigned int c : columns)
          local.push_back(values[c]);
        if (cracks_model != nullptr)
          {
            const auto         data  = particle.get_properties();
            const unsigned int count = cracks_model->crack_summaries(
              {data.data() + offsets.state, cracks_model->n_state_components()},
              cracks);
            double D = 0.;
            for (unsigned int k = 0; k < count; ++k)
              D += cracks[k].dissipated / G_f;
            local.push_back(D);
          }
      }
    const auto all = Utilities::MPI::gather(communicator, local, 0);
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    std::ofstream file(filename);
    file << header << '\n' << std::setprecision(6);
    for (const auto &rank : all)
      for (unsigned int i = 0; i < rank.size(); i += n_columns)
        for (unsigned int c = 0; c < n_columns; ++c)
          file << rank[i + c] << (c + 1 < n_columns ? ',' : '\n');
  }



  // @sect4{CompactTensionTest::write_results}
  //
  // The run must have reached the end of the curve: if the load never fell
  // below the stop fraction, the load stepping ended first, and the
  // energy balance of the summary would be meaningless -- unless the user
  // asked for a curve up to the final load factor (<Run/End at final load
  // factor>, e.g. a path-following run up to a chosen displacement). The
  // point fields of the last step are written all the same, to see how far
  // it got.
  template <int dim>
  void
  CompactTensionTest<dim>::write_results() const
  {
    if (!complete)
      write_point_csv(directory + "/points_final.csv");
    AssertThrow(complete || run_parameters.end_at_final_load_factor,
                ExcMessage(
                  "compact_tension: " +
                  (run_parameters.to_complete_failure ?
                     std::string("the crack band did not fail completely") :
                     "the load did not fall below " +
                       std::to_string(run_parameters.stop_fraction) +
                       " of its peak") +
                  " before the final load factor; raise 'Load "
                  "stepping/Final load factor' and the number of steps (or "
                  "let the increment grow)."));
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      curve.write_csv(directory + "/load_displacement.csv");
  }



  // @sect4{CompactTensionTest::print_summary}
  //
  // We compare the work of the load with the fracture energy of the
  // ligament and print what the solver needed per step (the paper reports
  // 1 to 6 Newton iterations per step).
  template <int dim>
  void
  CompactTensionTest<dim>::print_summary(const double wall_time)
  {
    unsigned int newton_min = 1000, newton_max = 0, newton_sum = 0,
                 gmres_sum = 0, gmres_max = 0, line_search = 0, cut_backs = 0;
    for (const auto &step : problem.step_reports())
      {
        newton_min = std::min(newton_min, step.newton.newton_iterations);
        newton_max = std::max(newton_max, step.newton.newton_iterations);
        newton_sum += step.newton.newton_iterations;
        gmres_sum += step.newton.linear_iterations;
        gmres_max = std::max(gmres_max, step.newton.linear_iterations);
        line_search += step.newton.line_search_steps;
        cut_backs += step.cut_backs;
      }
    const unsigned int n_steps = problem.step_reports().size();
    const double       energy  = G_f * geometry.ligament() * geometry.depth();
    const auto band = geometry.count_failed_band_points(problem, communicator);
    // With smeared cracks, where the energy went: the main crack, the
    // cracks beside it, and the rest of the work of the load (the elastic
    // energy still stored at the end and that released by failed points).
    const auto [main, beside] =
      geometry.crack_dissipation(problem, communicator);
    std::ostringstream dissipation;
    dissipation << std::setprecision(5);
    if (main + beside > 0.)
      dissipation << "  dissipated by cracks: main crack (centre line) = "
                  << main << " J, beside it = " << beside
                  << " J, rest of the work = " << curve.work() - main - beside
                  << " J\n";
    problem.pcout()
      << std::setprecision(5) << '\n'
      << "Compact tension " << run_parameters.plot_label << " finished\n"
      << "  peak load P_max                = " << curve.peak_force()
      << " N at delta = " << curve.peak_displacement() * 1e3 << " mm\n"
      << "  last step                      = " << n_steps
      << ", delta = " << curve.points().back().displacement * 1e3
      << " mm, P = " << curve.points().back().force << " N\n"
      << "  work of the load int P d(delta) = " << curve.work() << " J\n"
      << "  G_f b d                        = " << energy << " J\n"
      << "  energy ratio                   = " << curve.work() / energy << '\n'
      << "  band points failed completely  = " << band.second << " of "
      << band.first << " (the hinge not counted)\n"
      << dissipation.str()
      << "  Newton iterations per step     = " << newton_min << " to "
      << newton_max << ", mean " << static_cast<double>(newton_sum) / n_steps
      << '\n'
      << "  GMRES iterations               = " << gmres_sum << " in all, "
      << static_cast<double>(gmres_sum) / std::max(1u, newton_sum)
      << " per Newton iteration, at most " << gmres_max << " per step\n"
      << "  line-search halvings           = " << line_search << '\n'
      << "  load-step cut-backs            = " << cut_backs << '\n'
      << "  wall time                      = " << wall_time << " s on "
      << Utilities::MPI::n_mpi_processes(communicator) << " rank(s)"
      << std::endl;
  }



  template <int dim>
  double
  CompactTensionTest<dim>::peak_force() const
  {
    return curve.peak_force();
  }



  template <int dim>
  double
  CompactTensionTest<dim>::work() const
  {
    return curve.work();
  }



  template <int dim>
  double
  CompactTensionTest<dim>::fracture_energy() const
  {
    return G_f;
  }



  template <int dim>
  double
  CompactTensionTest<dim>::ligament_area() const
  {
    return geometry.ligament() * geometry.depth();
  }



  template <int dim>
  const std::string &
  CompactTensionTest<dim>::output_directory() const
  {
    return directory;
  }



  template <int dim>
  const std::string &
  CompactTensionTest<dim>::label() const
  {
    return run_parameters.plot_label;
  }



  // @sect3{Pictures of a size study}
  //
  // A gnuplot script next to the table, and the pictures if gnuplot is
  // installed: the load-deflection curves of all sizes (size_effect.png)
  // and the map of the energy the points' cracks dissipated at the end of
  // each run, over G_f (size_effect_cracks.png; with the decohesion model
  // the crack opening over u0).
  void
  write_size_plots(const std::string              &table_file,
                   const std::vector<std::string> &directories,
                   const std::vector<std::string> &labels,
                   const std::vector<double>      &ligaments,
                   const bool                      smeared)
  {
    const std::string stem = table_file.substr(0, table_file.find_last_of('.'));
    std::ofstream     gp(stem + ".gp");
    gp << "set terminal pngcairo size 800,560 noenhanced\n"
       << "set datafile separator ','\n"
       << "set output '" << stem << ".png'\n"
       << "set xlabel 'load-point displacement (mm)'\n"
       << "set ylabel 'load P (kN)'\nset grid\nplot ";
    for (unsigned int i = 0; i < directories.size(); ++i)
      gp << (i > 0 ? ", \\\n     " : "") << "'" << directories[i]
         << "/load_displacement.csv' skip 1 using ($2*1e3):($3*1e-3) w l lw "
            "2 t '"
         << labels[i] << "'";
    const std::string field =
      smeared ? "dissipated_over_Gf" : "opening_over_u0";
    gp << "\nset output '" << stem << "_cracks.png'\n"
       << "set terminal pngcairo size " << 420 * directories.size()
       << ",520 noenhanced\n"
       << "set multiplot layout 1," << directories.size() << "\n"
       << "set size ratio -1\nunset key\nunset grid\nset cbrange [0:1]\n"
       << "set xlabel 'x (m)'\nset ylabel 'y (m)'\n"
       << "set palette rgbformulae 33,13,10\n";
    // Only the points with at least 2 % of the full value: the rest
    // started a crack that unloaded on its initial branch. The other
    // points in grey show the specimen around the ligament (x within b/2
    // of the centre line, y from the back face to just above the notch
    // tip).
    for (unsigned int i = 0; i < directories.size(); ++i)
      gp << "set title '" << labels[i] << ": " << field << "'\n"
         << "set xrange [" << -0.5 * ligaments[i] << ":" << 0.5 * ligaments[i]
         << "]\nset yrange [0:" << 1.1 * ligaments[i] << "]\nset xtics "
         << 0.5 * ligaments[i] << "\nset ytics " << 0.5 * ligaments[i]
         << "\nf = '" << directories[i] << "/points_complete.csv'\n"
         << "plot f using 'x':'y' with points pt 5 ps 0.8 lc rgb '#c0c0c0', "
         << "f using 'x':'y':(column('" << field << "') >= 0.02 ? column('"
         << field << "') : 1/0) with points pt 5 ps 0.9 lc palette\n";
    gp << "unset multiplot\n";
    gp.close();
    if (Utils::run_gnuplot(stem + ".gp"))
      std::cout << "wrote " << stem << ".png and " << stem << "_cracks.png"
                << std::endl;
    else
      std::cout << "wrote " << stem << ".gp (gnuplot not found: no pictures)"
                << std::endl;
  }



  // @sect3{One run, or a size study}
  //
  // With `Size effect/Ligament lengths` empty, one run of the specimen of
  // the file; otherwise one run per ligament and the table of their peaks
  // and apparent fracture energies, written by rank 0.
  void
  run_program(const std::string &parameter_file, const bool resume)
  {
    ParameterHandler prm;
    CompactTensionTest<2>::declare_parameters(prm);
    prm.parse_input(parameter_file);
    SizeEffectParameters sizes;
    sizes.parse_parameters(prm);
    if (sizes.ligaments.empty())
      {
        CompactTensionTest<2> test(parameter_file, resume);
        test.run();
        return;
      }
    AssertThrow(!resume,
                ExcMessage("compact_tension: --resume does not continue a "
                           "size study (Size effect/Ligament lengths)."));

    std::ostringstream table;
    table << "b_cm,peak_N,apparent_Gf_J_per_m2,Gf_J_per_m2\n"
          << std::setprecision(6);
    std::vector<std::string> directories, labels;
    for (const double b : sizes.ligaments)
      {
        CompactTensionTest<2> test(parameter_file, false, b);
        test.run();
        table << 100. * b << ',' << test.peak_force() << ','
              << test.work() / test.ligament_area() << ','
              << test.fracture_energy() << '\n';
        directories.push_back(test.output_directory());
        labels.push_back(test.label());
      }
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::ofstream file(sizes.output_file);
        AssertThrow(file,
                    ExcMessage("Cannot write <" + sizes.output_file + ">."));
        file << table.str();
        std::cout << "\nwrote " << sizes.output_file << ":\n"
                  << table.str() << std::flush;
        prm.enter_subsection("Material");
        write_size_plots(sizes.output_file,
                         directories,
                         labels,
                         sizes.ligaments,
                         prm.get("Model") == "smeared cracks");
        prm.leave_subsection();
      }
  }
} // namespace CompactTension



// @sect3{The main function}
//
// As in the deal.II tutorials: initialize MPI, check the argument, and turn
// every exception (bad parameter, violated stability limit, a step that did
// not converge after the allowed cut-backs) into a message and a non-zero
// exit code.
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
      const bool resume = argc > 2 && std::string(argv[1]) == "--resume";
      AssertThrow(argc > (resume ? 2 : 1),
                  dealii::ExcMessage(
                    "Usage: compact_tension [--resume] file.prm"));
      const std::string parameter_file = argv[resume ? 2 : 1];
      // A missing file, a directory or an unreadable file: one line that
      // names it.
      qsmpm::Utils::check_parameter_file(parameter_file);
      CompactTension::run_program(parameter_file, resume);
    }
  catch (std::exception &exc)
    {
      // The errors of qsmpm are collective: every rank reads the same
      // parameter file and checks the same values, and a load step that
      // fails, fails on every rank with the same message (the library
      // broadcasts it). So one rank, rank 0, prints it, as one line
      // written at once: lines written piece by piece by several ranks
      // interleave ("compact_tension stopped: compact_tension stopped: ...").
      if (rank == 0)
        std::cerr << "compact_tension stopped: " +
                       qsmpm::Utils::error_message(exc) + "\n"
                  << std::flush;
      return 1;
    }
  catch (...)
    {
      if (rank == 0)
        std::cerr << "compact_tension stopped: unknown exception" << std::endl;
      return 1;
    }
  return 0;
}
