#include <Epetra_BlockMap.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <qsmpm/assembly/quasi_static_residual.h>
#include <qsmpm/base/tensor_functions.h>
#include <qsmpm/base/utilities.h>

namespace qsmpm
{
  namespace
  {
    /**
     * Store a finite-strain point's state of a converged step in its
     * property array @p out: the logarithmic strain 1/2 ln b (for output),
     * the Cauchy stress tau / J, F, J and the volume J Omega_0; and the F-bar
     * excess (own volume change over the cell's mean) if the points keep it.
     */
    template <int dim>
    void
    write_finite_strain_state(
      double                                        *out,
      const typename MaterialPointSet<dim>::Offsets &offsets,
      const Tensor<2, dim>                          &F,
      const SymmetricTensor<2, dim>                 &tau,
      const double                                   J,
      const double                                   initial_volume,
      const double                                   volume_change_over_mean)
    {
      Utils::write_symmetric<dim>(
        0.5 * TensorFunctions::log(TensorFunctions::left_cauchy_green(F)),
        out + offsets.strain);
      Utils::write_symmetric<dim>(tau / J, out + offsets.stress);
      Utils::write_tensor<dim>(F, out + offsets.deformation_gradient);
      out[offsets.J]      = J;
      out[offsets.volume] = J * initial_volume;
      if (offsets.fbar_volume_excess != numbers::invalid_unsigned_int)
        out[offsets.fbar_volume_excess] += std::log(volume_change_over_mean);
    }
  } // namespace



  template <int dim>
  QuasiStaticResidual<dim>::QuasiStaticResidual(const BackgroundGrid<dim> &grid,
                                                MaterialPointSet<dim> &points,
                                                const ShapeCache<dim> &cache,
                                                const bool update_volumes)
    : grid(grid)
    , points(points)
    , writable_points(points)
    , cache(cache)
    , model(points.get_model())
    , update_volumes(update_volumes)
    , track_dissipation(points.get_model().computes_dissipation())
  {
    // The fields the evaluations read: the model's (all of them if it
    // sees a whole PointState: at finite strain and for its dissipation),
    // and the residual's own.
    const auto        &offsets       = points.get_offsets();
    const auto         full          = points.batch_layout();
    const bool         finite_strain = points.get_formulation().finite_strain();
    constexpr unsigned n_sym =
      SymmetricTensor<2, dim>::n_independent_components;
    const typename PointStateBatch<dim>::Fields fields =
      (finite_strain || track_dissipation) ?
        typename PointStateBatch<dim>::Fields() :
        model.batch_fields();
    std::vector<unsigned int> sources;
    const auto                add = [&sources](const unsigned int first,
                                const unsigned int n) {
      for (unsigned int k = 0; k < n; ++k)
        sources.push_back(first + k);
    };
    if (fields.strain)
      add(full.strain, n_sym);
    if (fields.stress)
      add(full.stress, n_sym);
    if (fields.state)
      add(full.state, full.n_state);
    if (fields.volume)
      add(full.volume, 1);
    if (fields.material_id)
      add(full.material_id, 1);
    add(offsets.J, 1);
    add(offsets.initial_volume, 1);
    if (points.get_formulation().fbar())
      add(offsets.volume, 1);
    if (finite_strain)
      add(offsets.deformation_gradient, dim * dim);
    if (points.get_formulation().axisymmetric)
      add(offsets.hoop_stress, 1);
    std::sort(sources.begin(), sources.end());
    sources.erase(std::unique(sources.begin(), sources.end()), sources.end());

    // A copy of more than half the property array would cost more memory
    // than it saves memory traffic (CubicElastic, whose 21 stiffness
    // entries per point are most of its array, and every model that reads
    // the whole state).
    const unsigned int n_properties = points.get_layout().size();
    state_layout                    = full;
    own_offsets                     = offsets;
    if (2 * sources.size() <= n_properties)
      {
        packed_sources = std::move(sources);
        packed_record  = packed_sources.size();
        // A field's offset in the record: its position among the sources
        // (the doubles of a field stay consecutive).
        const auto packed_offset = [this](const unsigned int offset) {
          const auto it = std::lower_bound(packed_sources.begin(),
                                           packed_sources.end(),
                                           offset);
          return (it != packed_sources.end() && *it == offset) ?
                   static_cast<unsigned int>(it - packed_sources.begin()) :
                   numbers::invalid_unsigned_int;
        };
        state_layout.strain      = fields.strain ? packed_offset(full.strain) :
                                                   numbers::invalid_unsigned_int;
        state_layout.stress      = fields.stress ? packed_offset(full.stress) :
                                                   numbers::invalid_unsigned_int;
        state_layout.state       = (fields.state && full.n_state > 0) ?
                                     packed_offset(full.state) :
                                     numbers::invalid_unsigned_int;
        state_layout.volume      = fields.volume ? packed_offset(full.volume) :
                                                   numbers::invalid_unsigned_int;
        state_layout.material_id = fields.material_id ?
                                     packed_offset(full.material_id) :
                                     numbers::invalid_unsigned_int;
        own_offsets.J            = packed_offset(offsets.J);
        own_offsets.initial_volume = packed_offset(offsets.initial_volume);
        own_offsets.volume         = packed_offset(offsets.volume);
        own_offsets.deformation_gradient =
          finite_strain ? packed_offset(offsets.deformation_gradient) :
                          numbers::invalid_unsigned_int;
        own_offsets.hoop_stress = points.get_formulation().axisymmetric ?
                                    packed_offset(offsets.hoop_stress) :
                                    numbers::invalid_unsigned_int;
      }

    // F-bar at small strain with a model that keeps its elastic strain
    // apart: each point's plastic volume change stays its own
    // (share_plastic_volume_changes()).
    share_volume_changes =
      points.get_formulation().fbar() && !finite_strain &&
      state_layout.state != numbers::invalid_unsigned_int &&
      model.plastic_flow_changes_volume();
    reinit();
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::update_packed_state() const
  {
    if (packed_record == 0 || packed_generation == cache.generation())
      return;
    const unsigned int n_points = cache.n_points();
    packed.resize(std::size_t(n_points) * packed_record);
    double *out = packed.data();
    for (unsigned int p = 0; p < n_points; ++p)
      {
        const double *data = cache.properties(p);
        for (const unsigned int source : packed_sources)
          *out++ = data[source];
      }
    packed_generation = cache.generation();
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
  void
  QuasiStaticResidual<dim>::import_ghosts(
    const TrilinosWrappers::MPI::Vector &du,
    TrilinosWrappers::MPI::Vector       &ghosted) const
  {
    const int ierr =
      ghosted.trilinos_vector().Import(du.trilinos_vector(), *importer, Insert);
    AssertThrow(ierr == 0, ExcTrilinosError(ierr));
  }



  template <int dim>
  double
  QuasiStaticResidual<dim>::typical_increment_norm() const
  {
    return grid.min_cell_size() *
           std::sqrt(static_cast<double>(grid.get_dof_handler().n_dofs()));
  }



  template <int dim>
  typename QuasiStaticResidual<dim>::Evaluation
  QuasiStaticResidual<dim>::evaluate(const TrilinosWrappers::MPI::Vector &du,
                                     TrilinosWrappers::MPI::Vector &R) const
  {
    Evaluation result;
    update_packed_state();
    if (same_layout)
      {
        // One rank (no ghosts): the loop reads du and adds into R = f_ext
        // in place, without the copies of import and export.
        R = f_ext;
        loop<false>(du.trilinos_vector()[0], R.trilinos_vector()[0], result);
        return result;
      }
    du_ghosted.trilinos_vector().Import(du.trilinos_vector(),
                                        *importer,
                                        Insert);
    local_force->PutScalar(0.);
    loop<false>(du_ghosted.trilinos_vector()[0], local_force->Values(), result);
    R.trilinos_vector().PutScalar(0.);
    const int ierr = R.trilinos_vector().Export(*local_force, *exporter, Add);
    AssertThrow(ierr == 0, ExcTrilinosError(ierr));
    R += f_ext;
    return result;
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::iterate_kinematics(
    const TrilinosWrappers::MPI::Vector &du,
    IterateKinematics<dim>              &kinematics) const
  {
    const LoopKind kind = loop_kind();
    update_packed_state();
    const double *du_values = du.trilinos_vector()[0];
    if (!same_layout)
      {
        import_ghosts(du, du_ghosted);
        du_values = du_ghosted.trilinos_vector()[0];
      }
    const unsigned int n = cache.n_points();
    kinematics.strain_increments.resize(kind.finite_strain ? 0 : n);
    kinematics.hoop_strain_increments.resize(kind.axisymmetric ? n : 0);
    kinematics.deformation_increments.resize(kind.finite_strain ? n : 0);
    kinematics.mean_volume_changes.resize(kind.finite_strain && kind.fbar ? n :
                                                                            0);
    for (unsigned int c0 = 0; c0 < cache.n_cells(); c0 += block_cells)
      {
        const unsigned int c1    = std::min(c0 + block_cells, cache.n_cells());
        const unsigned int first = cache.cell(c0).first_point;
        const unsigned int n_points = cache.cell(c1 - 1).end_point - first;
        scratch.start_block(first, n_points, state_layout.n_state);
        block_kinematics(kind, c0, c1, du_values);
        // The volume changes the points have at the iterate, split into the
        // cell's elastic and their own plastic parts as in evaluate().
        if (share_volume_changes)
          {
            Evaluation unused;
            share_plastic_volume_changes<false>(kind, c0, c1, unused);
          }
        if (kind.axisymmetric)
          std::copy(scratch.hoop_increment.begin(),
                    scratch.hoop_increment.begin() + n_points,
                    kinematics.hoop_strain_increments.begin() + first);
        if (!kind.finite_strain)
          std::copy(scratch.strain_increment.begin(),
                    scratch.strain_increment.begin() + n_points,
                    kinematics.strain_increments.begin() + first);
        else
          for (unsigned int i = 0; i < n_points; ++i)
            {
              kinematics.deformation_increments[first + i] =
                unit_symmetric_tensor<dim>() + scratch.grad_du[i];
              if (kind.fbar)
                kinematics.mean_volume_changes[first + i] =
                  scratch.mean_volume_change[i];
            }
      }
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::commit(
    const TrilinosWrappers::MPI::Vector &du_increment)
  {
    Assert(du_increment.trilinos_vector().Map().SameAs(
             du_ghosted.trilinos_vector().Map()),
           ExcMessage("commit() needs du with the ghosted layout."));
    update_packed_state();
    Evaluation unused;
    loop<true>(du_increment.trilinos_vector()[0], nullptr, unused);
    // The points' state has changed: gathered again before the next
    // evaluation.
    packed_generation = std::numeric_limits<unsigned long>::max();
  }



  template <int dim>
  template <bool write_back>
  void
  QuasiStaticResidual<dim>::loop(const double *du_values,
                                 double       *force,
                                 Evaluation   &result) const
  {
    const LoopKind kind = loop_kind();
    // Blocks of cells: the kinematics of all their points first, one call
    // of the model for all of them (their committed states are consecutive
    // in the packed copy, or their property arrays are), then the forces.
    // Each phase is then a loop over independent cells or points that the
    // processor can overlap, where one cell at a time left it waiting for
    // the results of short dependent chains (blocks of 8 cells were the
    // fastest; the figures are in doc/benchmarks.md).
    for (unsigned int c0 = 0; c0 < cache.n_cells(); c0 += block_cells)
      {
        const unsigned int c1    = std::min(c0 + block_cells, cache.n_cells());
        const unsigned int first = cache.cell(c0).first_point;
        const unsigned int n_points = cache.cell(c1 - 1).end_point - first;
        scratch.start_block(first, n_points, state_layout.n_state);
        block_kinematics(kind, c0, c1, du_values);
        if (share_volume_changes)
          share_plastic_volume_changes<write_back>(kind, c0, c1, result);
        else
          block_stresses<write_back>(kind, first, n_points, result);
        if (write_back)
          continue;
        // F-bar at small strain: the forces of the virtual F-bar strain.
        if (kind.fbar && !kind.finite_strain)
          for (unsigned int c = c0; c < c1; ++c)
            project_fbar_force_stresses(cache.cell(c));
        block_forces(kind, c0, c1, force);
      }
  }



  template <int dim>
  typename QuasiStaticResidual<dim>::LoopKind
  QuasiStaticResidual<dim>::loop_kind() const
  {
    LoopKind kind;
    kind.finite_strain = points.get_formulation().finite_strain();
    kind.fbar          = points.get_formulation().fbar();
    kind.axisymmetric  = points.get_formulation().axisymmetric;
    kind.symmetric_small_strain =
      !kind.finite_strain && !kind.fbar && !kind.axisymmetric;
    kind.vertex_stencil =
      cache.stencil_size() == GeometryInfo<dim>::vertices_per_cell;
    return kind;
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::block_kinematics(const LoopKind    &kind,
                                             const unsigned int c0,
                                             const unsigned int c1,
                                             const double      *du_values) const
  {
    constexpr unsigned int max_dofs = ShapeCache<dim>::max_dofs_per_group;
    const unsigned int     first    = scratch.block_first;
    double                 du_cell[max_dofs];
    // (2.18): grad du = sum_i du_i (x) grad N_i, on the grid, i.e. in
    // the configuration at the start of the step; for all points of a
    // cell before their stresses, since F-bar needs the cell's mean
    // volume change. Small strain without F-bar on an affine cell needs
    // only sym(grad du), and its forces come from symmetric stresses.
    for (unsigned int c = c0; c < c1; ++c)
      {
        const int *dofs = cache.local_dofs(c);
        for (unsigned int i = 0; i < cache.n_dofs(c); ++i)
          du_cell[i] = du_values[dofs[i]];
        const auto              &range = cache.cell(c);
        const AffineQ1Cell<dim> *affine =
          (kind.vertex_stencil && !kind.axisymmetric) ? cache.affine_cell(c) :
                                                        nullptr;
        if (kind.axisymmetric)
          cell_hoop_increments(du_cell, c);
        if (affine && kind.symmetric_small_strain)
          affine_cell_kinematics<true>(*affine, du_cell, range);
        else if (affine)
          affine_cell_kinematics<false>(*affine, du_cell, range);
        else if (kind.vertex_stencil)
          cell_gradients<true>(du_cell, c);
        else
          cell_gradients<false>(du_cell, c);
        const double mean_volume_change =
          kind.fbar ? cell_mean_volume_change(range, kind.finite_strain) : 0.;
        if (kind.finite_strain)
          std::fill(scratch.mean_volume_change.begin() +
                      (range.first_point - first),
                    scratch.mean_volume_change.begin() +
                      (range.end_point - first),
                    mean_volume_change);
        else if (!affine || !kind.symmetric_small_strain)
          for (unsigned int p = range.first_point; p < range.end_point; ++p)
            {
              SymmetricTensor<2, dim> &d_eps =
                scratch.strain_increment[p - first];
              d_eps = symmetrize(scratch.grad_du[p - first]);
              if (kind.fbar && kind.axisymmetric)
                {
                  // The volume change has three parts, the hoop strain's
                  // among them: the correction is shared by all three.
                  double      &hoop = scratch.hoop_increment[p - first];
                  const double shift =
                    (mean_volume_change - trace(d_eps) - hoop) / 3.;
                  d_eps += shift * unit_symmetric_tensor<dim>();
                  hoop += shift;
                }
              else if (kind.fbar)
                d_eps += (mean_volume_change - trace(d_eps)) / dim *
                         unit_symmetric_tensor<dim>();
            }
      }
  }



  template <int dim>
  PointStateBatch<dim>
  QuasiStaticResidual<dim>::committed_batch(const unsigned int first,
                                            const unsigned int n_points) const
  {
    return packed_record > 0 ?
             PointStateBatch<dim>(state_layout,
                                  committed(first),
                                  packed_record,
                                  &cache.position(first),
                                  n_points) :
             PointStateBatch<dim>(state_layout,
                                  cache.property_arrays(first),
                                  &cache.position(first),
                                  n_points);
  }



  template <int dim>
  template <bool write_back>
  void
  QuasiStaticResidual<dim>::block_stresses(const LoopKind    &kind,
                                           const unsigned int first,
                                           const unsigned int n_points,
                                           Evaluation        &result) const
  {
    const unsigned int n_state = state_layout.n_state;
    // The stresses of all points of the block, and with them the
    // volume-weighted stress measures of the forces.
    const PointStateBatch<dim> old = committed_batch(first, n_points);
    if (kind.finite_strain && kind.axisymmetric)
      axisymmetric_finite_strain_stresses<write_back>(old, first, result);
    else if (kind.finite_strain)
      finite_strain_stresses<write_back>(old, first, result);
    else if (kind.axisymmetric)
      axisymmetric_stresses<write_back>(old, first, result);
    else
      small_strain_stresses<write_back>(old, first, result);

    if (write_back)
      {
        // The trial fields go back to the points only if the model changes
        // them.
        if (n_state > 0 && !model.state_is_constant())
          for (unsigned int i = 0; i < n_points; ++i)
            std::copy(scratch.state.data() + i * n_state,
                      scratch.state.data() + (i + 1) * n_state,
                      cache.properties(first + i, writable_points) +
                        points.get_offsets().state);
        return;
      }

    if (track_dissipation)
      for (unsigned int i = 0; i < n_points; ++i)
        {
          // Assembled once: old[i] reads the whole point state.
          const PointState<dim> point = old[i];
          result.dissipation +=
            point.volume *
            model.dissipation(point,
                              ArrayView<const double>(scratch.state.data() +
                                                        i * n_state,
                                                      n_state));
        }
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::block_forces(const LoopKind    &kind,
                                         const unsigned int c0,
                                         const unsigned int c1,
                                         double            *force) const
  {
    constexpr unsigned int max_dofs = ShapeCache<dim>::max_dofs_per_group;
    double                 f_cell[max_dofs];
    for (unsigned int c = c0; c < c1; ++c)
      {
        const auto              &range  = cache.cell(c);
        const unsigned int       n_dofs = cache.n_dofs(c);
        const AffineQ1Cell<dim> *affine =
          (kind.vertex_stencil && !kind.axisymmetric) ? cache.affine_cell(c) :
                                                        nullptr;
        std::fill(f_cell, f_cell + n_dofs, 0.);
        if (kind.axisymmetric)
          add_hoop_forces(c, f_cell);
        if (affine && kind.symmetric_small_strain)
          add_affine_symmetric_forces(*affine, range, f_cell);
        else if (affine)
          add_affine_cell_forces(*affine, range, f_cell);
        else if (kind.vertex_stencil)
          add_cell_forces<true>(c, f_cell);
        else
          add_cell_forces<false>(c, f_cell);
        const int *dofs = cache.local_dofs(c);
        for (unsigned int i = 0; i < n_dofs; ++i)
          force[dofs[i]] += f_cell[i];
      }
  }



  template <int dim>
  template <bool vertex_stencil>
  void
  QuasiStaticResidual<dim>::cell_gradients(const double      *du_cell,
                                           const unsigned int c) const
  {
    const auto                              &range = cache.cell(c);
    typename ShapeCache<dim>::GradientBuffer unused;
    for (unsigned int p = range.first_point; p < range.end_point; ++p)
      {
        const Tensor<1, dim> *grad_N  = cache.gradients(c, p, unused);
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
        scratch.grad_du[p - scratch.block_first] = grad_du;
      }
  }



  template <int dim>
  template <bool symmetric>
  void
  QuasiStaticResidual<dim>::affine_cell_kinematics(
    const AffineQ1Cell<dim>                   &affine,
    const double                              *du_cell,
    const typename ShapeCache<dim>::CellRange &range) const
  {
    constexpr unsigned int n_terms = AffineQ1Cell<dim>::n_terms;
    constexpr unsigned int n_sym   = AffineQ1Cell<dim>::n_sym;
    double                 K[n_terms][dim * dim], K_sym[n_terms][n_sym];
    affine.gradient_terms(du_cell, K);
    if (symmetric)
      AffineQ1Cell<dim>::symmetrize_terms(K, K_sym);
    for (unsigned int p = range.first_point; p < range.end_point; ++p)
      {
        // Kept for the forces of the same points.
        auto &m = scratch.monomials[p - scratch.block_first];
        AffineQ1Cell<dim>::monomials(cache.reference_location(p), m);
        if (symmetric)
          scratch.strain_increment[p - scratch.block_first] =
            AffineQ1Cell<dim>::symmetric_gradient(K_sym, m);
        else
          scratch.grad_du[p - scratch.block_first] =
            AffineQ1Cell<dim>::gradient(K, m);
      }
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::add_affine_symmetric_forces(
    const AffineQ1Cell<dim>                   &affine,
    const typename ShapeCache<dim>::CellRange &range,
    double                                    *f_cell) const
  {
    constexpr unsigned int n_terms               = AffineQ1Cell<dim>::n_terms;
    constexpr unsigned int n_sym                 = AffineQ1Cell<dim>::n_sym;
    double                 H_sym[n_terms][n_sym] = {};
    for (unsigned int i = range.first_point - scratch.block_first;
         i < range.end_point - scratch.block_first;
         ++i)
      {
        const auto                    &m      = scratch.monomials[i];
        const SymmetricTensor<2, dim> &sigma  = scratch.stress[i];
        const double                   volume = scratch.volume[i];
        for (unsigned int w = 0; w < n_terms; ++w)
          {
            const double scale = volume * m[w];
            for (unsigned int k = 0; k < n_sym; ++k)
              H_sym[w][k] += scale * sigma.access_raw_entry(k);
          }
      }
    double H[n_terms][dim * dim];
    AffineQ1Cell<dim>::unfold_symmetric_terms(H_sym, H);
    affine.add_nodal_forces(H, -1., f_cell);
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::add_affine_cell_forces(
    const AffineQ1Cell<dim>                   &affine,
    const typename ShapeCache<dim>::CellRange &range,
    double                                    *f_cell) const
  {
    constexpr unsigned int n_terms               = AffineQ1Cell<dim>::n_terms;
    double                 H[n_terms][dim * dim] = {};
    for (unsigned int p = range.first_point; p < range.end_point; ++p)
      AffineQ1Cell<dim>::add_force_terms(
        scratch.force_stress[p - scratch.block_first],
        scratch.monomials[p - scratch.block_first],
        H);
    affine.add_nodal_forces(H, -1., f_cell);
  }



  template <int dim>
  template <bool vertex_stencil>
  void
  QuasiStaticResidual<dim>::add_cell_forces(const unsigned int c,
                                            double            *f_cell) const
  {
    const auto                              &range = cache.cell(c);
    typename ShapeCache<dim>::GradientBuffer unused;
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
            const Tensor<1, dim> *grad_N = cache.gradients(c, p, unused);
            const Tensor<2, dim> &S =
              scratch.force_stress[p - scratch.block_first];
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
        const Tensor<1, dim> *grad_N  = cache.gradients(c, p, unused);
        const unsigned short *nodes   = cache.nodes(p);
        const unsigned int    stencil = cache.stencil_size(p);
        const Tensor<2, dim> &S = scratch.force_stress[p - scratch.block_first];
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
    Evaluation                 &result) const
  {
    const auto        &offsets         = own_offsets;
    const auto        &written_offsets = points.get_offsets();
    const unsigned int n               = old.size();
    // Every cell's forces from scratch.volume (add_affine_symmetric_forces()).
    const bool all_symmetric_affine = !points.get_formulation().fbar() &&
                                      cache.n_affine_cells() == cache.n_cells();

    // The strain increments are in scratch.strain_increment (see loop()).

    // (2.20)-(2.21): trial stresses from the committed states, one call of
    // the model for the whole cell.
    model.update_stresses(
      old,
      ArrayView<const SymmetricTensor<2, dim>>(scratch.strain_increment.data(),
                                               n),
      ArrayView<SymmetricTensor<2, dim>>(scratch.stress.data(), n),
      ArrayView<double>(scratch.state.data(), n * state_layout.n_state));

    // (2.23)-(2.24): J and the volume at the end of the step.
    double min_J = result.minimum_volume_ratio;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double *data = committed(first + i);
        const double  J =
          (1. + trace(scratch.strain_increment[i])) * data[offsets.J];
        const double volume = update_volumes ?
                                J * data[offsets.initial_volume] :
                                data[offsets.initial_volume];
        if (write_back)
          {
            double *const out = cache.properties(first + i, writable_points);
            // The committed strain from the property array: the batch
            // holds it only if the model reads it.
            Utils::write_symmetric<dim>(Utils::read_symmetric<dim>(
                                          out + written_offsets.strain) +
                                          scratch.strain_increment[i],
                                        out + written_offsets.strain);
            Utils::write_symmetric<dim>(scratch.stress[i],
                                        out + written_offsets.stress);
            out[written_offsets.J]      = J;
            out[written_offsets.volume] = volume;
            if (written_offsets.fbar_volume_excess !=
                numbers::invalid_unsigned_int)
              out[written_offsets.fbar_volume_excess] +=
                trace(scratch.grad_du[i]) - trace(scratch.strain_increment[i]);
          }
        else
          {
            min_J = std::min(min_J, J);
            // add_affine_symmetric_forces() scales the stresses itself;
            // the other cells' forces read scratch.force_stress.
            scratch.volume[i] = volume;
            if (all_symmetric_affine)
              continue;
            // Entry by entry: deal.II's conversion of a symmetric tensor
            // is a function call per point.
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = 0; b < dim; ++b)
                scratch.force_stress[i][a][b] =
                  volume * scratch.stress[i][a][b];
          }
      }
    result.minimum_volume_ratio = min_J;
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::cell_hoop_increments(const double      *du_cell,
                                                 const unsigned int c) const
  {
    // d eps_thetatheta = d u_r / r = sum_k N_k(x_p) du_k,r / r_p, with r_p
    // the point's radius at the start of the step (the grid's x). With GIMP
    // N_k is the average of the linear function over the point's domain,
    // and Omega_p = r_p A_p, so Omega_p N_k / r_p = integral of N_k r dA / r
    // over the domain: the hoop term is the domain's exact average.
    const auto                           &range = cache.cell(c);
    typename ShapeCache<dim>::ValueBuffer buffer;
    for (unsigned int p = range.first_point; p < range.end_point; ++p)
      {
        const unsigned int    i       = p - scratch.block_first;
        const double         *N       = cache.values(c, p, buffer);
        const unsigned short *nodes   = cache.nodes(p);
        const unsigned int    stencil = cache.stencil_size(p);
        const double          r       = cache.position(p)[0];
        double                u_r     = 0.;
        for (unsigned int k = 0; k < stencil; ++k)
          {
            scratch.hoop_values[i][k] = N[k] / r;
            u_r += N[k] * du_cell[nodes[k] * dim];
          }
        scratch.hoop_increment[i] = u_r / r;
      }
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::add_hoop_forces(const unsigned int c,
                                            double            *f_cell) const
  {
    const auto &range = cache.cell(c);
    for (unsigned int p = range.first_point; p < range.end_point; ++p)
      {
        const unsigned int    i       = p - scratch.block_first;
        const unsigned short *nodes   = cache.nodes(p);
        const unsigned int    stencil = cache.stencil_size(p);
        for (unsigned int k = 0; k < stencil; ++k)
          f_cell[nodes[k] * dim] -=
            scratch.hoop_force[i] * scratch.hoop_values[i][k];
      }
  }



  template <int dim>
  template <bool write_back>
  void
  QuasiStaticResidual<dim>::axisymmetric_stresses(
    const PointStateBatch<dim> &old,
    const unsigned int          first,
    Evaluation                 &result) const
  {
    const auto        &offsets         = own_offsets;
    const auto        &written_offsets = points.get_offsets();
    const unsigned int n_state         = state_layout.n_state;
    double             min_J           = result.minimum_volume_ratio;
    for (unsigned int i = 0; i < old.size(); ++i)
      {
        const double *data       = committed(first + i);
        const double  d_eps_hoop = scratch.hoop_increment[i];
        model.update_stress_axisymmetric(
          old[i],
          data[offsets.hoop_stress],
          scratch.strain_increment[i],
          d_eps_hoop,
          scratch.stress[i],
          scratch.hoop_stress[i],
          ArrayView<double>(scratch.state.data() + i * n_state, n_state));
        // The volume per radian, r dA, changes with the in-plane and the
        // hoop strain.
        const double J =
          (1. + trace(scratch.strain_increment[i]) + d_eps_hoop) *
          data[offsets.J];
        const double volume = update_volumes ?
                                J * data[offsets.initial_volume] :
                                data[offsets.initial_volume];
        if (write_back)
          {
            double *const out = cache.properties(first + i, writable_points);
            Utils::write_symmetric<dim>(Utils::read_symmetric<dim>(
                                          out + written_offsets.strain) +
                                          scratch.strain_increment[i],
                                        out + written_offsets.strain);
            Utils::write_symmetric<dim>(scratch.stress[i],
                                        out + written_offsets.stress);
            out[written_offsets.hoop_strain] += d_eps_hoop;
            out[written_offsets.hoop_stress] = scratch.hoop_stress[i];
            out[written_offsets.J]           = J;
            out[written_offsets.volume]      = volume;
            // F-bar shifted each of the three directions by the same
            // amount: the point's own volume change minus the cell's mean
            // is 3/2 of the in-plane traces' difference.
            if (written_offsets.fbar_volume_excess !=
                numbers::invalid_unsigned_int)
              out[written_offsets.fbar_volume_excess] +=
                1.5 * (trace(scratch.grad_du[i]) -
                       trace(scratch.strain_increment[i]));
          }
        else
          {
            min_J             = std::min(min_J, J);
            scratch.volume[i] = volume;
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = 0; b < dim; ++b)
                scratch.force_stress[i][a][b] =
                  volume * scratch.stress[i][a][b];
            scratch.hoop_force[i] = volume * scratch.hoop_stress[i];
          }
      }
    result.minimum_volume_ratio = min_J;
  }



  template <int dim>
  template <bool write_back>
  void
  QuasiStaticResidual<dim>::axisymmetric_finite_strain_stresses(
    const PointStateBatch<dim> &old,
    const unsigned int          first,
    Evaluation                 &result) const
  {
    const auto        &offsets         = own_offsets;
    const auto        &written_offsets = points.get_offsets();
    const unsigned int n_state         = state_layout.n_state;
    const bool         fbar            = points.get_formulation().fbar();
    double             min_J           = result.minimum_volume_ratio;
    for (unsigned int i = 0; i < old.size(); ++i)
      {
        const double   *data = committed(first + i);
        Tensor<2, dim> &S    = scratch.force_stress[i];
        // The step's stretches: in plane Delta F, out of it (hoop) r_{n+1}
        // / r_n = 1 + d u_r / r_n; their volume change, and with F-bar the
        // cell's mean shared by the three directions.
        const Tensor<2, dim> delta_F =
          unit_symmetric_tensor<dim>() + scratch.grad_du[i];
        const double hoop_stretch = 1. + scratch.hoop_increment[i];
        const double det_delta_F  = determinant(delta_F) * hoop_stretch;
        const double mean         = scratch.mean_volume_change[i];
        const double scale        = fbar ? std::cbrt(mean / det_delta_F) : 1.;
        FiniteStrainKinematics<dim> kinematics;
        kinematics.F_old =
          Utils::read_tensor<dim>(data + offsets.deformation_gradient);
        kinematics.delta_F            = scale * delta_F;
        kinematics.delta_hoop_stretch = scale * hoop_stretch;
        kinematics.F                  = kinematics.delta_F * kinematics.F_old;
        if (!(det_delta_F > 0. && hoop_stretch > 0. && (!fbar || mean > 0.)))
          {
            S                     = std::numeric_limits<double>::quiet_NaN();
            scratch.hoop_force[i] = std::numeric_limits<double>::quiet_NaN();
            continue;
          }
        SymmetricTensor<2, dim> tau;
        double                  tau_hoop;
        model.update_kirchhoff_stress_axisymmetric(
          old[i],
          kinematics,
          tau,
          tau_hoop,
          ArrayView<double>(scratch.state.data() + i * n_state, n_state));
        // The volume per radian follows the in-plane and the hoop stretch.
        const double J = data[offsets.J] * (fbar ? mean : det_delta_F);
        if (write_back)
          {
            double *const out = cache.properties(first + i, writable_points);
            write_finite_strain_state<dim>(out,
                                           written_offsets,
                                           kinematics.F,
                                           tau,
                                           J,
                                           data[offsets.initial_volume],
                                           fbar ? det_delta_F / mean : 1.);
            // The logarithmic hoop strain ln(r / R).
            out[written_offsets.hoop_strain] +=
              std::log(kinematics.delta_hoop_stretch);
            out[written_offsets.hoop_stress] = tau_hoop / J;
          }
        else
          {
            // Omega sigma grad_{n+1} N = Omega_0 tau Delta F^{-T} grad_n N,
            // and the hoop force Omega sigma_tt N / r_{n+1} = Omega_0 tau_tt
            // N / (r_n Delta F_tt), both with the point's own Delta F (as
            // finite_strain_stresses()).
            S = data[offsets.initial_volume] * Tensor<2, dim>(tau) *
                transpose(invert(delta_F));
            scratch.hoop_force[i] =
              data[offsets.initial_volume] * tau_hoop / hoop_stretch;
            min_J = std::min(min_J, det_delta_F * data[offsets.J]);
          }
      }
    result.minimum_volume_ratio = min_J;
  }



  template <int dim>
  template <bool write_back>
  void
  QuasiStaticResidual<dim>::finite_strain_stresses(
    const PointStateBatch<dim> &old,
    const unsigned int          first,
    Evaluation                 &result) const
  {
    const auto        &offsets         = own_offsets;
    const auto        &written_offsets = points.get_offsets();
    const unsigned int n_state         = state_layout.n_state;
    const bool         fbar            = points.get_formulation().fbar();
    double             min_J           = result.minimum_volume_ratio;

    for (unsigned int i = 0; i < old.size(); ++i)
      {
        const double   *data = committed(first + i);
        Tensor<2, dim> &S    = scratch.force_stress[i];

        FiniteStrainKinematics<dim> kinematics;
        kinematics.F_old =
          Utils::read_tensor<dim>(data + offsets.deformation_gradient);
        const Tensor<2, dim> delta_F =
          unit_symmetric_tensor<dim>() + scratch.grad_du[i];
        const double det_delta_F        = determinant(delta_F);
        const double mean_volume_change = scratch.mean_volume_change[i];
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
          ArrayView<double>(scratch.state.data() + i * n_state, n_state));
        if (write_back)
          {
            write_finite_strain_state<dim>(
              cache.properties(first + i, writable_points),
              written_offsets,
              kinematics.F,
              tau,
              determinant(kinematics.F),
              data[offsets.initial_volume],
              fbar ? det_delta_F / mean_volume_change : 1.);
          }
        else
          {
            // Omega sigma grad_{n+1} N = Omega_0 tau Delta F^{-T} grad_n N.
            S = data[offsets.initial_volume] * Tensor<2, dim>(tau) *
                transpose(invert(delta_F));
            min_J = std::min(min_J, det_delta_F * data[offsets.J]);
          }
      }
    result.minimum_volume_ratio = min_J;
  }



  template <int dim>
  double
  QuasiStaticResidual<dim>::cell_mean_volume_change(
    const typename ShapeCache<dim>::CellRange &range,
    const bool                                 finite_strain) const
  {
    // Weighted with the volumes at the start of the step: the mean is then
    // the volume change of the cell's material as a whole.
    const unsigned int volume       = own_offsets.volume;
    const bool         axisymmetric = points.get_formulation().axisymmetric;
    double             sum = 0., total_volume = 0.;
    for (unsigned int p = range.first_point; p < range.end_point; ++p)
      {
        const double          omega = committed(p)[volume];
        const Tensor<2, dim> &grad_du =
          scratch.grad_du[p - scratch.block_first];
        const double hoop =
          axisymmetric ? scratch.hoop_increment[p - scratch.block_first] : 0.;
        sum += omega * (finite_strain ?
                          determinant(unit_symmetric_tensor<dim>() + grad_du) *
                            (1. + hoop) :
                          trace(grad_du) + hoop);
        total_volume += omega;
      }
    return sum / total_volume;
  }



  template <int dim>
  template <bool write_back>
  void
  QuasiStaticResidual<dim>::share_plastic_volume_changes(
    const LoopKind    &kind,
    const unsigned int c0,
    const unsigned int c1,
    Evaluation        &result) const
  {
    const unsigned int first    = cache.cell(c0).first_point;
    const unsigned int n_points = cache.cell(c1 - 1).end_point - first;
    // One pass where no point of the block changes its plastic volume, four
    // or five where one does (the footings of examples/footing); the cap
    // guards against a return mapping that is not monotone in the volume
    // change.
    constexpr unsigned int max_passes = 30;
    const Evaluation       start      = result;
    for (unsigned int pass = 0;; ++pass)
      {
        result = start;
        block_stresses<false>(kind, first, n_points, result);
        if (pass + 1 == max_passes || !update_volume_shares(c0, c1, pass == 0))
          break;
      }
    if (write_back)
      block_stresses<true>(kind, first, n_points, result);
  }



  template <int dim>
  bool
  QuasiStaticResidual<dim>::update_volume_shares(const unsigned int c0,
                                                 const unsigned int c1,
                                                 const bool first_pass) const
  {
    const unsigned int n_state = state_layout.n_state;
    const unsigned int volume  = own_offsets.volume;
    const unsigned int first   = scratch.block_first;
    // Axisymmetric: the hoop strain is the third normal strain; a volume
    // change is shared by all three, as F-bar's correction is.
    const bool   axisymmetric  = points.get_formulation().axisymmetric;
    const double n_normal      = axisymmetric ? 3. : dim;
    const auto   volume_change = [&](const unsigned int i) {
      return trace(scratch.strain_increment[i]) +
             (axisymmetric ? scratch.hoop_increment[i] : 0.);
    };
    const PointStateBatch<dim> old =
      committed_batch(first, cache.cell(c1 - 1).end_point - first);
    // The common elastic volume change of a cell that keeps its mean total
    // volume change under the update dx_p = (common - e_p) / s_p:
    // sum_p w_p dx_p = 0.
    const auto common_of = [&](const typename ShapeCache<dim>::CellRange &r) {
      double sum = 0., weight = 0.;
      for (unsigned int p = r.first_point; p < r.end_point; ++p)
        {
          const unsigned int i = p - first;
          const double       w =
            committed(p)[volume] / scratch.elastic_volume_slope[i];
          sum += w * scratch.elastic_volume_change[i];
          weight += w;
        }
      return sum / weight;
    };

    // Each cell's common elastic volume change, for the mismatch and for
    // the update.
    std::array<double, block_cells> commons;
    Assert(c1 - c0 <= block_cells, ExcInternalError());
    double mismatch = 0., increments = 0., accumulated = 0.;
    for (unsigned int c = c0; c < c1; ++c)
      {
        const auto &range = cache.cell(c);
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const unsigned int i = p - first;
            // A point whose model does not split its strain changes its
            // elastic volume by all of its volume change.
            const auto strains = model.elastic_volume_strains(
              old[i],
              ArrayView<const double>(scratch.state.data() + i * n_state,
                                      n_state));
            const double e =
              strains ? (*strains)[1] - (*strains)[0] : volume_change(i);
            double &slope = scratch.elastic_volume_slope[i];
            if (first_pass)
              {
                slope                   = 1.;
                scratch.volume_shift[i] = 0.;
              }
            else if (scratch.volume_shift[i] != 0.)
              slope = std::clamp((e - scratch.elastic_volume_change[i]) /
                                   scratch.volume_shift[i],
                                 0.1,
                                 1.);
            scratch.elastic_volume_change[i] = e;
            increments =
              std::max(increments, scratch.strain_increment[i].norm());
            if (strains)
              accumulated = std::max(accumulated, std::abs((*strains)[0]));
          }
        const double common = commons[c - c0] = common_of(range);
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          mismatch =
            std::max(mismatch,
                     std::abs(scratch.elastic_volume_change[p - first] -
                              common));
      }
    // Well above the round-off of the traces, far below what a
    // finite-difference product of the Jacobian-free Newton resolves.
    if (mismatch <= 1e-12 * increments + 1e-14 * accumulated)
      return false;

    for (unsigned int c = c0; c < c1; ++c)
      {
        const auto  &range  = cache.cell(c);
        const double common = commons[c - c0];
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const unsigned int i = p - first;
            const double dx      = (common - scratch.elastic_volume_change[i]) /
                              scratch.elastic_volume_slope[i];
            scratch.volume_shift[i] = dx;
            scratch.strain_increment[i] +=
              dx / n_normal * unit_symmetric_tensor<dim>();
            if (axisymmetric)
              scratch.hoop_increment[i] += dx / n_normal;
          }
      }
    return true;
  }



  template <int dim>
  void
  QuasiStaticResidual<dim>::project_fbar_force_stresses(
    const typename ShapeCache<dim>::CellRange &range) const
  {
    // The work of the stresses on a virtual displacement v is that on the
    // virtual F-bar strain, d eps_bar_p(v) = d eps_p(v) + (theta_bar(v) -
    // tr d eps_p(v))/dim I with theta_bar(v) = sum_q w_q tr d eps_q(v) / W
    // (w_q the volumes of the mean, W their sum, V_p the volumes of the
    // forces):
    //
    //   sum_p V_p sigma_p : d eps_bar_p(v) = sum_p S_p : d eps_p(v),
    //   S_p = V_p sigma_p + (w_p / W sum_q V_q tr sigma_q
    //                        - V_p tr sigma_p) / dim I.
    //
    // The volumetric part of the forces is that of the cell's mean stress
    // trace: pressures that vary between the points of a cell do no work on
    // the points' own volume changes, which the F-bar kinematics does not
    // let them resist.
    //
    // Axisymmetric: the same with the traces and the identity of the three
    // directions, the hoop one (Scratch::hoop_force, Omega sigma_thetatheta)
    // among them.
    const unsigned int volume       = own_offsets.volume;
    const bool         axisymmetric = points.get_formulation().axisymmetric;
    const double       n_directions = axisymmetric ? 3. : dim;
    const auto         trace_of     = [&](const unsigned int i) {
      return trace(scratch.force_stress[i]) +
             (axisymmetric ? scratch.hoop_force[i] : 0.);
    };
    double W       = 0.;
    double V_trace = 0.;
    for (unsigned int p = range.first_point; p < range.end_point; ++p)
      {
        W += committed(p)[volume];
        V_trace += trace_of(p - scratch.block_first);
      }
    for (unsigned int p = range.first_point; p < range.end_point; ++p)
      {
        const unsigned int i = p - scratch.block_first;
        const double       shift =
          (committed(p)[volume] / W * V_trace - trace_of(i)) / n_directions;
        Tensor<2, dim> &S = scratch.force_stress[i];
        for (unsigned int a = 0; a < dim; ++a)
          S[a][a] += shift;
        if (axisymmetric)
          scratch.hoop_force[i] += shift;
      }
  }



  template class QuasiStaticResidual<2>;
  template class QuasiStaticResidual<3>;
} // namespace qsmpm
