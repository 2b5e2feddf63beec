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
    , state_scratch(points.get_model().n_state_components())
    , track_dissipation(points.get_model().computes_dissipation())
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
    du_ghosted.trilinos_vector().Import(du.trilinos_vector(),
                                        *importer,
                                        Insert);
    loop<false>(du_ghosted.trilinos_vector()[0], &R, nullptr);
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
  QuasiStaticResidual<dim>::loop(const double                  *du_values,
                                 TrilinosWrappers::MPI::Vector *R,
                                 MaterialPointSet<dim>         *written) const
  {
    constexpr unsigned int max_dofs = ShapeCache<dim>::max_dofs_per_group;
    const auto            &offsets  = points.get_offsets();
    const unsigned int     n_state  = state_scratch.size();
    const bool finite_strain        = points.get_formulation().finite_strain();
    const bool fbar                 = points.get_formulation().fbar();

    double *force = local_force->Values();
    if (!write_back)
      {
        local_force->PutScalar(0.);
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

        // (2.18): grad du = sum_i du_i (x) grad N_i, on the grid, i.e. in
        // the configuration at the start of the step; for all points of the
        // cell first, since F-bar needs the cell's mean volume change.
        const auto        &range    = cache.cell(c);
        const unsigned int n_points = range.end_point - range.first_point;
        if (grad_du_scratch.size() < n_points)
          grad_du_scratch.resize(n_points);
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const Tensor<1, dim> *grad_N  = cache.gradients(p);
            const unsigned int    stencil = cache.stencil_size(p);
            const unsigned short *nodes   = cache.nodes(p);
            Tensor<2, dim> &grad_du = grad_du_scratch[p - range.first_point];
            grad_du                 = 0.;
            for (unsigned int k = 0; k < stencil; ++k)
              for (unsigned int a = 0; a < dim; ++a)
                grad_du[a] += du_cell[nodes[k] * dim + a] * grad_N[k];
          }
        const double mean_volume_change =
          fbar ? cell_mean_volume_change(range, finite_strain) : 0.;

        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const Tensor<1, dim> *grad_N  = cache.gradients(p);
            const unsigned int    stencil = cache.stencil_size(p);
            const unsigned short *nodes   = cache.nodes(p);
            const double         *data    = cache.properties(p);
            // Where commit() writes: the same array.
            double *const out =
              write_back ? cache.properties(p, *written) : nullptr;
            const Tensor<2, dim> &grad_du =
              grad_du_scratch[p - range.first_point];

            const PointState<dim> old = MaterialPointSet<dim>::read_point_state(
              data, offsets, n_state, cache.position(p));
            ArrayView<double> new_state(state_scratch.data(), n_state);

            // The point's share of R = f_ext - f_int: small strain
            // -volume sigma grad N_i, finite strain -Omega_0 P grad_n N_i
            // with P = tau Delta F^{-T}.
            SymmetricTensor<2, dim> stress;
            Tensor<2, dim>          P;
            double                  volume = 0.;
            if (finite_strain)
              {
                FiniteStrainKinematics<dim> kinematics;
                kinematics.F_old =
                  Utils::read_tensor<dim>(data + offsets.deformation_gradient);
                const Tensor<2, dim> delta_F =
                  unit_symmetric_tensor<dim>() + grad_du;
                const double det_delta_F = determinant(delta_F);
                // F-bar: the model sees the cell's mean volume change.
                kinematics.delta_F =
                  fbar ? std::pow(mean_volume_change / det_delta_F, 1. / dim) *
                           delta_F :
                         delta_F;
                kinematics.F = kinematics.delta_F * kinematics.F_old;
                const bool admissible =
                  det_delta_F > 0. && (!fbar || mean_volume_change > 0.);
                if (!admissible)
                  {
                    // An inverted point: no admissible residual. Newton's
                    // line search backs off from non-finite norms.
                    volume = std::numeric_limits<double>::quiet_NaN();
                  }
                else
                  {
                    SymmetricTensor<2, dim> tau;
                    model.update_kirchhoff_stress(old,
                                                  kinematics,
                                                  tau,
                                                  new_state);
                    // Omega sigma grad_{n+1} N = Omega_0 tau Delta F^{-T}
                    // grad_n N.
                    volume = data[offsets.initial_volume];
                    P      = Tensor<2, dim>(tau) * transpose(invert(delta_F));
                    if (!write_back)
                      min_volume_ratio =
                        std::min(min_volume_ratio,
                                 det_delta_F * data[offsets.J]);
                    if (write_back)
                      {
                        const double J = determinant(kinematics.F);
                        // For output: the logarithmic strain 1/2 ln b.
                        Utils::write_symmetric<dim>(
                          0.5 *
                            TensorFunctions::log(
                              TensorFunctions::left_cauchy_green(kinematics.F)),
                          out + offsets.strain);
                        Utils::write_symmetric<dim>(tau / J,
                                                    out + offsets.stress);
                        Utils::write_tensor<dim>(
                          kinematics.F, out + offsets.deformation_gradient);
                        out[offsets.J]      = J;
                        out[offsets.volume] = J * data[offsets.initial_volume];
                      }
                  }
              }
            else
              {
                SymmetricTensor<2, dim> d_eps = symmetrize(grad_du);
                if (fbar)
                  d_eps += (mean_volume_change - trace(d_eps)) / dim *
                           unit_symmetric_tensor<dim>();

                // (2.20)-(2.21): trial stress from the committed state.
                model.update_stress(old, d_eps, stress, new_state);

                // (2.23)-(2.24): J and the volume at the end of the step.
                const double J = (1. + trace(d_eps)) * data[offsets.J];
                volume = update_volumes ? J * data[offsets.initial_volume] :
                                          data[offsets.initial_volume];
                if (!write_back)
                  min_volume_ratio = std::min(min_volume_ratio, J);
                if (write_back)
                  {
                    Utils::write_symmetric<dim>(old.strain + d_eps,
                                                out + offsets.strain);
                    Utils::write_symmetric<dim>(stress, out + offsets.stress);
                    out[offsets.J]      = J;
                    out[offsets.volume] = volume;
                  }
              }

            if (!write_back && track_dissipation)
              dissipated +=
                data[offsets.volume] *
                model.dissipation(old,
                                  ArrayView<const double>(state_scratch.data(),
                                                          n_state));

            // (2.25): f_int_i = Omega_p sigma_p . grad N_i (the paper's
            // f^int with the opposite sign), or its finite-strain form
            // Omega_0 P grad_n N_i; subtracted, since R = f_ext - f_int.
            const auto add_forces = [&](const auto &stress_measure) {
              for (unsigned int k = 0; k < stencil; ++k)
                {
                  const Tensor<1, dim> f = stress_measure * grad_N[k];
                  for (unsigned int a = 0; a < dim; ++a)
                    f_cell[nodes[k] * dim + a] -= volume * f[a];
                }
            };
            if (write_back)
              std::copy(state_scratch.begin(),
                        state_scratch.end(),
                        out + offsets.state);
            else if (finite_strain)
              add_forces(P);
            else
              add_forces(stress);
          }

        if (!write_back)
          for (unsigned int i = 0; i < n_dofs; ++i)
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
