// Rigid bodies driven by a force (RigidBody::load_direction, the .prm's
// <Load direction> and <Load>): their motion along the load is an unknown
// of each step, condensed out of the residual by RigidContact.
//
// 1. The rigid plate of contact_rigid_bodies compacting an elastic column
//    (1 x 1 on rollers, E = 1000, nu = 0.3, plane strain, cpGIMP, 2 x 2
//    points per cell), now pressed by a force q0 t per unit width, q0 =
//    0.01 M, instead of a motion. Exact (uniaxial strain): sigma_yy = -q0
//    at every point and the plate's motion q0 H / M = 0.01. Checks: the
//    material's force on the plate balances its load (to 1e-9: the root
//    of the plate's equation is found to round-off); every point's stress
//    within 1 % of q0 (as the test with the motion prescribed); the base
//    carries q0 (1e-6, global equilibrium); the plate's motion within
//    0.5 % of q0 H / M (the penalty lets the plate sink into the column by
//    about M h / (gamma kbar H) of its motion, below 0.2 % in
//    contact_rigid_bodies). The direct solver with the plate's rank-one
//    correction (RigidContact::precondition()) is the inverse of the
//    Jacobian of the condensed problem but for changes of the contact
//    set: at most 2 GMRES iterations per Newton iteration (measured 1.6;
//    3.25 without the correction, which sees the plate held in place).
// 2. The block of contact_rigid_bodies on a Coulomb floor (mu = 0.3),
//    pressed by q = 10 on its top (normal force N = 10) and held by the
//    grid's left boundary, while a force H drags the floor along x.
//    With H = 0.5 mu N the floor carries H (1e-9) and moves along H (by
//    more than 1e-3 of a cell: the block's shear and stretch, about
//    H L / (E t) = 3e-3 = 0.024 h; near the held left end the block
//    slips). The same problem with the floor's motion prescribed, through
//    the motions the force found at each step, must give the same forces
//    at every step (to 1e-6 of mu N: two Newton solutions to 1e-10); this
//    ties the condensed body to the motion-driven contact, which
//    contact_rigid_bodies checks against Coulomb's law. With H = 1.2 mu N
//    no motion balances the force (friction gives at most mu N): the run
//    must stop with a message naming the floor, not run on with a load it
//    does not carry.
//
// Output from rank 0; the results do not depend on the number of ranks.
#include "prm_text.h"
#include "tests.h"

#include <cmath>
#include <functional>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>

using namespace qsmpm;

namespace
{
  const double E = 1000., nu = 0.3;
  const double M  = E * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
  const double q0 = 0.01 * M;

  std::string
  plate_prm()
  {
    std::ostringstream prm;
    prm << std::setprecision(17) << "set Dimension = 2\n"
        << "subsection Geometry\n  set Lower corner = 0,0\n"
        << "  set Upper corner = 1,1.25\n  set Subdivisions = 8,10\nend\n"
        << "subsection Material points\n"
        << "  set Points per cell per direction = 2\n"
        << "  set Region lower corner = 0,0\n"
        << "  set Region upper corner = 1,1\n"
        << "  set Shape functions = cpGIMP\nend\n"
        << "subsection Material\n  set Model = linear elastic\n"
        << "  subsection linear elastic\n"
        << "    set Young's modulus = " << E << "\n"
        << "    set Poisson's ratio = " << nu << "\n  end\nend\n"
        << "subsection Boundary conditions\n"
        << "  set Dirichlet boundaries = 0:x, 1:x, 2:y\n"
        << "  subsection Rigid body\n"
        << "    set Shape = half-space\n    set Name = plate\n"
        << "    set Point = 0, 1\n    set Normal = 0, -1\n"
        << "    set Load direction = 0, -1\n"
        << "    subsection Load\n"
        << "      set Function expression = " << q0 << "*t\n"
        << "    end\n  end\nend\n"
        << "subsection Load stepping\n  set Number of steps = 4\nend\n"
        << "subsection Nonlinear solver\n  set Tolerance = 1e-10\nend\n"
        << "subsection Output\n  set Interval = 0\n"
        << "  set Directory = contact-out\nend\n";
    return prm.str();
  }

  std::string
  // The floor dragged by the force H max(t - 1, 0) along x, or, if
  // @p motion is not empty, moved by the motion with that x expression.
  floor_prm(const double H, const std::string &motion = "")
  {
    std::ostringstream prm;
    prm << "set Dimension = 2\n"
        << "subsection Geometry\n  set Lower corner = 0,0\n"
        << "  set Upper corner = 1.5,1\n  set Subdivisions = 12,8\nend\n"
        << "subsection Material points\n"
        << "  set Points per cell per direction = 2\n"
        << "  set Region lower corner = 0,0.25\n"
        << "  set Region upper corner = 1,0.75\nend\n"
        << "subsection Material\n  set Model = linear elastic\n"
        << "  subsection linear elastic\n"
        << "    set Young's modulus = " << E << "\n"
        << "    set Poisson's ratio = " << nu << "\n  end\nend\n"
        << "subsection Boundary conditions\n"
        << "  set Dirichlet boundaries = 0:x\n"
        << "  set Surface traction region = y > 0.74\n"
        << "  subsection Surface traction\n"
        << "    set Function expression = 0; -10*min(t, 1)\n  end\n"
        << "  subsection Rigid body\n"
        << "    set Shape = half-space\n    set Name = floor\n"
        << "    set Point = 0, 0.25\n    set Normal = 0, 1\n"
        << "    set Friction = "
        << "coulomb\n"
        << "    set Friction coefficient = 0.3\n"
        << std::setprecision(17);
    if (motion.empty())
      prm << "    set Load direction = 1, 0\n"
          << "    subsection Load\n"
          << "      set Function expression = " << H << "*max(t - 1, 0)\n";
    else
      prm << "    subsection Motion\n"
          << "      set Function expression = " << motion << "; 0\n";
    prm << "    end\n  end\nend\n"
        << "subsection Nonlinear solver\n  set Tolerance = 1e-10\nend\n"
        << "subsection Load stepping\n  set Final load factor = 2\n"
        << "  set Number of steps = 4\nend\n"
        << "subsection Output\n  set Interval = 0\n"
        << "  set Directory = contact-out\nend\n";
    return prm.str();
  }

  struct Run
  {
    bool                      completed = false;
    std::string               message;
    Tensor<1, 2>              force;
    double                    motion = 0.;
    std::vector<Tensor<1, 2>> reactions;
    /// Per step: the load factor, the body's force and its motion along
    /// the load.
    std::vector<double>       steps;
    std::vector<Tensor<1, 2>> forces;
    std::vector<double>       motions;
    unsigned int              newton_iterations = 0;
    unsigned int              linear_iterations = 0;
  };

  Run
  run(const std::string                                  &text,
      const std::function<void(QuasiStaticProblem<2> &)> &inspect = {})
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    initialize_from_text(problem, text);
    Run result;
    problem.set_step_callback([&](const StepReport &report) {
      result.steps.push_back(report.load_factor);
      result.forces.push_back(problem.rigid_body_loads().at(0).force);
      result.motions.push_back(problem.rigid_body_load_displacements().at(0));
      result.newton_iterations += report.newton.newton_iterations;
      result.linear_iterations += report.newton.linear_iterations;
      return true;
    });
    try
      {
        problem.run();
        result.completed = true;
        result.force     = problem.rigid_body_loads().at(0).force;
        result.motion    = problem.rigid_body_load_displacements().at(0);
        result.reactions = problem.reactions();
        if (inspect)
          inspect(problem);
      }
    catch (const std::exception &exc)
      {
        result.message = qsmpm::Utils::error_message(exc);
      }
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::MPILogInitAll       log;

  deallog << "1. A plate pressed onto an elastic column by a force"
          << std::endl;
  double    stress_error = 1.;
  const Run plate = run(plate_prm(), [&](QuasiStaticProblem<2> &problem) {
    const auto &offsets = problem.points().get_offsets();
    double      error   = 0.;
    for (const auto &particle : problem.points().get_particle_handler())
      {
        const auto                  data = particle.get_properties();
        const SymmetricTensor<2, 2> s =
          qsmpm::Utils::read_symmetric<2>(&data[offsets.stress]);
        error = std::max(error, std::abs(s[1][1] + q0));
      }
    stress_error = Utilities::MPI::max(error, MPI_COMM_WORLD) / q0;
  });
  deallog << "  run " << (plate.completed ? "completed" : plate.message)
          << std::endl;
  check("  plate's force against its load: |F_y / q0 - 1|",
        plate.force[1] / q0 - 1.,
        1e-9);
  check("  every point: |sigma_yy + q0| / q0", stress_error, 1e-2);
  check("  base reaction: |R_y / q0 - 1|",
        plate.reactions.size() > 2 ? plate.reactions[2][1] / q0 - 1. : 1.,
        1e-6);
  check("  plate's motion: |u / (q0 H / M) - 1|",
        plate.motion / 0.01 - 1.,
        5e-3);
  check("  GMRES iterations per Newton iteration",
        plate.newton_iterations > 0 ?
          static_cast<double>(plate.linear_iterations) /
            plate.newton_iterations :
          1e3,
        2.);

  deallog << "2. A Coulomb floor dragged by a force under a pressed block"
          << std::endl;
  const double mu_N  = 0.3 * 10.;
  const double H     = 0.5 * mu_N;
  const Run    stick = run(floor_prm(H));
  deallog << "  H = 0.5 mu N: run "
          << (stick.completed ? "completed" : stick.message) << std::endl;
  check("  floor's force against its load: |F_x / H - 1|",
        -stick.force[0] / H - 1.,
        1e-9);
  check_at_least("  floor's motion along H / h", stick.motion / 0.125, 1e-3);
  // The floor moved by the motions the force found, step by step (linear
  // in between), must carry the same forces.
  std::ostringstream motion;
  motion << std::setprecision(17);
  double      t_before = 0., u_before = 0.;
  std::string closing;
  for (unsigned int k = 0; k < stick.steps.size(); ++k)
    {
      motion << "if(t <= " << stick.steps[k] << ", " << u_before << " + (t - "
             << t_before << ") * "
             << (stick.motions[k] - u_before) / (stick.steps[k] - t_before)
             << ", ";
      closing += ")";
      t_before = stick.steps[k];
      u_before = stick.motions[k];
    }
  motion << u_before << closing;
  const Run moved   = run(floor_prm(0., motion.str()));
  double    largest = moved.completed ? 0. : 1.;
  for (unsigned int k = 0;
       k < std::min(moved.forces.size(), stick.forces.size());
       ++k)
    largest =
      std::max(largest, (moved.forces[k] - stick.forces[k]).norm() / mu_N);
  check("  the floor moved by those motions: max |F - F_force| / (mu N)",
        largest,
        1e-6);
  const Run  slide = run(floor_prm(1.2 * mu_N));
  const bool stopped =
    !slide.completed &&
    slide.message.find("Rigid body <floor>: no motion along its load "
                       "direction balances its load") != std::string::npos;
  deallog << "  H = 1.2 mu N: run "
          << (slide.completed ? "completed" : "stopped") << std::endl;
  check_that("  stopped with a message naming the floor", stopped);
  if (!stopped && Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << slide.message << std::endl;
}
