#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <qsmpm/loading/external_force_assembler.h>
#include <vector>

namespace qsmpm
{
  template <int dim>
  ExternalForceAssembler<dim>::ExternalForceAssembler(
    const BoundaryDescriptor<dim> &boundary)
    : boundary(boundary)
  {
  }



  template <int dim>
  void
  ExternalForceAssembler<dim>::set_axisymmetric(const bool value)
  {
    axisymmetric = value;
  }



  template <int dim>
  void
  ExternalForceAssembler<dim>::assemble(
    const BackgroundGrid<dim>     &grid,
    const ShapeCache<dim>         &cache,
    const unsigned int             volume_offset,
    const double                   t,
    TrilinosWrappers::MPI::Vector &f_ext) const
  {
    f_ext = 0;
    if (boundary.body_force())
      add_body_force(cache, volume_offset, t, f_ext);
    // With several bodies (a multi-field grid), what acts on a grid node
    // goes to the fields of the bodies there.
    TrilinosWrappers::MPI::Vector volumes;
    if (grid.n_bodies() > 1 &&
        (!boundary.tractions().empty() || !boundary.point_loads().empty()))
      {
        const TrilinosWrappers::MPI::Vector owned =
          cache.nodal_volumes(grid, volume_offset);
        volumes.reinit(grid.locally_owned_dofs(),
                       grid.locally_relevant_dofs(),
                       grid.get_communicator());
        // A copy, which imports the ghost values (assigning the temporary
        // would move its layout, without ghosts, into volumes).
        volumes = owned;
      }
    if (!boundary.tractions().empty())
      add_tractions(grid, volumes, t, f_ext);
    add_point_loads(grid, volumes, t, f_ext);
    f_ext.compress(VectorOperation::add);
  }



  // A grid node's force along d goes to the field of body b in proportion
  // to b's material at the node, sum_p Omega_p N_i(x_p) over b's points
  // (ShapeCache::nodal_volumes()): where one body touches a loaded face, it
  // carries the load alone; a node where two bodies meet divides it as
  // their material does. At a node without material the force stays on the
  // first field, at a node that the step holds: the load is lost there, as
  // on one field, and the equilibrium audit says so.
  template <int dim>
  double
  ExternalForceAssembler<dim>::field_share(
    const BackgroundGrid<dim>                  &grid,
    const TrilinosWrappers::MPI::Vector        &volumes,
    const std::vector<types::global_dof_index> &node_dofs,
    const unsigned int                          component)
  {
    if (grid.n_bodies() == 1)
      return 1.;
    const unsigned int d     = component % dim;
    double             total = 0.;
    for (unsigned int b = 0; b < grid.n_bodies(); ++b)
      total += volumes(node_dofs[b * dim + d]);
    if (!(total > 0.))
      return component < dim ? 1. : 0.;
    return volumes(node_dofs[component]) / total;
  }



  // Body force, paper eq. (2.11): b_i = sum_p Omega_p b(x_p) N_i(x_p),
  // summed per cell group of the ShapeCache and added to the group's dofs.
  template <int dim>
  void
  ExternalForceAssembler<dim>::add_body_force(
    const ShapeCache<dim>         &cache,
    const unsigned int             volume_offset,
    const double                   t,
    TrilinosWrappers::MPI::Vector &f_ext) const
  {
    Function<dim> &body_force = *boundary.body_force();
    body_force.set_time(t);
    Vector<double>                        b(dim);
    std::vector<types::global_dof_index>  dofs;
    std::vector<double>                   cell_force;
    typename ShapeCache<dim>::ValueBuffer buffer;
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        cell_force.assign(cache.n_dofs(c), 0.);
        const auto &range = cache.cell(c);
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            body_force.vector_value(cache.position(p), b);
            const double          volume = cache.properties(p)[volume_offset];
            const double         *N      = cache.values(c, p, buffer);
            const unsigned short *nodes  = cache.nodes(p);
            for (unsigned int k = 0; k < cache.stencil_size(p); ++k)
              for (unsigned int d = 0; d < dim; ++d)
                cell_force[nodes[k] * dim + d] += volume * b[d] * N[k];
          }
        dofs.assign(cache.global_dofs(c),
                    cache.global_dofs(c) + cache.n_dofs(c));
        f_ext.add(dofs, cell_force);
      }
  }



  // Tractions, paper eq. (2.12), on the grid's boundary faces with the
  // boundary ids of the descriptor: two Gauss points per direction
  // integrate the product of a linear traction and a Q1 shape function.
  template <int dim>
  void
  ExternalForceAssembler<dim>::add_tractions(
    const BackgroundGrid<dim>           &grid,
    const TrilinosWrappers::MPI::Vector &volumes,
    const double                         t,
    TrilinosWrappers::MPI::Vector       &f_ext) const
  {
    const FiniteElement<dim>            &fe = grid.get_fe();
    const QGauss<dim - 1>                face_quadrature(2);
    FEFaceValues<dim>                    fe_face(grid.get_mapping(),
                              grid.get_fe(),
                              face_quadrature,
                              update_values | update_quadrature_points |
                                update_JxW_values);
    Vector<double>                       traction(dim);
    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(dofs_per_cell);
    std::vector<types::global_dof_index> node_dofs(fe.n_components());
    std::vector<double>                  cell_force(dofs_per_cell);
    for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          for (const auto &[id, function] : boundary.tractions())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == id)
              {
                fe_face.reinit(cell, f);
                function->set_time(t);
                std::fill(cell_force.begin(), cell_force.end(), 0.);
                for (const unsigned int q : fe_face.quadrature_point_indices())
                  {
                    const Point<dim> &x = fe_face.quadrature_point(q);
                    function->vector_value(x, traction);
                    // Axisymmetric: the face's area per radian is r dGamma.
                    const double JxW =
                      fe_face.JxW(q) * (axisymmetric ? x[0] : 1.);
                    for (unsigned int i = 0; i < dofs_per_cell; ++i)
                      {
                        const unsigned int c =
                          fe.system_to_component_index(i).first;
                        cell_force[i] +=
                          traction[c % dim] * fe_face.shape_value(i, q) * JxW;
                      }
                  }
                cell->get_dof_indices(dofs);
                if (grid.n_bodies() > 1)
                  for (unsigned int i = 0; i < dofs_per_cell; ++i)
                    {
                      const auto [c, vertex] = fe.system_to_component_index(i);
                      for (unsigned int k = 0; k < fe.n_components(); ++k)
                        node_dofs[k] =
                          dofs[fe.component_to_system_index(k, vertex)];
                      cell_force[i] *= field_share(grid, volumes, node_dofs, c);
                    }
                f_ext.add(dofs, cell_force);
              }
  }



  // Point loads at grid nodes, scaled by the load factor; the owner of the
  // node's dofs adds them.
  template <int dim>
  void
  ExternalForceAssembler<dim>::add_point_loads(
    const BackgroundGrid<dim>           &grid,
    const TrilinosWrappers::MPI::Vector &volumes,
    const double                         t,
    TrilinosWrappers::MPI::Vector       &f_ext) const
  {
    std::vector<types::global_dof_index> node_dofs(
      grid.get_fe().n_components());
    for (const auto &[location, force] : boundary.point_loads())
      {
        bool found = false;
        for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
          if (!cell->is_artificial() && !found)
            for (const unsigned int v : cell->vertex_indices())
              if (cell->vertex(v).distance(location) < 1e-10 * cell->diameter())
                {
                  found = true;
                  for (unsigned int k = 0; k < node_dofs.size(); ++k)
                    node_dofs[k] = cell->vertex_dof_index(v, k);
                  for (unsigned int k = 0; k < node_dofs.size(); ++k)
                    if (grid.locally_owned_dofs().is_element(node_dofs[k]))
                      f_ext(node_dofs[k]) +=
                        t * force[k % dim] *
                        field_share(grid, volumes, node_dofs, k);
                  break;
                }
        AssertThrow(dealii::Utilities::MPI::max(found ? 1 : 0,
                                                grid.get_communicator()) == 1,
                    ExcMessage("A point load must sit on a grid node."));
      }
  }



  template class ExternalForceAssembler<2>;
  template class ExternalForceAssembler<3>;
} // namespace qsmpm
