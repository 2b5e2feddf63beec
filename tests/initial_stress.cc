// Material points/Initial stress (issue 31: a soil layer at rest under its
// weight before anything is built on it). A plane-strain layer, 2 m wide and
// H = 4 m deep (4 x 8 cells, 2 x 2 points per cell), rollers on the sides,
// fixed base, unit weight gamma = 20 kN/m^3 as a body force from the first
// step on, and the geostatic stress
//   sigma_yy = -gamma (H - y),  sigma_xx = sigma_zz = K0 sigma_yy,  K0 = 0.5,
// at the points. It balances the weight exactly (div sigma + b = 0, sigma n
// = 0 on the top, sigma_xx independent of x at the rollers), and the MPM
// integrals of these bilinear integrands are exact at the points of a 2 x 2
// regular rule, so the layer must not move: the largest displacement after
// 2 steps, relative to the settlement the weight gives a stress-free layer
// (gamma H^2 / (2 E_oed), 2e-3 m for E = 30 MPa, nu = 0.3), must vanish
// to the Newton tolerance (the default, 1e-6 of the forces: checked 1e-8 of
// the settlement), and every point must keep its stress (1e-8 of gamma H). For
// linear elastic (the stress it adds increments to), Drucker-Prager (a plastic
// model: its elastic strain) and Modified Cam Clay (a pressure-dependent
// elastic law, p_c0 = 200 kPa enclosing the deepest state; and normally
// consolidated, `Overconsolidation ratio` = 1: every point's yield surface
// through its own stress, so that every point is on it), on 1 and 2 ranks.
// Without the initial stress the stress-free linear elastic layer settles by
// the closed-form amount instead (2 % here: the layer's points are at rest only
// with it).
//
// Then: before the first step a Cam Clay point without an initial stress
// holds -p0 I; and the bad inputs (a model that cannot start from a stress,
// a stress outside the yield surface, a wrong number of components) stop
// with a message naming the entry.
#include "prm_text.h"
#include "tests.h"

#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>

using namespace qsmpm;

namespace
{
  const double gamma_w = 20., H = 4., E = 30e3, nu = 0.3;
  const char  *geostatic = "-10*(4-y); -20*(4-y); -10*(4-y); 0";

  std::string
  layer_prm(const std::string &material, const std::string &initial_stress)
  {
    std::ostringstream prm;
    prm << "set Dimension = 2\n"
        << "subsection Geometry\n  set Lower corner = 0,0\n"
        << "  set Upper corner = 2,4\n  set Subdivisions = 4,8\nend\n"
        << "subsection Material points\n"
        << "  set Points per cell per direction = 2\n"
        << "  set Initial stress = " << initial_stress << "\nend\n"
        << "subsection Material\n"
        << material << "end\n"
        << "subsection Boundary conditions\n"
        << "  set Dirichlet boundaries = 0:x, 1:x, 2:y\n"
        << "  subsection Body force\n"
        << "    set Function expression = 0; -" << gamma_w << "\n  end\nend\n"
        << "subsection Load stepping\n  set Number of steps = 2\nend\n"
        << "subsection Output\n  set Interval = 0\n"
        << "  set Directory = initial-stress-out\nend\n";
    return prm.str();
  }

  std::string
  linear_elastic()
  {
    std::ostringstream m;
    m << "  set Model = linear elastic\n  subsection linear elastic\n"
      << "    set Young's modulus = " << E << "\n"
      << "    set Poisson's ratio = " << nu << "\n  end\n";
    return m.str();
  }

  /// Largest |u| and largest |sigma - sigma0| over the points (all ranks)
  /// after the run of @p text (NaN if it stopped); the message if it
  /// stopped.
  struct Run
  {
    double      displacement = std::numeric_limits<double>::quiet_NaN();
    double      stress_error = std::numeric_limits<double>::quiet_NaN();
    std::string message;
  };

  Run
  run(const std::string &text)
  {
    Run result;
    try
      {
        QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
        initialize_from_text(problem, text);
        problem.run();
        const auto &offsets = problem.points().get_offsets();
        result.displacement = result.stress_error = 0.;
        for (const auto &particle : problem.points().get_particle_handler())
          {
            const auto   data = particle.get_properties();
            const double y    = problem.points().initial_location(particle)[1];
            SymmetricTensor<2, 2> sigma0;
            sigma0[1][1] = -gamma_w * (H - y);
            sigma0[0][0] = 0.5 * sigma0[1][1];
            const auto sigma =
              Utils::read_symmetric<2>(data.data() + offsets.stress);
            result.stress_error =
              std::max(result.stress_error,
                       (sigma - sigma0).norm() / (gamma_w * H));
            for (unsigned int d = 0; d < 2; ++d)
              result.displacement =
                std::max(result.displacement,
                         std::abs(data[offsets.displacement + d]));
          }
        result.displacement =
          Utilities::MPI::max(result.displacement, MPI_COMM_WORLD);
        result.stress_error =
          Utilities::MPI::max(result.stress_error, MPI_COMM_WORLD);
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

  const double E_oed   = E * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
  const double settles = gamma_w * H * H / (2. * E_oed);

  deallog << "1. A layer at rest under its weight" << std::endl;
  const std::vector<std::pair<std::string, std::string>> materials = {
    {"linear elastic", linear_elastic()},
    {"Drucker-Prager",
     "  set Model = Drucker-Prager\n  subsection Drucker-Prager\n"
     "    set Young's modulus = 30000\n    set Poisson's ratio = 0.3\n"
     "    set Cohesion = 10\n    set Friction angle = 30\n  end\n"},
    {"Modified Cam Clay",
     "  set Model = Modified Cam Clay\n  subsection Modified Cam Clay\n"
     "    set Shear modulus = 10000\n    set Initial pressure = 50\n"
     "    set Preconsolidation pressure = 200\n    set Critical state slope "
     "= 1.2\n  end\n"},
    {"Modified Cam Clay, OCR = 1",
     "  set Model = Modified Cam Clay\n  subsection Modified Cam Clay\n"
     "    set Shear modulus = 10000\n    set Initial pressure = 50\n"
     "    set Critical state slope = 1.2\n"
     "    set Overconsolidation ratio = 1\n  end\n"}};
  for (const auto &[name, text] : materials)
    {
      const Run r = run(layer_prm(text, geostatic));
      check_that("  " + name + ": runs" +
                   (r.message.empty() ? "" : " (" + r.message + ")"),
                 r.message.empty());
      check("  " + name + ": largest |u| / settlement without it",
            r.displacement / settles,
            1e-8);
      check("  " + name + ": largest |sigma - sigma0| / (gamma H)",
            r.stress_error,
            1e-8);
    }
  {
    const Run r = run(layer_prm(linear_elastic(), ""));
    check_at_least("  linear elastic without it: largest |u| / settlement",
                   r.displacement / settles,
                   0.5);
  }

  deallog << "2. Cam Clay before the first step" << std::endl;
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    initialize_from_text(problem, layer_prm(materials[2].second, ""));
    const auto &offsets = problem.points().get_offsets();
    double      error   = 0.;
    for (const auto &particle : problem.points().get_particle_handler())
      {
        const auto sigma = Utils::read_symmetric<2>(
          particle.get_properties().data() + offsets.stress);
        error =
          std::max(error,
                   (sigma + 50. * unit_symmetric_tensor<2>()).norm() / 50.);
      }
    check("  every point holds -p0 I: |sigma + p0 I| / p0",
          Utilities::MPI::max(error, MPI_COMM_WORLD),
          1e-14);
  }

  deallog << "3. Bad input" << std::endl;
  const auto names = [](const Run &r, const std::string &what) {
    return !r.message.empty() && r.message.find(what) != std::string::npos;
  };
  check_that("  hencky cannot start from a stress: names 'Initial stress'",
             names(run(layer_prm("  set Model = hencky\n", geostatic)),
                   "Initial stress"));
  check_that(
    "  a stress outside the Drucker-Prager cone: names 'Initial stress'",
    names(run(layer_prm(materials[1].second, "0; 0; 0; 100")),
          "outside the yield surface"));
  check_that("  three components in 2D: names 'Initial stress'",
             names(run(layer_prm(linear_elastic(), "0; 0; 0")),
                   "Initial stress"));
  check_that("  Cam Clay under tension: names 'Initial stress'",
             names(run(layer_prm(materials[2].second, "10; 10; 10; 0")),
                   "Initial stress"));
}
