#ifndef qsmpm_loading_preconditioner_correction_h
#define qsmpm_loading_preconditioner_correction_h

#include <functional>

namespace qsmpm
{
  /**
   * What a boundary condition adds to the step's preconditioner when the
   * preconditioner's matrix cannot hold it: a rigid plate's tie
   * (RigidPlates) or the free motion of a body driven by a force
   * (RigidContact). precondition() applies the completed preconditioner
   * with the given one, M, inside; StepOperator chains the corrections.
   */
  template <typename VectorType>
  class PreconditionerCorrection
  {
  public:
    /// dst = M(src): a preconditioner of the step's matrix K_A, with the
    /// sign of Preconditioner::vmult() (dst = -K_A^{-1} src).
    using Preconditioning =
      std::function<void(VectorType &, const VectorType &)>;

    virtual ~PreconditionerCorrection() = default;

    /// Whether there is a correction to apply in this step.
    virtual bool
    has_preconditioner() const = 0;

    /// dst = the completed preconditioner applied to @p src, with @p M
    /// inside. Collective.
    virtual void
    precondition(const Preconditioning &M,
                 VectorType            &dst,
                 const VectorType      &src) const = 0;
  };
} // namespace qsmpm

#endif
