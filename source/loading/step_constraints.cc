#include <deal.II/base/mpi.h>
#include <qsmpm/loading/step_constraints.h>

namespace qsmpm
{
  void
  StepConstraints::reinit(AffineConstraints<double> &&new_constraints,
                          const IndexSet             &owned,
                          const MPI_Comm              communicator)
  {
    constraints      = std::move(new_constraints);
    mpi_communicator = communicator;

    coupled.clear();
    IndexSet masters(owned.size());
    for (const auto &line : constraints.get_lines())
      if (!line.entries.empty() && owned.is_element(line.index))
        {
          coupled.emplace_back(line.index, line.entries);
          for (const auto &entry : line.entries)
            masters.add_index(entry.first);
        }
    any_coupling =
      dealii::Utilities::MPI::max(coupled.empty() ? 0 : 1, communicator) > 0;
    if (!any_coupling)
      return;

    masters.add_indices(owned);
    masters.compress();
    master_forces.reinit(owned, masters, communicator, /*writable=*/true);
    master_values.reinit(owned, masters, communicator);
  }



  const AffineConstraints<double> &
  StepConstraints::get() const
  {
    return constraints;
  }



  MPI_Comm
  StepConstraints::get_communicator() const
  {
    return mpi_communicator;
  }



  void
  StepConstraints::distribute(VectorType &du) const
  {
    constraints.distribute(du);
  }



  void
  StepConstraints::make_admissible(VectorType &v) const
  {
    if (!any_coupling)
      {
        constraints.set_zero(v);
        return;
      }
    // Masters are never constrained (the constraints are closed), so their
    // values can be imported before the constrained entries are set.
    master_values = v;
    constraints.set_zero(v);
    for (const auto &[slave, entries] : coupled)
      {
        double value = 0.;
        for (const auto &[master, weight] : entries)
          value += weight * master_values[master];
        v[slave] = value;
      }
    v.compress(VectorOperation::insert);
  }



  void
  StepConstraints::condense(VectorType &R) const
  {
    if (!any_coupling)
      return;
    master_forces = 0.;
    for (const auto &[slave, entries] : coupled)
      {
        const double force = R[slave];
        for (const auto &[master, weight] : entries)
          master_forces[master] += weight * force;
        R[slave] = 0.;
      }
    R.compress(VectorOperation::insert);
    master_forces.compress(VectorOperation::add);
    R += master_forces;
  }



  void
  StepConstraints::set_constrained_to_zero(VectorType &v) const
  {
    constraints.set_zero(v);
  }
} // namespace qsmpm
