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
    communicator          = grid.get_communicator();
    stiffness             = stiffness_scale;
    preconditioner_matrix = nullptr;
    const auto &ids       = boundary.rigid_plates();
    const auto &owned     = grid.locally_owned_dofs();
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
                // direction d (BackgroundGrid::make_box()). With several
                // bodies the plate moves the field of each body there (a
                // field without material at a node is held).
                for (unsigned int v = 0; v < cell->face(f)->n_vertices(); ++v)
                  for (unsigned int b = 0; b < grid.n_bodies(); ++b)
                    {
                      const types::global_dof_index dof =
                        cell->face(f)->vertex_dof_index(v,
                                                        b * dim + ids[k] / 2);
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
    projected = du;
    return average_plates(projected);
  }



  template <int dim>
  std::vector<double>
  RigidPlates<dim>::average_plates(VectorType &v) const
  {
    std::vector<double> mean = means(v);
    for (unsigned int k = 0; k < dofs.size(); ++k)
      for (const auto dof : dofs[k])
        v(dof) = mean[k];
    v.compress(VectorOperation::insert);
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
  RigidPlates<dim>::add_to(TrilinosWrappers::SparseMatrix &K,
                           const bool preconditioner_matrix) const
  {
    if (preconditioner_matrix)
      {
        matrix_dofs.clear();
        matrix_stiffness = stiffness;
      }
    for (const auto &plate : dofs)
      for (const auto dof : plate)
        {
          K.add(dof, dof, stiffness);
          if (preconditioner_matrix)
            matrix_dofs.push_back(dof);
        }
  }



  template <int dim>
  void
  RigidPlates<dim>::material_vmult(const TrilinosWrappers::SparseMatrix &K_A,
                                   VectorType                           &y,
                                   const VectorType &x) const
  {
    K_A.vmult(y, x);
    for (const auto dof : matrix_dofs)
      y(dof) -= matrix_stiffness * x(dof);
    y.compress(VectorOperation::add);
  }



  template <int dim>
  void
  RigidPlates<dim>::setup_preconditioner(
    const TrilinosWrappers::SparseMatrix    &K_A,
    const Preconditioning                   &M,
    const std::function<void(VectorType &)> &zero_constrained,
    const bool                               new_preconditioner,
    const unsigned int                       sweeps)
  {
    const unsigned int n = dofs.size();
    const bool         same_nodes =
      Utilities::MPI::min(mode_dofs == dofs ? 1 : 0, communicator) == 1;
    if (!new_preconditioner && same_nodes && modes.size() == n)
      {
        preconditioner_matrix = &K_A;
        return;
      }
    mode_dofs = dofs;
    // Each plate's entries of phi_k: one on plate k, zero on the others.
    const auto set_plates = [this](VectorType &v, const unsigned int k) {
      for (unsigned int l = 0; l < dofs.size(); ++l)
        for (const auto dof : dofs[l])
          v(dof) = (l == k ? 1. : 0.);
      v.compress(VectorOperation::insert);
    };
    scratch.reinit(K_A.locally_owned_domain_indices(), communicator);
    VectorType correction(scratch);
    modes.assign(n, scratch);
    std::vector<VectorType> stiffness_modes(n, scratch);
    for (unsigned int k = 0; k < n; ++k)
      {
        set_plates(modes[k], k);
        // Richardson sweeps on K phi = 0 in the rows of the free dofs,
        // phi fixed on the plates: the body follows the plate.
        for (unsigned int sweep = 0; sweep < sweeps; ++sweep)
          {
            material_vmult(K_A, scratch, modes[k]);
            set_plates(scratch, numbers::invalid_unsigned_int);
            zero_constrained(scratch);
            // M = -K_A^{-1}: correction = -K_A^{-1} K phi.
            M(correction, scratch);
            modes[k] += correction;
            set_plates(modes[k], k);
            zero_constrained(modes[k]);
          }
        material_vmult(K_A, stiffness_modes[k], modes[k]);
      }
    FullMatrix<double> coarse(n, n);
    bool               positive = true;
    for (unsigned int k = 0; k < n; ++k)
      {
        for (unsigned int l = 0; l < n; ++l)
          coarse(k, l) = modes[k] * stiffness_modes[l];
        positive = positive && coarse(k, k) > 0.;
      }
    // A plate whose mode has no stiffness (a body that only the plate
    // holds): the preconditioner without the correction; Newton will say
    // whether the step converges.
    if (!positive)
      {
        modes.clear();
        return;
      }
    coarse_inverse.reinit(n, n);
    coarse_inverse.invert(coarse);
    coarse_rhs.reinit(n);
    coarse_solution.reinit(n);
    preconditioner_matrix = &K_A;
  }



  template <int dim>
  bool
  RigidPlates<dim>::has_preconditioner() const
  {
    return preconditioner_matrix != nullptr;
  }



  template <int dim>
  void
  RigidPlates<dim>::precondition(const Preconditioning &M,
                                 VectorType            &dst,
                                 const VectorType      &src) const
  {
    Assert(has_preconditioner(), ExcInternalError());
    // With the sign of Preconditioner::vmult(): dst solves K z = -src.
    M(dst, src);
    average_plates(dst);
    // The coarse correction: (Phi^T K Phi) c = Phi^T (-src - K z).
    material_vmult(*preconditioner_matrix, scratch, dst);
    scratch += src;
    for (unsigned int k = 0; k < modes.size(); ++k)
      coarse_rhs[k] = -(modes[k] * scratch);
    coarse_inverse.vmult(coarse_solution, coarse_rhs);
    for (unsigned int k = 0; k < modes.size(); ++k)
      dst.add(coarse_solution[k], modes[k]);
    // The deviations from the plate's mean, exactly.
    const std::vector<double> src_mean = means(src);
    for (unsigned int k = 0; k < dofs.size(); ++k)
      for (const auto dof : dofs[k])
        dst(dof) += (src_mean[k] - src(dof)) / stiffness;
    dst.compress(VectorOperation::add);
  }



  template class RigidPlates<2>;
  template class RigidPlates<3>;
} // namespace qsmpm
