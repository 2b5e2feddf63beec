// The user program of the test install_package: built out of tree against
// an installed qsmpm (find_package(qsmpm), target qsmpm::qsmpm) together with
// the user model of usermodel.cc, and run on 2 MPI ranks.
//
// It runs the problem of the parameter file (argument 1) twice:
//  1. as given, with the user model "K-G elastic" (registered by
//     usermodel.cc, which is linked into this executable);
//  2. with the built-in "linear elastic" and E, nu converted from K, G.
// and checks
//  - that the plate forces agree to 1e-9 (relative): both runs are solved
//    to a Newton tolerance of 1e-10, and the two models round C : eps
//    differently (K tr eps I + 2 G dev eps against lambda tr eps I + 2 mu
//    eps), so they agree to a small multiple of the solver tolerance, not
//    bitwise (measured 1.7e-10),
//  - that they equal the analytical plate force E' delta/H A of uniaxial
//    compression in plane strain, E' = E/(1-nu^2) (to 1e-6; the .prm file
//    switches off volume updates, so the small-strain value is exact up to
//    the solver tolerance),
//  - the version macros of qsmpm/base/version.h.
// It prints PASS/FAIL lines and exits non-zero on any failure.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <iomanip>
#include <iostream>
#include <qsmpm/base/utilities.h>
#include <qsmpm/base/version.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/constitutive_model.h>
#include <string>

using namespace dealii;

struct Result
{
  double plate_force;
  double area;
};

// Declare, read, optionally change the model, run; the plate is the third
// displacement condition (boundary id 3) of the .prm file.
Result
run(const std::string &filename, const bool linear_elastic)
{
  ParameterHandler prm;
  prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
  qsmpm::QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
  prm.parse_input(filename);

  if (linear_elastic)
    {
      prm.enter_subsection("Material");
      prm.enter_subsection("K-G elastic");
      const double K = prm.get_double("Bulk modulus");
      const double G = prm.get_double("Shear modulus");
      prm.leave_subsection();
      prm.set("Model", "linear elastic");
      prm.enter_subsection("linear elastic");
      prm.set("Young's modulus", 9. * K * G / (3. * K + G));
      prm.set("Poisson's ratio", (3. * K - 2. * G) / (2. * (3. * K + G)));
      prm.leave_subsection();
      prm.leave_subsection();
      prm.enter_subsection("Output");
      prm.set("Directory", "output-linear-elastic");
      prm.leave_subsection();
    }

  qsmpm::QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
  problem.pcout().set_condition(false);
  problem.initialize(prm);
  const double area = problem.points().total_volume() / 1.0; // H = 1
  problem.run();
  return {-problem.reactions()[2][1], area};
}

int
main(int argc, char *argv[])
{
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      ConditionalOStream               out(std::cout,
                             Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) ==
                               0);
      AssertThrow(argc > 1, ExcMessage("Usage: app kg.prm"));
      bool ok    = true;
      auto check = [&](const std::string &what, const bool passed) {
        out << (passed ? "PASS: " : "FAIL: ") << what << std::endl;
        ok = ok && passed;
      };

      check("version " + std::string(QSMPM_VERSION) + " = " +
              std::to_string(QSMPM_VERSION_MAJOR) + "." +
              std::to_string(QSMPM_VERSION_MINOR) + "." +
              std::to_string(QSMPM_VERSION_SUBMINOR),
            std::string(QSMPM_VERSION) ==
                std::to_string(QSMPM_VERSION_MAJOR) + "." +
                  std::to_string(QSMPM_VERSION_MINOR) + "." +
                  std::to_string(QSMPM_VERSION_SUBMINOR) &&
              QSMPM_VERSION_GTE(0, 9, 0));

      const auto names = qsmpm::ConstitutiveModelFactory<2>::names();
      check("the user model is registered",
            std::find(names.begin(), names.end(), "K-G elastic") !=
              names.end());

      const Result kg = run(argv[1], false);
      const Result le = run(argv[1], true);

      // The analytical value, from K and G: E' = E/(1-nu^2) = 4G(3K+G)/(3K+4G)
      // for plane strain.
      ParameterHandler prm;
      prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
      qsmpm::QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
      prm.parse_input(argv[1]);
      prm.enter_subsection("Material");
      prm.enter_subsection("K-G elastic");
      const double K = prm.get_double("Bulk modulus");
      const double G = prm.get_double("Shear modulus");
      prm.leave_subsection();
      prm.leave_subsection();
      const double E_prime = 4. * G * (3. * K + G) / (3. * K + 4. * G);
      const double delta   = 0.01; // the .prm file's -0.01*t*y at t = 1
      const double F_exact = E_prime * delta * kg.area;

      out << std::setprecision(12) << "plate force K-G elastic      "
          << kg.plate_force << '\n'
          << "plate force linear elastic   " << le.plate_force << '\n'
          << "analytical E' delta/H A      " << F_exact << std::endl;
      const double diff =
        std::abs(kg.plate_force - le.plate_force) / std::abs(le.plate_force);
      const double error = std::abs(kg.plate_force - F_exact) / F_exact;
      out << std::setprecision(3);
      check("K-G elastic = linear elastic, relative difference " +
              Utilities::to_string(diff) + " <= 1e-9",
            diff <= 1e-9);
      check("K-G elastic = analytical, relative difference " +
              Utilities::to_string(error) + " <= 1e-6",
            error <= 1e-6);
      return ok ? 0 : 1;
    }
  catch (std::exception &exc)
    {
      std::cerr << "FAIL: app stopped: " << qsmpm::Utils::error_message(exc)
                << std::endl;
      return 1;
    }
}
