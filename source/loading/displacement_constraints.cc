#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>
#include <qsmpm/loading/displacement_constraints.h>
#include <unordered_map>

namespace qsmpm
{
  namespace
  {
    // The coordinate direction normal to an axis-aligned face.
    template <typename FaceIterator>
    unsigned int
    face_normal_direction(const FaceIterator &face, const unsigned int dim)
    {
      for (unsigned int d = 0; d < dim; ++d)
        {
          bool constant = true;
          for (unsigned int v = 1; v < face->n_vertices(); ++v)
            constant =
              constant && std::abs(face->vertex(v)[d] - face->vertex(0)[d]) <=
                            1e-12 * face->diameter();
          if (constant)
            return d;
        }
      AssertThrow(false,
                  ExcMessage("Sliding (normal-component) conditions need "
                             "axis-aligned boundary faces."));
      return 0;
    }
  } // namespace



  template <int dim>
  DisplacementConstraints<dim>::DisplacementConstraints(
    const BoundaryDescriptor<dim> &boundary)
    : boundary(boundary)
  {
  }



  template <int dim>
  void
  DisplacementConstraints<dim>::make(const BackgroundGrid<dim> &grid,
                                     const double               t_old,
                                     const double               t_new,
                                     AffineConstraints<double> &constraints)
  {
    constraints.clear();
    constraints.reinit(grid.locally_relevant_dofs());
    AssertThrow(!boundary.has_macroscopic_gradient() ||
                  !grid.periodic_directions().empty(),
                ExcMessage("A macroscopic displacement gradient needs a grid "
                           "with periodic directions (Geometry: <Periodic "
                           "directions>)."));
    // Periodicity first: a node tied across the period keeps its tie even
    // if a displacement condition selects it as well.
    if (!grid.periodic_directions().empty())
      add_periodicity_constraints(grid, t_old, t_new, constraints);

    const auto &conditions = boundary.dirichlet_conditions();
    prescribed.assign(conditions.size(), {});
    for (unsigned int k = 0; k < conditions.size(); ++k)
      {
        add_condition(k, grid, t_old, t_new, constraints);
        AssertThrow(dealii::Utilities::MPI::sum(prescribed[k].size(),
                                                grid.get_communicator()) > 0,
                    ExcMessage("The displacement condition <" +
                               conditions[k].name +
                               "> does not select any grid node."));
      }
  }



  template <int dim>
  void
  DisplacementConstraints<dim>::add_condition(
    const unsigned int         k,
    const BackgroundGrid<dim> &grid,
    const double               t_old,
    const double               t_new,
    AffineConstraints<double> &constraints)
  {
    const auto     &condition = boundary.dirichlet_conditions()[k];
    const IndexSet &owned     = grid.locally_owned_dofs();
    auto           &dofs      = prescribed[k];
    Vector<double>  g_old(dim), g_new(dim);

    // Constrain the components in mask of the vertex x. A degree of freedom
    // that an earlier condition (or periodicity) constrained keeps that
    // constraint, but still counts as one of this condition's.
    const auto constrain = [&](const Point<dim>            &x,
                               const std::array<bool, dim> &mask,
                               const auto                  &dof_index) {
      condition.displacement->set_time(t_old);
      condition.displacement->vector_value(x, g_old);
      condition.displacement->set_time(t_new);
      condition.displacement->vector_value(x, g_new);
      // On a multi-field grid the condition holds every body's field.
      for (unsigned int b = 0; b < grid.n_bodies(); ++b)
        for (unsigned int c = 0; c < dim; ++c)
          if (mask[c])
            {
              const types::global_dof_index dof       = dof_index(b * dim + c);
              const double                  increment = g_new[c] - g_old[c];
              if (!constraints.is_constrained(dof))
                {
                  constraints.add_line(dof);
                  constraints.set_inhomogeneity(dof, increment);
                }
              if (owned.is_element(dof))
                dofs.push_back({dof, c, x, increment});
            }
    };

    for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        if (condition.boundary_id != numbers::invalid_boundary_id)
          {
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->boundary_id() == condition.boundary_id)
                {
                  const auto            face = cell->face(f);
                  std::array<bool, dim> mask = condition.components;
                  if (condition.normal_only)
                    {
                      mask.fill(false);
                      mask[face_normal_direction(face, dim)] = true;
                    }
                  for (unsigned int v = 0; v < face->n_vertices(); ++v)
                    constrain(face->vertex(v), mask, [&](const unsigned int c) {
                      return face->vertex_dof_index(v, c);
                    });
                }
          }
        else
          for (const unsigned int v : cell->vertex_indices())
            if (condition.selector(cell->vertex(v)))
              constrain(cell->vertex(v),
                        condition.components,
                        [&](const unsigned int c) {
                          return cell->vertex_dof_index(v, c);
                        });
      }

    // A node is reached from every cell (and face) around it.
    const auto by_index = [](const PrescribedDof &a, const PrescribedDof &b) {
      return a.index < b.index;
    };
    std::sort(dofs.begin(), dofs.end(), by_index);
    dofs.erase(std::unique(dofs.begin(),
                           dofs.end(),
                           [](const PrescribedDof &a, const PrescribedDof &b) {
                             return a.index == b.index;
                           }),
               dofs.end());
  }



  template <int dim>
  void
  DisplacementConstraints<dim>::add_periodicity_constraints(
    const BackgroundGrid<dim> &grid,
    const double               t_old,
    const double               t_new,
    AffineConstraints<double> &constraints) const
  {
    grid.make_periodicity_constraints(constraints);
    const Tensor<2, dim> dH =
      boundary.has_macroscopic_gradient() ?
        Tensor<2, dim>(boundary.macroscopic_gradient(t_new) -
                       boundary.macroscopic_gradient(t_old)) :
        Tensor<2, dim>();

    // Node and direction of every locally relevant degree of freedom (of
    // every body's field: periodicity ties each of them).
    std::unordered_map<types::global_dof_index,
                       std::pair<Point<dim>, unsigned int>>
      nodes;
    nodes.reserve(grid.locally_relevant_dofs().n_elements());
    for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int c = 0; c < grid.n_node_dofs(); ++c)
            nodes.emplace(cell->vertex_dof_index(v, c),
                          std::make_pair(cell->vertex(v), c % dim));
    auto node = [&](const types::global_dof_index dof) {
      const auto it = nodes.find(dof);
      AssertThrow(it != nodes.end(),
                  ExcMessage("Periodicity constraints: a node tied across "
                             "the period is not in the ghost layer."));
      return it->second;
    };

    // Every line is u_s = u_m between two nodes one period (or, at edges
    // and corners, several) apart: u_s - u_m = H (x_s - x_m).
    std::vector<std::pair<types::global_dof_index, double>> jumps;
    for (const auto &line : constraints.get_lines())
      {
        AssertThrow(line.entries.size() == 1 &&
                      std::abs(line.entries[0].second - 1.) < 1e-12,
                    ExcMessage("Periodicity constraints: expected one node "
                               "tied to one node."));
        const auto [x_s, c]   = node(line.index);
        const auto [x_m, c_m] = node(line.entries[0].first);
        AssertThrow(c == c_m,
                    ExcMessage("Periodicity constraints: components differ."));
        jumps.emplace_back(line.index, (dH * (x_s - x_m))[c]);
      }
    for (const auto &[dof, jump] : jumps)
      constraints.set_inhomogeneity(dof, jump);

    // Fully periodic: hold the free corner node (all corners are tied to it).
    if (grid.periodic_directions().size() < dim)
      return;
    const Point<dim> &lower = grid.lower_corner(), &upper = grid.upper_corner();
    const double      tolerance = 1e-10 * lower.distance(upper);
    for (const auto &[dof, x_c] : nodes)
      {
        bool corner = true;
        for (unsigned int d = 0; d < dim; ++d)
          corner = corner && (std::abs(x_c.first[d] - lower[d]) < tolerance ||
                              std::abs(x_c.first[d] - upper[d]) < tolerance);
        if (corner && !constraints.is_constrained(dof))
          {
            constraints.add_line(dof);
            constraints.set_inhomogeneity(
              dof,
              (dH *
               (x_c.first - boundary.macroscopic_reference()))[x_c.second]);
          }
      }
  }



  template <int dim>
  unsigned int
  DisplacementConstraints<dim>::n_conditions() const
  {
    return prescribed.size();
  }



  template <int dim>
  const std::vector<typename DisplacementConstraints<dim>::PrescribedDof> &
  DisplacementConstraints<dim>::prescribed_dofs(const unsigned int k) const
  {
    AssertIndexRange(k, prescribed.size());
    return prescribed[k];
  }



  template class DisplacementConstraints<2>;
  template class DisplacementConstraints<3>;
} // namespace qsmpm
