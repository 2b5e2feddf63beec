#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/loading/rigid_contact.h>
#include <sstream>

namespace qsmpm
{
  namespace
  {
    // The stiffness of sticking relative to that of the normal contact. At
    // the full penalty a point goes from stick to slip within a
    // thousandth of a step's motion, and Newton cycled between the two
    // (the block on a sliding floor of test contact_rigid_bodies: no
    // convergence in the first sliding step even with line search and
    // four cut-backs); at a tenth it converges in 4-11 iterations.
    constexpr double tangential_scale = 0.1;
  } // namespace
  template <int dim>
  RigidContact<dim>::RigidContact(const BoundaryDescriptor<dim> &boundary)
    : boundary(boundary)
  {
  }



  template <int dim>
  bool
  RigidContact<dim>::empty() const
  {
    return boundary.rigid_bodies().empty();
  }



  template <int dim>
  void
  RigidContact<dim>::reinit_step(const BackgroundGrid<dim>   &grid,
                                 const ShapeCache<dim>       &shape_cache,
                                 const MaterialPointSet<dim> &points,
                                 const VectorType            &ghosted_layout,
                                 const double                 t_old,
                                 const double                 t_new,
                                 const double                 stiffness_scale)
  {
    const auto &bodies = boundary.rigid_bodies();
    cache              = &shape_cache;
    candidates.clear();
    dof_global.clear();
    dof_local.clear();
    dof_component.clear();
    dof_values.clear();
    if (bodies.empty())
      return;
    const auto &offsets = points.get_offsets();
    AssertThrow(offsets.contact != numbers::invalid_unsigned_int,
                ExcMessage("Rigid bodies: the material points carry no "
                           "contact traction; add the rigid bodies before "
                           "the points are made."));
    contact_offset       = offsets.contact;
    const double h       = grid.min_cell_size();
    const double margin  = 2. * h;
    const bool   finite  = points.get_formulation().finite_strain();
    const bool   gimp    = points.get_formulation().gimp();
    const double h_power = std::pow(h, dim - 1);
    const auto  &fe      = grid.get_dof_handler().get_fe();
    dofs_per_cell        = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> cell_dofs(dofs_per_cell);
    const Epetra_BlockMap &ghosted_map = ghosted_layout.trilinos_vector().Map();
    penalty.resize(bodies.size());
    body_displacement.resize(bodies.size());
    body_increment.resize(bodies.size());
    // At the start of a run no body may hold material: a point whose
    // surface lies deeper in a body than the point's own size is a body
    // placed inside the material (a tied body holds what lies in it).
    const bool          first_step = t_old == 0.;
    std::vector<double> overlap(bodies.size(), 0.);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        penalty[b] = bodies[b].penalty_factor * stiffness_scale / h_power;
        body_displacement[b] = bodies[b].displacement(t_new);
        body_increment[b] =
          body_displacement[b] - bodies[b].displacement(t_old);
      }

    for (unsigned int c = 0; c < cache->n_cells(); ++c)
      {
        const auto &range = cache->cell(c);
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const double    *data = cache->properties(p);
            const Point<dim> x    = cache->position(p);
            // The point's box: half-lengths and its deformation so far.
            Tensor<1, dim> half;
            for (unsigned int d = 0; d < dim; ++d)
              half[d] =
                gimp ? data[offsets.initial_half_length + d] :
                       0.5 * std::pow(data[offsets.initial_volume], 1. / dim);
            const Tensor<2, dim> F =
              finite ?
                Utils::read_tensor<dim>(data + offsets.deformation_gradient) :
                Tensor<2, dim>(
                  unit_symmetric_tensor<dim>() +
                  Utils::read_symmetric<dim>(data + offsets.strain));
            for (unsigned int b = 0; b < bodies.size(); ++b)
              {
                Tensor<1, dim> n;
                const double   centre_gap =
                  bodies[b].signed_distance(x, body_displacement[b], n);
                if (centre_gap > margin + half.norm() * F.norm())
                  continue;
                Tensor<1, dim> a;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    Tensor<1, dim> edge;
                    for (unsigned int i = 0; i < dim; ++i)
                      edge[i] = F[i][d] * half[d];
                    a -= (n * edge) / edge.norm() * edge;
                  }
                const double r = -(n * a);
                if (!(r > 0.))
                  continue;
                const Point<dim> corner = x + a;
                // Relative to the body's reference point, as the gap is
                // evaluated in every residual (small near the surface).
                const Tensor<1, dim> relative =
                  (corner - bodies[b].point) - body_displacement[b];
                Tensor<1, dim> n_corner;
                const double   gap =
                  bodies[b].signed_distance_from_point(relative, n_corner);
                if (first_step &&
                    bodies[b].friction != RigidBody<dim>::Friction::tied)
                  {
                    Tensor<1, dim> n_start;
                    const double depth = -bodies[b].signed_distance_from_point(
                      (corner - bodies[b].point) -
                        bodies[b].displacement(t_old),
                      n_start);
                    if (depth > 2. * r)
                      overlap[b] = std::max(overlap[b], depth);
                  }
                if (gap > margin)
                  continue;
                // A tied body holds the points whose surface touches it
                // (within half their size) or lies in it, and no others.
                const bool tied =
                  bodies[b].friction == RigidBody<dim>::Friction::tied;
                if (tied && !(gap < r))
                  continue;
                Candidate candidate;
                candidate.point    = p;
                candidate.body     = b;
                candidate.first    = dof_values.size();
                candidate.relative = relative;
                candidate.area     = data[offsets.volume] / (2. * r);
                // Points that touch the body count too: a body resting on
                // another is held only by the contact.
                candidate.penetrates = tied || gap <= 1e-8 * h;
                // The grid's Q1 functions of the point's cell at the
                // corner (extrapolated if the corner lies beyond the
                // cell): the nodes of that cell are in the point's stencil
                // and in the pattern of the stiffness.
                const auto &cell = cache->cell(c).cell;
                const typename DoFHandler<dim>::active_cell_iterator dof_cell(
                  &grid.get_triangulation(),
                  cell->level(),
                  cell->index(),
                  &grid.get_dof_handler());
                dof_cell->get_dof_indices(cell_dofs);
                const Point<dim> xi =
                  grid.get_mapping().transform_real_to_unit_cell(cell, corner);
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  {
                    const unsigned int component =
                      fe.system_to_component_index(i).first;
                    dof_global.push_back(cell_dofs[i]);
                    dof_local.push_back(ghosted_map.LID(
                      static_cast<TrilinosWrappers::types::int_type>(
                        cell_dofs[i])));
                    dof_component.push_back(component);
                    dof_values.push_back(
                      fe.shape_value_component(i, xi, component));
                  }
                candidates.push_back(candidate);
              }
          }
      }
    if (first_step)
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          const double depth =
            dealii::Utilities::MPI::max(overlap[b], grid.get_communicator());
          if (depth == 0.)
            continue;
          std::ostringstream message;
          message << "Rigid body <" << bodies[b].name
                  << "> starts inside the material: at t = 0 the surface of "
                     "a material point lies "
                  << depth
                  << " inside it, more than the point's size. Move the "
                     "body's <Point> (or the material) so that they touch "
                     "at most; a support that holds the material in it is "
                     "<Friction = tied>.";
          AssertThrow(false, ExcMessage(message.str()));
        }
    any = dealii::Utilities::MPI::logical_or(!candidates.empty(),
                                             grid.get_communicator());
    if (any)
      {
        du_ghosted.reinit(ghosted_layout);
        forces.reinit(ghosted_layout.locally_owned_elements(),
                      ghosted_layout.get_mpi_communicator());
        values.resize(dofs_per_cell);
      }
  }



  template <int dim>
  double
  RigidContact<dim>::motion_scale(const VectorType &layout) const
  {
    double largest = 0.;
    for (const auto &increment : body_increment)
      largest = std::max(largest, increment.norm());
    return largest * std::sqrt(static_cast<double>(layout.size()));
  }



  template <int dim>
  Tensor<1, dim>
  RigidContact<dim>::traction(const Candidate &c,
                              const double    *du_local,
                              Tensor<1, dim>  &n,
                              double          &gap,
                              bool            &active) const
  {
    const RigidBody<dim> &body = boundary.rigid_bodies()[c.body];
    // The contact point's displacement in the step: sum_i N_i(x_c) du_i.
    Tensor<1, dim> u;
    for (unsigned int i = c.first; i < c.first + dofs_per_cell; ++i)
      u[dof_component[i]] += dof_values[i] * du_local[dof_local[i]];
    gap             = body.signed_distance_from_point(c.relative + u, n);
    const bool tied = body.friction == RigidBody<dim>::Friction::tied;
    active          = tied || gap < 0.;
    if (!active)
      return Tensor<1, dim>();
    const double pressure = -penalty[c.body] * gap;
    if (body.friction == RigidBody<dim>::Friction::frictionless)
      return pressure * n;
    // The traction of the last step, stored on the point.
    const double *old =
      cache->properties(c.point) + contact_offset + c.body * dim;
    Tensor<1, dim> t_old;
    for (unsigned int d = 0; d < dim; ++d)
      t_old[d] = old[d];
    // Tied: the last step's traction plus the penalty of the contact
    // point's motion relative to the body, in every direction.
    if (tied)
      return t_old - penalty[c.body] * (u - body_increment[c.body]);
    Tensor<1, dim> t = pressure * n;
    // Return map of the tangential traction: the last step's, plus the
    // penalty of the slip of the contact point relative to the body.
    Tensor<1, dim> tau = t_old;
    tau -= tangential_scale * penalty[c.body] * (u - body_increment[c.body]);
    tau -= (tau * n) * n;
    if (body.friction == RigidBody<dim>::Friction::coulomb)
      {
        const double limit = body.friction_coefficient * pressure;
        const double size  = tau.norm();
        if (size > limit)
          tau *= limit / size;
      }
    return t + tau;
  }



  template <int dim>
  template <typename Action>
  void
  RigidContact<dim>::for_each_contact(const VectorType &du,
                                      const Action     &action) const
  {
    if (!any)
      return;
    du_ghosted             = du;
    const double *du_local = du_ghosted.trilinos_vector()[0];
    for (const Candidate &c : candidates)
      {
        Tensor<1, dim>       n;
        double               gap;
        bool                 active;
        const Tensor<1, dim> t = traction(c, du_local, n, gap, active);
        if (active)
          action(c, t, gap);
      }
  }



  template <int dim>
  void
  RigidContact<dim>::add_contact_forces(const VectorType &du,
                                        VectorType       &R) const
  {
    if (!any)
      return;
    forces = 0.;
    for_each_contact(
      du, [&](const Candidate &c, const Tensor<1, dim> &t, double) {
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          values[i] =
            dof_values[c.first + i] * c.area * t[dof_component[c.first + i]];
        forces.add(dofs_per_cell, &dof_global[c.first], values.data());
      });
    forces.compress(VectorOperation::add);
    R += forces;
  }



  template <int dim>
  std::vector<typename RigidContact<dim>::BodyLoad>
  RigidContact<dim>::body_loads(const VectorType &du) const
  {
    std::vector<BodyLoad> loads(boundary.rigid_bodies().size());
    for_each_contact(
      du, [&](const Candidate &c, const Tensor<1, dim> &t, const double gap) {
        BodyLoad &load = loads[c.body];
        load.force -= c.area * t;
        ++load.n_points;
        load.penetration = std::max(load.penetration, -gap);
      });
    const MPI_Comm communicator = du.get_mpi_communicator();
    for (BodyLoad &load : loads)
      {
        load.force = dealii::Utilities::MPI::sum(load.force, communicator);
        load.n_points =
          dealii::Utilities::MPI::sum(load.n_points, communicator);
        load.penetration =
          dealii::Utilities::MPI::max(load.penetration, communicator);
      }
    return loads;
  }



  template <int dim>
  bool
  RigidContact<dim>::slipped(const Candidate &c, const Tensor<1, dim> &n) const
  {
    const double *stored =
      cache->properties(c.point) + contact_offset + c.body * dim;
    Tensor<1, dim> t;
    for (unsigned int d = 0; d < dim; ++d)
      t[d] = stored[d];
    const double pressure = t * n;
    const double mu = boundary.rigid_bodies()[c.body].friction_coefficient;
    return pressure > 0. &&
           (t - pressure * n).norm() >= (1. - 1e-9) * mu * pressure;
  }



  template <int dim>
  void
  RigidContact<dim>::add_to(const AffineConstraints<double> &constraints,
                            TrilinosWrappers::SparseMatrix  &K) const
  {
    FullMatrix<double>                   K_point;
    std::vector<types::global_dof_index> dofs;
    for (const Candidate &c : candidates)
      {
        if (!c.penetrates)
          continue;
        const RigidBody<dim> &body = boundary.rigid_bodies()[c.body];
        Tensor<1, dim>        n;
        body.signed_distance_from_point(c.relative, n);
        // epsilon A (n (x) n), with friction plus epsilon_T A P if the
        // point sticks. Which points slip in this step is not known yet:
        // those whose traction of the last step was at the Coulomb limit
        // are taken to slip on (their tangential stiffness is zero, and a
        // preconditioner that gave them the stick's would be far from the
        // Jacobian: GMRES then met its tolerance on directions along
        // which Newton's residual did not fall, and the block on a
        // sliding floor stalled at 1e-5 of its first residual).
        const Tensor<2, dim> normal_part = outer_product(n, n);
        Tensor<2, dim>       stiffness   = normal_part;
        if (body.friction == RigidBody<dim>::Friction::tied)
          stiffness = unit_symmetric_tensor<dim>();
        else if (body.friction == RigidBody<dim>::Friction::rough ||
                 (body.friction == RigidBody<dim>::Friction::coulomb &&
                  !slipped(c, n)))
          stiffness +=
            tangential_scale * (unit_symmetric_tensor<dim>() - normal_part);
        stiffness *= penalty[c.body] * c.area;
        K_point.reinit(dofs_per_cell, dofs_per_cell);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = 0; j < dofs_per_cell; ++j)
            K_point(i, j) =
              dof_values[c.first + i] * dof_values[c.first + j] *
              stiffness[dof_component[c.first + i]][dof_component[c.first + j]];
        dofs.assign(dof_global.begin() + c.first,
                    dof_global.begin() + c.first + dofs_per_cell);
        constraints.distribute_local_to_global(K_point, dofs, K);
      }
  }



  template <int dim>
  void
  RigidContact<dim>::commit(MaterialPointSet<dim> &points,
                            const VectorType      &du_ghosted_step) const
  {
    const double *du_local = du_ghosted_step.trilinos_vector()[0];
    for (const Candidate &c : candidates)
      {
        Tensor<1, dim>       n;
        double               gap;
        bool                 active;
        const Tensor<1, dim> t = traction(c, du_local, n, gap, active);
        double              *data =
          cache->properties(c.point, points) + contact_offset + c.body * dim;
        for (unsigned int d = 0; d < dim; ++d)
          data[d] = t[d];
      }
  }



  template class RigidContact<2>;
  template class RigidContact<3>;
} // namespace qsmpm
