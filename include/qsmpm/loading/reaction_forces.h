#ifndef qsmpm_loading_reaction_forces_h
#define qsmpm_loading_reaction_forces_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>
#include <qsmpm/loading/displacement_constraints.h>
#include <vector>

namespace qsmpm
{
  /**
   * The reaction force of each displacement condition: the force that the
   * support exerts on the body, summed over its nodes. The residual
   * R = f_int + f_ext of a converged step vanishes on every free degree of
   * freedom; on a prescribed one it is the force the body would need from
   * outside to stay in equilibrium, so the support's force is -R there
   * (QuasiStaticResidual keeps these rows). The degrees of freedom of each
   * condition are those that DisplacementConstraints prescribed in the
   * step.
   */
  template <int dim>
  class ReactionForces
  {
  public:
    /// The supports of the step that @p constraints made.
    explicit ReactionForces(const DisplacementConstraints<dim> &constraints);

    /**
     * Per displacement condition, minus the sum of @p residual over its
     * prescribed degrees of freedom, summed over all ranks of
     * @p communicator.
     */
    std::vector<Tensor<1, dim>>
    evaluate(const TrilinosWrappers::MPI::Vector &residual,
             const MPI_Comm                       communicator) const;

  private:
    const DisplacementConstraints<dim> &constraints;
  };
} // namespace qsmpm

#endif
