// Checkpoint and restart (Output/Checkpoint interval, QuasiStaticProblem::
// resume()) on the coarse compact-tension specimen of cts_coarse: a
// softening, path-dependent material, so that a resume that lost or mixed
// up the points' history (the crack openings) would give another curve.
//
//  A: the uninterrupted run, 40 steps of 5e-3 mm (through the peak into
//     the softening branch).
//  B: the same with a checkpoint every 5 steps, stopped after step 23 (as
//     if killed); only the newest two checkpoints (steps 15 and 20) are
//     left. A half-written checkpoint.tmp (garbage) is then put next to
//     them, as a crash while writing would leave it. B is resumed on all
//     ranks: it must start from step 20, ignore checkpoint.tmp, and end
//     with A's reactions.csv -- the same rows (none repeated) and the same
//     numbers to 1e-10 of the largest reaction.
//  C: written on one rank (MPI_COMM_SELF), resumed on all ranks; D: a copy
//     of B's checkpoints resumed on one rank. With another number of ranks
//     the partitioned AMG gives other, equally converged, Newton iterates
//     (see cts_coarse), so these agree with A within the solver tolerance:
//     1e-4 of the largest reaction.
//  E: negative control, a copy of B's checkpoints resumed with the crack
//     openings set to zero after resume(): the comparison must see the
//     difference (> 1e-3), i.e. the check above can fail.
//  Finally, a resume without checkpoints and one with a checkpoint of
//  another grid must stop with a message.
//
// The measured differences and the messages of the bad resumes are printed
// to stdout; the output file holds only PASS/FAIL.
#include "prm_text.h"
#include "tests.h"

// The specimen of the example compact_tension (examples/compact_tension/,
// on the include path of the tests).
#include "compact_tension_geometry.h"

#include <filesystem>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/decohesion.h>

using namespace qsmpm;
using CompactTension::CompactTensionGeometry;
namespace fs = std::filesystem;

namespace
{
  const double E = 34.9e9, nu = 0.18, tau_nf = 2.77e6, G_f = 122.7;

  struct Options
  {
    std::string  directory;
    unsigned int checkpoint_interval = 0;
    unsigned int stop_after          = 0;
    bool         resume              = false;
    bool         forget_cracks       = false;
    double       cell_size           = 0.025;
  };

  // Set the specimen up as for a fresh run, resume if asked, and run.
  // Returns the step resumed from.
  unsigned int
  run(const MPI_Comm communicator, const Options &options)
  {
    CompactTensionGeometry<2>::Parameters parameters;
    parameters.ligament             = 0.15;
    parameters.cell_size            = options.cell_size;
    parameters.back_face_refinement = 8;
    const CompactTensionGeometry<2> geometry(parameters);

    QuasiStaticProblem<2> problem(communicator);
    problem.pcout().set_condition(false);
    Tensor<1, 2> x_normal;
    x_normal[0] = 1.;
    geometry.setup(problem,
                   std::make_unique<Decohesion<2>>(
                     E, nu, true, tau_nf, G_f, x_normal, geometry.cell_size()),
                   1,
                   MaterialPointSet<2>::Placement::regular);

    auto &prm                                  = problem.parameters();
    prm.nonlinear_solver.tolerance             = 1e-5;
    prm.nonlinear_solver.linear_tolerance      = 1e-3;
    prm.nonlinear_solver.max_line_search_steps = 4;
    // Bit-identical resumption needs a step that does not depend on what
    // the checkpoint does not hold: the last step's increment
    // (extrapolation) and the age of a reused preconditioner. With the
    // defaults a resumed run agrees to the Newton tolerance (measured:
    // 3.8e-6 of the largest reaction), see doc/restart.md.
    prm.nonlinear_solver.preconditioner_reuse_steps = 1;
    prm.nonlinear_solver.initial_guess =
      NewtonParameters::InitialGuess::linear_predictor;
    prm.nonlinear_solver.forcing        = NewtonParameters::Forcing::constant;
    prm.load_stepping.n_steps           = 40;
    prm.load_stepping.final_load_factor = 2e-4;
    prm.load_stepping.max_cut_backs     = 6;
    prm.output.directory                = options.directory;
    prm.output.interval                 = 0;
    prm.output.checkpoint_interval      = options.checkpoint_interval;

    const unsigned int step = options.resume ? problem.resume() : 0;
    if (options.forget_cracks)
      {
        const unsigned int opening = problem.points().get_layout().offset(
          Decohesion<2>::crack_opening_name);
        for (auto &particle : problem.points().get_particle_handler())
          particle.get_properties()[opening] = 0.;
      }
    if (options.stop_after > 0)
      problem.set_step_callback(
        [&](const QuasiStaticProblem<2>::StepReport &report) {
          return report.step < options.stop_after;
        });
    problem.run();
    return step;
  }

  // Whether the steps of the two files are the same, and the largest
  // difference of load factors and reactions relative to the largest
  // reaction of @p reference.
  std::pair<bool, double>
  compare(const std::string &reference, const std::string &other)
  {
    const auto a = read_csv(reference), b = read_csv(other);
    bool       same_steps = a.size() == b.size() && !a.empty();
    double     largest = 0., difference = 0.;
    for (const auto &row : a)
      for (unsigned int j = 2; j < row.size(); ++j)
        largest = std::max(largest, std::abs(row[j]));
    for (unsigned int i = 0; i < std::min(a.size(), b.size()); ++i)
      {
        same_steps = same_steps && a[i].size() == b[i].size() &&
                     a[i][0] == b[i][0] && a[i][0] == i + 1;
        for (unsigned int j = 1; j < std::min(a[i].size(), b[i].size()); ++j)
          difference =
            std::max(difference,
                     std::abs(a[i][j] - b[i][j]) / (j == 1 ? 2e-4 : largest));
      }
    return {same_steps, difference};
  }

  std::vector<std::string>
  checkpoints(const std::string &directory)
  {
    std::vector<std::string> names;
    for (const auto &entry : fs::directory_iterator(directory))
      if (entry.path().filename().string().rfind("checkpoint", 0) == 0)
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  void
  report(const std::string &what, const std::pair<bool, double> &result)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << what << ": same steps " << result.first
                << ", max difference / max reaction " << result.second
                << std::endl;
  }

  // A resume that must fail: it must stop with a message that contains
  // every phrase of @p expected (the cause and the entry or directory to
  // fix). One PASS/FAIL line per phrase; the message itself only to stdout
  // (its wording and the grid coordinates in it are not compared).
  void
  expect_failure(const std::string              &what,
                 const Options                  &options,
                 const std::vector<std::string> &expected)
  {
    bool        stopped = false;
    std::string message;
    try
      {
        run(MPI_COMM_WORLD, options);
      }
    catch (const std::exception &exc)
      {
        stopped = true;
        message = Utils::error_message(exc);
      }
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << what << ": " << (stopped ? message : "resumed") << std::endl;
    check_that(what + ": stops", stopped);
    for (const auto &phrase : expected)
      check_that(what + ": the message names '" + phrase + "'",
                 stopped && message.find(phrase) != std::string::npos);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  const MPI_Comm                   world = MPI_COMM_WORLD;
  const bool root = Utilities::MPI::this_mpi_process(world) == 0;
  if (root)
    for (const std::string d : {"A", "B", "C", "D", "E", "F"})
      fs::remove_all(d);
  MPI_Barrier(world);

  Options a;
  a.directory = "A";
  run(world, a);

  Options b;
  b.directory           = "B";
  b.checkpoint_interval = 5;
  b.stop_after          = 23;
  run(world, b);
  if (root)
    {
      check_that("interrupted run: reactions.csv has the 23 rows",
                 read_csv("B/reactions.csv").size() == 23);
      const auto kept = checkpoints("B");
      check_that("only the newest two checkpoints are kept "
                 "(checkpoint-00015, checkpoint-00020)",
                 kept == std::vector<std::string>{"checkpoint-00015",
                                                  "checkpoint-00020"});
      // A crash while writing the next checkpoint leaves this behind.
      fs::create_directories("B/checkpoint.tmp");
      std::ofstream("B/checkpoint.tmp/state.txt") << "half written";
      std::ofstream("B/checkpoint.tmp/grid") << "garbage";
      for (const std::string d : {"D", "E"})
        fs::copy("B", d, fs::copy_options::recursive);
    }
  MPI_Barrier(world);

  b.stop_after            = 0;
  b.resume                = true;
  const unsigned int from = run(world, b);
  check_that("resumed from the newest complete checkpoint (step 20)",
             from == 20);
  if (root)
    {
      const auto result = compare("A/reactions.csv", "B/reactions.csv");
      report("B (resumed, same ranks)", result);
      check_that("resumed run: the steps of the uninterrupted run, none "
                 "repeated",
                 result.first);
      check("resumed run: max |reaction - uninterrupted| / max |reaction|",
            result.second,
            1e-10);
      check_that("checkpoint.tmp was ignored and replaced",
                 checkpoints("B") ==
                   std::vector<std::string>{"checkpoint-00030",
                                            "checkpoint-00035"});
    }

  // Another number of ranks: written on one, resumed on all, and the
  // reverse.
  Options c    = b;
  c.directory  = "C";
  c.resume     = false;
  c.stop_after = 23;
  if (root)
    run(MPI_COMM_SELF, c);
  MPI_Barrier(world);
  c.stop_after = 0;
  c.resume     = true;
  run(world, c);
  Options d   = b;
  d.directory = "D";
  if (root)
    {
      run(MPI_COMM_SELF, d);
      const auto written_on_one = compare("A/reactions.csv", "C/reactions.csv");
      const auto resumed_on_one = compare("A/reactions.csv", "D/reactions.csv");
      report("C (1 rank -> all)", written_on_one);
      report("D (all ranks -> 1)", resumed_on_one);
      check_that("checkpoint of 1 rank resumed on all: same steps",
                 written_on_one.first);
      check("checkpoint of 1 rank resumed on all: max difference",
            written_on_one.second,
            1e-4);
      check_that("checkpoint of all ranks resumed on 1: same steps",
                 resumed_on_one.first);
      check("checkpoint of all ranks resumed on 1: max difference",
            resumed_on_one.second,
            1e-4);
    }
  MPI_Barrier(world);

  // The check can fail: without the crack openings the curve differs.
  Options e       = b;
  e.directory     = "E";
  e.forget_cracks = true;
  run(world, e);
  if (root)
    {
      const auto result = compare("A/reactions.csv", "E/reactions.csv");
      report("E (crack openings lost)", result);
      check_at_least("resume without crack openings: max difference",
                     result.second,
                     1e-3);
    }

  // Bad resumes.
  Options f;
  f.directory = "F";
  f.resume    = true;
  expect_failure("resume without checkpoint",
                 f,
                 {"no complete checkpoint", "<F>", "Checkpoint interval"});
  if (root)
    fs::copy("B", "F", fs::copy_options::recursive);
  MPI_Barrier(world);
  f.cell_size = 0.0125;
  expect_failure("resume with a checkpoint of another grid",
                 f,
                 {"checkpoint-00035", "another problem", "grid"});
}
