#include <algorithm>
#include <deal.II/base/mpi.h>
#include <qsmpm/loading/rigid_plates.h>
#include <string>

namespace qsmpm
{
  template <int dim>
  RigidPlates<dim>::RigidPlates(const BoundaryDescriptor<dim> &boundary)
    : boundary(boundary)
  {
  }



  template <int dim>
  bool
  RigidPlates<dim>::empty() const
  {
    return boundary.rigid_plates().empty();
  }



  template <int dim>
  void
  RigidPlates<dim>::reinit_step(const BackgroundGrid<dim>       &grid,
                                const AffineConstraints<double> &constraints,
                                const double stiffness_scale)
  {
    communicator      = grid.get_communicator();
    stiffness         = stiffness_scale;
    const auto &ids   = boundary.rigid_plates();
    const auto &owned = grid.locally_owned_dofs();
    for (const auto id : ids)
      for (const auto &condition : boundary.dirichlet_conditions())
        AssertThrow(condition.boundary_id != id ||
                      !(condition.normal_only || condition.components[id / 2]),
                    ExcMessage("Boundary conditions: boundary " +
                               std::to_string(id) +
                               " is a rigid plate and has a displacement "
                               "condition along its normal; a plate moves "
                               "by its load, so give it only one of them."));
    dofs.assign(ids.size(), {});
    n_dofs.assign(ids.size(), 0.);
    for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            for (unsigned int k = 0; k < ids.size(); ++k)
              if (cell->face(f)->boundary_id() == ids[k])
                // Boundary id 2d + s is the face of the box normal to
                // direction d (BackgroundGrid::make_box()).
                for (unsigned int v = 0; v < cell->face(f)->n_vertices(); ++v)
                  {
                    const types::global_dof_index dof =
                      cell->face(f)->vertex_dof_index(v, ids[k] / 2);
                    if (owned.is_element(dof) &&
                        !constraints.is_constrained(dof))
                      dofs[k].push_back(dof);
                  }
    for (unsigned int k = 0; k < ids.size(); ++k)
      {
        std::sort(dofs[k].begin(), dofs[k].end());
        dofs[k].erase(std::unique(dofs[k].begin(), dofs[k].end()),
                      dofs[k].end());
        n_dofs[k] = Utilities::MPI::sum(static_cast<double>(dofs[k].size()),
                                        communicator);
        AssertThrow(n_dofs[k] > 0.,
                    ExcMessage("Boundary conditions: the rigid plate on "
                               "boundary " +
                               std::to_string(ids[k]) +
                               " has no grid node with material that is "
                               "free to move along its normal."));
      }
  }



  template <int dim>
  std::vector<double>
  RigidPlates<dim>::means(const VectorType &v) const
  {
    std::vector<double> sums(dofs.size(), 0.);
    for (unsigned int k = 0; k < dofs.size(); ++k)
      for (const auto dof : dofs[k])
        sums[k] += v(dof);
    MPI_Allreduce(MPI_IN_PLACE,
                  sums.data(),
                  sums.size(),
                  MPI_DOUBLE,
                  MPI_SUM,
                  communicator);
    for (unsigned int k = 0; k < dofs.size(); ++k)
      sums[k] /= n_dofs[k];
    return sums;
  }



  template <int dim>
  std::vector<double>
  RigidPlates<dim>::project(const VectorType &du, VectorType &projected) const
  {
    std::vector<double> mean = means(du);
    projected                = du;
    for (unsigned int k = 0; k < dofs.size(); ++k)
      for (const auto dof : dofs[k])
        projected(dof) = mean[k];
    projected.compress(VectorOperation::insert);
    return mean;
  }



  template <int dim>
  void
  RigidPlates<dim>::tie(const VectorType          &du,
                        const std::vector<double> &mean,
                        VectorType                &R) const
  {
    const std::vector<double> force = means(R);
    for (unsigned int k = 0; k < dofs.size(); ++k)
      for (const auto dof : dofs[k])
        R(dof) = force[k] - stiffness * (du(dof) - mean[k]);
    R.compress(VectorOperation::insert);
  }



  template <int dim>
  void
  RigidPlates<dim>::add_to(TrilinosWrappers::SparseMatrix &K) const
  {
    for (const auto &plate : dofs)
      for (const auto dof : plate)
        K.add(dof, dof, stiffness);
  }



  template class RigidPlates<2>;
  template class RigidPlates<3>;
} // namespace qsmpm
