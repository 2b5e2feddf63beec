// When a preconditioner may serve another load step (PreconditionerReuse):
// with Preconditioner reuse steps = 10,
//  - the first step builds one, the next steps with the same constrained
//    degrees of freedom reuse it;
//  - a step in which a constrained dof is freed and another held (the
//    same number of constraints, other indices) builds a new one: the old
//    one acts on the freed dof as on a fixed one. At finite strain with
//    GIMP the body reaches new nodes every few steps; reuse across such
//    changes took the cantilever example from 8 to 317 GMRES iterations
//    per Newton iteration;
//  - so does a step with fewer constrained dofs, and one after a failed
//    step, and one in which GMRES needed more than twice the iterations
//    per Newton iteration of the preconditioner's first step;
//  - after 10 steps a new one is built whatever the constraints.
// On all ranks of MPI_COMM_WORLD (the constrained dofs are counted over all
// ranks; each rank owns a contiguous block of 10 dofs here).
#include "tests.h"

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>
#include <qsmpm/solvers/preconditioner_reuse.h>

using namespace qsmpm;

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  const unsigned int rank    = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  IndexSet           owned(10 * n_ranks);
  owned.add_range(10 * rank, 10 * rank + 10);

  // Constraints on the dofs @p local (0 to 9) of this rank.
  const auto constrain = [&](const std::vector<unsigned int> &local) {
    AffineConstraints<double> c;
    for (const unsigned int i : local)
      c.add_line(10 * rank + i);
    c.close();
    return c;
  };

  NewtonParameters parameters;
  parameters.preconditioner_reuse_steps  = 10;
  parameters.preconditioner_reuse_growth = 2.;
  PreconditionerReuse reuse;
  NewtonReport        report;
  report.converged         = true;
  report.newton_iterations = 2;
  report.linear_iterations = 10;

  const auto step = [&](const AffineConstraints<double> &c) {
    const bool built =
      reuse.build_for_step(true, parameters, c, owned, MPI_COMM_WORLD);
    reuse.count_use(report, parameters);
    return built;
  };

  const auto held = constrain({0, 5});
  check_that("first step: a new preconditioner", step(held));
  check_that("same constraints: reused", !step(held) && !step(held));
  check_that("a dof freed and another held: a new one",
             step(constrain({0, 6})));
  check_that("then reused", !step(constrain({0, 6})));
  check_that("fewer constrained dofs: a new one", step(constrain({0})));
  report.linear_iterations = 50;
  check_that("GMRES 2.5 times slower: reused this step", !step(constrain({0})));
  report.linear_iterations = 10;
  check_that("and a new one in the next", step(constrain({0})));
  report.converged = false;
  check_that("a failed step: reused in it", !step(constrain({0})));
  report.converged = true;
  check_that("and a new one after it", step(constrain({0})));
  unsigned int reused = 0;
  bool         built  = false;
  for (unsigned int i = 0; i < 10 && !built; ++i)
    {
      built = step(constrain({0}));
      if (!built)
        ++reused;
    }
  check_that("unchanged constraints: reused for 9 more steps, then rebuilt",
             built && reused == 9);
  check_that("builds counted", reuse.n_builds() == 6);
}
