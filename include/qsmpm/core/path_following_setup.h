#ifndef qsmpm_core_path_following_setup_h
#define qsmpm_core_path_following_setup_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <functional>
#include <memory>
#include <qsmpm/core/step_operator.h>
#include <qsmpm/loading/boundary_descriptor.h>
#include <qsmpm/loading/load_stepper.h>
#include <qsmpm/loading/opening_gauge.h>
#include <qsmpm/loading/step_constraints.h>
#include <qsmpm/materials/constitutive_model.h>
#include <qsmpm/particles/shape_cache.h>
#include <qsmpm/solvers/path_following_newton.h>

namespace qsmpm
{
  /**
   * What a load step of path following (Load stepping/Control =
   * dissipation or opening) needs besides the step's constraints and
   * residual: the checks that the problem allows it, the direction g of
   * the prescribed increments per unit load factor, and the path
   * constraint with its force guard for PathFollowingNewton. Path
   * following scales the prescribed displacements with the unknown load
   * factor, so they must be proportional to it (u = t g(x)), and nothing
   * else may load the body.
   */
  template <int dim>
  class PathFollowingSetup
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;
    using Solver     = PathFollowingNewton<StepOperator<dim>, VectorType>;

    /**
     * With Control = opening: make the gauge of @p stepper's parameters
     * (anew, at the start of every run, so that a malformed gauge stops the
     * run before any output; constraint() makes it if it was not made).
     */
    void
    make_gauge(const LoadStepper &stepper);

    /**
     * Check that @p stepper's Control applies to the problem: loads that
     * are functions of t would need their own scaling, and the generalized
     * force (the sign guard) assumes that the prescribed displacements are
     * the only work-conjugate of the load factor; Control = dissipation
     * needs a @p model that computes its dissipation.
     */
    static void
    check_problem(const LoadStepper             &stepper,
                  const BoundaryDescriptor<dim> &bcs,
                  const ConstitutiveModel<dim>  &model);

    /**
     * The direction @p g (a vector of the layout of the step's vectors):
     * the inhomogeneities of @p unit, the step constraints of a unit
     * load-factor increment. Checks that it is not zero and, the first
     * time, that the prescribed displacements are proportional to the
     * load factor: @p make_doubled makes the constraints of an increment
     * of two, whose inhomogeneities must be 2 g on the locally owned dofs
     * @p owned (of all ranks of @p communicator).
     */
    void
    make_direction(
      const LoadStepper                                      &stepper,
      const StepConstraints                                  &unit,
      const std::function<void(AffineConstraints<double> &)> &make_doubled,
      const IndexSet                                         &owned,
      const MPI_Comm                                          communicator,
      VectorType                                             &g);

    /**
     * The path constraint of the next attempt of @p stepper: either the
     * energy the points dissipate in the step (see PathFollowingNewton for
     * why not the global formula of Gutierrez) or the opening of the
     * gauge, whose vector is made for the step's shape functions in
     * @p cache (the points' displacements at @p displacement in their
     * data; @p cell_size the grid's smallest cell) with the layout of
     * @p layout. The constraint refers to that vector, which this object
     * keeps until the next call.
     */
    typename Solver::Constraint
    constraint(const LoadStepper     &stepper,
               const ShapeCache<dim> &cache,
               const unsigned int     displacement,
               const double           cell_size,
               const MPI_Comm         communicator,
               const VectorType      &layout);

    /**
     * The load keeps the sign of its peak so far, up to 1e-3 of the peak
     * (the noise of a converged step in the tail is far below that).
     */
    static typename Solver::ForceGuard
    force_guard(const LoadStepper &stepper);

  private:
    /// Whether make_direction() has checked the proportionality.
    bool proportionality_checked = false;
    /// With Control = opening: the gauge, and its vector of the step.
    std::unique_ptr<OpeningGauge<dim>> gauge;
    VectorType                         w;
  };
} // namespace qsmpm

#endif
