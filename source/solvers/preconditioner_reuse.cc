#include <algorithm>
#include <qsmpm/solvers/preconditioner_reuse.h>

namespace qsmpm
{
  void
  PreconditionerReuse::reset()
  {
    age = 0;
  }



  bool
  PreconditionerReuse::build_for_step(const bool              needs_matrix,
                                      const NewtonParameters &parameters)
  {
    const bool build =
      needs_matrix &&
      (age == 0 || age >= parameters.preconditioner_reuse_steps);
    last_reused = needs_matrix && !build;
    if (build)
      {
        age = 0;
        ++builds;
      }
    return build;
  }



  void
  PreconditionerReuse::count_use(const NewtonReport     &report,
                                 const NewtonParameters &parameters)
  {
    // A failed step, or one in which GMRES slowed down by more than the
    // growth factor, gets a new preconditioner next time.
    const double step_rate =
      double(report.linear_iterations) /
      std::max<unsigned int>(1, report.newton_iterations);
    if (age == 0)
      rate = std::max(step_rate, 1.);
    ++age;
    if (!report.converged ||
        step_rate > parameters.preconditioner_reuse_growth * rate)
      age = 0;
  }



  bool
  PreconditionerReuse::reused() const
  {
    return last_reused;
  }



  unsigned int
  PreconditionerReuse::n_builds() const
  {
    return builds;
  }
} // namespace qsmpm
