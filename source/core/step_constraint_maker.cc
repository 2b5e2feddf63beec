#include <cmath>
#include <deal.II/base/mpi.h>
#include <map>
#include <qsmpm/assembly/tangent_assembler.h>
#include <qsmpm/core/step_constraint_maker.h>
#include <qsmpm/loading/constraint_checks.h>
#include <utility>
#include <vector>

namespace qsmpm
{
  template <int dim>
  StepConstraintMaker<dim>::StepConstraintMaker(
    const BackgroundGrid<dim>     &grid,
    const BoundaryDescriptor<dim> &bcs,
    DisplacementConstraints<dim>  &displacement_constraints,
    const ShapeCache<dim>         &cache,
    const MPI_Comm                 communicator)
    : grid(grid)
    , bcs(bcs)
    , displacement_constraints(displacement_constraints)
    , cache(cache)
    , communicator(communicator)
  {
  }



  template <int dim>
  IndexSet
  StepConstraintMaker<dim>::inactive_dofs(
    const MaterialPointSet<dim>                      &points,
    const typename MaterialPointSet<dim>::Parameters &parameters) const
  {
    const double h_dim = std::pow(grid.min_cell_size(), dim);
    return cache.dofs_without_points(grid,
                                     points.get_offsets().volume,
                                     parameters.min_nodal_volume_fraction *
                                       h_dim);
  }



  template <int dim>
  double
  StepConstraintMaker<dim>::mean_stiffness(
    const MaterialPointSet<dim> &points) const
  {
    if (diagonal_of_cache == cache.generation())
      return mean;
    diagonal_of_cache = cache.generation();
    diagonal.reinit(grid.locally_owned_dofs(), communicator);
    TangentAssembler<dim>::assemble_diagonal(points, cache, diagonal);
    // Per node and direction, summed over the bodies' fields (a node's
    // dofs are consecutive, body by body, and owned by one rank): the
    // stiffness scale must not depend on how a node's stiffness is split
    // among the fields of bodies that touch there. Counted per dof of each
    // field, two blocks pressed together had a mean a few percent below
    // that of one block, and a rigid plate's penalty with it (test
    // contact_bodies_loads).
    const unsigned int n_fields = grid.n_bodies();
    const unsigned int stride   = grid.n_node_dofs();
    double             sum = 0., count = 0.;
    for (const auto dof : grid.locally_owned_dofs())
      if (dof % stride < dim)
        {
          double k = 0.;
          for (unsigned int b = 0; b < n_fields; ++b)
            k += diagonal(dof + b * dim);
          if (k > 0.)
            {
              sum += k;
              count += 1.;
            }
        }
    sum   = dealii::Utilities::MPI::sum(sum, communicator);
    count = dealii::Utilities::MPI::sum(count, communicator);
    mean  = count > 0. ? sum / count : 0.;
    return mean;
  }



  template <int dim>
  IndexSet
  StepConstraintMaker<dim>::dofs_without_stiffness(
    const MaterialPointSet<dim>                      &points,
    const typename MaterialPointSet<dim>::Parameters &parameters,
    const GhostPenalty<dim>                          *ghost_penalty) const
  {
    // The stiffness of each dof against its own motion, compared with the
    // mean over the dofs that have any: relative, so that the threshold
    // does not depend on the units or the material.
    const double threshold =
      parameters.min_nodal_stiffness_fraction * mean_stiffness(points);
    if (ghost_penalty == nullptr)
      return grid.dofs_at_most(diagonal, threshold);
    // The ghost penalty gives the nodes of cut cells stiffness: such a node
    // need not be held (held, it would carry the penalty's forces as a
    // support).
    TrilinosWrappers::MPI::Vector stabilized(diagonal);
    ghost_penalty->add_diagonal_to(stabilized);
    return grid.dofs_at_most(stabilized, threshold);
  }



  template <int dim>
  void
  StepConstraintMaker<dim>::make(
    const MaterialPointSet<dim>                      &points,
    const typename MaterialPointSet<dim>::Parameters &parameters,
    const double                                      t_old,
    const double                                      t_new,
    AffineConstraints<double>                        &constraints,
    IndexSet                                         &held_dofs,
    const GhostPenalty<dim>                          *ghost_penalty,
    BodyContact<dim>                                 *body_contact,
    const bool                                        new_contact_set)
  {
    displacement_constraints.make(grid, t_old, t_new, constraints);

    // Which nodes carry material is a matter of the step, not of the
    // boundary conditions: the points move, and a node may lose or gain
    // material from one step to the next (paper Section 2.2).
    const IndexSet inactive = inactive_dofs(points, parameters);

    // Each displacement condition that moves its nodes must still hold
    // material; and all the nodes with material that the conditions hold
    // (each once, in the order of their dofs) must prevent every rigid-body
    // motion, or the step's linear systems are singular. Periodicity holds
    // the body itself.
    const auto &conditions = bcs.dirichlet_conditions();
    std::map<types::global_dof_index, std::pair<Point<dim>, unsigned int>> held;
    for (unsigned int k = 0; k < conditions.size(); ++k)
      {
        unsigned int n_active          = 0;
        double       largest_increment = 0.;
        for (const auto &dof : displacement_constraints.prescribed_dofs(k))
          {
            largest_increment =
              std::max(largest_increment, std::abs(dof.increment));
            if (!inactive.is_element(dof.index))
              {
                ++n_active;
                held.emplace(dof.index,
                             std::make_pair(dof.node, dof.component));
              }
          }
        ConstraintChecks::assert_condition_acts(conditions[k].name,
                                                n_active,
                                                largest_increment,
                                                t_old,
                                                t_new,
                                                communicator);
      }
    // Contact with a rigid body may be what holds the body (a block on a
    // floor): that the points touch it is known only in the step's
    // solution, so the check is left to Newton.
    if (grid.periodic_directions().empty() && bcs.rigid_bodies().empty())
      {
        std::vector<std::pair<Point<dim>, unsigned int>> held_nodes;
        held_nodes.reserve(held.size());
        for (const auto &entry : held)
          held_nodes.push_back(entry.second);
        const Point<dim> &lower = grid.lower_corner();
        const Point<dim> &upper = grid.upper_corner();
        ConstraintChecks::assert_no_rigid_body_motion<dim>(
          held_nodes,
          lower + 0.5 * (upper - lower),
          lower.distance(upper),
          communicator,
          points.get_formulation().axisymmetric);
      }

    // Where two bodies press on each other, their fields are tied (after
    // the displacement conditions, which they respect; between nodes that
    // both have material).
    if (body_contact != nullptr && body_contact->enabled())
      {
        if (new_contact_set)
          body_contact->reinit_step(grid, cache, points, inactive);
        body_contact->add_constraints(constraints);
      }

    // Nodes with no point in their support have no equation: fix their
    // increment to zero. It does not influence any point. Any load on them
    // is lost; the equilibrium audit of the step says so.
    held_dofs = inactive;
    for (const auto dof : inactive)
      if (!constraints.is_constrained(dof))
        constraints.add_line(dof);

    // A node may have points but no stiffness in a direction: all of them
    // have lost it, as the points of a completely failed crack band that
    // opens, when the intact points beside it have moved out of the node's
    // cells. Its equation in that direction is 0 = 0 (the points carry no
    // stress that it could balance), the step's Jacobian is singular, and
    // Newton diverges. Holding it, like a node without points, leaves the
    // equilibrium of the other nodes unchanged.
    if (parameters.min_nodal_stiffness_fraction > 0.)
      {
        const IndexSet without_stiffness =
          dofs_without_stiffness(points, parameters, ghost_penalty);
        held_dofs.add_indices(without_stiffness);
        for (const auto dof : without_stiffness)
          if (!constraints.is_constrained(dof))
            constraints.add_line(dof);
      }
    constraints.close();
  }



  template class StepConstraintMaker<2>;
  template class StepConstraintMaker<3>;
} // namespace qsmpm
