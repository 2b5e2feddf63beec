#include <qsmpm/loading/reaction_forces.h>

namespace qsmpm
{
  template <int dim>
  ReactionForces<dim>::ReactionForces(
    const DisplacementConstraints<dim> &constraints)
    : constraints(constraints)
  {
  }



  template <int dim>
  std::vector<Tensor<1, dim>>
  ReactionForces<dim>::evaluate(const TrilinosWrappers::MPI::Vector &residual,
                                const MPI_Comm communicator) const
  {
    std::vector<Tensor<1, dim>> result(constraints.n_conditions());
    for (unsigned int k = 0; k < result.size(); ++k)
      {
        for (const auto &dof : constraints.prescribed_dofs(k))
          result[k][dof.component] -= residual(dof.index);
        result[k] = dealii::Utilities::MPI::sum(result[k], communicator);
      }
    return result;
  }



  template class ReactionForces<2>;
  template class ReactionForces<3>;
} // namespace qsmpm
