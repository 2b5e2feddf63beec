#ifndef qsmpm_core_preconditioner_handover_h
#define qsmpm_core_preconditioner_handover_h

#include <array>
#include <memory>
#include <qsmpm/assembly/tangent_assembler.h>
#include <qsmpm/solvers/preconditioner.h>

namespace qsmpm
{
  /**
   * The stiffness matrix at the points and the preconditioner built from
   * it, as one QuasiStaticProblem hands them to another
   * (QuasiStaticProblem::hand_over_preconditioner() and
   * take_over_preconditioner()): the load cases of one sample, which start
   * from the same points in the same state, need the same stiffness as long
   * as they fix the same degrees of freedom (VirtualTests).
   *
   * The preconditioner (an AMG hierarchy, a factorization) refers to the
   * matrix, so both travel together.
   */
  template <int dim>
  struct PreconditionerHandover
  {
    std::unique_ptr<TangentAssembler<dim>> tangent;
    std::unique_ptr<Preconditioner<dim>>   preconditioner;
    /// The tangent the matrix holds.
    typename TangentAssembler<dim>::Tangent tangent_kind =
      TangentAssembler<dim>::Tangent::secant;
    /// The constrained degrees of freedom it was built for
    /// (PreconditionerReuse::constrained_signature()).
    std::array<double, 2> constrained{{-1., -1.}};
  };
} // namespace qsmpm

#endif
