#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <limits>
#include <qsmpm/base/utilities.h>
#include <qsmpm/loading/body_contact.h>
#include <qsmpm/particles/initial_measure.h>
#include <set>
#include <sstream>
#include <unordered_map>

namespace qsmpm
{
  namespace
  {
    /// The component of @p n of the largest magnitude.
    template <int dim>
    unsigned int
    largest_component(const Tensor<1, dim> &n)
    {
      unsigned int s = 0;
      for (unsigned int d = 1; d < dim; ++d)
        if (std::abs(n[d]) > std::abs(n[s]))
          s = d;
      return s;
    }
  } // namespace



  template <int dim>
  void
  BodyContact<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact between bodies");
    {
      prm.add_parameter(
        "Bodies",
        bodies,
        "The material ids of each body that may touch another: bodies "
        "separated by ';', the ids of one body by ',' (e.g. '0; 1' or "
        "'0, 2; 1'). Each body gets its own displacement field on the grid "
        "(a multi-field grid), so that bodies can separate; where two meet "
        "at a node, their fields are tied while they press on each other. "
        "A pore fluid is one pressure field that all bodies share. "
        "Empty: one body, every point on one field.",
        Patterns::Anything());
      Utils::add_selection<Friction>(
        prm,
        "Friction",
        friction,
        {{"frictionless", Friction::frictionless},
         {"rough", Friction::rough},
         {"coulomb", Friction::coulomb}},
        "frictionless: the normal displacements of two bodies in contact "
        "are tied, they slide freely; rough: all displacements are tied, no "
        "slip; coulomb: a node sticks (all displacements tied) while its "
        "tangential force is at most <Friction coefficient> times its normal "
        "force, and slips otherwise, with that much tangential force against "
        "the slip.");
      prm.add_parameter("Friction coefficient",
                        friction_coefficient,
                        "mu of Coulomb friction (Friction = coulomb).",
                        Patterns::Double(0.));
      prm.add_parameter("Gap tolerance",
                        gap_tolerance,
                        "A gap between two bodies at most this times the "
                        "cell size counts as closed.",
                        Patterns::Double(0.));
      prm.add_parameter(
        "Max contact iterations",
        max_iterations,
        "A step whose contact set (the nodes where bodies press on each "
        "other) changes after a solve is solved again with the new set, at "
        "most this many times; then it fails and is cut back.",
        Patterns::Integer(1));
    }
    prm.leave_subsection();
  }



  template <int dim>
  std::vector<unsigned int>
  BodyContact<dim>::Parameters::body_of_material() const
  {
    std::vector<unsigned int> body_of;
    const auto bodies_text = dealii::Utilities::split_string_list(bodies, ';');
    if (bodies_text.size() < 2)
      {
        AssertThrow(bodies_text.empty(),
                    ExcMessage("Contact between bodies/Bodies: '" + bodies +
                               "' names one body; contact needs two or more "
                               "(separated by ';'), or none."));
        return body_of;
      }
    for (unsigned int b = 0; b < bodies_text.size(); ++b)
      {
        const auto ids = dealii::Utilities::split_string_list(bodies_text[b]);
        AssertThrow(!ids.empty(),
                    ExcMessage("Contact between bodies/Bodies: body " +
                               std::to_string(b) + " has no material id."));
        for (const auto &text : ids)
          {
            int id = -1;
            try
              {
                id = dealii::Utilities::string_to_int(text);
              }
            catch (...)
              {
              }
            AssertThrow(id >= 0,
                        ExcMessage("Contact between bodies/Bodies: '" + text +
                                   "' is no material id."));
            if (body_of.size() <= static_cast<unsigned int>(id))
              body_of.resize(id + 1, numbers::invalid_unsigned_int);
            AssertThrow(body_of[id] == numbers::invalid_unsigned_int,
                        ExcMessage("Contact between bodies/Bodies: material "
                                   "id " +
                                   text + " is given to two bodies."));
            body_of[id] = b;
          }
      }
    return body_of;
  }



  template <int dim>
  void
  BodyContact<dim>::Parameters::check() const
  {
    // Reads the list (and stops on a malformed one).
    body_of_material();
    AssertThrow(dealii::Utilities::split_string_list(bodies, ';').size() <=
                  ShapeCache<dim>::max_bodies,
                ExcMessage("Contact between bodies/Bodies: at most " +
                           std::to_string(ShapeCache<dim>::max_bodies) +
                           " bodies."));
    AssertThrow(friction_coefficient >= 0.,
                ExcMessage("Contact between bodies/Friction coefficient: "
                           "must not be negative."));
  }



  template <int dim>
  void
  BodyContact<dim>::initialize(const Parameters &prm)
  {
    prm.check();
    parameters    = prm;
    body_of       = prm.body_of_material();
    n_body_fields = 1;
    for (const unsigned int b : body_of)
      if (b != numbers::invalid_unsigned_int)
        n_body_fields = std::max(n_body_fields, b + 1);
    nodes.clear();
  }



  template <int dim>
  void
  BodyContact<dim>::check_points(const MaterialPointSet<dim> &points,
                                 const MPI_Comm communicator) const
  {
    if (!enabled())
      return;
    const unsigned int id_offset = points.get_offsets().material_id;
    std::string        error;
    for (const auto &particle : points.get_particle_handler())
      {
        const auto id =
          static_cast<unsigned int>(particle.get_properties()[id_offset]);
        if (id >= body_of.size() ||
            body_of[id] == numbers::invalid_unsigned_int)
          {
            error = "Contact between bodies/Bodies: material id " +
                    std::to_string(id) + " belongs to none of the bodies.";
            break;
          }
      }
    Utils::throw_if_any_rank(error, communicator);
  }



  template <int dim>
  void
  BodyContact<dim>::reinit_step(const BackgroundGrid<dim>   &grid,
                                const ShapeCache<dim>       &cache,
                                const MaterialPointSet<dim> &points,
                                const IndexSet              &inactive)
  {
    nodes.clear();
    if (!enabled())
      return;
    const MPI_Comm communicator = grid.get_communicator();
    const auto    &offsets      = points.get_offsets();
    const bool     finite       = points.get_formulation().finite_strain();
    const bool     axisymmetric = points.get_formulation().axisymmetric;
    gap_tolerance = parameters.gap_tolerance * grid.min_cell_size();

    // The gradient of each body's nodal volume, in the body's dofs.
    // Axisymmetric: of its area in the (r, z) plane, Omega_p / r_p (the
    // volume per radian r dA grows with r inside a body, and its gradient
    // would tilt every normal towards the outside).
    TrilinosWrappers::MPI::Vector gradient(grid.locally_owned_dofs(),
                                           communicator);
    {
      std::vector<double> local(ShapeCache<dim>::max_dofs_per_group);
      typename ShapeCache<dim>::GradientBuffer buffer;
      for (unsigned int c = 0; c < cache.n_cells(); ++c)
        {
          std::fill(local.begin(), local.begin() + cache.n_dofs(c), 0.);
          const auto &range = cache.cell(c);
          for (unsigned int p = range.first_point; p < range.end_point; ++p)
            {
              const double omega = cache.properties(p)[offsets.volume] /
                                   (axisymmetric ? cache.position(p)[0] : 1.);
              const auto           *grad = cache.gradients(c, p, buffer);
              const unsigned short *node = cache.nodes(p);
              for (unsigned int k = 0; k < cache.stencil_size(p); ++k)
                for (unsigned int d = 0; d < dim; ++d)
                  local[node[k] * dim + d] += omega * grad[k][d];
            }
          gradient.add(cache.n_dofs(c), cache.global_dofs(c), local.data());
        }
      gradient.compress(VectorOperation::add);
    }
    TrilinosWrappers::MPI::Vector gradient_ghosted(grid.locally_owned_dofs(),
                                                   grid.locally_relevant_dofs(),
                                                   communicator);
    gradient_ghosted = gradient;

    const Point<dim> &lower = grid.lower_corner(), &upper = grid.upper_corner();
    const double      edge_tolerance = 1e-10 * grid.min_cell_size();

    // The nodes where two bodies have material, each once.
    const unsigned int n_bodies = n_body_fields;
    std::unordered_map<types::global_dof_index, unsigned int> role_of_dof;
    std::set<types::global_dof_index>                         seen;
    std::string                                               error;
    for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          {
            if (!seen.insert(cell->vertex_dof_index(v, 0)).second)
              continue;
            std::vector<unsigned int> present;
            for (unsigned int b = 0; b < n_bodies; ++b)
              if (!inactive.is_element(cell->vertex_dof_index(v, b * dim)))
                present.push_back(b);
            if (present.size() < 2)
              continue;
            if (present.size() > 2)
              {
                // Stop on all ranks together, after the loop (a rank that
                // does not see this node would wait in the collective
                // operations below).
                if (error.empty())
                  {
                    std::ostringstream text;
                    text << "Contact between bodies: " << present.size()
                         << " bodies meet at the node at (" << cell->vertex(v)
                         << "); contact is between two bodies at a node (a "
                            "finer grid separates them).";
                    error = text.str();
                  }
                continue;
              }
            Node node;
            node.location = cell->vertex(v);
            Tensor<1, dim> g_a, g_b;
            for (unsigned int d = 0; d < dim; ++d)
              {
                node.dofs_a[d] =
                  cell->vertex_dof_index(v, present[0] * dim + d);
                node.dofs_b[d] =
                  cell->vertex_dof_index(v, present[1] * dim + d);
                g_a[d] = gradient_ghosted(node.dofs_a[d]);
                g_b[d] = gradient_ghosted(node.dofs_b[d]);
              }
            // sum_p Omega_p grad N_i(x_p) points from the body's points
            // towards the node: out of the body at its surface. From a to b
            // is along a's and against b's. At a node on the grid's edge
            // both also point out of the grid, where no body can be, each
            // in proportion to its volume at the node: that component is
            // no direction of contact.
            for (unsigned int d = 0; d < dim; ++d)
              if (std::abs(node.location[d] - lower[d]) < edge_tolerance ||
                  std::abs(node.location[d] - upper[d]) < edge_tolerance)
                g_a[d] = g_b[d] = 0.;
            // The normal is that of the body with the larger gradient
            // (Nairn's "maximum volume gradient"): where the corner of one
            // body rests on the flat face of the other, the face's normal,
            // not a mean tilted towards the corner, which would tie the
            // corner's sliding along the face to a normal motion.
            const Tensor<1, dim> n = g_a.norm() >= g_b.norm() ? g_a : -g_b;
            if (!(n.norm() > 0.))
              continue;
            node.normal = n / n.norm();
            role_of_dof.emplace(node.dofs_a[0], 2 * nodes.size());
            role_of_dof.emplace(node.dofs_b[0], 2 * nodes.size() + 1);
            nodes.push_back(node);
          }

    Utils::throw_if_any_rank(error, communicator);

    // The extent of each body's points along the node's normal: the
    // largest n . x of a corner of a's boxes, and minus the smallest of
    // b's, a maximum over the ranks in the slot of the body's first dof.
    LinearAlgebra::distributed::Vector<double> extent(
      grid.locally_owned_dofs(), grid.locally_relevant_dofs(), communicator);
    // (Assigning a number other than 0 leaves the ghost entries as they
    // are.)
    for (unsigned int i = 0; i < extent.locally_owned_size() +
                                   extent.get_partitioner()->n_ghost_indices();
         ++i)
      extent.local_element(i) = std::numeric_limits<double>::lowest();
    // Per group, its nodes (the cell's vertices; with GIMP the nodes its
    // points reach) that are contact nodes, with their role; each point
    // counts at the nodes of its stencil.
    constexpr unsigned int max_nodes =
      ShapeCache<dim>::max_dofs_per_group / dim;
    std::array<unsigned int, max_nodes> role;
    std::array<double, max_nodes>       largest;
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        const types::global_dof_index *dofs     = cache.global_dofs(c);
        const unsigned int             n_nodes  = cache.n_dofs(c) / dim;
        unsigned int                   n_shared = 0;
        for (unsigned int k = 0; k < n_nodes; ++k)
          {
            const auto it = role_of_dof.find(dofs[k * dim]);
            role[k] = it == role_of_dof.end() ? numbers::invalid_unsigned_int :
                                                it->second;
            largest[k] = std::numeric_limits<double>::lowest();
            n_shared += it != role_of_dof.end();
          }
        if (n_shared == 0)
          continue;
        const auto &range = cache.cell(c);
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            // The point's box: half-length and its deformation so far
            // (the points move: body contact needs Move points).
            const double *data = cache.properties(p);
            const double  half =
              0.5 * std::pow(initial_measure<dim>(
                               data, offsets, cache.position(p), axisymmetric),
                             1. / dim);
            const Tensor<2, dim> F =
              finite ?
                Utils::read_tensor<dim>(data + offsets.deformation_gradient) :
                Tensor<2, dim>(
                  unit_symmetric_tensor<dim>() +
                  Utils::read_symmetric<dim>(data + offsets.strain));
            const Tensor<1, dim>  x(cache.position(p));
            const unsigned short *stencil = cache.nodes(p);
            for (unsigned int j = 0; j < cache.stencil_size(p); ++j)
              {
                const unsigned int k = stencil[j];
                if (role[k] == numbers::invalid_unsigned_int)
                  continue;
                const Tensor<1, dim> &n = nodes[role[k] / 2].normal;
                // The box's half-extent along n: sum_d |n . F e_d| l_d.
                const Tensor<1, dim> FTn   = transpose(F) * n;
                double               reach = 0.;
                for (unsigned int d = 0; d < dim; ++d)
                  reach += std::abs(FTn[d]) * half;
                const double x_n = n * x;
                largest[k] =
                  std::max(largest[k],
                           role[k] % 2 == 1 ? reach - x_n : x_n + reach);
              }
          }
        for (unsigned int k = 0; k < n_nodes; ++k)
          if (role[k] != numbers::invalid_unsigned_int)
            extent(dofs[k * dim]) = std::max(extent(dofs[k * dim]), largest[k]);
      }
    extent.compress(VectorOperation::max);
    extent.update_ghost_values();

    for (auto &node : nodes)
      {
        node.gap         = -extent(node.dofs_b[0]) - extent(node.dofs_a[0]);
        node.active      = node.gap <= gap_tolerance;
        node.touching    = node.active;
        node.stick       = true;
        node.stuck_again = false;
        node.friction    = Tensor<1, dim>();
        node.tied.fill(-1);
      }
  }



  template <int dim>
  void
  BodyContact<dim>::add_constraints(AffineConstraints<double> &constraints)
  {
    // u_s = sum_k w_k u_k + g for a dof s that is still free.
    const auto tie =
      [&](
        const types::global_dof_index                                  s,
        const std::vector<std::pair<types::global_dof_index, double>> &entries,
        const double                                                   g) {
        constraints.add_line(s);
        for (const auto &[dof, w] : entries)
          if (w != 0.)
            constraints.add_entry(s, dof, w);
        constraints.set_inhomogeneity(s, g);
      };
    for (auto &node : nodes)
      {
        node.tied.fill(-1);
        if (!node.active)
          continue;
        const Tensor<1, dim> &n = node.normal;
        // Bodies that touch stay where they are; a gap that the step's
        // solution closed is closed by the tie.
        const double closing = node.touching ? 0. : node.gap;
        if (ties_all(node))
          {
            // u_b = u_a - closing n, component by component (a component
            // that a displacement condition holds for both bodies needs
            // no tie).
            for (unsigned int d = 0; d < dim; ++d)
              if (!constraints.is_constrained(node.dofs_b[d]))
                {
                  tie(node.dofs_b[d], {{node.dofs_a[d], 1.}}, -closing * n[d]);
                  node.tied[d] = 0;
                }
              else if (!constraints.is_constrained(node.dofs_a[d]))
                {
                  tie(node.dofs_a[d], {{node.dofs_b[d], 1.}}, closing * n[d]);
                  node.tied[d] = 1;
                }
            continue;
          }
        // (u_b - u_a) . n = -closing, solved for the component s of the
        // largest |n_s| of b (or of a, if b's is held).
        const unsigned int s = largest_component(n);
        std::vector<std::pair<types::global_dof_index, double>> entries;
        if (!constraints.is_constrained(node.dofs_b[s]))
          {
            for (unsigned int d = 0; d < dim; ++d)
              {
                entries.emplace_back(node.dofs_a[d], n[d] / n[s]);
                if (d != s)
                  entries.emplace_back(node.dofs_b[d], -n[d] / n[s]);
              }
            tie(node.dofs_b[s], entries, -closing / n[s]);
            node.tied[s] = 0;
          }
        else if (!constraints.is_constrained(node.dofs_a[s]))
          {
            for (unsigned int d = 0; d < dim; ++d)
              {
                entries.emplace_back(node.dofs_b[d], n[d] / n[s]);
                if (d != s)
                  entries.emplace_back(node.dofs_a[d], -n[d] / n[s]);
              }
            tie(node.dofs_a[s], entries, closing / n[s]);
            node.tied[s] = 1;
          }
      }
  }



  template <int dim>
  void
  BodyContact<dim>::add_friction_forces(
    TrilinosWrappers::MPI::Vector &f_ext) const
  {
    const IndexSet &owned = f_ext.locally_owned_elements();
    for (const auto &node : nodes)
      if (node.active && !ties_all(node))
        for (unsigned int d = 0; d < dim; ++d)
          {
            if (owned.is_element(node.dofs_b[d]))
              f_ext(node.dofs_b[d]) += node.friction[d];
            if (owned.is_element(node.dofs_a[d]))
              f_ext(node.dofs_a[d]) -= node.friction[d];
          }
  }



  template <int dim>
  Tensor<1, dim>
  BodyContact<dim>::tie_force(const Node                          &node,
                              const TrilinosWrappers::MPI::Vector &R) const
  {
    // R = f_ext - f_int before condensation: minus the force of the other
    // body on b at b's tied dofs, plus it at a's.
    Tensor<1, dim> force;
    for (unsigned int d = 0; d < dim; ++d)
      if (node.tied[d] == 0)
        force[d] = -R(node.dofs_b[d]);
      else if (node.tied[d] == 1)
        force[d] = R(node.dofs_a[d]);
    return force;
  }



  template <int dim>
  double
  BodyContact<dim>::normal_force(const Node                          &node,
                                 const TrilinosWrappers::MPI::Vector &R) const
  {
    // The force on b is +lambda n in compression. With the normal tie, the
    // tied component alone carries it (the other components' condensed
    // equations make the force parallel to n): lambda = f_s / n_s.
    const Tensor<1, dim> force = tie_force(node, R);
    if (ties_all(node))
      return force * node.normal;
    const unsigned int s = largest_component(node.normal);
    return force[s] / node.normal[s];
  }



  template <int dim>
  bool
  BodyContact<dim>::update(const BackgroundGrid<dim>           &grid,
                           const TrilinosWrappers::MPI::Vector &du,
                           const TrilinosWrappers::MPI::Vector &R)
  {
    if (!enabled())
      return false;
    const MPI_Comm                communicator = grid.get_communicator();
    TrilinosWrappers::MPI::Vector du_ghosted(grid.locally_owned_dofs(),
                                             grid.locally_relevant_dofs(),
                                             communicator);
    TrilinosWrappers::MPI::Vector R_ghosted(du_ghosted);
    du_ghosted = du;
    R_ghosted  = R;

    // The normal force of each tied node (0 for the others); forces below
    // 1e-8 of the largest are round-off. The force between the bodies
    // counts each node on the owner of body a's first dof.
    std::vector<double> lambdas(nodes.size(), 0.);
    double              largest = 0.;
    total_force                 = 0.;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (nodes[i].active)
        {
          lambdas[i] = normal_force(nodes[i], R_ghosted);
          largest    = std::max(largest, std::abs(lambdas[i]));
          if (grid.locally_owned_dofs().is_element(nodes[i].dofs_a[0]))
            total_force += lambdas[i];
        }
    largest     = dealii::Utilities::MPI::max(largest, communicator);
    total_force = dealii::Utilities::MPI::sum(total_force, communicator);
    const double force_floor = 1e-8 * largest;
    // The tolerance to which the friction forces of a step are converged.
    const double friction_tolerance = 1e-4 * largest;

    // The increment of b's displacement relative to a's at a node.
    const auto relative_increment = [&](const Node &node) {
      Tensor<1, dim> increment;
      for (unsigned int d = 0; d < dim; ++d)
        increment[d] = du_ghosted(node.dofs_b[d]) - du_ghosted(node.dofs_a[d]);
      return increment;
    };

    const bool coulomb = parameters.friction == Parameters::Friction::coulomb;
    // A slip below 1e-10 of the largest displacement is round-off: the
    // node does not slip.
    const double slip_floor = coulomb ? 1e-10 * du.linfty_norm() : 0.;
    const double mu         = parameters.friction_coefficient;
    bool         changed    = false;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (Node &node = nodes[i]; node.active)
        {
          const double lambda = lambdas[i];
          if (lambda < -force_floor)
            {
              node.active = false;
              changed     = true;
            }
          else if (coulomb && node.stick)
            {
              // Sticking needs the tangential tie force f_t: more than
              // mu lambda, and the node slips, pulled along f_t. A node
              // that has already slipped and stuck again in this step
              // slips again only beyond the tolerance of the friction
              // forces (below): otherwise a node that a body reaches only
              // through the edge of its points' cpGIMP domains, with a
              // normal force of a few 1e-6 of the largest, alternates
              // between the two in every solve, and the step never settles
              // (the sliding blocks with block A across the whole grid,
              // doc/contact.md).
              const Tensor<1, dim> f   = tie_force(node, R_ghosted);
              const Tensor<1, dim> f_t = f - (f * node.normal) * node.normal;
              const double         allowed =
                node.stuck_again ? friction_tolerance : force_floor;
              if (f_t.norm() > mu * std::max(lambda, 0.) + allowed)
                {
                  node.stick    = false;
                  node.friction = mu * std::max(lambda, 0.) / f_t.norm() * f_t;
                  changed       = true;
                }
            }
          else if (coulomb)
            {
              // The slip of b along a in this step; the friction force
              // opposes it. A node that does not slide, or slides along its
              // friction force (the force has reversed the slip), sticks.
              Tensor<1, dim> slip = relative_increment(node);
              slip -= (slip * node.normal) * node.normal;
              if (slip.norm() <= slip_floor || slip * node.friction > 0.)
                {
                  node.stick       = true;
                  node.stuck_again = true;
                  node.friction    = Tensor<1, dim>();
                  changed          = true;
                  continue;
                }
              const Tensor<1, dim> friction =
                -mu * std::max(lambda, 0.) / slip.norm() * slip;
              // The friction forces converge linearly in the solves of a
              // step; 1e-4 of the largest contact force changes mu's share
              // of the sliding blocks' force (contact_friction_blocks) by
              // 4e-5 against 1e-6, in 34 solves of the 12 steps instead of
              // 53.
              if ((friction - node.friction).norm() > friction_tolerance)
                changed = true;
              node.friction = friction;
            }
        }
      else
        {
          const double opening = relative_increment(node) * node.normal;
          // A node released in this step (its bodies touched at the start)
          // is tied again only if the bodies move into each other there:
          // the gap measured between the points' boxes is an estimate, off
          // by a fraction of the strain's variation times h, and an overlap
          // of that size would tie a tensile node again in every solve.
          const double closure = node.touching ? opening : node.gap + opening;
          if (closure < -gap_tolerance)
            {
              node.active   = true;
              node.stick    = true;
              node.friction = Tensor<1, dim>();
              changed       = true;
            }
        }
    return dealii::Utilities::MPI::max(changed ? 1 : 0, communicator) > 0;
  }



  template <int dim>
  unsigned int
  BodyContact<dim>::n_active(const BackgroundGrid<dim> &grid) const
  {
    unsigned int count = 0;
    for (const auto &node : nodes)
      if (node.active && grid.locally_owned_dofs().is_element(node.dofs_a[0]))
        ++count;
    return dealii::Utilities::MPI::sum(count, grid.get_communicator());
  }



  template class BodyContact<2>;
  template class BodyContact<3>;
} // namespace qsmpm
