#ifndef qsmpm_core_step_operator_h
#define qsmpm_core_step_operator_h

#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_vector.h>
#include <functional>
#include <iomanip>
#include <qsmpm/assembly/local_stiffness.h>
#include <qsmpm/assembly/quasi_static_residual.h>
#include <qsmpm/loading/rigid_contact.h>
#include <qsmpm/loading/rigid_plates.h>
#include <qsmpm/loading/step_constraints.h>
#include <qsmpm/loading/surface_tractions.h>
#include <qsmpm/solvers/newton_krylov.h>
#include <qsmpm/solvers/preconditioner.h>
#include <sstream>
#include <utility>
#include <vector>

namespace qsmpm
{
  /**
   * The nonlinear problem of one load step as NewtonKrylov sees it: the
   * residual of the points, condensed with the step's constraints, the
   * projections of residuals and corrections onto their spaces, and the
   * preconditioner.
   */
  template <int dim>
  class StepOperator
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;
    /// What a residual evaluation found on this rank's points.
    using Evaluation = typename QuasiStaticResidual<dim>::Evaluation;

    /// The step's operator; @p stabilizations, linear terms G du (the
    /// ghost penalty of cut cells, the springs of NullModeHold), stabilize
    /// nodes with little or no stiffness; @p pressures, if given, add the
    /// pressures on the body's surface, which follow the increment; @p contact,
    /// if given, the contact forces of rigid bodies; @p plates, if given, ties
    /// the nodes of rigid plates.
    StepOperator(const QuasiStaticResidual<dim>     &residual,
                 const StepConstraints              &constraints,
                 const Preconditioner<dim>          &preconditioner,
                 std::vector<const LocalStiffness *> stabilizations  = {},
                 const SurfaceTractions<dim>        *pressures       = nullptr,
                 const RigidContact<dim>            *contact         = nullptr,
                 const double                        increment_floor = 0.,
                 const RigidPlates<dim>             *plates          = nullptr)
      : residual_evaluator(residual)
      , constraints(constraints)
      , preconditioner(preconditioner)
      , stabilizations(std::move(stabilizations))
      , pressures(pressures)
      , contact(contact)
      , increment_floor(increment_floor)
      , plates(plates)
    {
    }

    /// R(du) = f_ext - f_int(du) (QuasiStaticResidual) - G du (the
    /// stabilizations, if any) + f_p(du) (the pressures, if any) + f_c(du) (the
    /// contact forces, if any), with coupled rows added to their masters,
    /// and with rigid plates (if any) evaluated at P du with their rows
    /// tied (RigidPlates); returns what the evaluation found on this
    /// rank's points.
    Evaluation
    residual(const VectorType &du, VectorType &R) const
    {
      if (plates == nullptr)
        return residual_of(du, R);
      // With rigid plates: the residual of the increment in which each
      // plate moves as one, with the plates' rows tied (RigidPlates).
      projected.reinit(du, /*omit_zeroing_entries=*/true);
      const std::vector<double> mean       = plates->project(du, projected);
      const Evaluation          evaluation = residual_of(projected, R);
      plates->tie(du, mean, R);
      return evaluation;
    }

    /// Zero the rows without an equation of a residual-like vector.
    void
    set_constrained_to_zero(VectorType &v) const
    {
      constraints.set_constrained_to_zero(v);
    }

    /// Make a correction satisfy the homogeneous constraints.
    void
    make_admissible(VectorType &v) const
    {
      constraints.make_admissible(v);
    }

    /**
     * The size of a typical increment where none is known (the
     * finite-difference step at du = 0): a displacement of one cell size
     * at every degree of freedom, so that a perturbation of relative size
     * sqrt(eps) strains the points by about sqrt(eps).
     */
    double
    typical_increment_norm() const
    {
      return residual_evaluator.typical_increment_norm();
    }

    /**
     * The smallest size of the increments of interest for the
     * Jacobian-free products (JacobianFreeOperator): the constructor's
     * @p increment_floor (0 by default) or, if larger, the rigid bodies'
     * motion in the step at every degree of freedom. A step of a
     * consolidating body under a constant load moves it by a tiny amount
     * while its stresses are large: finite differences relative to that
     * increment would be round-off (QuasiStaticProblem gives a floor of
     * 1e-6 of typical_increment_norm() with a pore fluid). The floor holds
     * with rigid bodies too: a footing held at a constant force does not
     * move by a prescribed motion, and without the floor its consolidating
     * soil's Newton iterations stalled (the products were round-off).
     */
    double
    increment_scale_floor() const
    {
      if (contact == nullptr)
        return increment_floor;
      // A motion of round-off size (a body that starts to move at the end
      // of the step) is none.
      const double motion =
        contact->motion_scale(residual_evaluator.ghosted_layout());
      return std::max(increment_floor,
                      motion > 1e-10 * typical_increment_norm() ? motion : 0.);
    }

    /**
     * The energy all points dissipate in the trial state of the residual()
     * that returned @p evaluation (summed over the ranks), for path
     * following.
     */
    double
    dissipation(const Evaluation &evaluation) const
    {
      return dealii::Utilities::MPI::sum(evaluation.dissipation,
                                         constraints.get_communicator());
    }

    /**
     * Reject a converged step whose solution, the state of the residual()
     * that returned @p evaluation, turned a point inside out: at small
     * strain J = (1 + tr d eps) J_old can pass zero while the residual
     * stays finite. Such a step fails (and is cut back) like one that did
     * not converge.
     */
    void
    reject_inverted_points(const Evaluation &evaluation,
                           NewtonReport     &report) const
    {
      if (!report.converged)
        return;
      const double min_J =
        dealii::Utilities::MPI::min(evaluation.minimum_volume_ratio,
                                    constraints.get_communicator());
      if (!(min_J > 0.))
        {
          std::ostringstream message;
          message << "a material point was turned inside out (J = "
                  << std::setprecision(3) << min_J << " <= 0)";
          report.converged = false;
          report.failure   = message.str();
        }
    }

    /**
     * Have update_preconditioner() call @p update, which builds the
     * preconditioner anew for the iterate it is given
     * (QuasiStaticProblem: the stiffness at the iterate).
     */
    void
    set_preconditioner_update(std::function<void(const VectorType &)> update)
    {
      preconditioner_update = std::move(update);
    }

    /// Called by NewtonKrylov before each linear solve with the iterate
    /// @p du: the update of set_preconditioner_update(), if any.
    void
    update_preconditioner(const VectorType &du) const
    {
      if (preconditioner_update)
        preconditioner_update(du);
    }

    /// The preconditioner, completed by the bodies driven by a force
    /// (RigidContact::precondition()) and then by the plates' tie
    /// (RigidPlates::precondition()) where there are such.
    void
    precondition(VectorType &dst, const VectorType &src) const
    {
      corrected_preconditioner(2, dst, src);
    }

  private:
    /// The preconditioner completed by the first @p n of the bodies'
    /// and the plates' corrections (those that have one in this step).
    void
    corrected_preconditioner(const unsigned int n,
                             VectorType        &dst,
                             const VectorType  &src) const
    {
      if (n == 0)
        {
          preconditioner.vmult(dst, src);
          return;
        }
      const PreconditionerCorrection<VectorType> *correction =
        n == 1 ?
          static_cast<const PreconditionerCorrection<VectorType> *>(contact) :
          plates;
      if (correction == nullptr || !correction->has_preconditioner())
        corrected_preconditioner(n - 1, dst, src);
      else
        correction->precondition(
          [this, n](VectorType &d, const VectorType &s) {
            corrected_preconditioner(n - 1, d, s);
          },
          dst,
          src);
    }

    /// The residual of all the terms above but the plates' tie.
    Evaluation
    residual_of(const VectorType &du, VectorType &R) const
    {
      const Evaluation evaluation = residual_evaluator.evaluate(du, R);
      for (const LocalStiffness *term : stabilizations)
        term->subtract_forces(du, R);
      if (pressures != nullptr)
        pressures->add_pressure_forces(du, R);
      if (contact != nullptr)
        contact->add_contact_forces(du, R);
      constraints.condense(R);
      return evaluation;
    }

    const QuasiStaticResidual<dim>           &residual_evaluator;
    const StepConstraints                    &constraints;
    const Preconditioner<dim>                &preconditioner;
    std::function<void(const VectorType &)>   preconditioner_update;
    const std::vector<const LocalStiffness *> stabilizations;
    const SurfaceTractions<dim>              *pressures;
    const RigidContact<dim>                  *contact;
    /// increment_scale_floor() without rigid bodies.
    const double            increment_floor;
    const RigidPlates<dim> *plates;
    /// The increment with the plates moved as one (scratch of residual()).
    mutable VectorType projected;
  };
} // namespace qsmpm

#endif
