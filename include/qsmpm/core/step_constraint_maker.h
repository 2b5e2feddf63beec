#ifndef qsmpm_core_step_constraint_maker_h
#define qsmpm_core_step_constraint_maker_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <qsmpm/assembly/ghost_penalty.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/loading/body_contact.h>
#include <qsmpm/loading/boundary_descriptor.h>
#include <qsmpm/loading/displacement_constraints.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>

namespace qsmpm
{
  /**
   * The constraints of a load step t_old -> t_new: those of the
   * displacement conditions (and periodicity), checked against the
   * material, and zero increments on the nodes without enough material or
   * stiffness. Which nodes carry material is a matter of the step, not of
   * the boundary conditions: the points move, and a node may lose or gain
   * material from one step to the next (paper Section 2.2).
   */
  template <int dim>
  class StepConstraintMaker
  {
  public:
    /// The objects are kept; the step's shape functions must be in
    /// @p cache when make() is called, and @p displacement_constraints
    /// records the prescribed dofs of the step (for its reactions).
    StepConstraintMaker(const BackgroundGrid<dim>     &grid,
                        const BoundaryDescriptor<dim> &bcs,
                        DisplacementConstraints<dim>  &displacement_constraints,
                        const ShapeCache<dim>         &cache,
                        const MPI_Comm                 communicator);

    /**
     * The closed @p constraints of the step t_old -> t_new for @p points
     * (with the thresholds of @p parameters), and in @p held the degrees
     * of freedom held for lack of material or stiffness. Throws if a
     * displacement condition that moves its nodes holds no material, or if
     * the held nodes with material allow a rigid-body motion.
     */
    void
    make(const MaterialPointSet<dim>                      &points,
         const typename MaterialPointSet<dim>::Parameters &parameters,
         const double                                      t_old,
         const double                                      t_new,
         AffineConstraints<double>                        &constraints,
         IndexSet                                         &held,
         const GhostPenalty<dim> *ghost_penalty   = nullptr,
         BodyContact<dim>        *body_contact    = nullptr,
         const bool               new_contact_set = true);

    /**
     * The mean over the dofs that have stiffness of the diagonal of the
     * tangent at the points (TangentAssembler::assemble_diagonal()), on a
     * grid of several bodies' fields over each node's directions with the
     * diagonal summed over its fields: the stiffness scale of the ghost
     * penalty, the rigid bodies' and plates' penalties and the
     * held-stiffness threshold. Computed once per state of the shape cache (a
     * pass over all points), however often a step asks.
     */
    double
    mean_stiffness(const MaterialPointSet<dim> &points) const;

  private:
    /// The degrees of freedom without enough material (no equation).
    IndexSet
    inactive_dofs(
      const MaterialPointSet<dim>                      &points,
      const typename MaterialPointSet<dim>::Parameters &parameters) const;

    /**
     * The degrees of freedom whose stiffness against their own motion (the
     * diagonal of the tangent, TangentAssembler::assemble_diagonal()) is at
     * most <Material points/Minimum nodal stiffness> times the mean over
     * the dofs: held fixed in the step.
     */
    IndexSet
    dofs_without_stiffness(
      const MaterialPointSet<dim>                      &points,
      const typename MaterialPointSet<dim>::Parameters &parameters,
      const GhostPenalty<dim>                          *ghost_penalty) const;

    const BackgroundGrid<dim>     &grid;
    const BoundaryDescriptor<dim> &bcs;
    /// Records the dofs of the reactions of every step it makes.
    DisplacementConstraints<dim> &displacement_constraints;
    const ShapeCache<dim>        &cache;
    const MPI_Comm                communicator;
    /// The diagonal of the last mean_stiffness(), its mean, and the
    /// generation of the shape cache it belongs to.
    mutable TrilinosWrappers::MPI::Vector diagonal;
    mutable double                        mean = 0.;
    mutable unsigned long diagonal_of_cache    = static_cast<unsigned long>(-1);
  };
} // namespace qsmpm

#endif
