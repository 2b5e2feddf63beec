#include <algorithm>
#include <qsmpm/solvers/preconditioner_reuse.h>

namespace qsmpm
{
  void
  PreconditionerReuse::reset()
  {
    age         = 0;
    constrained = {{-1., -1.}};
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



  bool
  PreconditionerReuse::build_for_step(
    const bool                       needs_matrix,
    const NewtonParameters          &parameters,
    const AffineConstraints<double> &constraints,
    const IndexSet                  &owned,
    const MPI_Comm                   communicator)
  {
    if (!needs_matrix)
      return build_for_step(needs_matrix, parameters);
    // The constrained dofs this rank owns: their number and the sum of
    // their indices (a checksum that changes when a dof is freed or held).
    std::array<double, 2> now{{0., 0.}};
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        {
          now[0] += 1.;
          now[1] += static_cast<double>(line.index);
        }
    Utilities::MPI::sum(ArrayView<const double>(now.data(), now.size()),
                        communicator,
                        ArrayView<double>(now.data(), now.size()));
    if (now != constrained)
      age = 0;
    const bool build = build_for_step(needs_matrix, parameters);
    if (build)
      constrained = now;
    return build;
  }



  const std::array<double, 2> &
  PreconditionerReuse::constrained_signature() const
  {
    return constrained;
  }



  void
  PreconditionerReuse::count_as_taken_over()
  {
    Assert(builds > 0 && age == 0, ExcInternalError());
    --builds;
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
