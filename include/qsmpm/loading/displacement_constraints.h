#ifndef qsmpm_loading_displacement_constraints_h
#define qsmpm_loading_displacement_constraints_h

#include <deal.II/lac/affine_constraints.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/loading/boundary_descriptor.h>
#include <vector>

namespace qsmpm
{
  /**
   * The constraints that the displacement conditions of a BoundaryDescriptor
   * impose on the grid displacement increment of one load step t_old ->
   * t_new (paper eq. 2.16): du_i = g(x_i, t_new) - g(x_i, t_old) on every
   * node and component a condition selects, and, on a grid with periodic
   * directions, the periodicity constraints with the increment of the
   * macroscopic jump.
   *
   * make() also records, for every condition, the locally owned degrees of
   * freedom it prescribes: ReactionForces sums the residual over them, and
   * the checks of the step (ConstraintChecks) ask whether they carry
   * material. Which nodes carry material is not a boundary condition: the
   * caller adds the constraints of the nodes without points (see
   * QuasiStaticProblem) and closes the constraints.
   */
  template <int dim>
  class DisplacementConstraints
  {
  public:
    /**
     * A locally owned degree of freedom that a displacement condition
     * prescribes: its index, component and node, and the increment that the
     * condition prescribes there (the constraint itself holds the increment
     * of the first condition that reached it).
     */
    struct PrescribedDof
    {
      types::global_dof_index index;
      unsigned int            component;
      Point<dim>              node;
      double                  increment;
    };

    /// The conditions of @p boundary, which must outlive this object.
    explicit DisplacementConstraints(const BoundaryDescriptor<dim> &boundary);

    /**
     * Clear @p constraints and fill them, for the locally relevant degrees
     * of freedom of @p grid, with the periodicity constraints (if the grid
     * is periodic) and the displacement increments of the step t_old ->
     * t_new. They are not closed. Throws if a condition selects no node of
     * the grid.
     */
    void
    make(const BackgroundGrid<dim> &grid,
         const double               t_old,
         const double               t_new,
         AffineConstraints<double> &constraints);

    /// The number of displacement conditions of the last make().
    unsigned int
    n_conditions() const;

    /**
     * The locally owned degrees of freedom that condition @p k (in the order
     * of BoundaryDescriptor::dirichlet_conditions()) prescribed in the last
     * make(), sorted by index, each once.
     */
    const std::vector<PrescribedDof> &
    prescribed_dofs(const unsigned int k) const;

  private:
    /// The periodicity lines of make(), with the macroscopic jump.
    void
    add_periodicity_constraints(const BackgroundGrid<dim> &grid,
                                const double               t_old,
                                const double               t_new,
                                AffineConstraints<double> &constraints) const;

    /// The lines of condition @p k.
    void
    add_condition(const unsigned int         k,
                  const BackgroundGrid<dim> &grid,
                  const double               t_old,
                  const double               t_new,
                  AffineConstraints<double> &constraints);

    const BoundaryDescriptor<dim>          &boundary;
    std::vector<std::vector<PrescribedDof>> prescribed;
  };
} // namespace qsmpm

#endif
