#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <qsmpm/assembly/ghost_penalty.h>

namespace qsmpm
{
  template <int dim>
  void
  GhostPenalty<dim>::reinit(const BackgroundGrid<dim> &grid,
                            const ShapeCache<dim>     &cache,
                            const unsigned int         volume_offset,
                            const double               gamma,
                            const double               stiffness_scale,
                            const bool                 axisymmetric)
  {
    const auto &dof_handler = grid.get_dof_handler();

    // The cells that take part: those all of whose nodes carry material
    // (the cells with points, and with GIMP the cells that their domains
    // reach across). A cell with a node without material would tie the
    // increments to that node's, which are held at zero.
    const IndexSet empty = cache.dofs_without_points(grid);
    // The nodes the material only partly surrounds: less than a quarter of
    // a cell's volume of material in their support (an interior node has a
    // whole cell's, a node on a straight surface half of it). A cell with
    // such a node is cut.
    const double   h_dim = std::pow(grid.min_cell_size(), dim);
    const IndexSet weak  = cache.dofs_without_points(grid,
                                                    volume_offset,
                                                    0.25 * h_dim,
                                                    axisymmetric);
    // With several bodies (BackgroundGrid::set_n_bodies()) each body has
    // its own field, and the choice is made for each: a face is penalized
    // in a body's field where both cells carry that body's material at all
    // their nodes and one of them is cut by it. Over all fields at once
    // every cell near another body would count as one without material.
    const FESystem<dim> &fe       = grid.get_fe();
    const unsigned int   n        = fe.n_dofs_per_cell();
    const unsigned int   n_fields = grid.n_bodies();
    AssertThrow(n_fields <= 8 * sizeof(unsigned int),
                ExcMessage("The ghost penalty takes at most " +
                           std::to_string(8 * sizeof(unsigned int)) +
                           " bodies."));
    // The component of each dof of the two cells of a face; its field is
    // component / dim.
    std::vector<unsigned int> component(2 * n);
    for (unsigned int i = 0; i < n; ++i)
      component[i] = component[n + i] = fe.system_to_component_index(i).first;
    std::vector<types::global_dof_index> dofs(n), neighbor_dofs(n);
    // Bit b: the cell has a dof of field b in @p set.
    const auto fields_in = [&](const auto &cell, const IndexSet &set) {
      cell->get_dof_indices(dofs);
      unsigned int mask = 0;
      for (unsigned int i = 0; i < n; ++i)
        if (set.is_element(dofs[i]))
          mask |= 1u << (component[i] / dim);
      return mask;
    };
    const unsigned int all_fields =
      n_fields == 8 * sizeof(unsigned int) ? ~0u : (1u << n_fields) - 1u;

    // The faces: between two such cells of which one is cut, each once
    // (from the cell with the smaller id; a ghost neighbour's rank takes the
    // faces where its cell is the smaller), with the fields penalized.
    struct Face
    {
      typename DoFHandler<dim>::active_cell_iterator cell;
      unsigned int                                   face;
      unsigned int                                   fields;
    };
    std::vector<Face> penalized;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const unsigned int full = all_fields & ~fields_in(cell, empty);
        if (full == 0)
          continue;
        const unsigned int cut = fields_in(cell, weak);
        for (const unsigned int f : cell->face_indices())
          {
            if (cell->at_boundary(f))
              continue;
            const auto neighbor = cell->neighbor(f);
            if (neighbor->is_artificial() || !(cell->id() < neighbor->id()))
              continue;
            const unsigned int fields = full & ~fields_in(neighbor, empty) &
                                        (cut | fields_in(neighbor, weak));
            if (fields != 0)
              penalized.push_back({cell, f, fields});
          }
      }

    // g = gamma E_s h int_F [[grad du . n]] . [[grad v . n]] on each face,
    // from both cells' gradients at the face's Gauss points.
    const QGauss<dim - 1> quadrature(2);
    FEFaceValues<dim>     here(grid.get_mapping(),
                           fe,
                           quadrature,
                           update_gradients | update_JxW_values |
                             update_normal_vectors | update_quadrature_points);
    const double          mid_radius =
      0.5 * (grid.lower_corner()[0] + grid.upper_corner()[0]);
    FEFaceValues<dim>  there(grid.get_mapping(),
                            fe,
                            quadrature,
                            update_gradients);
    FullMatrix<double> local(2 * n, 2 * n);
    clear();
    std::vector<types::global_dof_index> local_dofs(2 * n);
    std::vector<double>                  jump(2 * n);
    for (const auto &[cell, f, fields] : penalized)
      {
        const auto neighbor = cell->neighbor(f);
        here.reinit(cell, f);
        there.reinit(neighbor, cell->neighbor_of_neighbor(f));
        cell->get_dof_indices(dofs);
        neighbor->get_dof_indices(neighbor_dofs);
        std::copy(dofs.begin(), dofs.end(), local_dofs.begin());
        std::copy(neighbor_dofs.begin(),
                  neighbor_dofs.end(),
                  local_dofs.begin() + n);
        const double h = cell->measure() / cell->face(f)->measure();
        local          = 0.;
        for (const unsigned int q : here.quadrature_point_indices())
          {
            const Tensor<1, dim> &normal = here.normal_vector(q);
            for (unsigned int i = 0; i < n; ++i)
              {
                jump[i]     = here.shape_grad(i, q) * normal;
                jump[n + i] = -(there.shape_grad(i, q) * normal);
              }
            const double weight =
              gamma * stiffness_scale * h * here.JxW(q) *
              (axisymmetric ? here.quadrature_point(q)[0] / mid_radius : 1.);
            for (unsigned int i = 0; i < 2 * n; ++i)
              for (unsigned int j = 0; j < 2 * n; ++j)
                if (component[i] == component[j] &&
                    (fields & (1u << (component[i] / dim))) != 0)
                  local(i, j) += weight * jump[i] * jump[j];
          }
        add(local_dofs, local);
      }
    build(grid.locally_owned_dofs(),
          grid.locally_relevant_dofs(),
          grid.get_communicator());
  }



  template class GhostPenalty<2>;
  template class GhostPenalty<3>;
} // namespace qsmpm
