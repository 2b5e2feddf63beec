#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <iomanip>
#include <limits>
#include <qsmpm/base/utilities.h>
#include <qsmpm/grid/field_shape_values.h>
#include <qsmpm/loading/rigid_contact.h>
#include <qsmpm/particles/initial_measure.h>
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

    // A point goes on from the contact point the grid moved while the
    // body's normal, taken this many cell sizes behind it (far more than a
    // contact point's penetration under the penalty, about 1e-4 h under a
    // footing), has turned by less than arccos(follow_cosine) = 60 degrees
    // (RigidContact's class description).
    constexpr double follow_probe_depth = 0.01;
    constexpr double follow_cosine      = 0.5;

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
                                 const double                 stiffness_scale,
                                 const std::vector<double> &load_displacements)
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
    offsets = points.get_offsets();
    AssertThrow(offsets.contact != numbers::invalid_unsigned_int,
                ExcMessage("Rigid bodies: the material points carry no "
                           "contact traction; add the rigid bodies before "
                           "the points are made."));
    contact_offset       = offsets.contact;
    const double h       = grid.min_cell_size();
    const double margin  = 2. * h;
    finite               = points.get_formulation().finite_strain();
    gimp                 = points.get_formulation().gimp();
    move_points          = points.get_formulation().move_points;
    const double h_power = std::pow(h, dim - 1);
    // Axisymmetric: the grid's stiffness is per radian, r times that of a
    // plane problem; the penalty is the plane one at the grid's mid-radius.
    axisymmetric = points.get_formulation().axisymmetric;
    const double radius =
      axisymmetric ? 0.5 * (grid.lower_corner()[0] + grid.upper_corner()[0]) :
                     1.;
    // On a multi-field grid (Contact between bodies) a point meets a body
    // through its own body's field only: a candidate holds the dofs of
    // that field, dofs_per_cell of the cell's fe.n_dofs_per_cell().
    const auto        &fe       = grid.get_dof_handler().get_fe();
    const unsigned int all_dofs = fe.n_dofs_per_cell();
    dofs_per_cell               = field_dofs_per_cell(fe);
    std::vector<types::global_dof_index> cell_dofs(all_dofs);
    const Epetra_BlockMap &ghosted_map = ghosted_layout.trilinos_vector().Map();
    penalty.resize(bodies.size());
    body_displacement.resize(bodies.size());
    body_increment.resize(bodies.size());
    // At the start of a run no body may hold material: a point whose
    // surface lies deeper in a body than the point's own size is a body
    // placed inside the material (a tied body holds what lies in it).
    const bool          first_step = t_old == 0.;
    std::vector<double> overlap(bodies.size(), 0.);
    load_unit.resize(bodies.size());
    load_force.resize(bodies.size());
    load_start.assign(bodies.size(), 0.);
    shift.assign(bodies.size(), 0.);
    cell_size = h;
    // A body driven by a force starts the step where the last one left it
    // along its load direction; the step moves it on by shift.
    std::vector<Tensor<1, dim>> start(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const RigidBody<dim> &body = bodies[b];
        penalty[b] = body.penalty_factor * stiffness_scale / (radius * h_power);
        load_unit[b]  = body.load_unit();
        load_force[b] = body.force(t_new);
        if (body.load_driven() && b < load_displacements.size())
          load_start[b] = load_displacements[b];
        if (body.load_driven())
          {
            start[b] = body.prescribed_displacement(t_old) +
                       load_start[b] * load_unit[b];
            body_displacement[b] = body.prescribed_displacement(t_new) +
                                   load_start[b] * load_unit[b];
          }
        else
          {
            start[b]             = body.displacement(t_old);
            body_displacement[b] = body.displacement(t_new);
          }
        body_increment[b] = body_displacement[b] - start[b];
      }

    std::vector<std::vector<typename RigidBody<dim>::Face>> faces;
    for (const RigidBody<dim> &body : bodies)
      faces.push_back(body.faces());

    for (unsigned int c = 0; c < cache->n_cells(); ++c)
      {
        const auto &range = cache->cell(c);
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const double    *data = cache->properties(p);
            const Point<dim> x    = material_position(p);
            // Points that do not move (small displacements): the contact's
            // geometry from the point's place on the grid, the class
            // description.
            const Point<dim> place = cache->position(p);
            Tensor<1, dim>   half;
            Tensor<2, dim>   F;
            point_box(p, half, F);
            for (unsigned int b = 0; b < bodies.size(); ++b)
              {
                const bool tied =
                  bodies[b].friction == RigidBody<dim>::Friction::tied;
                // Small displacements (the class description).
                const bool small =
                  !move_points &&
                  bodies[b].friction == RigidBody<dim>::Friction::frictionless;
                const Point<dim> &centre = small ? place : x;
                Tensor<1, dim>    n;
                const double      centre_gap =
                  bodies[b].signed_distance(centre, body_displacement[b], n);
                if (centre_gap > margin + half.norm() * F.norm())
                  continue;
                // The contact point x_p + a of a box facing along n.
                const auto support = [&](const Tensor<1, dim> &normal) {
                  Tensor<1, dim> a;
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      Tensor<1, dim> edge;
                      for (unsigned int i = 0; i < dim; ++i)
                        edge[i] = F[i][d] * half[d];
                      a -= (normal * edge) / edge.norm() * edge;
                    }
                  return a;
                };
                // Points that do not move, against a frictionless body,
                // meet a box or a polygon at one of its faces, with their
                // own face: the face that pressed the point in the last
                // step (its traction, along the normal without friction)
                // while the point's face still overlaps it, otherwise the
                // one nearest to the point's place. At its place a point
                // under a sinking footing lies below the base by the
                // settlement, and near the base's edge it comes nearer to
                // the side face once the settlement exceeds its distance
                // from the edge: measured with the signed distance there,
                // it went over to the side face and was pushed sideways,
                // and the plateau fell by 4.9 % after s = 0.3 h (a/h = 8).
                // A point nearest to an edge or a vertex touches that (the
                // signed distance).
                Candidate candidate;
                candidate.body = b;
                const std::vector<typename RigidBody<dim>::Face> &options =
                  faces[b];
                const auto take_face =
                  [&](const typename RigidBody<dim>::Face &face) {
                    candidate.flat = true;
                    candidate.face = face;
                    // The half-widths of the box's projection on the face.
                    for (unsigned int k = 0; k < dim - 1; ++k)
                      {
                        candidate.half_width[k] = 0.;
                        for (unsigned int d = 0; d < dim; ++d)
                          {
                            double along = 0.;
                            for (unsigned int i = 0; i < dim; ++i)
                              along += face.tangents[k][i] * F[i][d];
                            candidate.half_width[k] +=
                              std::abs(along) * half[d];
                          }
                      }
                  };
                // The face whose outward normal is @p normal, if the body has
                // one.
                const auto take_face_along = [&](const Tensor<1, dim> &normal) {
                  for (const auto &face : options)
                    if (face.normal * normal > 1. - 1e-12)
                      {
                        take_face(face);
                        return true;
                      }
                  return false;
                };
                // Whether the body's surface turns by more than the follow
                // angle at @p vertex, a point (relative to the body) of the
                // end of @p face: there the next face's normal is more than
                // 60 degrees from the face's. A vertex on the axis of an
                // axisymmetric problem is none: the surface goes on in its
                // mirror image.
                const auto turns_sharply =
                  [&](const typename RigidBody<dim>::Face &face,
                      const Tensor<1, dim>                &vertex) {
                    if (axisymmetric &&
                        std::abs(bodies[b].point[0] + start[b][0] + vertex[0]) <
                          1e-9 * h)
                      return false;
                    const double tol = 1e-9 * (1. + vertex.norm());
                    for (const auto &next : options)
                      {
                        if (next.normal * face.normal > 1. - 1e-12 ||
                            std::abs(next.normal * vertex - next.offset) > tol)
                          continue;
                        bool on = true;
                        for (unsigned int j = 0; j < dim - 1; ++j)
                          on =
                            on &&
                            vertex * next.tangents[j] > next.lower[j] - tol &&
                            vertex * next.tangents[j] < next.upper[j] + tol;
                        if (on)
                          return next.normal * face.normal <= follow_cosine;
                      }
                    return true;
                  };
                if (small && !options.empty())
                  {
                    const double  *stored = data + contact_offset + b * dim;
                    Tensor<1, dim> pressed;
                    for (unsigned int d = 0; d < dim; ++d)
                      pressed[d] = stored[d];
                    unsigned int last = 0;
                    for (unsigned int f = 1; f < options.size(); ++f)
                      if (options[f].normal * pressed >
                          options[last].normal * pressed)
                        last = f;
                    if (options[last].normal * pressed > 0.)
                      {
                        take_face(options[last]);
                        Tensor<1, dim> normal;
                        double         share;
                        contact_gap(candidate,
                                    (place - bodies[b].point) -
                                      body_displacement[b] +
                                      support(options[last].normal),
                                    normal,
                                    share);
                        candidate.flat = share > 0.;
                      }
                    if (!candidate.flat)
                      take_face_along(n);
                    if (candidate.flat)
                      n = candidate.face.normal;
                  }
                // Near the body in the last step: the contact point goes on
                // from where the grid moved it while the body's normal has
                // not turned by more than 60 degrees just behind it (by
                // h / 100, far more than a contact point's penetration
                // under the penalty), the class description.
                bool           follows = false;
                Tensor<1, dim> tracked;
                double         rest_fraction = 0.;
                Tensor<1, dim> to_vertex, vertex_point;
                if (!small)
                  {
                    const double *track =
                      data + offsets.contact_point + 2 * dim * b;
                    Tensor<1, dim> last_normal;
                    for (unsigned int d = 0; d < dim; ++d)
                      {
                        tracked[d]     = track[d];
                        last_normal[d] = track[dim + d];
                      }
                    // On a flat face of a box or a polygon that it met it
                    // goes on with the share of its own face that lies over
                    // the face, until none does. Where its face reaches
                    // past the face's end at a vertex at which the surface
                    // turns by more than the follow angle (a footing's
                    // edge), it is measured (probed, moved and pressed) at
                    // the middle of that share, and the rest of its face
                    // is pressed by the vertex, in 3D the edge (a second
                    // candidate; none at a corner, past ends along both
                    // tangents: the 3D slab of contact_footing_deep_3d
                    // fell by 1.16 % of (2 + pi) c in a step without it,
                    // 0.91 % with it).
                    // At the middle of its face, which passes the edge
                    // while part of the face still presses the base, the
                    // probe saw the side's normal and the point was let go
                    // at once: one point carrying 12 % of a footing's force
                    // (a/h = 4, pushed in by 0.79 a) took 8.3 % of (2 + pi)
                    // c with it in one step. Over a gentler vertex (a
                    // cone's shoulder) the probe follows the point onto the
                    // next face anyway; at a cone's tip on the axis, where
                    // the surface goes on in its mirror image, the change
                    // made the cone's steps fail (doc/example_footing.md).
                    Tensor<1, dim> to_share;
                    Tensor<1, dim> n_tracked;
                    rest_fraction           = 0.;
                    unsigned int sharp_ends = 0;
                    if (last_normal.norm_square() > 0.)
                      {
                        const Tensor<1, dim> from =
                          (tracked - bodies[b].point) - start[b];
                        if (take_face_along(last_normal))
                          for (unsigned int k = 0; k < dim - 1; ++k)
                            {
                              const Tensor<1, dim> &e =
                                candidate.face.tangents[k];
                              const double middle = from * e;
                              const double w      = candidate.half_width[k];
                              const double lower =
                                std::max(middle - w, candidate.face.lower[k]);
                              const double upper =
                                std::min(middle + w, candidate.face.upper[k]);
                              if (!(upper > lower))
                                continue;
                              // The face's end that the point's face
                              // reaches past, if any, and whether the
                              // surface turns sharply there.
                              const bool past_upper =
                                middle + w > candidate.face.upper[k];
                              const double end = past_upper ?
                                                   candidate.face.upper[k] :
                                                   candidate.face.lower[k];
                              if (!(past_upper ||
                                    middle - w < candidate.face.lower[k]) ||
                                  !turns_sharply(candidate.face,
                                                 from +
                                                   (candidate.face.offset -
                                                    from *
                                                      candidate.face.normal) *
                                                     candidate.face.normal +
                                                   (end - middle) * e))
                                continue;
                              // The rest of the point's face, past the
                              // end: pressed by the vertex (in 3D the
                              // edge), unless the face also reaches past
                              // an end along its other tangent (a corner
                              // of the base, see below).
                              ++sharp_ends;
                              if (w > 0.)
                                {
                                  rest_fraction =
                                    std::abs(
                                      (past_upper ? middle + w : middle - w) -
                                      end) /
                                    (2. * w);
                                  to_vertex = (end - middle) * e;
                                }
                              // contact_gap() takes the share about the
                              // face's middle: the face's bounds move with
                              // the point where the share is measured.
                              const double shift =
                                0.5 * (lower + upper) - middle;
                              to_share += shift * e;
                              candidate.face.lower[k] += shift;
                              candidate.face.upper[k] += shift;
                            }
                        bodies[b].signed_distance_from_point(
                          from + to_share +
                            follow_probe_depth * h * last_normal,
                          n_tracked);
                      }
                    follows = n_tracked * last_normal > follow_cosine;
                    if (!follows || !candidate.flat || sharp_ends > 1)
                      rest_fraction = 0.;
                    if (rest_fraction > 0.)
                      vertex_point = tracked + to_vertex;
                    if (!follows)
                      candidate.flat = false;
                    else
                      {
                        tracked += to_share;
                        n = candidate.flat ? candidate.face.normal : n_tracked;
                      }
                  }
                // The box's depth along n, which its contact area needs.
                const Tensor<1, dim> box = support(n);
                const double         r   = -(n * box);
                if (!(r > 0.))
                  continue;
                const Tensor<1, dim> a      = follows ? tracked - x : box;
                const Point<dim>     corner = x + a;
                // Where the corner lies on the grid: the point's place
                // there, which for points that do not move is x - u_p.
                const Point<dim> grid_corner = place + a;
                // Relative to the body's reference point, as the gap is
                // evaluated in every residual (small near the surface).
                // Points that do not move add their displacement u_p
                // along the normal there.
                Tensor<1, dim> relative =
                  ((small ? grid_corner : corner) - bodies[b].point) -
                  body_displacement[b];
                Tensor<1, dim> n_corner;
                double         share;
                contact_gap(candidate, relative, n_corner, share);
                // Zero: the contact point moves with the full motion.
                candidate.normal = small ? n_corner : Tensor<1, dim>();
                if (small)
                  relative += (n_corner * (x - place)) * n_corner;
                const double gap =
                  contact_gap(candidate, relative, n_corner, share);
                if (first_step &&
                    bodies[b].friction != RigidBody<dim>::Friction::tied)
                  {
                    Tensor<1, dim> n_start;
                    const double depth = -bodies[b].signed_distance_from_point(
                      (corner - bodies[b].point) - start[b], n_start);
                    if (depth > 2. * r)
                      overlap[b] = std::max(overlap[b], depth);
                  }
                if (gap > margin)
                  continue;
                // A tied body holds the points whose surface touches it
                // (within half their size) or lies in it, and no others.
                if (tied && !(gap < r))
                  continue;
                candidate.point    = p;
                candidate.first    = dof_values.size();
                candidate.relative = relative;
                candidate.reach    = half.norm() * F.norm();
                candidate.area     = contact_area(F,
                                              half,
                                              n,
                                              r,
                                              data[offsets.volume],
                                              axisymmetric ? x[0] : 1.);
                // Points that touch the body count too: a body resting on
                // another is held only by the contact.
                candidate.penetrates = tied || (gap <= 1e-8 * h && share > 0.);
                // The grid's Q1 functions at the corner, of the cell that
                // holds it. With linear shape functions that is the
                // point's own cell (extrapolated if the corner lies beyond
                // it), whose nodes are the point's stencil. With GIMP the
                // corner may lie in a cell that touches the point's cell,
                // whose nodes are then in the group of the point's cell
                // (and so in the stiffness's pattern); RigidContact
                // explains why. Otherwise the point's cell is
                // extrapolated: beyond the grid, and where the corner lies
                // outside the point's GIMP domain (an axis-parallel box,
                // at most a cell wide, while the box whose surface touches
                // the body is sheared with the point: a point stretched
                // along a cone's face had its contact point in a cell none
                // of whose points reaches its far nodes, and the contact
                // stiffness fell outside the pattern).
                const auto push = [&](const Candidate  &cand,
                                      const Point<dim> &at) {
                  const auto own   = cache->cell(c).cell;
                  auto       found = std::make_pair(own, Point<dim>());
                  if (gimp)
                    found = grid.find_cell_around(at, own);
                  const auto group_holds = [&](const auto &cell) {
                    grid.dof_cell(cell)->get_dof_indices(cell_dofs);
                    const types::global_dof_index *group =
                      cache->global_dofs(c);
                    const types::global_dof_index *group_end =
                      group + cache->n_dofs(c);
                    for (unsigned int i = 0; i < all_dofs; ++i)
                      if (fe.system_to_component_index(i).first / dim ==
                            cache->cell(c).body &&
                          std::find(group, group_end, cell_dofs[i]) ==
                            group_end)
                        return false;
                    return true;
                  };
                  if (!gimp || found.first.state() != IteratorState::valid ||
                      !group_holds(found.first))
                    found = {
                      own,
                      grid.get_mapping().transform_real_to_unit_cell(own, at)};
                  const auto &[cell, xi] = found;
                  grid.dof_cell(cell)->get_dof_indices(cell_dofs);
                  append_field_shape_values(fe,
                                            cell_dofs,
                                            xi,
                                            cache->cell(c).body,
                                            dof_global,
                                            dof_component,
                                            dof_values);
                  for (unsigned int i = cand.first; i < dof_global.size(); ++i)
                    dof_local.push_back(ghosted_map.LID(
                      static_cast<TrilinosWrappers::types::int_type>(
                        dof_global[i])));
                  candidates.push_back(cand);
                };
                push(candidate, grid_corner);
                if (rest_fraction > 0. &&
                    bodies[b].friction ==
                      RigidBody<dim>::Friction::frictionless)
                  {
                    Candidate rest = candidate;
                    rest.flat      = false;
                    rest.relative =
                      (Point<dim>(vertex_point) - bodies[b].point) -
                      body_displacement[b];
                    Tensor<1, dim> n_rest;
                    double         share_rest;
                    const double   gap_rest =
                      contact_gap(rest, rest.relative, n_rest, share_rest);
                    if (gap_rest <= margin)
                      {
                        // Within the step the rest meets the plane through
                        // the vertex with the normal of the step's start:
                        // the signed distance's normal at a vertex turns
                        // between the two faces as the iterate moves.
                        rest.flat        = true;
                        rest.face.normal = n_rest;
                        rest.face.offset = n_rest * rest.relative - gap_rest;
                        for (unsigned int k = 0; k < dim - 1; ++k)
                          {
                            rest.face.lower[k] =
                              -std::numeric_limits<double>::infinity();
                            rest.face.upper[k] =
                              std::numeric_limits<double>::infinity();
                          }
                        rest.first      = dof_values.size();
                        rest.area       = candidate.area * rest_fraction;
                        rest.penetrates = gap_rest <= 1e-8 * h;
                        push(rest, place + (Point<dim>(vertex_point) - x));
                      }
                  }
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
    // unresolved_contact() reads the increment at every point.
    du_ghosted.reinit(ghosted_layout);
    if (any)
      {
        forces.reinit(ghosted_layout.locally_owned_elements(),
                      ghosted_layout.get_mpi_communicator());
        values.resize(dofs_per_cell);
      }
  }



  template <int dim>
  Point<dim>
  RigidContact<dim>::material_position(const unsigned int p) const
  {
    if (move_points)
      return cache->position(p);
    const double *data = cache->properties(p);
    Point<dim>    x    = cache->position(p);
    for (unsigned int d = 0; d < dim; ++d)
      x[d] += data[offsets.displacement + d];
    return x;
  }



  template <int dim>
  void
  RigidContact<dim>::point_box(const unsigned int p,
                               Tensor<1, dim>    &half,
                               Tensor<2, dim>    &F) const
  {
    const double    *data = cache->properties(p);
    const Point<dim> x    = material_position(p);
    // The point's box: half-lengths and its deformation so far.
    const double initial_size =
      initial_measure<dim>(data, offsets, x, axisymmetric);
    for (unsigned int d = 0; d < dim; ++d)
      half[d] = gimp ? data[offsets.initial_half_length + d] :
                       0.5 * std::pow(initial_size, 1. / dim);
    // With F-bar, the point's own volume change replaces the cell's that
    // F-bar stores: the contact point moves in a step with the grid's
    // motion at it, and the box of the next step must start where that
    // left it. With the cell's volume change the contact force jumped
    // between two steps at the same position by the penalty times the
    // difference (a footing's force by up to 10 %, and Newton stalled under
    // a load held constant).
    const double excess =
      offsets.fbar_volume_excess != numbers::invalid_unsigned_int ?
        data[offsets.fbar_volume_excess] :
        0.;
    // Axisymmetric: the excess is shared by the three directions.
    const double n_directions = axisymmetric ? 3. : dim;
    if (finite)
      F = std::exp(excess / n_directions) *
          Utils::read_tensor<dim>(data + offsets.deformation_gradient);
    else
      F = Tensor<2, dim>((1. + excess / n_directions) *
                           unit_symmetric_tensor<dim>() +
                         Utils::read_symmetric<dim>(data + offsets.strain));
  }



  namespace
  {
    // The smallest signed distance of a convex body to the points of the
    // segment from @p from to @p to (both relative to the body's reference
    // point): the distance is a convex function along the segment, so a
    // golden-section search finds its minimum.
    template <int dim>
    double
    closest_approach(const RigidBody<dim> &body,
                     const Tensor<1, dim> &from,
                     const Tensor<1, dim> &to)
    {
      Tensor<1, dim> n;
      const auto     distance = [&](const double s) {
        return body.signed_distance_from_point(from + s * (to - from), n);
      };
      const double ratio = 0.5 * (std::sqrt(5.) - 1.);
      double       a = 0., b = 1.;
      double       c = b - ratio * (b - a), d = a + ratio * (b - a);
      double       fc = distance(c), fd = distance(d);
      for (unsigned int i = 0; i < 60 && b - a > 1e-12; ++i)
        if (fc < fd)
          {
            b  = d;
            d  = c;
            fd = fc;
            c  = b - ratio * (b - a);
            fc = distance(c);
          }
        else
          {
            a  = c;
            c  = d;
            fc = fd;
            d  = a + ratio * (b - a);
            fd = distance(d);
          }
      return std::min({fc, fd, distance(0.), distance(1.)});
    }
  } // namespace



  template <int dim>
  std::string
  RigidContact<dim>::unresolved_contact(const VectorType &du) const
  {
    const auto &bodies = boundary.rigid_bodies();
    if (bodies.empty() || cache == nullptr)
      return "";
    const MPI_Comm communicator = du.get_mpi_communicator();
    du_ghosted                  = du;
    const double *du_local      = du_ghosted.trilinos_vector()[0];
    solve_shifts(du_local);
    // Per body: candidates that went through it, the deepest penetration
    // over the point's size, points that reached it unseen.
    std::vector<double> crossed(bodies.size(), 0.);
    std::vector<double> depth_ratio(bodies.size(), 0.);
    std::vector<double> unseen(bodies.size(), 0.);
    std::vector<double> deepest(bodies.size(), 0.);
    const auto          body_shift = [&](const unsigned int b) {
      return Tensor<1, dim>(shift[b] * load_unit[b]);
    };
    for (const Candidate &c : candidates)
      {
        const RigidBody<dim> &body = bodies[c.body];
        if (body.friction == RigidBody<dim>::Friction::tied)
          continue;
        const Tensor<1, dim> end =
          contact_position(c, contact_motion(c, du_local));
        Tensor<1, dim> n_start, n_end;
        body.signed_distance_from_point(c.relative, n_start);
        const double gap = body.signed_distance_from_point(end, n_end);
        // Deeper than half the box's radius: a point beside a vertex (a
        // cone's tip on its axis) that penetrates a little may find its
        // nearest face change sides.
        if (n_start * n_end < 0. &&
            closest_approach(body, c.relative, end) < -0.5 * c.reach)
          crossed[c.body] += 1.;
        if (gap < 0. && -gap > c.reach)
          if (-gap / c.reach > depth_ratio[c.body])
            {
              depth_ratio[c.body] = -gap / c.reach;
              deepest[c.body]     = -gap;
            }
      }
    // The points that were no candidates of a body: their centres' paths
    // must stay further from it than their boxes reach. Candidates come in
    // the order of the points, and of the bodies for each point.
    auto next = candidates.begin();
    for (unsigned int c = 0; c < cache->n_cells(); ++c)
      {
        const auto &range = cache->cell(c);
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const Point<dim>     x = material_position(p);
            const Tensor<1, dim> u = cache->interpolate(c, p, du_local);
            Tensor<1, dim>       half;
            Tensor<2, dim>       F;
            point_box(p, half, F);
            const double size = half.norm() * F.norm();
            for (unsigned int b = 0; b < bodies.size(); ++b)
              {
                if (next != candidates.end() && next->point == p &&
                    next->body == b)
                  {
                    while (next != candidates.end() && next->point == p &&
                           next->body == b)
                      ++next;
                    continue;
                  }
                Tensor<1, dim>       n;
                const Tensor<1, dim> start =
                  (x - bodies[b].point) - body_displacement[b];
                const Tensor<1, dim> motion = u - body_shift(b);
                // Only points that started clear of the body: a tied body
                // also leaves out points beside it that do not touch it.
                const double clearance =
                  bodies[b].signed_distance_from_point(start, n) - size;
                if (clearance <= 0. || clearance > motion.norm())
                  continue;
                if (closest_approach(bodies[b], start, start + motion) < size)
                  unseen[b] += 1.;
              }
          }
      }
    const auto reduce = [&](std::vector<double> &values, const MPI_Op op) {
      const int ierr = MPI_Allreduce(MPI_IN_PLACE,
                                     values.data(),
                                     static_cast<int>(values.size()),
                                     MPI_DOUBLE,
                                     op,
                                     communicator);
      AssertThrowMPI(ierr);
    };
    reduce(crossed, MPI_SUM);
    reduce(unseen, MPI_SUM);
    reduce(depth_ratio, MPI_MAX);
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const double deepest_b =
          depth_ratio[b] > 0. ?
            dealii::Utilities::MPI::max(deepest[b], communicator) :
            0.;
        std::ostringstream message;
        message << std::setprecision(3);
        if (crossed[b] > 0.)
          message << "the step moved " << crossed[b]
                  << " material point(s) through rigid body <" << bodies[b].name
                  << "> (the contact of a step sees the side a point starts "
                     "on)";
        else if (unseen[b] > 0.)
          message << unseen[b] << " material point(s) reached rigid body <"
                  << bodies[b].name
                  << "> from further than the contact's search distance "
                     "(two cells) in one step";
        else if (depth_ratio[b] > 0.)
          message << "a material point lies " << deepest_b
                  << " inside rigid body <" << bodies[b].name
                  << ">, more than its size (a step too large for the "
                     "contact, or a <Penalty factor> too small for the "
                     "pressure)";
        if (!message.str().empty())
          return message.str();
      }
    return "";
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
  RigidContact<dim>::contact_motion(const Candidate &c,
                                    const double    *du_local) const
  {
    Tensor<1, dim> u;
    for (unsigned int i = c.first; i < c.first + dofs_per_cell; ++i)
      u[dof_component[i]] += dof_values[i] * du_local[dof_local[i]];
    return u - shift[c.body] * load_unit[c.body];
  }



  template <int dim>
  Tensor<1, dim>
  RigidContact<dim>::contact_position(const Candidate      &c,
                                      const Tensor<1, dim> &motion) const
  {
    if (c.normal.norm_square() == 0.)
      return c.relative + motion;
    return c.relative + (c.normal * motion) * c.normal;
  }



  template <int dim>
  double
  RigidContact<dim>::contact_gap(const Candidate      &c,
                                 const Tensor<1, dim> &y,
                                 Tensor<1, dim>       &n,
                                 double               &share) const
  {
    share = 1.;
    if (!c.flat)
      return boundary.rigid_bodies()[c.body].signed_distance_from_point(y, n);
    n = c.face.normal;
    for (unsigned int k = 0; k < dim - 1; ++k)
      {
        const double centre = y * c.face.tangents[k];
        const double w      = c.half_width[k];
        const double length = std::min(centre + w, c.face.upper[k]) -
                              std::max(centre - w, c.face.lower[k]);
        share *= w > 0. ? std::clamp(length / (2. * w), 0., 1.) :
                          static_cast<double>(length >= 0.);
      }
    return n * y - c.face.offset;
  }



  template <int dim>
  Tensor<1, dim>
  RigidContact<dim>::traction(const Candidate &c,
                              const double    *du_local,
                              Tensor<1, dim>  &n,
                              double          &gap,
                              double          &share,
                              bool            &active) const
  {
    const RigidBody<dim> &body   = boundary.rigid_bodies()[c.body];
    const Tensor<1, dim>  motion = contact_motion(c, du_local);
    gap             = contact_gap(c, contact_position(c, motion), n, share);
    const bool tied = body.friction == RigidBody<dim>::Friction::tied;
    active          = tied || (gap < 0. && share > 0.);
    if (!active)
      return Tensor<1, dim>();
    // Over the share of the point's face that meets the body.
    const double pressure = -penalty[c.body] * share * gap;
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
      return t_old - penalty[c.body] * (motion - body_increment[c.body]);
    Tensor<1, dim> t = pressure * n;
    // Return map of the tangential traction: the last step's, plus the
    // penalty of the slip of the contact point relative to the body.
    Tensor<1, dim> tau = t_old;
    tau -= tangential_scale * penalty[c.body] * share *
           (motion - body_increment[c.body]);
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
  void
  RigidContact<dim>::solve_shifts(const double *du_local) const
  {
    const auto    &bodies       = boundary.rigid_bodies();
    const MPI_Comm communicator = du_ghosted.get_mpi_communicator();
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        if (!bodies[b].load_driven())
          continue;
        const Tensor<1, dim> &d = load_unit[b];
        // f(s), and its slope at a point that sticks: sum_c A eps ((n . d)^2
        // + eps_T / eps |P d|^2) (exact for flat faces; tied: A eps).
        const bool tangential =
          bodies[b].friction != RigidBody<dim>::Friction::frictionless;
        const auto evaluate = [&](const double s, double &slope) {
          shift[b] = s;
          Tensor<1, 2> fs;
          for (const Candidate &c : candidates)
            {
              if (c.body != b)
                continue;
              Tensor<1, dim>       n;
              double               gap, share;
              bool                 active;
              const Tensor<1, dim> t =
                traction(c, du_local, n, gap, share, active);
              if (!active)
                continue;
              const double normal = (n * d) * (n * d);
              fs[0] += c.area * (t * d);
              fs[1] += c.area * share * penalty[b] *
                       (bodies[b].friction == RigidBody<dim>::Friction::tied ?
                          1. :
                          normal + (tangential ? tangential_scale : 0.) *
                                     (1. - normal));
            }
          fs    = dealii::Utilities::MPI::sum(fs, communicator);
          slope = fs[1];
          return fs[0] - load_force[b];
        };
        // First a bracket [lo, hi] of the root, f(lo) < 0 < f(hi): Newton
        // steps with the slope above from the start (the last step's s),
        // a step twice as long whenever f did not change sign and fell by
        // less than half (points that slip or leave the contact flatten
        // f). Then, inside the bracket, Newton from the end with the
        // smaller |f| where it lands inside (on the root's piece of the
        // piecewise linear f it lands on the root), else false position
        // with the Illinois halving. Beyond two cells of motion in a step
        // the candidates no longer cover the body's surface: no root,
        // which check_loads() reports.
        const double limit = 2. * cell_size;
        const double width = 1e-15 * (limit + std::abs(shift[b]));
        double       slope = 0.;
        double       s     = shift[b];
        double       value = evaluate(s, slope);
        if (value == 0.)
          continue;
        const double tolerance =
          1e-14 * std::max(std::abs(load_force[b]), std::abs(value));
        double lo = s, f_lo = value, k_lo = slope;
        double hi = s, f_hi = value, k_hi = slope;
        double step = slope > 0. ? std::abs(value) / slope : 1e-3 * cell_size;
        // Expand until the signs differ (lo == hi marks a missing end).
        for (unsigned int iteration = 0;
             (f_lo > 0. || f_hi < 0.) && iteration < 200;
             ++iteration)
          {
            const double sign = value < 0. ? 1. : -1.;
            const double next = std::clamp(s + sign * step, -limit, limit);
            if (next == s)
              break;
            const double previous = value;
            s                     = next;
            value                 = evaluate(s, slope);
            if (value == 0.)
              break;
            if (value < 0.)
              {
                lo   = s;
                f_lo = value;
                k_lo = slope;
                if (f_hi < 0.)
                  {
                    hi   = s;
                    f_hi = value;
                    k_hi = slope;
                  }
              }
            else
              {
                hi   = s;
                f_hi = value;
                k_hi = slope;
                if (f_lo > 0.)
                  {
                    lo   = s;
                    f_lo = value;
                    k_lo = slope;
                  }
              }
            step = (slope > 0. && std::abs(value) < 0.5 * std::abs(previous)) ?
                     std::abs(value) / slope :
                     2. * step;
          }
        // (g_lo, g_hi: the ends' values for false position, halved at the
        // end that stays twice in a row.)
        double g_lo = f_lo, g_hi = f_hi;
        int    last_side = 0;
        if (value != 0. && f_lo < 0. && f_hi > 0.)
          for (unsigned int iteration = 0; iteration < 200; ++iteration)
            {
              double next = std::numeric_limits<double>::quiet_NaN();
              if (-f_lo <= f_hi && k_lo > 0.)
                next = lo - f_lo / k_lo;
              else if (f_hi < -f_lo && k_hi > 0.)
                next = hi - f_hi / k_hi;
              if (!(next > lo && next < hi))
                next = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
              if (!(next > lo && next < hi))
                next = 0.5 * (lo + hi);
              s     = next;
              value = evaluate(s, slope);
              if (std::abs(value) <= tolerance || hi - lo <= width)
                break;
              const int side = value < 0. ? -1 : 1;
              if (side < 0)
                {
                  lo   = s;
                  f_lo = g_lo = value;
                  k_lo        = slope;
                  if (last_side < 0)
                    g_hi *= 0.5;
                }
              else
                {
                  hi   = s;
                  f_hi = g_hi = value;
                  k_hi        = slope;
                  if (last_side > 0)
                    g_lo *= 0.5;
                }
              last_side = side;
            }
        shift[b] = s;
      }
  }



  template <int dim>
  void
  RigidContact<dim>::check_loads(const std::vector<BodyLoad> &loads,
                                 const double                 force_scale) const
  {
    const auto &bodies = boundary.rigid_bodies();
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        if (!bodies[b].load_driven())
          continue;
        // The material's force on the body along d balances the load.
        const double balance = loads[b].force * load_unit[b] + load_force[b];
        if (std::abs(balance) <=
            1e-6 * std::max(std::abs(load_force[b]), force_scale))
          continue;
        std::ostringstream message;
        message << "Rigid body <" << bodies[b].name
                << ">: no motion along its load direction balances its load "
                << load_force[b] << " (the material pushes back with "
                << -(loads[b].force * load_unit[b])
                << "): the body finds no material to push against within "
                   "two cells of its surface in this step, or pulls on "
                   "material it does not hold (only a tied body can pull).";
        AssertThrow(false, ExcMessage(message.str()));
      }
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
    solve_shifts(du_local);
    for (const Candidate &c : candidates)
      {
        Tensor<1, dim>       n;
        double               gap, share;
        bool                 active;
        const Tensor<1, dim> t = traction(c, du_local, n, gap, share, active);
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
  double
  RigidContact<dim>::contact_area(const Tensor<2, dim> &F,
                                  const Tensor<1, dim> &half,
                                  const Tensor<1, dim> &n,
                                  const double          r,
                                  const double          volume,
                                  const double          radius)
  {
    // The projection of the parallelogram (parallelepiped) with the edges
    // 2 e_d: the sum of |n x e_d| (of |n . (e_i x e_j)|) over its edges
    // (face pairs).
    std::array<Tensor<1, dim>, dim> e;
    for (unsigned int d = 0; d < dim; ++d)
      for (unsigned int i = 0; i < dim; ++i)
        e[d][i] = F[i][d] * half[d];
    double projection;
    if constexpr (dim == 2)
      projection = 2. * (std::abs(n[0] * e[0][1] - n[1] * e[0][0]) +
                         std::abs(n[0] * e[1][1] - n[1] * e[1][0]));
    else
      projection = 4. * (std::abs(n * cross_product_3d(e[0], e[1])) +
                         std::abs(n * cross_product_3d(e[1], e[2])) +
                         std::abs(n * cross_product_3d(e[0], e[2])));
    return std::min(volume / (2. * r), 2. * projection * radius);
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
                            TrilinosWrappers::SparseMatrix  &K,
                            const bool preconditioner_matrix) const
  {
    FullMatrix<double>                   K_point;
    std::vector<types::global_dof_index> dofs;
    Vector<double>                       b_point(dofs_per_cell);
    const auto                          &bodies = boundary.rigid_bodies();
    if (preconditioner_matrix)
      {
        unit_shift_forces.resize(bodies.size());
        unit_shift_stiffness.assign(bodies.size(), 0.);
        for (unsigned int b = 0; b < bodies.size(); ++b)
          if (bodies[b].load_driven())
            unit_shift_forces[b].reinit(K.locally_owned_range_indices(),
                                        K.get_mpi_communicator());
      }
    for (const Candidate &c : candidates)
      {
        if (!c.penetrates)
          continue;
        const RigidBody<dim> &body = boundary.rigid_bodies()[c.body];
        Tensor<1, dim>        n;
        double                share;
        contact_gap(c, c.relative, n, share);
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
        stiffness *= penalty[c.body] * c.area * share;
        K_point.reinit(dofs_per_cell, dofs_per_cell);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = 0; j < dofs_per_cell; ++j)
            K_point(i, j) =
              dof_values[c.first + i] * dof_values[c.first + j] *
              stiffness[dof_component[c.first + i]][dof_component[c.first + j]];
        dofs.assign(dof_global.begin() + c.first,
                    dof_global.begin() + c.first + dofs_per_cell);
        constraints.distribute_local_to_global(K_point, dofs, K);
        if (preconditioner_matrix && body.load_driven())
          {
            // b = K_c e_d and beta = e_d^T K_c e_d of this point.
            const Tensor<1, dim> &d = load_unit[c.body];
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                b_point[i] = 0.;
                for (unsigned int j = 0; j < dofs_per_cell; ++j)
                  b_point[i] += K_point(i, j) * d[dof_component[c.first + j]];
                unit_shift_stiffness[c.body] +=
                  d[dof_component[c.first + i]] * b_point[i];
              }
            constraints.distribute_local_to_global(b_point,
                                                   dofs,
                                                   unit_shift_forces[c.body]);
          }
      }
    if (preconditioner_matrix)
      for (unsigned int b = 0; b < bodies.size(); ++b)
        if (bodies[b].load_driven())
          {
            unit_shift_forces[b].compress(VectorOperation::add);
            unit_shift_stiffness[b] =
              Utilities::MPI::sum(unit_shift_stiffness[b],
                                  K.get_mpi_communicator());
          }
  }



  template <int dim>
  void
  RigidContact<dim>::setup_preconditioner(
    const TrilinosWrappers::SparseMatrix &K_A,
    const Preconditioning                &M,
    const bool                            new_preconditioner)
  {
    if (!new_preconditioner)
      return;
    corrected_bodies.clear();
    corrections.clear();
    const auto &bodies = boundary.rigid_bodies();
    if (unit_shift_forces.size() != bodies.size())
      return;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (bodies[b].load_driven() && unit_shift_stiffness[b] > 0.)
        corrected_bodies.push_back(b);
    if (corrected_bodies.empty())
      return;
    // m = K_A^{-1} b, to 1e-10: G = beta - b^T m is a small difference of
    // two large numbers where the penalty is much stiffer than the
    // material.
    struct Inverse
    {
      const Preconditioning &M;
      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        M(dst, src);
        dst *= -1.;
      }
    } inverse{M};
    const unsigned int n = corrected_bodies.size();
    corrections.assign(n, unit_shift_forces[corrected_bodies[0]]);
    for (unsigned int k = 0; k < n; ++k)
      {
        const VectorType &b = unit_shift_forces[corrected_bodies[k]];
        corrections[k]      = 0.;
        // Right preconditioning: the stopping test sees the true residual,
        // a force like b.
        SolverControl           control(500, 1e-10 * b.l2_norm(), false, false);
        SolverGMRES<VectorType> gmres(
          control, typename SolverGMRES<VectorType>::AdditionalData(50, true));
        try
          {
            gmres.solve(K_A, corrections[k], b, inverse);
          }
        catch (const SolverControl::NoConvergence &)
          {
            // The preconditioner without the correction; Newton will say
            // whether the step converges.
            corrected_bodies.clear();
            corrections.clear();
            return;
          }
      }
    FullMatrix<double> G(n, n);
    bool               positive = true;
    for (unsigned int k = 0; k < n; ++k)
      {
        for (unsigned int l = 0; l < n; ++l)
          G(k, l) = (k == l ? unit_shift_stiffness[corrected_bodies[k]] : 0.) -
                    unit_shift_forces[corrected_bodies[k]] * corrections[l];
        positive = positive &&
                   G(k, k) > 1e-12 * unit_shift_stiffness[corrected_bodies[k]];
      }
    if (!positive)
      {
        corrected_bodies.clear();
        corrections.clear();
        return;
      }
    correction_inverse.reinit(n, n);
    correction_inverse.invert(G);
    correction_rhs.reinit(n);
    correction_solution.reinit(n);
  }



  template <int dim>
  bool
  RigidContact<dim>::has_preconditioner() const
  {
    return !corrected_bodies.empty();
  }



  template <int dim>
  void
  RigidContact<dim>::precondition(const Preconditioning &M,
                                  VectorType            &dst,
                                  const VectorType      &src) const
  {
    // dst = -(K_A - B Beta^{-1} B^T)^{-1} src = M(src) - m G^{-1} m^T src.
    M(dst, src);
    for (unsigned int k = 0; k < corrections.size(); ++k)
      correction_rhs[k] = corrections[k] * src;
    correction_inverse.vmult(correction_solution, correction_rhs);
    for (unsigned int k = 0; k < corrections.size(); ++k)
      dst.add(-correction_solution[k], corrections[k]);
  }



  template <int dim>
  std::vector<double>
  RigidContact<dim>::commit(MaterialPointSet<dim> &points,
                            const VectorType      &du_ghosted_step) const
  {
    const double *du_local = du_ghosted_step.trilinos_vector()[0];
    // The bodies' motions by a force at du, from the tractions of the last
    // step, which the loop below replaces.
    std::vector<double> motion(load_start);
    if (any)
      {
        solve_shifts(du_local);
        for (unsigned int b = 0; b < motion.size(); ++b)
          motion[b] += shift[b];
      }
    // Where the grid moved each contact point: the next step's (the class
    // description); none for the points that were not near a body.
    const auto        &bodies   = boundary.rigid_bodies();
    const unsigned int tracking = offsets.contact_point;
    std::vector<std::vector<typename RigidBody<dim>::Face>> faces;
    for (const RigidBody<dim> &body : bodies)
      faces.push_back(body.faces());
    if (!bodies.empty())
      for (unsigned int cell = 0; cell < cache->n_cells(); ++cell)
        for (unsigned int p = cache->cell(cell).first_point;
             p < cache->cell(cell).end_point;
             ++p)
          std::fill_n(cache->properties(p, points) + tracking,
                      2 * dim * bodies.size(),
                      0.);
    const Candidate *previous = nullptr;
    for (const Candidate &c : candidates)
      {
        const bool secondary = previous != nullptr &&
                               previous->point == c.point &&
                               previous->body == c.body;
        previous = &c;
        if (secondary)
          continue;
        Tensor<1, dim>       n;
        double               gap, share;
        bool                 active;
        const Tensor<1, dim> t = traction(c, du_local, n, gap, share, active);
        double              *data =
          cache->properties(c.point, points) + contact_offset + c.body * dim;
        for (unsigned int d = 0; d < dim; ++d)
          data[d] = t[d];
        if (c.normal.norm_square() == 0.)
          {
            // The contact point's own motion, the body's by a force
            // included.
            const Tensor<1, dim> moved =
              c.relative + bodies[c.body].point + body_displacement[c.body] +
              contact_motion(c, du_local) + shift[c.body] * load_unit[c.body];
            double *track =
              cache->properties(c.point, points) + tracking + 2 * dim * c.body;
            // On a flat face the point's face's middle goes on: the
            // contact point was the middle of its share (reinit_step()),
            // whose offset from the face's middle moved the face's bounds.
            Tensor<1, dim> face_middle = moved;
            if (c.flat)
              for (const auto &face : faces[c.body])
                if (face.normal * c.face.normal > 1. - 1e-12)
                  for (unsigned int k = 0; k < dim - 1; ++k)
                    face_middle -=
                      (c.face.lower[k] - face.lower[k]) * face.tangents[k];
            // A point whose face has left the body's face starts afresh.
            if (!c.flat || share > 0.)
              for (unsigned int d = 0; d < dim; ++d)
                {
                  track[d]       = face_middle[d];
                  track[dim + d] = n[d];
                }
          }
      }
    return motion;
  }



  template class RigidContact<2>;
  template class RigidContact<3>;
} // namespace qsmpm
