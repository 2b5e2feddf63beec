#include <Epetra_BlockMap.h>
#include <deal.II/base/exceptions.h>
#include <qsmpm/particles/shape_cache.h>

namespace qsmpm
{
  namespace
  {
    // Q1 shape functions on the unit cell; vertex v sits at the corner whose
    // d-th coordinate is bit d of v (deal.II's vertex numbering).
    template <int dim>
    void
    q1_shape(const Point<dim> &xi,
             double           *values,
             Tensor<1, dim>   *reference_gradients)
    {
      for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell; ++v)
        {
          double value = 1.;
          for (unsigned int d = 0; d < dim; ++d)
            value *= ((v >> d) & 1) ? xi[d] : 1. - xi[d];
          values[v] = value;
          for (unsigned int d = 0; d < dim; ++d)
            {
              double g = 1.;
              for (unsigned int e = 0; e < dim; ++e)
                if (e == d)
                  g *= ((v >> e) & 1) ? 1. : -1.;
                else
                  g *= ((v >> e) & 1) ? xi[e] : 1. - xi[e];
              reference_gradients[v][d] = g;
            }
        }
    }
  } // namespace



  template <int dim>
  void
  ShapeCache<dim>::reinit(const BackgroundGrid<dim>           &grid,
                          MaterialPointSet<dim>               &points,
                          const TrilinosWrappers::MPI::Vector &ghosted)
  {
    [[maybe_unused]] const FESystem<dim> &fe = grid.get_fe();
    for (unsigned int v = 0; v < n_vertices; ++v)
      for (unsigned int c = 0; c < dim; ++c)
        Assert(fe.system_to_component_index(v * dim + c).first == c &&
                 fe.system_to_component_index(v * dim + c).second == v,
               ExcInternalError());

    auto              &particle_handler = points.get_particle_handler();
    const unsigned int n_local_points =
      particle_handler.n_locally_owned_particles();

    cells.clear();
    cell_local_dofs.clear();
    cell_global_dofs.clear();
    shape_values.resize(n_local_points * n_vertices);
    shape_gradients.resize(n_local_points * n_vertices);
    point_properties.resize(n_local_points);
    point_positions.resize(n_local_points);

    const Epetra_BlockMap               &map = ghosted.trilinos_vector().Map();
    std::vector<types::global_dof_index> dofs(dofs_per_cell);
    Tensor<1, dim>                       reference_gradients[n_vertices];

    unsigned int p = 0;
    for (const auto &dof_cell : grid.get_dof_handler().active_cell_iterators())
      if (dof_cell->is_locally_owned())
        {
          const typename Triangulation<dim>::active_cell_iterator cell(
            dof_cell);
          const auto particles = particle_handler.particles_in_cell(cell);
          if (particles.begin() == particles.end())
            continue;

          dof_cell->get_dof_indices(dofs);
          for (const auto dof : dofs)
            {
              const int lid =
                map.LID(static_cast<TrilinosWrappers::types::int_type>(dof));
              AssertThrow(lid >= 0, ExcInternalError());
              cell_local_dofs.push_back(lid);
              cell_global_dofs.push_back(dof);
            }

          const unsigned int first = p;
          for (const auto &particle : particles)
            {
              // The Jacobian of the Q1 map at the point: exact for any
              // (bi/tri)linear cell, and diagonal on the Cartesian grid.
              const Point<dim> xi = particle.get_reference_location();
              q1_shape<dim>(xi,
                            &shape_values[p * n_vertices],
                            reference_gradients);
              Tensor<2, dim> jacobian;
              for (unsigned int v = 0; v < n_vertices; ++v)
                jacobian +=
                  outer_product(cell->vertex(v), reference_gradients[v]);
              const Tensor<2, dim> inverse_transpose =
                transpose(invert(jacobian));
              for (unsigned int v = 0; v < n_vertices; ++v)
                shape_gradients[p * n_vertices + v] =
                  inverse_transpose * reference_gradients[v];
              // ParticleAccessor::get_properties() is not const, but the
              // pointer stays valid until particles are added or sorted.
              point_properties[p] =
                const_cast<double *>(particle.get_properties().data());
              point_positions[p] = particle.get_location();
              ++p;
            }
          cells.push_back({cell, first, p});
        }
    AssertThrow(p == n_local_points,
                ExcMessage("Some locally owned material points were not found "
                           "in locally owned cells."));
  }



  template <int dim>
  IndexSet
  ShapeCache<dim>::dofs_without_points(const BackgroundGrid<dim> &grid) const
  {
    // Count, for every degree of freedom, the cells with points around it;
    // the sum over ranks tells which nodes are inactive everywhere.
    TrilinosWrappers::MPI::Vector count(grid.locally_owned_dofs(),
                                        grid.get_communicator());
    std::vector<double>           ones(dofs_per_cell, 1.);
    for (unsigned int c = 0; c < n_cells(); ++c)
      count.add(std::vector<types::global_dof_index>(global_dofs(c),
                                                     global_dofs(c) +
                                                       dofs_per_cell),
                ones);
    count.compress(VectorOperation::add);
    TrilinosWrappers::MPI::Vector ghosted(grid.locally_owned_dofs(),
                                          grid.locally_relevant_dofs(),
                                          grid.get_communicator());
    ghosted = count;

    IndexSet inactive(grid.get_dof_handler().n_dofs());
    for (const auto dof : grid.locally_relevant_dofs())
      if (ghosted(dof) == 0.)
        inactive.add_index(dof);
    inactive.compress();
    return inactive;
  }



  template <int dim>
  Tensor<1, dim>
  ShapeCache<dim>::interpolate(const unsigned int c,
                               const unsigned int p,
                               const double      *local_values) const
  {
    const int     *dofs = local_dofs(c);
    const double  *N    = values(p);
    Tensor<1, dim> result;
    for (unsigned int v = 0; v < n_vertices; ++v)
      for (unsigned int d = 0; d < dim; ++d)
        result[d] += N[v] * local_values[dofs[v * dim + d]];
    return result;
  }



  template class ShapeCache<2>;
  template class ShapeCache<3>;
} // namespace qsmpm
