#include <Epetra_BlockMap.h>
#include <cmath>
#include <limits>
#include <qsmpm/assembly/quasi_static_residual.h>
#include <qsmpm/base/tensor_functions.h>
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
    , track_dissipation(points.get_model().computes_dissipation())
  {
    state_layout = points.batch_layout();
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
    same_layout = relevant_map.SameAs(owned_map);
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
    return grid.min_cell_size() *
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
    ++evaluation_count;
    if (same_layout)
      {
        // One rank (no ghosts): the loop reads du and adds into R = f_ext
        // in place, without the copies of import and export.
        R = f_ext;
        loop<false>(du.trilinos_vector()[0], R.trilinos_vector()[0], nullptr);
        return;
      }
    du_ghosted.trilinos_vector().Import(du.trilinos_vector(),
                                        *importer,
                                        Insert);
    local_force->PutScalar(0.);
    loop<false>(du_ghosted.trilinos_vector()[0],
                local_force->Values(),
                nullptr);
    R.trilinos_vector().PutScalar(0.);
    const int ierr = R.trilinos_vector().Export(*local_force, *exporter, Add);
    AssertThrow(ierr == 0, ExcTrilinosError(ierr));
    R += f_ext;
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::commit(
    const TrilinosWrappers::MPI::Vector &du_increment,
    MaterialPointSet<dim>               &written)
  {
    Assert(&written == &points,
           ExcMessage("commit() must be given the points of the residual."));
    Assert(du_increment.trilinos_vector().Map().SameAs(
             du_ghosted.trilinos_vector().Map()),
           ExcMessage("commit() needs du with the ghosted layout."));
    loop<true>(du_increment.trilinos_vector()[0], nullptr, &written);
  }



  template <int dim>
  template <bool write_back>
  void
  QuasiStaticResidual<dim>::loop(const double          *du_values,
                                 double                *force,
                                 MaterialPointSet<dim> *written) const
  {
    constexpr unsigned int max_dofs = ShapeCache<dim>::max_dofs_per_group;
    const unsigned int     n_state  = state_layout.n_state;
    const bool finite_strain        = points.get_formulation().finite_strain();
    const bool fbar                 = points.get_formulation().fbar();
    // The trial fields go back to the points only if the model changes
    // them.
    const bool copy_state = n_state > 0 && !model.state_is_constant();
    // Linear shape functions: every point's stencil is the cell's vertices
    // in their order, known at compile time.
    const bool vertex_stencil =
      cache.stencil_size() == GeometryInfo<dim>::vertices_per_cell;

    if (!write_back)
      {
        min_volume_ratio = std::numeric_limits<double>::infinity();
        dissipated       = 0.;
      }

    double du_cell[max_dofs];
    double f_cell[max_dofs];
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        const int         *dofs   = cache.local_dofs(c);
        const unsigned int n_dofs = cache.n_dofs(c);
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            du_cell[i] = du_values[dofs[i]];
            f_cell[i]  = 0.;
          }
        const auto        &range    = cache.cell(c);
        const unsigned int first    = range.first_point;
        const unsigned int n_points = range.end_point - first;
        if (grad_du_scratch.size() < n_points)
          {
            grad_du_scratch.resize(n_points);
            strain_increment_scratch.resize(n_points);
            stress_scratch.resize(n_points);
            force_stress_scratch.resize(n_points);
            state_scratch.resize(n_points * n_state);
          }

        // (2.18): grad du = sum_i du_i (x) grad N_i, on the grid, i.e. in
        // the configuration at the start of the step; for all points of the
        // cell first, since F-bar needs the cell's mean volume change.
        if (vertex_stencil)
          cell_gradients<true>(du_cell, range);
        else
          cell_gradients<false>(du_cell, range);
        const double mean_volume_change =
          fbar ? cell_mean_volume_change(range, finite_strain) : 0.;

        // The stresses of all points of the cell, and with them the
        // volume-weighted stress measures of the forces.
        const PointStateBatch<dim> old(state_layout,
                                       cache.property_arrays(first),
                                       &cache.position(first),
                                       n_points);
        if (finite_strain)
          finite_strain_stresses<write_back>(old,
                                             first,
                                             mean_volume_change,
                                             written);
        else
          small_strain_stresses<write_back>(old,
                                            first,
                                            mean_volume_change,
                                            written);

        if (write_back)
          {
            if (copy_state)
              for (unsigned int i = 0; i < n_points; ++i)
                std::copy(state_scratch.data() + i * n_state,
                          state_scratch.data() + (i + 1) * n_state,
                          cache.properties(first + i, *written) +
                            state_layout.state);
            continue;
          }

        if (track_dissipation)
          for (unsigned int i = 0; i < n_points; ++i)
            {
              // Assembled once: old[i] reads the whole point state.
              const PointState<dim> point = old[i];
              dissipated +=
                point.volume *
                model.dissipation(point,
                                  ArrayView<const double>(state_scratch.data() +
                                                            i * n_state,
                                                          n_state));
            }

        if (vertex_stencil)
          add_cell_forces<true>(range, f_cell);
        else
          add_cell_forces<false>(range, f_cell);
        for (unsigned int i = 0; i < n_dofs; ++i)
          force[dofs[i]] += f_cell[i];
      }
  }



  template <int dim>
  template <bool vertex_stencil>
  void
  QuasiStaticResidual<dim>::cell_gradients(
    const double                              *du_cell,
    const typename ShapeCache<dim>::CellRange &range) const
  {
    for (unsigned int p = range.first_point; p < range.end_point; ++p)
      {
        const Tensor<1, dim> *grad_N  = cache.gradients(p);
        const unsigned short *nodes   = cache.nodes(p);
        const unsigned int    stencil = vertex_stencil ?
                                          GeometryInfo<dim>::vertices_per_cell :
                                          cache.stencil_size(p);
        // Summed in a local tensor: the compiler cannot know that the
        // scratch array does not overlap du_cell, and would store and load
        // it at every node.
        Tensor<2, dim> grad_du;
        for (unsigned int k = 0; k < stencil; ++k)
          {
            const unsigned int node = vertex_stencil ? k : nodes[k];
            for (unsigned int a = 0; a < dim; ++a)
              grad_du[a] += du_cell[node * dim + a] * grad_N[k];
          }
        grad_du_scratch[p - range.first_point] = grad_du;
      }
  }



  template <int dim>
  template <bool vertex_stencil>
  void
  QuasiStaticResidual<dim>::add_cell_forces(
    const typename ShapeCache<dim>::CellRange &range,
    double                                    *f_cell) const
  {
    // (2.25): f_int_i = Omega_p sigma_p . grad N_i (the paper's f^int with
    // the opposite sign), or its finite-strain form Omega_0 P grad_n N_i;
    // subtracted, since R = f_ext - f_int.
    if (vertex_stencil)
      {
        // The forces on the cell's vertices summed in a local array of
        // fixed size, which the compiler can keep in registers.
        constexpr unsigned int n_vertices =
          GeometryInfo<dim>::vertices_per_cell;
        Tensor<1, dim> f[n_vertices];
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const Tensor<1, dim> *grad_N = cache.gradients(p);
            const Tensor<2, dim> &S =
              force_stress_scratch[p - range.first_point];
            for (unsigned int k = 0; k < n_vertices; ++k)
              f[k] += S * grad_N[k];
          }
        for (unsigned int k = 0; k < n_vertices; ++k)
          for (unsigned int a = 0; a < dim; ++a)
            f_cell[k * dim + a] -= f[k][a];
        return;
      }
    for (unsigned int p = range.first_point; p < range.end_point; ++p)
      {
        const Tensor<1, dim> *grad_N  = cache.gradients(p);
        const unsigned short *nodes   = cache.nodes(p);
        const unsigned int    stencil = cache.stencil_size(p);
        const Tensor<2, dim> &S = force_stress_scratch[p - range.first_point];
        for (unsigned int k = 0; k < stencil; ++k)
          {
            const Tensor<1, dim> f = S * grad_N[k];
            for (unsigned int a = 0; a < dim; ++a)
              f_cell[nodes[k] * dim + a] -= f[a];
          }
      }
  }



  template <int dim>
  template <bool write_back>
  void
  QuasiStaticResidual<dim>::small_strain_stresses(
    const PointStateBatch<dim> &old,
    const unsigned int          first,
    const double                mean_volume_change,
    MaterialPointSet<dim>      *written) const
  {
    const auto        &offsets = points.get_offsets();
    const unsigned int n       = old.size();
    const bool         fbar    = points.get_formulation().fbar();

    for (unsigned int i = 0; i < n; ++i)
      {
        SymmetricTensor<2, dim> &d_eps = strain_increment_scratch[i];
        d_eps                          = symmetrize(grad_du_scratch[i]);
        if (fbar)
          d_eps += (mean_volume_change - trace(d_eps)) / dim *
                   unit_symmetric_tensor<dim>();
      }

    // (2.20)-(2.21): trial stresses from the committed states, one call of
    // the model for the whole cell.
    model.update_stresses(
      old,
      ArrayView<const SymmetricTensor<2, dim>>(strain_increment_scratch.data(),
                                               n),
      ArrayView<SymmetricTensor<2, dim>>(stress_scratch.data(), n),
      ArrayView<double>(state_scratch.data(), n * state_layout.n_state));

    // (2.23)-(2.24): J and the volume at the end of the step.
    double min_J = min_volume_ratio;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double *data = cache.properties(first + i);
        const double  J =
          (1. + trace(strain_increment_scratch[i])) * data[offsets.J];
        const double volume = update_volumes ?
                                J * data[offsets.initial_volume] :
                                data[offsets.initial_volume];
        if (write_back)
          {
            double *const out = cache.properties(first + i, *written);
            Utils::write_symmetric<dim>(old.strain(i) +
                                          strain_increment_scratch[i],
                                        out + offsets.strain);
            Utils::write_symmetric<dim>(stress_scratch[i],
                                        out + offsets.stress);
            out[offsets.J]      = J;
            out[offsets.volume] = volume;
          }
        else
          {
            min_J = std::min(min_J, J);
            // Entry by entry: deal.II's conversion of a symmetric tensor
            // is a function call per point.
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = 0; b < dim; ++b)
                force_stress_scratch[i][a][b] =
                  volume * stress_scratch[i][a][b];
          }
      }
    min_volume_ratio = min_J;
  }



  template <int dim>
  template <bool write_back>
  void
  QuasiStaticResidual<dim>::finite_strain_stresses(
    const PointStateBatch<dim> &old,
    const unsigned int          first,
    const double                mean_volume_change,
    MaterialPointSet<dim>      *written) const
  {
    const auto        &offsets = points.get_offsets();
    const unsigned int n_state = state_layout.n_state;
    const bool         fbar    = points.get_formulation().fbar();

    for (unsigned int i = 0; i < old.size(); ++i)
      {
        const double   *data = cache.properties(first + i);
        Tensor<2, dim> &S    = force_stress_scratch[i];

        FiniteStrainKinematics<dim> kinematics;
        kinematics.F_old =
          Utils::read_tensor<dim>(data + offsets.deformation_gradient);
        const Tensor<2, dim> delta_F =
          unit_symmetric_tensor<dim>() + grad_du_scratch[i];
        const double det_delta_F = determinant(delta_F);
        // F-bar: the model sees the cell's mean volume change.
        kinematics.delta_F =
          fbar ?
            std::pow(mean_volume_change / det_delta_F, 1. / dim) * delta_F :
            delta_F;
        kinematics.F = kinematics.delta_F * kinematics.F_old;
        if (!(det_delta_F > 0. && (!fbar || mean_volume_change > 0.)))
          {
            // An inverted point: no admissible residual. Newton's line
            // search backs off from non-finite norms.
            S = std::numeric_limits<double>::quiet_NaN();
            continue;
          }

        SymmetricTensor<2, dim> tau;
        model.update_kirchhoff_stress(
          old[i],
          kinematics,
          tau,
          ArrayView<double>(state_scratch.data() + i * n_state, n_state));
        if (write_back)
          {
            double *const out = cache.properties(first + i, *written);
            const double  J   = determinant(kinematics.F);
            // For output: the logarithmic strain 1/2 ln b.
            Utils::write_symmetric<dim>(
              0.5 * TensorFunctions::log(
                      TensorFunctions::left_cauchy_green(kinematics.F)),
              out + offsets.strain);
            Utils::write_symmetric<dim>(tau / J, out + offsets.stress);
            Utils::write_tensor<dim>(kinematics.F,
                                     out + offsets.deformation_gradient);
            out[offsets.J]      = J;
            out[offsets.volume] = J * data[offsets.initial_volume];
          }
        else
          {
            // Omega sigma grad_{n+1} N = Omega_0 tau Delta F^{-T} grad_n N.
            S = data[offsets.initial_volume] * Tensor<2, dim>(tau) *
                transpose(invert(delta_F));
            min_volume_ratio =
              std::min(min_volume_ratio, det_delta_F * data[offsets.J]);
          }
      }
  }



  template <int dim>
  double
  QuasiStaticResidual<dim>::cell_mean_volume_change(
    const typename ShapeCache<dim>::CellRange &range,
    const bool                                 finite_strain) const
  {
    // Weighted with the volumes at the start of the step: the mean is then
    // the volume change of the cell's material as a whole.
    const unsigned int volume = points.get_offsets().volume;
    double             sum = 0., total_volume = 0.;
    for (unsigned int p = range.first_point; p < range.end_point; ++p)
      {
        const double          omega   = cache.properties(p)[volume];
        const Tensor<2, dim> &grad_du = grad_du_scratch[p - range.first_point];
        sum += omega * (finite_strain ?
                          determinant(unit_symmetric_tensor<dim>() + grad_du) :
                          trace(grad_du));
        total_volume += omega;
      }
    return sum / total_volume;
  }



  template <int dim>
  double
  QuasiStaticResidual<dim>::minimum_volume_ratio() const
  {
    return min_volume_ratio;
  }



  template <int dim>
  double
  QuasiStaticResidual<dim>::dissipation() const
  {
    return dissipated;
  }



  template class QuasiStaticResidual<2>;
  template class QuasiStaticResidual<3>;
} // namespace qsmpm
