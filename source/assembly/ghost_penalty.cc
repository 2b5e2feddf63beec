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
    std::vector<types::global_dof_index> dofs(grid.get_fe().n_dofs_per_cell()),
      neighbor_dofs(dofs.size());
    const auto any_in = [&](const auto &cell, const IndexSet &set) {
      cell->get_dof_indices(dofs);
      for (const auto dof : dofs)
        if (set.is_element(dof))
          return true;
      return false;
    };

    // The faces: between two such cells of which one is cut,
    // each once (from the cell with the smaller id; a ghost neighbour's
    // rank takes the faces where its cell is the smaller).
    std::vector<
      std::pair<typename DoFHandler<dim>::active_cell_iterator, unsigned int>>
      penalized;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned() || any_in(cell, empty))
          continue;
        const bool cell_cut = any_in(cell, weak);
        for (const unsigned int f : cell->face_indices())
          {
            if (cell->at_boundary(f))
              continue;
            const auto neighbor = cell->neighbor(f);
            if (neighbor->is_artificial() || !(cell->id() < neighbor->id()) ||
                any_in(neighbor, empty) ||
                !(cell_cut || any_in(neighbor, weak)))
              continue;
            penalized.emplace_back(cell, f);
          }
      }

    // g = gamma E_s h int_F [[grad du . n]] . [[grad v . n]] on each face,
    // from both cells' gradients at the face's Gauss points.
    const FESystem<dim>  &fe = grid.get_fe();
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
    const unsigned int n = fe.n_dofs_per_cell();
    FullMatrix<double> local(2 * n, 2 * n);
    clear();
    std::vector<types::global_dof_index> local_dofs(2 * n);
    std::vector<double>                  jump(2 * n);
    std::vector<unsigned int>            component(2 * n);
    for (unsigned int i = 0; i < n; ++i)
      component[i] = component[n + i] = fe.system_to_component_index(i).first;
    for (const auto &[cell, f] : penalized)
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
                if (component[i] == component[j])
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
