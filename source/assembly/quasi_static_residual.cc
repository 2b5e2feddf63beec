#include <Epetra_BlockMap.h>
#include <qsmpm/assembly/quasi_static_residual.h>
#include <qsmpm/base/utilities.h>

namespace qsmpm
{
  template <int dim>
  QuasiStaticResidual<dim>::QuasiStaticResidual(
    const BackgroundGrid<dim>   &grid,
    const MaterialPointSet<dim> &points,
    const ShapeCache<dim>       &cache,
    const bool                   update_volumes)
    : grid(grid)
    , points(points)
    , cache(cache)
    , model(points.get_model())
    , update_volumes(update_volumes)
    , state_scratch(points.get_model().n_state_components())
  {
    reinit();
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::reinit()
  {
    f_ext.reinit(grid.locally_owned_dofs(), grid.get_communicator());
    du_ghosted.reinit(grid.locally_owned_dofs(),
                      grid.locally_relevant_dofs(),
                      grid.get_communicator());
    const Epetra_BlockMap &relevant_map = du_ghosted.trilinos_vector().Map();
    const Epetra_BlockMap &owned_map    = f_ext.trilinos_vector().Map();
    importer    = std::make_unique<Epetra_Import>(relevant_map, owned_map);
    exporter    = std::make_unique<Epetra_Export>(relevant_map, owned_map);
    local_force = std::make_unique<Epetra_Vector>(relevant_map);
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::set_external_force(
    const TrilinosWrappers::MPI::Vector &f)
  {
    f_ext = f;
  }



  template <int dim>
  const TrilinosWrappers::MPI::Vector &
  QuasiStaticResidual<dim>::ghosted_layout() const
  {
    return du_ghosted;
  }



  template <int dim>
  double
  QuasiStaticResidual<dim>::typical_increment_norm() const
  {
    const Tensor<1, dim> h = grid.cell_size();
    double               h_min = h[0];
    for (unsigned int d = 1; d < dim; ++d)
      h_min = std::min(h_min, h[d]);
    return h_min *
           std::sqrt(static_cast<double>(grid.get_dof_handler().n_dofs()));
  }



  template <int dim>
  unsigned long
  QuasiStaticResidual<dim>::n_evaluations() const
  {
    return evaluation_count;
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::evaluate(const TrilinosWrappers::MPI::Vector &du,
                                     TrilinosWrappers::MPI::Vector &R) const
  {
    loop<false>(du, &R);
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::commit(
    const TrilinosWrappers::MPI::Vector &du) const
  {
    loop<true>(du, nullptr);
  }



  template <int dim>
  template <bool write_back>
  void
  QuasiStaticResidual<dim>::loop(const TrilinosWrappers::MPI::Vector &du,
                                 TrilinosWrappers::MPI::Vector       *R) const
  {
    constexpr unsigned int n_vertices    = ShapeCache<dim>::n_vertices;
    constexpr unsigned int dofs_per_cell = ShapeCache<dim>::dofs_per_cell;
    const auto            &offsets       = points.get_offsets();
    const unsigned int     n_state       = state_scratch.size();

    du_ghosted.trilinos_vector().Import(du.trilinos_vector(),
                                        *importer,
                                        Insert);
    const double *du_values = du_ghosted.trilinos_vector()[0];
    double       *force     = local_force->Values();
    if (!write_back)
      local_force->PutScalar(0.);

    double du_cell[dofs_per_cell];
    double f_cell[dofs_per_cell];
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        const int *dofs = cache.local_dofs(c);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            du_cell[i] = du_values[dofs[i]];
            f_cell[i]  = 0.;
          }

        const auto &range = cache.cell(c);
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const Tensor<1, dim> *grad_N = cache.gradients(p);
            double               *data   = cache.properties(p);

            // (2.18): d_eps = sym(sum_i du_i (x) grad N_i).
            Tensor<2, dim> grad_du;
            for (unsigned int v = 0; v < n_vertices; ++v)
              for (unsigned int a = 0; a < dim; ++a)
                grad_du[a] += du_cell[v * dim + a] * grad_N[v];
            const SymmetricTensor<2, dim> d_eps = symmetrize(grad_du);

            // (2.20)-(2.21): trial stress from the committed state.
            const PointState<dim> old{
              Utils::read_symmetric<dim>(data + offsets.strain),
              Utils::read_symmetric<dim>(data + offsets.stress),
              ArrayView<const double>(data + offsets.state, n_state),
              data[offsets.volume]};
            SymmetricTensor<2, dim> stress;
            model.update_stress(old,
                                d_eps,
                                stress,
                                ArrayView<double>(state_scratch.data(),
                                                  n_state));

            // (2.23)-(2.24): J and the volume at the end of the step.
            const double J      = (1. + trace(d_eps)) * data[offsets.J];
            const double volume = update_volumes ?
                                    J * data[offsets.initial_volume] :
                                    data[offsets.initial_volume];

            if (write_back)
              {
                Utils::write_symmetric<dim>(old.strain + d_eps,
                                            data + offsets.strain);
                Utils::write_symmetric<dim>(stress, data + offsets.stress);
                std::copy(state_scratch.begin(),
                          state_scratch.end(),
                          data + offsets.state);
                data[offsets.J]      = J;
                data[offsets.volume] = volume;
              }
            else
              // (2.25): f_int_i = -Omega_p sigma_p . grad N_i.
              for (unsigned int v = 0; v < n_vertices; ++v)
                {
                  const Tensor<1, dim> force = stress * grad_N[v];
                  for (unsigned int a = 0; a < dim; ++a)
                    f_cell[v * dim + a] -= volume * force[a];
                }
          }

        if (!write_back)
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            force[dofs[i]] += f_cell[i];
      }

    if (!write_back)
      {
        ++evaluation_count;
        R->trilinos_vector().PutScalar(0.);
        const int ierr =
          R->trilinos_vector().Export(*local_force, *exporter, Add);
        AssertThrow(ierr == 0, ExcTrilinosError(ierr));
        *R += f_ext;
      }
  }



  template class QuasiStaticResidual<2>;
  template class QuasiStaticResidual<3>;
} // namespace qsmpm
