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
    std::string solver;
    if (!preconditioner.empty())
      solver += "  set Preconditioner = " + preconditioner + "\n";
    if (paper_settings)
      solver += "  set Preconditioner reuse steps = 1\n"
                "  set Forcing term = constant\n"
                "  set Initial guess = linear predictor\n";
    return yielding_strip_prm(model, "", solver, "auto-out");
  }

  using Run = RecordedRun<2>;

  Run
  run(const std::string &model,
      const bool         paper_settings,
      const std::string &preconditioner = "")
  {
    return run_and_record<2>(strip_prm(model, paper_settings, preconditioner));
  }

  double
  difference(const Run &a, const Run &b)
  {
    return max_relative_difference(a, b);
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
