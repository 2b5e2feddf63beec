// Contact of material points with rigid bodies (RigidContact), from the
// driver's .prm route (Boundary conditions/Rigid body), against exact
// solutions:
//
// 1. A rigid plate compacting an elastic column (as the rigid-plate
//    tutorial of AMPSSIE): a block 1 x 1 on rollers (sides and base),
//    E = 1000, nu = 0.3, plane strain, pressed by a frictionless
//    half-space that moves down by d = 0.01 t. In uniaxial strain the
//    exact stress is sigma_yy = -M d / H, sigma_xx = -lambda d / H,
//    M = lambda + 2 mu, everywhere. The penalty lets the plate penetrate
//    by g = |sigma_yy| / epsilon, of the order M h / (gamma kbar H) of
//    the plate's motion (checked: below 0.2 %). With cpGIMP, whose
//    domains tile the body, the uniform stress is then reproduced (with
//    linear shape functions the cell under the plate is off by about
//    u / h, doc/contact.md). Tolerance: 1 % (the issue's) on the stress of
//    every point and on the plate's force, which must also equal the base's
//    reaction (global equilibrium) to 1e-6.
// 2. The same at finite strain (hencky, cpGIMP), compacted by 5 %:
//    exact Cauchy stress sigma_yy = M ln(lambda) / lambda with the stretch
//    lambda = 0.95 (Hencky's law in uniaxial strain), 1 % again.
// 3. A block pushed across a rigid floor with Coulomb friction mu = 0.3:
//    the block [0,1] x [0.25,0.75] rests on a half-space floor y < 0.25,
//    is pressed by a surface traction q = 10 on its top (t <= 1), and the
//    floor then slides in x by 0.2 in 100 steps while the grid's left
//    boundary holds the block. Once every point slips (steps 21-100), the
//    floor's tangential force over its normal force is mu (to 1 %, the issue's
//    tolerance; the penalty does not enter a ratio of forces at slip),
//    and the normal force equals the applied q * 1 to 1e-6; in the first
//    sliding step, 2e-3 of floor motion, the block sticks: the ratio is
//    below mu, and it never exceeds mu. With rough contact the ratio
//    exceeds mu (5 sliding steps).
// 4. Case 1 with linear shape functions and points that do not move
//    (Move points = false, Update volumes = false): the small-displacement
//    theory with the points as a fixed quadrature, in which the uniform stress
//    is exact; the plate meets the points where their displacement puts them
//    (X_p + u_p). 1 % on every point's stress and the plate's force, as
//    in case 1. Control: the same with moving points, whose cell under the
//    plate is off by about u / h (doc/contact.md), must be off by more than
//    1 %.
//
// Output from rank 0; the results do not depend on the number of ranks.
#include "prm_text.h"
#include "tests.h"

#include <cmath>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>

using namespace qsmpm;

namespace
{
  void
  check(const std::string &what, const bool passed)
  {
    deallog << what << ": " << (passed ? "PASS" : "FAIL") << std::endl;
  }

  const double E = 1000., nu = 0.3;
  const double lambda_lame = E * nu / ((1. + nu) * (1. - 2. * nu));
  const double M           = E * (1. - nu) / ((1. + nu) * (1. - 2. * nu));

  std::string
  plate_prm(const std::string &kinematics,
            const std::string &shape_functions,
            const std::string &model,
            const double       compaction,
            const unsigned int steps,
            const double       gamma,
            const bool         move_points = true)
  {
    std::ostringstream prm;
    prm << "set Dimension = 2\n"
        << "subsection Geometry\n  set Lower corner = 0,0\n"
        << "  set Upper corner = 1,1.25\n  set Subdivisions = 8,10\nend\n"
        << "subsection Material points\n"
        << "  set Points per cell per direction = 2\n"
        << "  set Region lower corner = 0,0\n"
        << "  set Region upper corner = 1,1\n"
        << "  set Kinematics = " << kinematics << "\n"
        << "  set Shape functions = " << shape_functions << "\n"
        << "  set Move points = " << (move_points ? "true" : "false")
        << "\n  set Update volumes = " << (move_points ? "true" : "false")
        << "\nend\n"
        << "subsection Material\n  set Model = " << model << "\n"
        << "  subsection " << model << "\n"
        << "    set Young's modulus = " << E << "\n"
        << "    set Poisson's ratio = " << nu << "\n  end\nend\n"
        << "subsection Boundary conditions\n"
        << "  set Dirichlet boundaries = 0:x, 1:x, 2:y\n"
        << "  subsection Rigid body\n"
        << "    set Shape = half-space\n    set Name = plate\n"
        << "    set Point = 0, 1\n    set Normal = 0, -1\n"
        << "    set Penalty factor = " << gamma << "\n"
        << "    subsection Motion\n"
        << "      set Function expression = 0; " << -compaction << "*t\n"
        << "    end\n  end\nend\n"
        << "subsection Load stepping\n  set Number of steps = " << steps
        << "\nend\n"
        << "subsection Nonlinear solver\n  set Tolerance = 1e-10\nend\n"
        << "subsection Output\n  set Interval = 0\n"
        << "  set Directory = contact-out\nend\n";
    return prm.str();
  }

  struct PlateResult
  {
    bool   completed    = false;
    double stress_error = 0., plate_error = 0., balance = 0.;
    double penetration = 0.;
  };

  // Run the plate problem; stresses against sigma_yy, sigma_xx exact.
  PlateResult
  run_plate(const std::string &text,
            const double       sigma_yy,
            const double       sigma_xx)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    initialize_from_text(problem, text);
    PlateResult result;
    try
      {
        problem.run();
        result.completed = true;
      }
    catch (const std::exception &exc)
      {
        deallog << "  run stopped: " << qsmpm::Utils::error_message(exc)
                << std::endl;
        return result;
      }
    const auto &offsets = problem.points().get_offsets();
    double      error   = 0.;
    for (const auto &particle : problem.points().get_particle_handler())
      {
        const auto                  data = particle.get_properties();
        const SymmetricTensor<2, 2> s =
          qsmpm::Utils::read_symmetric<2>(&data[offsets.stress]);
        const double e = std::max({std::abs(s[1][1] - sigma_yy),
                                   std::abs(s[0][0] - sigma_xx),
                                   std::abs(s[0][1])});
        error          = std::max(error, e);
      }
    result.stress_error =
      Utilities::MPI::max(error, MPI_COMM_WORLD) / std::abs(sigma_yy);
    const auto &plate = problem.rigid_body_loads().at(0);
    // The plate's force per unit width (the block is 1 wide) against the
    // exact stress; the base (third condition) carries the same force.
    result.plate_error = std::abs(plate.force[1] + sigma_yy) / -sigma_yy;
    result.balance =
      std::abs(plate.force[1] - problem.reactions().at(2)[1]) / -sigma_yy;
    result.penetration = plate.penetration;
    return result;
  }

  std::string
  floor_prm(const std::string &friction, const unsigned int steps)
  // (the default Newton tolerance, 1e-6)
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
        << "    set Friction = " << friction << "\n"
        << "    set Friction coefficient = 0.3\n"
        << "    subsection Motion\n"
        << "      set Function expression = 0.2*max(t - 1, 0); 0\n"
        << "    end\n  end\nend\n"
        << "subsection Load stepping\n  set Final load factor = 2\n"
        << "  set Number of steps = " << steps << "\nend\n"
        << "subsection Output\n  set Interval = 0\n"
        << "  set Directory = contact-out\nend\n";
    return prm.str();
  }

  struct FloorResult
  {
    bool completed = false;
    // F_x / F_y of the floor at each step of the sliding phase.
    std::vector<double> ratio;
    double              normal_error = 0.;
  };

  FloorResult
  run_floor(const std::string &friction, const unsigned int sliding_steps)
  {
    // 2 steps of pressing, 200 of sliding (the first slides by 2.5e-4).
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    initialize_from_text(problem, floor_prm(friction, 202));
    FloorResult result;
    problem.set_step_callback([&](const StepReport &report) {
      const auto &floor = problem.rigid_body_loads().at(0);
      if (report.load_factor > 1. + 1e-12)
        result.ratio.push_back(std::abs(floor.force[0] / floor.force[1]));
      const double q = 10. * std::min(report.load_factor, 1.);
      result.normal_error =
        std::max(result.normal_error, std::abs(floor.force[1] + q) / q);
      return result.ratio.size() < sliding_steps;
    });
    try
      {
        problem.run();
        result.completed = true;
      }
    catch (const std::exception &exc)
      {
        deallog << "  run stopped: " << qsmpm::Utils::error_message(exc)
                << std::endl;
      }
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::MPILogInitAll       log;
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  deallog << "1. Rigid plate compacting an elastic column, small strain"
          << std::endl;
  const double d = 0.01;
  // The column compacted by d in 4 steps at small strain.
  const auto compacted = [&](const std::string &shape_functions,
                             const bool         move_points) {
    return run_plate(plate_prm("small strain",
                               shape_functions,
                               "linear elastic",
                               d,
                               4,
                               100.,
                               move_points),
                     -M * d,
                     -lambda_lame * d);
  };
  const PlateResult small = compacted("cpGIMP", true);
  if (root)
    std::cout << "plate: stress error " << small.stress_error
              << "; plate force error " << small.plate_error
              << "; penetration / d " << small.penetration / d << std::endl;
  check("  completed", small.completed);
  check("  stress of every point within 1 % of the exact",
        small.stress_error < 1e-2);
  check("  plate force within 1 % of the exact", small.plate_error < 1e-2);
  check("  plate force = base reaction to 1e-6", small.balance < 1e-6);
  check("  penetration below 0.2 % of the plate's motion",
        small.penetration < 2e-3 * d);

  deallog << "2. The same at finite strain (hencky, cpGIMP), 5 % compaction"
          << std::endl;
  const double      stretch = 0.95;
  const PlateResult large =
    run_plate(plate_prm("finite strain", "cpGIMP", "hencky", 0.05, 4, 100.),
              M * std::log(stretch) / stretch,
              lambda_lame * std::log(stretch) / stretch);
  if (root)
    std::cout << "plate, finite strain: stress error " << large.stress_error
              << ", plate force error " << large.plate_error << std::endl;
  check("  completed", large.completed);
  check("  stress of every point within 1 % of the exact",
        large.stress_error < 1e-2);
  check("  plate force within 1 % of the exact", large.plate_error < 1e-2);
  check("  plate force = base reaction to 1e-6", large.balance < 1e-6);

  deallog << "3. A block on a sliding floor, Coulomb friction mu = 0.3"
          << std::endl;
  // The whole sliding phase: 100 steps, 0.2 of floor motion.
  const FloorResult coulomb = run_floor("coulomb", 100);
  check("  completed", coulomb.completed && coulomb.ratio.size() == 100);
  if (coulomb.ratio.size() == 100)
    {
      double largest = 0., last_error = 0.;
      for (unsigned int k = 0; k < 100; ++k)
        {
          largest = std::max(largest, coulomb.ratio[k]);
          if (k >= 20)
            last_error =
              std::max(last_error, std::abs(coulomb.ratio[k] - 0.3) / 0.3);
        }
      if (root)
        std::cout << "floor: F_x/F_y first sliding step "
                  << coulomb.ratio.front() << ", steps 21-100 within "
                  << last_error << " of mu, largest " << largest
                  << "; normal force error " << coulomb.normal_error
                  << std::endl;
      check("  steps 21-100 (all points slip): F_x / F_y = mu within 1 %",
            last_error < 1e-2);
      check("  every step: F_x / F_y <= mu (1 + 1e-3)",
            largest <= 0.3 * (1. + 1e-3));
      check("  first step (2e-3 of floor motion): stick, F_x / F_y < mu",
            coulomb.ratio.front() < 0.3 * 0.99);
      check("  normal force = applied load to 1e-6",
            coulomb.normal_error < 1e-6);
    }
  const FloorResult rough = run_floor("rough", 5);
  check("  rough: F_x / F_y > mu after 5 sliding steps",
        rough.completed && !rough.ratio.empty() && rough.ratio.back() > 0.3);

  deallog << "4. Case 1 with linear shape functions, points that do not move"
          << std::endl;
  const PlateResult fixed  = compacted("linear", false);
  const PlateResult moving = compacted("linear", true);
  if (root)
    std::cout << "plate, linear: stress error " << fixed.stress_error
              << " with points that do not move, " << moving.stress_error
              << " with moving points" << std::endl;
  check("  completed", fixed.completed && moving.completed);
  check("  stress of every point within 1 % of the exact",
        fixed.stress_error < 1e-2);
  check("  plate force within 1 % of the exact", fixed.plate_error < 1e-2);
  check("  plate force = base reaction to 1e-6", fixed.balance < 1e-6);
  check("  control, moving points: stress error above 1 %",
        moving.stress_error > 1e-2);
}
