// No load goes missing (issue 35): the equilibrium audit of every step.
//
// A cantilever of length 10 and height 1 (E = 1e5, nu = 0.3, Hencky, finite
// strain, 2 x 2 points per cell of h = 0.25) clamped at x = 0, in a grid that
// leaves room below it. Each of the ways in which a run used to lose load
// with exit code 0 must now stop the run with a message that names the
// cause, or lose no load; a sound run must not be stopped, and its clamp
// must carry the applied load.
//
// 0. Sound: self-weight q = 7.5 in 5 steps, linear shape functions. Every
//    step: |applied + clamp| / |applied| below 1e-6 (the Newton tolerance is
//    1e-6 of each step's first residual, a fraction of the load increment),
//    and the clamp carries q L h = 75 to 1e-6 at the end.
// 1. An end traction on the grid face x = 10 (the grid ends with the body):
//    at finite strain the tip moves off that face, the traction acts on
//    nodes without material, and the clamp carried 18.75 of an applied 30 in
//    step 2. Stops: "nodes without material".
// 2. cpGIMP with Minimum nodal volume = 0.01 (the value the docs recommended
//    with cpGIMP): the held nodes carry part of the self-weight. Stops: "held
//    fixed".
// 3. uGIMP in a grid that ends at the tip, x = 10, self-weight 15 t in 10
//    steps (on 2 ranks a point may move at most a cell per step): the
//    tip's point domains reach beyond it as the beam bends, and they are cut
//    at the edge (ShapeCache), so no load is lost: the clamp carries
//    q L h = 150 to 1e-6 at the end, and in every step the lost load is
//    below 1e-4 on this grid and on one that reaches a unit beyond the tip
//    (what Newton's stopping test leaves: up to 4e-5 in a step, its
//    tolerance being relative to the step's first residual, not to the
//    load); the tip deflection is that of the beam in the larger grid to
//    1e-3 (only the weights of the tip's points differ; a loss of 1e-3 of
//    the load would change it by as much; dropping the weights beyond the
//    edge instead loses 9-15 % of the load under 30 t).
// 4. The cantilever of case 0 in other units of force (E and q times 1e-9)
//    with the paper's absolute Residual floor = 1: Newton's test is met
//    with zero displacement. Stops: "Residual floor".
// 5. Units: with the default (relative) stopping test, the same cantilever
//    in units of force scaled by 1e-9 and by 1e+9 has the same tip
//    deflection as in the original units, to 1e-9 relative (the iterates
//    are the same up to round-off).
// 6. Case 1 with Stop on lost load = false: the step that loses load is
//    accepted (the run goes on until the body, which lost its load, no
//    longer makes sense: on 2 ranks a point moves by more than a cell), and
//    the imbalance recorded for it is above the tolerance.
//
// One PASS/FAIL line per check; the messages themselves go to stdout only.
#include "tests.h"

#include <array>
#include <iostream>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <vector>

namespace
{
  /// The cantilever; @p grid_x is the grid's extent in x, @p extra is
  /// appended to the parameter file (later entries win).
  std::string
  cantilever(const std::string &loads,
             const std::string &grid_upper,
             const std::string &subdivisions,
             const std::string &extra = "")
  {
    return "subsection Geometry\n"
           "  set Lower corner = 0,-6\n"
           "  set Upper corner = " +
           grid_upper +
           "\n"
           "  set Subdivisions = " +
           subdivisions +
           "\n"
           "end\n"
           "subsection Material points\n"
           "  set Region lower corner = 0,0\n"
           "  set Region upper corner = 10,1\n"
           "  set Points per cell per direction = 2\n"
           "  set Kinematics = finite strain\n"
           "end\n"
           "subsection Material\n"
           "  set Model = hencky\n"
           "  subsection hencky\n"
           "    set Young's modulus = 1e5\n"
           "    set Poisson's ratio = 0.3\n"
           "  end\n"
           "end\n"
           "subsection Boundary conditions\n"
           "  set Dirichlet boundaries = 0:xy\n" +
           loads +
           "end\n"
           "subsection Load stepping\n"
           "  set Number of steps = 5\n"
           "end\n"
           "subsection Output\n"
           "  set Interval = 0\n"
           "  set Directory = equilibrium-audit-out\n"
           "end\n" +
           extra;
  }

  const std::string self_weight = "  subsection Body force\n"
                                  "    set Function expression = 0; -7.5*t\n"
                                  "  end\n";
  const std::string end_traction =
    "  set Traction boundaries = 1\n"
    "  subsection Traction\n"
    "    set Function expression = 0; (y > -0.01 && y < 1.01) ? -150*t : 0\n"
    "  end\n";

  struct Outcome
  {
    bool        stopped = false;
    std::string message;
    /// Per step: the lost load and the applied load's y component and
    /// the clamp's.
    std::vector<double> imbalance, applied, clamp;
    /// The largest downward displacement of a point.
    double deflection = 0.;

    /// The largest lost load over the steps.
    double
    largest_imbalance() const
    {
      double largest = 0.;
      for (const double value : imbalance)
        largest = std::max(largest, value);
      return largest;
    }
  };

  Outcome
  run(const std::string &what, const std::string &input)
  {
    ParameterHandler prm;
    qsmpm::QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
    Outcome outcome;
    try
      {
        prm.parse_input_from_string(input);
        qsmpm::QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
        problem.pcout().set_condition(false);
        problem.initialize(prm);
        problem.set_step_callback([&](const auto &) {
          const auto &balance = problem.equilibrium();
          outcome.imbalance.push_back(balance.imbalance());
          outcome.applied.push_back(balance.applied[1]);
          outcome.clamp.push_back(balance.reactions[0][1]);
          return true;
        });
        problem.run();
        const unsigned int u = problem.points().get_offsets().displacement;
        for (const auto &particle : problem.points().get_particle_handler())
          outcome.deflection =
            std::max(outcome.deflection, -particle.get_properties()[u + 1]);
        outcome.deflection =
          Utilities::MPI::max(outcome.deflection, MPI_COMM_WORLD);
      }
    catch (const std::exception &exc)
      {
        outcome.stopped = true;
        outcome.message = qsmpm::Utils::error_message(exc);
      }
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << what << ": "
                << (outcome.stopped ? "stopped: " : "ran to the end")
                << outcome.message << std::endl;
    return outcome;
  }

  void
  check_stops(const std::string              &what,
              const Outcome                  &outcome,
              const std::vector<std::string> &phrases)
  {
    qsmpm_tests::check_that(what + ": stops", outcome.stopped);
    for (const auto &phrase : phrases)
      qsmpm_tests::check_that(what + ": the message names '" + phrase + "'",
                              outcome.message.find(phrase) !=
                                std::string::npos);
  }

  /// The parameter file of case 0 with Young's modulus @p E and the body
  /// force @p q: the forces in other units.
  std::string
  in_units(const std::string &input, const std::string &E, const std::string &q)
  {
    std::string result  = input;
    const auto  replace = [&](const std::string &from, const std::string &to) {
      const auto pos = result.find(from);
      AssertThrow(pos != std::string::npos, ExcInternalError());
      result.replace(pos, from.size(), to);
    };
    replace("Young's modulus = 1e5", "Young's modulus = " + E);
    replace("-7.5*t", "-" + q + "*t");
    return result;
  }
} // namespace

int
main(int argc, char *argv[])
{
  using namespace qsmpm_tests;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  deallog << "0. Sound: self-weight, linear shape functions" << std::endl;
  const std::string sound = cantilever(self_weight, "11,2", "44,32");
  const Outcome     ok    = run("sound", sound);
  check_that("  runs to the end", !ok.stopped && ok.imbalance.size() == 5);
  check("  largest |applied + clamp| / |applied| over the steps",
        ok.largest_imbalance(),
        1e-6);
  check("  |clamp - q L h| / (q L h) at the end",
        ok.clamp.empty() ? 1. : std::abs(ok.clamp.back() - 75.) / 75.,
        1e-6);

  deallog << "1. End traction on the grid face the tip leaves" << std::endl;
  {
    const Outcome traction =
      run("traction", cantilever(end_traction, "10,2", "40,32"));
    check_stops("  traction",
                traction,
                {"nodes without material", "Stop on lost load"});
    // Utils::error_message() cuts a message of more than 600 characters
    // in its middle. The message ends with the note on the last converged
    // state; a run that writes fields names its output directory there
    // instead of "Output/Interval = 0 writes no fields": room for a name of
    // 80 characters.
    qsmpm_tests::check_that("  traction: the message is at most 520 "
                            "characters long",
                            traction.message.size() <= 520);
  }

  deallog << "2. cpGIMP with Minimum nodal volume = 0.01" << std::endl;
  check_stops("  held nodes",
              run("held nodes",
                  cantilever(self_weight,
                             "11,2",
                             "44,32",
                             "subsection Material points\n"
                             "  set Shape functions = cpGIMP\n"
                             "  set Minimum nodal volume = 0.01\n"
                             "end\n"
                             "subsection Boundary conditions\n"
                             "  subsection Body force\n"
                             "    set Function expression = 0; -30*t\n"
                             "  end\n"
                             "end\n")),
              {"held fixed", "Minimum nodal volume"});

  deallog << "3. uGIMP in a grid that ends at the tip" << std::endl;
  {
    const std::string longer = "subsection Material points\n"
                               "  set Shape functions = uGIMP\n"
                               "end\n"
                               "subsection Boundary conditions\n"
                               "  subsection Body force\n"
                               "    set Function expression = 0; -15*t\n"
                               "  end\n"
                               "end\n"
                               "subsection Load stepping\n"
                               "  set Number of steps = 10\n"
                               "end\n";
    const Outcome     edge =
      run("grid edge", cantilever(self_weight, "10,2", "40,32", longer));
    const Outcome room = run("grid beyond the tip",
                             cantilever(self_weight, "11,2", "44,32", longer));
    check_that("  grid edge: runs to the end",
               !edge.stopped && edge.imbalance.size() == 10);
    check("  grid edge: largest |applied + clamp| / |applied| over the steps",
          edge.largest_imbalance(),
          1e-4);
    check("  grid edge: |clamp - q L h| / (q L h) at the end",
          edge.clamp.empty() ? 1. : std::abs(edge.clamp.back() - 150.) / 150.,
          1e-6);
    check_that("  grid beyond the tip: runs to the end", !room.stopped);
    check("  grid beyond the tip: largest |applied + clamp| / |applied|",
          room.largest_imbalance(),
          1e-4);
    check("  |deflection, grid edge / deflection, grid beyond the tip - 1|",
          room.deflection > 0. ?
            std::abs(edge.deflection / room.deflection - 1.) :
            1.,
          1e-3);
  }

  deallog << "4. Forces in units 1e-9 with Residual floor = 1" << std::endl;
  check_stops("  floor",
              run("floor",
                  in_units(sound, "1e-4", "7.5e-9") +
                    "subsection Nonlinear solver\n"
                    "  set Residual floor = 1\n"
                    "end\n"),
              {"Residual floor"});

  deallog << "5. Units of force scaled, default stopping test" << std::endl;
  check_at_least("  tip deflection in the original units (positive)",
                 ok.deflection,
                 0.1);
  for (const auto &[factor, E, q] :
       std::vector<std::array<std::string, 3>>{{"1e-9", "1e-4", "7.5e-9"},
                                               {"1e+9", "1e14", "7.5e9"}})
    {
      const Outcome other = run("units " + factor, in_units(sound, E, q));
      check_that("  units x " + factor + ": runs to the end", !other.stopped);
      check("  units x " + factor + ": |deflection / original - 1|",
            std::abs(other.deflection / ok.deflection - 1.),
            1e-9);
    }

  deallog << "6. Case 1 with Stop on lost load = false" << std::endl;
  const Outcome warned = run("warned",
                             cantilever(end_traction,
                                        "10,2",
                                        "40,32",
                                        "subsection Equilibrium check\n"
                                        "  set Stop on lost load = false\n"
                                        "end\n"));
  check_that("  does not stop for the lost load",
             warned.message.find("Stop on lost load") == std::string::npos);
  check_at_least("  largest imbalance recorded",
                 warned.largest_imbalance(),
                 0.01);
}
