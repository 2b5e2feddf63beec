#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <qsmpm/assembly/ghost_penalty.h>

namespace qsmpm
{
  template <int dim>
  void
  GhostPenalty<dim>::reinit(const BackgroundGrid<dim> &grid,
                            const ShapeCache<dim>     &cache,
                            const unsigned int         volume_offset,
                            const double               gamma,
                            const double               stiffness_scale)
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
    const IndexSet weak =
      cache.dofs_without_points(grid, volume_offset, 0.25 * h_dim);
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

    TrilinosWrappers::SparsityPattern pattern(grid.locally_owned_dofs(),
                                              grid.locally_owned_dofs(),
                                              grid.locally_relevant_dofs(),
                                              grid.get_communicator());
    for (const auto &[cell, f] : penalized)
      {
        cell->get_dof_indices(dofs);
        cell->neighbor(f)->get_dof_indices(neighbor_dofs);
        for (const auto i : {&dofs, &neighbor_dofs})
          for (const auto j : {&dofs, &neighbor_dofs})
            for (const auto row : *i)
              for (const auto column : *j)
                pattern.add(row, column);
      }
    pattern.compress();
    G.reinit(pattern);

    // g = gamma E_s h int_F [[grad du . n]] . [[grad v . n]] on each face,
    // from both cells' gradients at the face's Gauss points.
    const FESystem<dim>  &fe = grid.get_fe();
    const QGauss<dim - 1> quadrature(2);
    FEFaceValues<dim>     here(grid.get_mapping(),
                           fe,
                           quadrature,
                           update_gradients | update_JxW_values |
                             update_normal_vectors);
    FEFaceValues<dim>     there(grid.get_mapping(),
                            fe,
                            quadrature,
                            update_gradients);
    const unsigned int    n = fe.n_dofs_per_cell();
    FullMatrix<double>    local(2 * n, 2 * n);
    face_dofs.clear();
    face_matrices.clear();
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
            const double weight = gamma * stiffness_scale * h * here.JxW(q);
            for (unsigned int i = 0; i < 2 * n; ++i)
              for (unsigned int j = 0; j < 2 * n; ++j)
                if (component[i] == component[j])
                  local(i, j) += weight * jump[i] * jump[j];
          }
        G.add(local_dofs, local);
        face_dofs.push_back(local_dofs);
        face_matrices.push_back(local);
      }
    G.compress(VectorOperation::add);
    faces =
      dealii::Utilities::MPI::sum(static_cast<unsigned int>(penalized.size()),
                                  grid.get_communicator());
  }



  template <int dim>
  bool
  GhostPenalty<dim>::active() const
  {
    return faces > 0;
  }



  template <int dim>
  unsigned int
  GhostPenalty<dim>::n_faces() const
  {
    return faces;
  }



  template <int dim>
  void
  GhostPenalty<dim>::subtract_forces(const TrilinosWrappers::MPI::Vector &du,
                                     TrilinosWrappers::MPI::Vector &R) const
  {
    if (!active())
      return;
    scratch.reinit(R, /*omit_zeroing_entries=*/true);
    G.vmult(scratch, du);
    R -= scratch;
  }



  template <int dim>
  void
  GhostPenalty<dim>::add_diagonal_to(
    TrilinosWrappers::MPI::Vector &diagonal) const
  {
    if (!active())
      return;
    for (const auto row : diagonal.locally_owned_elements())
      diagonal(row) += G.diag_element(row);
    diagonal.compress(VectorOperation::add);
  }



  template <int dim>
  void
  GhostPenalty<dim>::add_couplings(
    const AffineConstraints<double>   &periodicity,
    TrilinosWrappers::SparsityPattern &pattern) const
  {
    for (const auto &dofs : face_dofs)
      periodicity.add_entries_local_to_global(dofs,
                                              pattern,
                                              /*keep_constrained=*/true);
  }



  template <int dim>
  void
  GhostPenalty<dim>::add_to(const AffineConstraints<double> &constraints,
                            TrilinosWrappers::SparseMatrix  &K) const
  {
    for (unsigned int f = 0; f < face_dofs.size(); ++f)
      constraints.distribute_local_to_global(face_matrices[f], face_dofs[f], K);
  }



  template class GhostPenalty<2>;
  template class GhostPenalty<3>;
} // namespace qsmpm
