// Checkpoint and restart with a rigid body in Coulomb contact (issue 30:
// "bodies and contact in checkpoints, resume gives the same curve"). The
// block of contact_rigid_bodies (E = 1000, nu = 0.3, [0,1] x [0.25,0.75]
// on 12 x 8 cells) is pressed by q = 10 onto a half-space floor in 10
// steps, and the floor then slides by 0.002 per step in x for 10 steps
// with mu = 0.3: the points go from stick to slip, and each step's
// tangential traction starts from the last step's (the field
// contact_floor on the points), which is what a resume must restore.
//
//  A: the uninterrupted run.
//  B: the same with a checkpoint every 11 steps, stopped after step 14
//     (as if killed), then resumed from the checkpoint of step 11 (the
//     first sliding step, in which the points stick): its reactions.csv
//     (with the floor's force, floor_Fx and floor_Fy) must be A's, the
//     same rows and the same numbers to 1e-10 of the largest force (the
//     same ranks and the paper's solver settings, so that the steps are
//     bitwise those of A; doc/restart.md).
//  C: negative control, B's checkpoints resumed with the contact
//     tractions set to zero after resume(): the floor's force must differ
//     by more than 1e-4 of the largest (measured 5e-4: the traction's
//     history decides the steps until the points slip, after which the
//     return map puts them at mu p_N again), so that the check above,
//     six orders of magnitude tighter, can fail.
//  D, E: A and B with the floor dragged by a force instead (Load
//     direction = 1, 0; H = 1.5 (t - 1) after the pressing, at most half
//     the friction mu N; its motion along x an unknown of each step,
//     the column floor_u): the resumed run must have the uninterrupted
//     run's forces and the floor's motion, each to 1e-10 of its largest
//     value, which needs the motion so far from the checkpoint.
//  F: negative control, E's checkpoint with the floor's motion so far
//     (the line "bodies 1 u" of its state.txt) set to 0: the floor then
//     starts the resumed step at rest, and its motion must differ by more
//     than 1e-3 of the largest.
//  G, H: contact between deformable bodies with Coulomb friction (the
//     sliding blocks of contact_friction_blocks: block B pressed onto
//     block A and pushed along it, mu = 0.3, 12 steps, B slides from step
//     10): H with a checkpoint every 6 steps, stopped after step 8, resumed
//     from step 6 (two fields on the grid, the points' material ids
//     telling the bodies apart): its forces must be G's to 1e-10.
//  I: negative control, H's checkpoint resumed with B's points given A's
//     material id (one body on one field: the blocks glued): the force
//     must differ by more than 1e-3 of the largest.
#include "prm_text.h"
#include "tests.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <qsmpm/core/quasi_static_problem.h>

using namespace qsmpm;
namespace fs = std::filesystem;

namespace
{
  struct Options
  {
    std::string  directory;
    unsigned int checkpoint_interval = 0;
    unsigned int stop_after          = 0;
    bool         resume              = false;
    bool         forget_tractions    = false;
    bool         force_driven        = false;
    bool         two_bodies          = false;
    bool         forget_bodies       = false;
  };

  // The sliding blocks: A [0, 2] x [0, 0.5] (material id 0) held at its
  // base, B [0.5, 1.5] x [0.5625, 1] (id 1) moved by its top face onto A
  // (steps 1-2), pressed by 0.005 (3-4) and pushed along A by 0.001 per
  // step (5-12).
  std::string
  sliding_blocks()
  {
    return "set Dimension = 2\n"
           "subsection Geometry\n  set Upper corner = 2, 1\n"
           "  set Subdivisions = 16, 8\nend\n"
           "subsection Material points\n"
           "  set Region expression = "
           "if(y < 0.5 || (y > 0.5625 && x > 0.5 && x < 1.5), 1, 0)\n"
           "  set Material id = if(y < 0.5, 0, 1)\nend\n"
           "subsection Contact between bodies\n"
           "  set Bodies = 0; 1\n  set Friction = coulomb\n"
           "  set Friction coefficient = 0.3\nend\n"
           "subsection Material\n  set Model = linear elastic\n"
           "  subsection linear elastic\n"
           "    set Young's modulus = 1000\n"
           "    set Poisson's ratio = 0.3\n  end\nend\n"
           "subsection Boundary conditions\n"
           "  set Dirichlet boundaries = 2:xy, 3:xy\n"
           "  subsection Displacement\n"
           "    set Function constants = g = 0.0625\n"
           "    set Function expression = "
           "if(y > 0.99, if(12 * t <= 4, 0, 0.001 * (12 * t - 4)), 0); "
           "if(y > 0.99, if(12 * t <= 2, -g * 6 * t, "
           "if(12 * t <= 4, -g - 0.0025 * (12 * t - 2), -g - 0.005)), 0)\n"
           "  end\nend\n"
           "subsection Load stepping\n  set Number of steps = 12\nend\n"
           "subsection Nonlinear solver\n  set Tolerance = 1e-10\n"
           "  set Preconditioner reuse steps = 1\n"
           "  set Forcing term = constant\n"
           "  set Initial guess = linear predictor\nend\n";
  }

  void
  run(const Options &options)
  {
    std::ostringstream text;
    if (options.two_bodies)
      text << sliding_blocks();
    else
      text << "set Dimension = 2\n"
           << "subsection Geometry\n  set Lower corner = 0,0\n"
           << "  set Upper corner = 1.5,1\n  set Subdivisions = 12,8\nend\n"
           << "subsection Material points\n"
           << "  set Points per cell per direction = 2\n"
           << "  set Region lower corner = 0,0.25\n"
           << "  set Region upper corner = 1,0.75\nend\n"
           << "subsection Material\n  set Model = linear elastic\n"
           << "  subsection linear elastic\n"
           << "    set Young's modulus = 1000\n"
           << "    set Poisson's ratio = 0.3\n  end\nend\n"
           << "subsection Boundary conditions\n"
           << "  set Dirichlet boundaries = 0:x\n"
           << "  set Surface traction region = y > 0.74\n"
           << "  subsection Surface traction\n"
           << "    set Function expression = 0; -10*min(t, 1)\n  end\n"
           << "  subsection Rigid body\n"
           << "    set Shape = half-space\n    set Name = floor\n"
           << "    set Point = 0, 0.25\n    set Normal = 0, 1\n"
           << "    set Friction = coulomb\n"
           << "    set Friction coefficient = 0.3\n"
           << (options.force_driven ?
                 "    set Load direction = 1, 0\n"
                 "    subsection Load\n"
                 "      set Function expression = 1.5*max(t - 1, 0)\n" :
                 "    subsection Motion\n"
                 "      set Function expression = 0.02*max(t - 1, 0); 0\n")
           << "    end\n  end\nend\n"
           << "subsection Load stepping\n  set Final load factor = 2\n"
           << "  set Number of steps = 20\nend\n"
           << "subsection Nonlinear solver\n"
           << "  set Preconditioner reuse steps = 1\n"
           << "  set Forcing term = constant\n"
           << "  set Initial guess = linear predictor\nend\n";
    text << "subsection Output\n  set Interval = 0\n"
         << "  set Directory = " << options.directory << "\n"
         << "  set Checkpoint interval = " << options.checkpoint_interval
         << "\nend\n";
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    initialize_from_text(problem, text.str());
    if (options.resume)
      problem.resume();
    if (options.forget_tractions)
      {
        const unsigned int traction =
          problem.points().get_layout().offset("contact_floor");
        for (auto &particle : problem.points().get_particle_handler())
          for (unsigned int d = 0; d < 2; ++d)
            particle.get_properties()[traction + d] = 0.;
      }
    if (options.forget_bodies)
      {
        const unsigned int id = problem.points().get_offsets().material_id;
        for (auto &particle : problem.points().get_particle_handler())
          particle.get_properties()[id] = 0.;
      }
    if (options.stop_after > 0)
      problem.set_step_callback(
        [&](const QuasiStaticProblem<2>::StepReport &report) {
          return report.step < options.stop_after;
        });
    problem.run();
  }

  /// Whether the two files have the same steps, and the largest difference
  /// of their columns [first, end) relative to the largest value of
  /// @p reference there (end = 0: to the last column).
  std::pair<bool, double>
  compare(const std::string &reference,
          const std::string &other,
          const unsigned int first = 2,
          const unsigned int end   = 0,
          const unsigned int rows  = 20)
  {
    const auto a = read_csv(reference), b = read_csv(other);
    bool       same    = a.size() == b.size() && a.size() == rows;
    double     largest = 0., difference = 0.;
    const auto last = [&](const std::vector<double> &row) {
      return end == 0 ? row.size() : std::min<std::size_t>(end, row.size());
    };
    for (const auto &row : a)
      for (unsigned int j = first; j < last(row); ++j)
        largest = std::max(largest, std::abs(row[j]));
    for (unsigned int i = 0; i < std::min(a.size(), b.size()); ++i)
      {
        same = same && a[i].size() == b[i].size() && a[i][0] == b[i][0];
        for (unsigned int j = first; j < std::min(last(a[i]), last(b[i])); ++j)
          difference = std::max(difference, std::abs(a[i][j] - b[i][j]));
      }
    return {same, difference / largest};
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  if (root)
    for (const std::string d : {"A", "B", "C", "D", "E", "F", "G", "H", "I"})
      fs::remove_all(d);
  MPI_Barrier(MPI_COMM_WORLD);

  run({"A", 0, 0, false, false});
  run({"B", 11, 14, false, false});
  if (root)
    {
      check_that("interrupted run: 14 rows",
                 read_csv("B/reactions.csv").size() == 14);
      fs::copy("B", "C", fs::copy_options::recursive);
    }
  MPI_Barrier(MPI_COMM_WORLD);
  run({"B", 11, 0, true, false});
  run({"C", 11, 0, true, true});
  run({"D", 0, 0, false, false, true});
  run({"E", 11, 14, false, false, true});
  if (root)
    {
      fs::copy("E", "F", fs::copy_options::recursive);
      // F: the floor's motion so far forgotten.
      const std::string state = "F/checkpoint-00011/state.txt";
      std::ifstream     in(state);
      std::string       text((std::istreambuf_iterator<char>(in)),
                       std::istreambuf_iterator<char>());
      in.close();
      const auto begin = text.find("\nbodies 1 ");
      const auto end   = text.find('\n', begin + 1);
      check_that("force-driven floor: the checkpoint holds its motion",
                 begin != std::string::npos && end != std::string::npos);
      if (begin != std::string::npos && end != std::string::npos)
        text.replace(begin, end - begin, "\nbodies 1 0");
      std::ofstream(state) << text;
    }
  MPI_Barrier(MPI_COMM_WORLD);
  run({"E", 11, 0, true, false, true});
  run({"F", 11, 0, true, false, true});
  run({"G", 0, 0, false, false, false, true});
  run({"H", 6, 8, false, false, false, true});
  if (root)
    {
      check_that("two bodies, interrupted: 8 rows",
                 read_csv("H/reactions.csv").size() == 8);
      fs::copy("H", "I", fs::copy_options::recursive);
    }
  MPI_Barrier(MPI_COMM_WORLD);
  run({"H", 6, 0, true, false, false, true});
  run({"I", 6, 0, true, false, false, true, true});
  if (root)
    {
      const auto header = [](const std::string &file) {
        std::ifstream in(file);
        std::string   line;
        std::getline(in, line);
        return line;
      };
      check_that("reactions.csv has the floor's force (floor_Fx, floor_Fy)",
                 header("A/reactions.csv").find("floor_Fx") !=
                     std::string::npos &&
                   header("A/reactions.csv").find("floor_Fy") !=
                     std::string::npos);
      const auto resumed = compare("A/reactions.csv", "B/reactions.csv");
      std::cout << "resumed: max difference / max force " << resumed.second
                << std::endl;
      check_that("resumed: the 20 steps of the uninterrupted run",
                 resumed.first);
      check("resumed: max |force - uninterrupted| / max |force|",
            resumed.second,
            1e-10);
      const auto forgotten = compare("A/reactions.csv", "C/reactions.csv");
      std::cout << "tractions forgotten: max difference / max force "
                << forgotten.second << std::endl;
      check_at_least("control, tractions set to zero on resume: max "
                     "|difference| / max |force|",
                     forgotten.second,
                     1e-4);
      // The floor driven by a force: its motion is the column before the
      // last (imbalance).
      const unsigned int motion = read_csv("D/reactions.csv")[0].size() - 2;
      check_that("force-driven floor: reactions.csv has floor_u",
                 header("D/reactions.csv").find("floor_u") !=
                   std::string::npos);
      const auto forces =
        compare("D/reactions.csv", "E/reactions.csv", 2, motion);
      check_that("force-driven floor, resumed: the 20 steps", forces.first);
      check("force-driven floor, resumed: max |force - uninterrupted| / max "
            "|force|",
            forces.second,
            1e-10);
      const auto moved =
        compare("D/reactions.csv", "E/reactions.csv", motion, motion + 1);
      std::cout << "force-driven floor resumed: max motion difference / max "
                << moved.second << std::endl;
      check("force-driven floor, resumed: max |u - uninterrupted| / max |u|",
            moved.second,
            1e-10);
      const auto at_rest =
        compare("D/reactions.csv", "F/reactions.csv", motion, motion + 1);
      check_at_least("control, the floor's motion forgotten on resume: max "
                     "|u - uninterrupted| / max |u|",
                     at_rest.second,
                     1e-3);
      const auto bodies =
        compare("G/reactions.csv", "H/reactions.csv", 2, 0, 12);
      check_that("two bodies, resumed: the 12 steps", bodies.first);
      check("two bodies, resumed: max |force - uninterrupted| / max |force|",
            bodies.second,
            1e-10);
      const auto glued =
        compare("G/reactions.csv", "I/reactions.csv", 2, 0, 12);
      std::cout << "bodies forgotten: max difference / max force "
                << glued.second << std::endl;
      check_at_least("control, B's points given A's id on resume: max "
                     "|difference| / max |force|",
                     glued.second,
                     1e-3);
    }
}
