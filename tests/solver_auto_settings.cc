// The solver's `auto` defaults (NewtonParameters::resolve(),
// doc/benchmarks.md#the-driver-defaults-and-the-faster-settings): for an
// elastic model the extrapolated initial guess (the linear predictor at
// finite strain), Eisenstat-Walker forcing and a preconditioner that serves
// up to 10 steps; for every other model the paper's settings.
//
// 1. resolve() itself: the three cases, and entries that are not auto
//    are kept; Preconditioner = auto's threshold (direct up to 20000 dofs
//    in 2D, 1500 in 3D, or the threshold given).
// 2. A strip under a partial traction (the benchmark strip, 32 x 32 cells,
//    5 load steps), linear elastic, with AMG, from .prm text with no other
//    solver entry against the same with the paper's settings written out:
//    the points' displacements agree to 1e-6 of the largest (both solved
//    to a Newton tolerance of 1e-9: the two paths differ by what Newton
//    leaves, not by the answer), and the defaults need fewer GMRES
//    iterations (the reason for them: the extrapolated guess of a
//    proportional load meets the stopping test in one Newton iteration).
//    With Preconditioner = auto (2178 dofs: the direct factorization)
//    the displacements agree to 1e-6 as well.
// 3. The same strip with von Mises plasticity (yield stress 600; it yields
//    under the loaded half's edge, below the punch's limit load, about
//    (2 + pi) 600 / sqrt 3 = 1780): the defaults are the paper's, so the
//    displacements are bitwise those of the written-out settings.
#include "prm_text.h"
#include "tests.h"

#include <qsmpm/core/quasi_static_problem.h>

using namespace qsmpm;

namespace
{
  using InitialGuess = NewtonParameters::InitialGuess;
  using Forcing      = NewtonParameters::Forcing;

  std::string
  strip_prm(const std::string &model,
            const bool         paper_settings,
            const std::string &preconditioner)
  {
    std::ostringstream prm;
    prm << "set Dimension = 2\n"
        << "subsection Geometry\n  set Subdivisions = 32,32\nend\n"
        << "subsection Material\n  set Model = " << model << "\n"
        << "  subsection " << model << "\n"
        << "    set Young's modulus = 1e6\n"
        << "    set Poisson's ratio = 0.3\n";
    if (model == "von Mises")
      prm << "    set Yield stress = 600\n";
    prm << "  end\nend\n"
        << "subsection Boundary conditions\n"
        << "  set Dirichlet boundaries = 0:x, 1:x, 2:y\n"
        << "  set Traction boundaries = 3\n"
        << "  subsection Traction\n"
        << "    set Function expression = 0; -1e3*t*(x<0.5 ? 1 : 0)\n"
        << "  end\nend\n"
        << "subsection Load stepping\n  set Number of steps = 5\nend\n"
        << "subsection Nonlinear solver\n  set Tolerance = 1e-9\n";
    if (!preconditioner.empty())
      prm << "  set Preconditioner = " << preconditioner << "\n";
    if (paper_settings)
      prm << "  set Preconditioner reuse steps = 1\n"
          << "  set Forcing term = constant\n"
          << "  set Initial guess = linear predictor\n";
    prm << "end\n"
        << "subsection Output\n  set Interval = 0\n"
        << "  set Directory = auto-out\nend\n";
    return prm.str();
  }

  struct Run
  {
    /// Displacements of the points by particle id.
    std::map<types::particle_index, Tensor<1, 2>> displacement;
    unsigned int                                  gmres = 0;
  };

  Run
  run(const std::string &model,
      const bool         paper_settings,
      const std::string &preconditioner = "")
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    initialize_from_text(problem,
                         strip_prm(model, paper_settings, preconditioner));
    Run result;
    problem.set_step_callback(
      [&](const QuasiStaticProblem<2>::StepReport &report) {
        result.gmres += report.newton.linear_iterations;
        return true;
      });
    problem.run();
    result.displacement = point_displacements(problem);
    return result;
  }

  /// max |u_a - u_b| / max |u_a| over the points.
  double
  difference(const Run &a, const Run &b)
  {
    return max_relative_difference(a.displacement, b.displacement);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  deallog << "1. resolve()" << std::endl;
  const NewtonParameters defaults;
  const auto             elastic = defaults.resolve(true, false);
  check_that("elastic, small strain: reuse 10, Eisenstat-Walker, "
             "extrapolation",
             elastic.preconditioner_reuse_steps == 10 &&
               elastic.forcing == Forcing::eisenstat_walker &&
               elastic.initial_guess == InitialGuess::extrapolation);
  const auto finite = defaults.resolve(true, true);
  check_that("elastic, finite strain: the linear predictor",
             finite.preconditioner_reuse_steps == 10 &&
               finite.forcing == Forcing::eisenstat_walker &&
               finite.initial_guess == InitialGuess::linear_predictor);
  const auto other = defaults.resolve(false, false);
  check_that("not elastic: reuse 1, constant forcing, the linear predictor",
             other.preconditioner_reuse_steps == 1 &&
               other.forcing == Forcing::constant &&
               other.initial_guess == InitialGuess::linear_predictor);
  NewtonParameters explicit_entries;
  explicit_entries.preconditioner_reuse_steps = 3;
  explicit_entries.forcing                    = Forcing::constant;
  explicit_entries.initial_guess              = InitialGuess::boundary_values;
  const auto kept = explicit_entries.resolve(true, false);
  check_that("entries that are not auto are kept",
             kept.preconditioner_reuse_steps == 3 &&
               kept.forcing == Forcing::constant &&
               kept.initial_guess == InitialGuess::boundary_values);
  NewtonParameters threshold_given;
  threshold_given.direct_threshold = 300;
  check_that("preconditioner auto: direct up to 20000 dofs in 2D, 1500 in "
             "3D, or the threshold given",
             defaults.direct_threshold_for(2) == 20000 &&
               defaults.direct_threshold_for(3) == 1500 &&
               threshold_given.direct_threshold_for(3) == 300);

  deallog << "2. Linear elastic strip: defaults against the paper's settings"
          << std::endl;
  const Run elastic_auto  = run("linear elastic", false, "amg");
  const Run elastic_paper = run("linear elastic", true, "amg");
  check("max |u_auto - u_paper| / max |u|",
        difference(elastic_paper, elastic_auto),
        1e-6);
  check_that("fewer GMRES iterations with the defaults",
             elastic_auto.gmres < elastic_paper.gmres);
  const Run elastic_direct = run("linear elastic", false, "auto");
  check("Preconditioner = auto (direct): max |u_direct - u_paper| / max |u|",
        difference(elastic_paper, elastic_direct),
        1e-6);

  deallog << "3. Von Mises strip: the defaults are the paper's settings"
          << std::endl;
  const Run plastic_auto  = run("von Mises", false);
  const Run plastic_paper = run("von Mises", true);
  check_at_least("it yields: max |u_plastic - u_elastic| / max |u|",
                 difference(plastic_paper, elastic_paper),
                 1e-3);
  check_that("the same displacements, bitwise",
             difference(plastic_paper, plastic_auto) == 0.);
  check_that("the same GMRES iterations",
             plastic_auto.gmres == plastic_paper.gmres);
}
