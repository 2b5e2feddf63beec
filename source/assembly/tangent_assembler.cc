#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <qsmpm/assembly/tangent_assembler.h>
#include <qsmpm/base/utilities.h>

namespace qsmpm
{
  namespace
  {
    /**
     * The couplings of linear shape functions, row by row: the dofs of a
     * node couple with those of every node of the cells around it. Each row
     * of @p pattern (the locally relevant ones) is inserted once, sorted
     * and complete, instead of cell by cell as DoFTools::
     * make_sparsity_pattern() does (one insert per cell around the node,
     * 4 in 2D and 8 in 3D, each merged into the row so far). The dim dofs
     * of a node are consecutive in the grid's numbering, which AMG's
     * rigid-body modes rely on as well (make_rigid_body_modes()).
     */
    template <int dim>
    void
    add_node_couplings(const BackgroundGrid<dim>         &grid,
                       TrilinosWrappers::SparsityPattern &pattern)
    {
      using index_type                   = types::global_dof_index;
      constexpr unsigned int n_vertices  = GeometryInfo<dim>::vertices_per_cell;
      const IndexSet        &relevant    = grid.locally_relevant_dofs();
      const auto            &dof_handler = grid.get_dof_handler();
      // dim dofs per node, or dim per body on a multi-field grid.
      const unsigned int node_dofs = grid.n_node_dofs();

      // The relevant nodes, numbered by the position of their first dof in
      // the relevant set, and the cells around each (counted, then filled).
      const auto node_of = [&](const index_type first_dof) {
        return relevant.index_within_set(first_dof) / node_dofs;
      };
      const std::size_t        n_nodes = relevant.n_elements() / node_dofs;
      std::vector<std::size_t> start(n_nodes + 1, 0);
      std::array<index_type, n_vertices> first;
      const auto                         cell_nodes = [&](const auto &cell) {
        for (unsigned int v = 0; v < n_vertices; ++v)
          {
            first[v] = cell->vertex_dof_index(v, 0);
            for (unsigned int d = 1; d < node_dofs; ++d)
              Assert(cell->vertex_dof_index(v, d) == first[v] + d,
                     ExcMessage("The dofs of a vertex are not consecutive."));
          }
      };
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            cell_nodes(cell);
            for (unsigned int v = 0; v < n_vertices; ++v)
              start[node_of(first[v]) + 1] += n_vertices;
          }
      for (std::size_t n = 0; n < n_nodes; ++n)
        start[n + 1] += start[n];
      std::vector<index_type>  neighbours(start.back());
      std::vector<std::size_t> end(start.begin(), start.end() - 1);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            cell_nodes(cell);
            for (unsigned int v = 0; v < n_vertices; ++v)
              {
                const std::size_t n = node_of(first[v]);
                std::copy(first.begin(), first.end(), &neighbours[end[n]]);
                end[n] += n_vertices;
              }
          }

      // Each node's rows: the dofs of its distinct neighbours, sorted.
      std::vector<index_type> columns;
      for (std::size_t n = 0; n < n_nodes; ++n)
        {
          const auto begin = neighbours.begin() + start[n];
          auto       last  = neighbours.begin() + end[n];
          if (begin == last)
            continue;
          std::sort(begin, last);
          last = std::unique(begin, last);
          columns.clear();
          for (auto u = begin; u != last; ++u)
            for (unsigned int d = 0; d < node_dofs; ++d)
              columns.push_back(*u + d);
          const index_type row = relevant.nth_index_in_set(n * node_dofs);
          for (unsigned int d = 0; d < node_dofs; ++d)
            pattern.add_entries(row + d, columns.begin(), columns.end(), true);
        }
    }



    /**
     * The tangents C_akbl of the stiffness K = sum_p Omega_p B^T C B at the
     * committed states of the points of one cell, and the volumes Omega_p
     * they are integrated over: the small-strain tangent on the current
     * volume (one batched call of the model per cell), or at finite strain
     * the tangent of the first Piola stress on the initial volume.
     *
     * At a Newton iterate (IterateKinematics) each point's consistent
     * tangent there instead; at finite strain, where the residual's
     * stress tau Delta F^{-T} and its virtual gradients grad_n N follow
     * the iterate's Delta F, the tangent is c - tau_al delta_kb for the
     * current gradients Delta F^{-T} grad_n N (spatial_gradients()), the
     * form it has at Delta F = I.
     *
     * With hoop tangents (the stiffness at an iterate of an axisymmetric
     * problem), also each point's 3D tangent, index 2 the hoop direction:
     * at small strain consistent_tangent_axisymmetric(); at finite strain
     * kirchhoff_tangent_axisymmetric() minus its geometric terms, the
     * residual's hoop force Omega_0 tau_tt N / (r Delta F_tt) being
     * Omega_0 tau : l with l_22 = N / (r Delta F_tt) (hoop_radius()).
     */
    template <int dim>
    class CellTangents
    {
    public:
      CellTangents(const MaterialPointSet<dim>                  &points,
                   const typename TangentAssembler<dim>::Tangent kind =
                     TangentAssembler<dim>::Tangent::secant,
                   const bool hoop_tangents = false)
        : model(points.get_model())
        , loading(kind == TangentAssembler<dim>::Tangent::loading)
        , offsets(points.get_offsets())
        , layout(points.batch_layout())
        , finite_strain(points.get_formulation().finite_strain())
        , fbar(points.get_formulation().fbar())
        , with_hoop(hoop_tangents && points.get_formulation().axisymmetric)
        , new_state(layout.n_state)
      {
      }

      /**
       * Fill C() and volume() for the points of the cell @p c of
       * @p cache, in their order.
       */
      void
      reinit(const ShapeCache<dim>        &cache,
             const unsigned int            c,
             const IterateKinematics<dim> *iterate = nullptr)
      {
        const auto        &range = cache.cell(c);
        const unsigned int n     = range.end_point - range.first_point;
        at_iterate               = iterate != nullptr;
        // Grown to the largest cell, then reused: no allocation per cell.
        if (tangents.size() < n)
          {
            symmetric.resize(n);
            tangents.resize(n);
            volumes.resize(n);
            kirchhoff_stresses.resize(finite_strain ? n : 0);
            inverse_increments.resize(finite_strain ? n : 0);
            volume_ratios.resize(finite_strain ? n : 0);
            hoop_tangents.resize(with_hoop ? n : 0);
            hoop_kirchhoff_stresses.resize(with_hoop && finite_strain ? n : 0);
            hoop_stretches.resize(with_hoop && finite_strain ? n : 0);
          }
        if (with_hoop && !finite_strain)
          for (unsigned int i = 0; i < n; ++i)
            axisymmetric_tangent(cache, range.first_point + i, i, iterate);
        else if (finite_strain)
          for (unsigned int i = 0; i < n; ++i)
            finite_strain_tangent(cache, range.first_point + i, i, iterate);
        else if (iterate != nullptr)
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int    p     = range.first_point + i;
              const double         *data  = cache.properties(p);
              const PointState<dim> state = point_state(cache, p);
              tangents[i]                 = Tensor<4, dim>(
                iterate_tangent(state, iterate->strain_increments[p]));
              volumes[i] = data[offsets.volume];
            }
        else
          {
            const PointStateBatch<dim>               old(layout,
                                           cache.property_arrays(
                                             range.first_point),
                                           &cache.position(range.first_point),
                                           n);
            const ArrayView<SymmetricTensor<4, dim>> C(symmetric.data(), n);
            if (loading)
              model.loading_tangents(old, C);
            else
              model.tangents(old, C);
            for (unsigned int i = 0; i < n; ++i)
              {
                tangents[i] = Tensor<4, dim>(symmetric[i]);
                volumes[i] =
                  cache.properties(range.first_point + i)[offsets.volume];
              }
          }
      }

      /// C of the @p i-th point of the cell.
      const Tensor<4, dim> &
      C(const unsigned int i) const
      {
        return tangents[i];
      }

      /// Omega of the @p i-th point of the cell.
      double
      volume(const unsigned int i) const
      {
        return volumes[i];
      }

      /// At finite strain, the Kirchhoff stress tau of the @p i-th point,
      /// whose geometric term C() holds.
      const SymmetricTensor<2, dim> &
      kirchhoff_stress(const unsigned int i) const
      {
        return kirchhoff_stresses[i];
      }

      bool
      is_finite_strain() const
      {
        return finite_strain;
      }

      /**
       * The gradients the stiffness of the @p i-th point reads, from the
       * gradients @p grad_N (on the grid, the configuration at the step's
       * start) of its @p stencil: at a finite-strain iterate the current
       * ones, Delta F^{-T} grad_N, in @p buffer; otherwise @p grad_N.
       */
      const Tensor<1, dim> *
      spatial_gradients(const unsigned int    i,
                        const Tensor<1, dim> *grad_N,
                        const unsigned int    stencil,
                        Tensor<1, dim>       *buffer) const
      {
        if (!finite_strain || !at_iterate)
          return grad_N;
        const Tensor<2, dim> inverse_transpose =
          transpose(inverse_increments[i]);
        for (unsigned int v = 0; v < stencil; ++v)
          buffer[v] = inverse_transpose * grad_N[v];
        return buffer;
      }

      /**
       * With hoop tangents: the 3D tangent of the @p i-th point, index 2
       * the hoop direction (at finite strain with the geometric terms).
       */
      const Tensor<4, 3> &
      hoop_tangent(const unsigned int i) const
      {
        return hoop_tangents[i];
      }

      /**
       * With hoop tangents at finite strain: the 3D Kirchhoff stress of the
       * @p i-th point (tau_22 the hoop one), which F-bar's terms need.
       */
      Tensor<2, 3>
      kirchhoff_stress_3d(const unsigned int i) const
      {
        Tensor<2, 3> tau;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            tau[a][b] = kirchhoff_stresses[i][a][b];
        tau[2][2] = hoop_kirchhoff_stresses[i];
        return tau;
      }

      /// The radius the hoop terms of the @p i-th point, at @p r at the
      /// step's start, divide by: r Delta F_tt at a finite-strain iterate.
      double
      hoop_radius(const unsigned int i, const double r) const
      {
        return finite_strain && with_hoop ? r * hoop_stretches[i] : r;
      }

      /// The weight of the @p i-th point's volume change in F-bar's mean,
      /// relative to its volume at the step's start: det Delta F at a
      /// finite-strain iterate, 1 otherwise.
      double
      volume_ratio(const unsigned int i) const
      {
        return finite_strain ? volume_ratios[i] : 1.;
      }

    private:
      /// The committed state of the point @p p of @p cache.
      PointState<dim>
      point_state(const ShapeCache<dim> &cache, const unsigned int p) const
      {
        return MaterialPointSet<dim>::read_point_state(cache.properties(p),
                                                       offsets,
                                                       layout.n_state,
                                                       cache.position(p));
      }

      /**
       * The consistent tangent at the strain increment @p increment from
       * @p state; where the model cannot give it (the Mohr-Coulomb
       * footing at a/h = 16 stopped in an eigenvalue solver's exception at
       * an iterate whose residual it had evaluated), the tangent of the
       * committed state: the matrix is a preconditioner, and one point's
       * entries in it change only how fast GMRES converges.
       */
      SymmetricTensor<4, dim>
      iterate_tangent(const PointState<dim>         &state,
                      const SymmetricTensor<2, dim> &increment) const
      {
        try
          {
            const SymmetricTensor<4, dim> C =
              model.consistent_tangent(state, increment);
            if (std::isfinite(C.norm()))
              return C;
          }
        catch (const std::exception &)
          {
          }
        return model.tangent(state);
      }

      /// The in-plane part of hoop_tangents[i] into tangents[i].
      void
      copy_in_plane_part(const unsigned int i)
      {
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int b = 0; b < dim; ++b)
              for (unsigned int l = 0; l < dim; ++l)
                tangents[i][a][k][b][l] = hoop_tangents[i][a][k][b][l];
      }

      /**
       * Axisymmetric, small strain: the 3D tangent of the point @p p (the
       * @p i-th of its cell) at @p iterate's strain and hoop strain
       * increments if given, else at the committed state
       * (ConstitutiveModel::consistent_tangent_axisymmetric()), into
       * hoop_tangents[i] and its in-plane part into tangents[i]; where the
       * model cannot give it at the iterate, that of the committed state.
       */
      void
      axisymmetric_tangent(const ShapeCache<dim>        &cache,
                           const unsigned int            p,
                           const unsigned int            i,
                           const IterateKinematics<dim> *iterate)
      {
        const double         *data        = cache.properties(p);
        const PointState<dim> state       = point_state(cache, p);
        const double          hoop_stress = data[offsets.hoop_stress];
        Tensor<4, 3>         &C3          = hoop_tangents[i];
        bool                  done        = false;
        if (iterate != nullptr)
          try
            {
              C3 = model.consistent_tangent_axisymmetric(
                state,
                hoop_stress,
                iterate->strain_increments[p],
                iterate->hoop_strain_increments[p]);
              done = std::isfinite(C3.norm());
            }
          catch (const std::exception &)
            {
            }
        if (!done)
          C3 = model.consistent_tangent_axisymmetric(state,
                                                     hoop_stress,
                                                     SymmetricTensor<2, dim>(),
                                                     0.);
        copy_in_plane_part(i);
        volumes[i] = data[offsets.volume];
      }

      /**
       * c - tau_al delta_kb of the point @p p (the @p i-th of its cell) on
       * its initial volume: at @p iterate's Delta F if given (with F-bar's
       * scaling to the cell's mean volume change, as in the residual),
       * otherwise, or where the model cannot give it there, at Delta F = I,
       * where d(tau Delta F^{-T}) = c : G - tau G^T for G = grad_n d(du)
       * (see QuasiStaticResidual).
       */
      void
      finite_strain_tangent(const ShapeCache<dim>        &cache,
                            const unsigned int            p,
                            const unsigned int            i,
                            const IterateKinematics<dim> *iterate)
      {
        const double               *data  = cache.properties(p);
        const PointState<dim>       state = point_state(cache, p);
        FiniteStrainKinematics<dim> kinematics;
        kinematics.F_old =
          Utils::read_tensor<dim>(data + offsets.deformation_gradient);
        Tensor<4, dim>          &C   = tangents[i];
        SymmetricTensor<2, dim> &tau = kirchhoff_stresses[i];
        volumes[i]                   = data[offsets.initial_volume];
        if (iterate == nullptr ||
            !iterate_kirchhoff_tangent(state, kinematics, *iterate, p, i))
          {
            kinematics.delta_F = unit_symmetric_tensor<dim>();
            kinematics.F       = kinematics.F_old;
            tau                = data[offsets.J] * state.stress;
            if (with_hoop)
              {
                hoop_tangents[i] =
                  model.kirchhoff_tangent_axisymmetric(state, kinematics);
                hoop_kirchhoff_stresses[i] =
                  data[offsets.J] * data[offsets.hoop_stress];
                hoop_stretches[i] = 1.;
              }
            else
              C = model.kirchhoff_tangent(state, kinematics);
            inverse_increments[i] = unit_symmetric_tensor<dim>();
            volume_ratios[i]      = 1.;
          }
        if (with_hoop)
          {
            // -tau : (l_v l_w) in 3D: the in-plane terms below, and the
            // hoop one; the rest of the 3D form meets only the zero
            // entries l_a2, l_2a (a in-plane) of the virtual gradients.
            Tensor<4, 3> &C3 = hoop_tangents[i];
            C3[2][2][2][2] -= hoop_kirchhoff_stresses[i];
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int k = 0; k < dim; ++k)
                for (unsigned int l = 0; l < dim; ++l)
                  C3[a][k][k][l] -= tau[a][l];
            copy_in_plane_part(i);
          }
        else
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int l = 0; l < dim; ++l)
                C[a][k][k][l] -= tau[a][l];
      }

      /**
       * The tangent c and the stress tau of the @p i-th point (the point
       * @p p of the cache) at @p iterate into tangents[i] and
       * kirchhoff_stresses[i] (with hoop tangents the 3D c and the hoop
       * stress into hoop_tangents[i] and hoop_kirchhoff_stresses[i]), and
       * its Delta F^{-1}, det Delta F (times the hoop stretch) and hoop
       * stretch; false where the point is inverted there or the model
       * gives no finite tangent.
       */
      bool
      iterate_kirchhoff_tangent(const PointState<dim>        &state,
                                FiniteStrainKinematics<dim>  &kinematics,
                                const IterateKinematics<dim> &iterate,
                                const unsigned int            p,
                                const unsigned int            i)
      {
        // As QuasiStaticResidual: F-bar scales the in-plane and the hoop
        // stretch alike to the cell's mean volume change.
        const Tensor<2, dim> &delta_F = iterate.deformation_increments[p];
        const double          hoop_stretch =
          with_hoop ? 1. + iterate.hoop_strain_increments[p] : 1.;
        const double det  = determinant(delta_F) * hoop_stretch;
        const double mean = fbar ? iterate.mean_volume_changes[p] : det;
        if (!(det > 0. && hoop_stretch > 0. && mean > 0.))
          return false;
        const double scale = std::pow(mean / det, 1. / (with_hoop ? 3 : dim));
        kinematics.delta_F = scale * delta_F;
        kinematics.delta_hoop_stretch = with_hoop ? scale * hoop_stretch : 1.;
        kinematics.F                  = kinematics.delta_F * kinematics.F_old;
        double tau_hoop               = 0.;
        try
          {
            const ArrayView<double> state_out(new_state);
            if (with_hoop)
              {
                hoop_tangents[i] =
                  model.kirchhoff_tangent_axisymmetric(state, kinematics);
                model.update_kirchhoff_stress_axisymmetric(
                  state,
                  kinematics,
                  kirchhoff_stresses[i],
                  tau_hoop,
                  state_out);
              }
            else
              {
                tangents[i] = model.kirchhoff_tangent(state, kinematics);
                model.update_kirchhoff_stress(state,
                                              kinematics,
                                              kirchhoff_stresses[i],
                                              state_out);
              }
          }
        catch (const std::exception &)
          {
            return false;
          }
        if (!std::isfinite(with_hoop ? hoop_tangents[i].norm() :
                                       tangents[i].norm()) ||
            !std::isfinite(kirchhoff_stresses[i].norm()) ||
            !std::isfinite(tau_hoop))
          return false;
        inverse_increments[i] = invert(delta_F);
        volume_ratios[i]      = det;
        if (with_hoop)
          {
            hoop_kirchhoff_stresses[i] = tau_hoop;
            hoop_stretches[i]          = hoop_stretch;
          }
        return true;
      }

      const ConstitutiveModel<dim>                  &model;
      const bool                                     loading;
      const typename MaterialPointSet<dim>::Offsets &offsets;
      const typename PointStateBatch<dim>::Layout    layout;
      const bool                                     finite_strain;
      const bool                                     fbar;
      const bool                                     with_hoop;
      bool                                           at_iterate = false;
      std::vector<double>                            new_state;
      std::vector<SymmetricTensor<4, dim>>           symmetric;
      std::vector<Tensor<4, dim>>                    tangents;
      std::vector<double>                            volumes;
      std::vector<SymmetricTensor<2, dim>>           kirchhoff_stresses;
      std::vector<Tensor<2, dim>>                    inverse_increments;
      std::vector<double>                            volume_ratios;
      std::vector<Tensor<4, 3>>                      hoop_tangents;
      std::vector<double>                            hoop_kirchhoff_stresses;
      std::vector<double>                            hoop_stretches;
    };



    /**
     * The F-bar terms of one cell's stiffness (the cell is the patch of
     * the mean volume change). QuasiStaticResidual replaces the volume
     * change of each point's strain increment by the cell's mean,
     *
     *   d eps_bar_p = d eps_p + (theta_bar - tr d eps_p) / dim I,
     *   theta_bar = sum_q w_q tr d eps_q / W,
     *
     * w_q the points' volumes at the start of the step and W their sum,
     * so that a virtual displacement of dof (v, a) changes theta_bar by
     * bbar_va = sum_q w_q dN_v/dx_a(x_q) / W over the cell's group of
     * nodes, and the point's volume change by g_p,va = dN_v/dx_a(x_p).
     * With d_p = bbar - g_p the exact stiffness is then
     *
     *   small strain (the forces of the virtual F-bar strain, B-bar):
     *     K = K_B + sum_p Omega_p [(m_p (x) d_p + d_p (x) n_p) / dim
     *                              + kappa_p d_p (x) d_p / dim^2],
     *   finite strain (F-bar kinematics, plain virtual gradients):
     *     K = K_B + sum_p Omega_p m_p (x) d_p / dim,
     *
     * K_B = sum_p Omega_p B_p^T C_p B_p the stiffness without F-bar
     * (axisymmetric, small strain: dim becomes 3, the three normal strains
     * share the mean, and g, m, n have the hoop parts of B_p,
     * add_point_axisymmetric()),
     * m_p,va = dN_v/dx_k Y_ak with Y = C : I the stress of a unit volume
     * change (at finite strain of the material tangent c : I = C : I +
     * tau, without the geometric term -tau G^T, which the virtual
     * gradient carries unchanged), n_p,wb = Y'_bl dN_w/dx_l with Y' = I :
     * C, and kappa_p = I : C : I. Without these terms K locks where the
     * Jacobian does not (a nearly incompressible or flowing plastic body:
     * K_B then holds the bulk stiffness of every point's own volume
     * change), and GMRES needs many more iterations to make up the
     * difference. The d_p (x) d_p and bbar terms span the whole group, so
     * they are summed over the cell's points first (W, the sums below)
     * and added as outer products once per cell; only the terms in g_p
     * alone are added point by point, within the point's stencil.
     */
    template <int dim>
    class FbarTerms
    {
    public:
      static constexpr unsigned int max_dofs =
        ShapeCache<dim>::max_dofs_per_group;

      /// Start the cell @p c of @p cache: bbar and the sums set to zero.
      void
      reinit(const ShapeCache<dim> &cache,
             const unsigned int     c,
             const bool             symmetric_form)
      {
        symmetric = symmetric_form;
        n_dofs    = cache.n_dofs(c);
        std::fill(bbar.begin(), bbar.begin() + n_dofs, 0.);
        std::fill(m_sum.begin(), m_sum.begin() + n_dofs, 0.);
        std::fill(n_sum.begin(), n_sum.begin() + n_dofs, 0.);
        std::fill(g_sum.begin(), g_sum.begin() + n_dofs, 0.);
        kappa_sum    = 0.;
        total_weight = 0.;
      }

      /**
       * The terms of one point (gradients @p grad_N on its @p stencil of
       * the group's @p nodes, tangent @p C, Kirchhoff stress @p tau at
       * finite strain, integrated over @p volume; @p weight its volume at
       * the start of the step, its weight in the mean): those in g_p alone
       * into @p K_cell, the others and its part of bbar into the cell's
       * sums, with the gradients the stiffness reads anyway.
       */
      void
      add_point(const Tensor<1, dim>          *grad_N,
                const unsigned int             stencil,
                const unsigned short          *nodes,
                const Tensor<4, dim>          &C,
                const SymmetricTensor<2, dim> *tau,
                const double                   volume,
                const double                   weight,
                FullMatrix<double>            &K_cell)
      {
        // Y = C : I (plus tau at finite strain), Y' = I : C, kappa.
        Tensor<2, dim> Y, Y_left;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int j = 0; j < dim; ++j)
              {
                Y[a][k] += C[a][k][j][j];
                Y_left[a][k] += C[j][j][a][k];
              }
        if (tau != nullptr)
          Y += Tensor<2, dim>(*tau);
        // The point's m, n and g over its stencil.
        for (unsigned int v = 0; v < stencil; ++v)
          for (unsigned int a = 0; a < dim; ++a)
            {
              double m_va = 0., n_va = 0.;
              for (unsigned int k = 0; k < dim; ++k)
                {
                  m_va += grad_N[v][k] * Y[a][k];
                  n_va += Y_left[a][k] * grad_N[v][k];
                }
              m[v * dim + a] = m_va;
              n[v * dim + a] = n_va;
              g[v * dim + a] = grad_N[v][a];
            }
        add_terms(stencil, nodes, dim, trace(Y), volume, weight, K_cell);
      }

      /**
       * add_point() of an axisymmetric problem, where the volume change has
       * three parts, the hoop strain d u_r / r among them, and F-bar shifts
       * all three: dim becomes 3, the virtual strains of dof (v, a) have
       * the hoop part delta_a0 N_v / r (values @p N, radius @p r: at a
       * finite-strain iterate r Delta F_tt, CellTangents::hoop_radius()),
       * and Y = C : I, Y' = I : C of the 3D tangent @p C (index 2 the hoop
       * direction; at finite strain Y plus the 3D Kirchhoff stress @p tau).
       */
      void
      add_point_axisymmetric(const double         *N,
                             const Tensor<1, dim> *grad_N,
                             const unsigned int    stencil,
                             const unsigned short *nodes,
                             const Tensor<4, 3>   &C,
                             const Tensor<2, 3>   *tau,
                             const double          r,
                             const double          volume,
                             const double          weight,
                             FullMatrix<double>   &K_cell)
      {
        Tensor<2, 3> Y, Y_left;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int j = 0; j < 3; ++j)
              {
                Y[a][k] += C[a][k][j][j];
                Y_left[a][k] += C[j][j][a][k];
              }
        if (tau != nullptr)
          Y += *tau;
        for (unsigned int v = 0; v < stencil; ++v)
          for (unsigned int a = 0; a < dim; ++a)
            {
              const double hoop = a == 0 ? N[v] / r : 0.;
              double       m_va = hoop * Y[2][2], n_va = hoop * Y_left[2][2];
              for (unsigned int k = 0; k < dim; ++k)
                {
                  m_va += grad_N[v][k] * Y[a][k];
                  n_va += Y_left[a][k] * grad_N[v][k];
                }
              m[v * dim + a] = m_va;
              n[v * dim + a] = n_va;
              g[v * dim + a] = grad_N[v][a] + hoop;
            }
        add_terms(stencil, nodes, 3, trace(Y), volume, weight, K_cell);
      }

      /// The cell's terms in bbar: m_sum (x) bbar, and in the symmetric
      /// form bbar (x) n_sum + kappa_sum bbar (x) bbar - bbar (x) g_sum -
      /// g_sum (x) bbar.
      void
      add_cell(FullMatrix<double> &K_cell)
      {
        for (unsigned int i = 0; i < n_dofs; ++i)
          bbar[i] /= total_weight;
        for (unsigned int i = 0; i < n_dofs; ++i)
          for (unsigned int j = 0; j < n_dofs; ++j)
            K_cell(i, j) +=
              m_sum[i] * bbar[j] +
              (symmetric ? bbar[i] * (n_sum[j] + kappa_sum * bbar[j]) -
                             bbar[i] * g_sum[j] - g_sum[i] * bbar[j] :
                           0.);
      }

    private:
      /**
       * The terms of one point from its m, n and g (in the members of the
       * same names; @p n_directions the number of normal strains that share
       * the mean, @p kappa = I : C : I): those in g alone into @p K_cell,
       * the others and its part of bbar (with weight @p weight) into the
       * cell's sums.
       */
      void
      add_terms(const unsigned int    stencil,
                const unsigned short *nodes,
                const unsigned int    n_directions,
                const double          kappa,
                const double          volume,
                const double          weight,
                FullMatrix<double>   &K_cell)
      {
        const unsigned int size = stencil * dim;
        const auto         row  = [&](const unsigned int i) {
          return nodes[i / dim] * dim + i % dim;
        };
        for (unsigned int i = 0; i < size; ++i)
          bbar[row(i)] += weight * g[i];
        total_weight += weight;
        const double f  = volume / n_directions;
        const double f2 = volume * kappa / (n_directions * n_directions);
        // -f m (x) g, and in the symmetric form -f g (x) n + f2 g (x) g.
        for (unsigned int i = 0; i < size; ++i)
          for (unsigned int j = 0; j < size; ++j)
            K_cell(row(i), row(j)) -=
              f * m[i] * g[j] +
              (symmetric ? f * g[i] * n[j] - f2 * g[i] * g[j] : 0.);
        for (unsigned int i = 0; i < size; ++i)
          {
            m_sum[row(i)] += f * m[i];
            if (symmetric)
              {
                n_sum[row(i)] += f * n[i];
                g_sum[row(i)] += f2 * g[i];
              }
          }
        if (symmetric)
          kappa_sum += f2;
      }

      std::array<double, ShapeCache<dim>::max_stencil_size * dim> m, n, g;
      bool                         symmetric = true;
      unsigned int                 n_dofs    = 0;
      std::array<double, max_dofs> bbar, m_sum, n_sum, g_sum;
      double                       kappa_sum    = 0.;
      double                       total_weight = 0.;
    };



    /**
     * Axisymmetric (r, z): the terms of the hoop strain d eps_thetatheta =
     * du_r / r of one point at radius @p r,
     *
     *   K_(v,a),(w,b) += Omega [C_tttt N_v N_w / r^2 delta_a0 delta_b0
     *                    + C_ttkk (N_v / r delta_a0 dN_w/dx_b
     *                              + dN_v/dx_a N_w / r delta_b0)],
     *
     * with the hoop entries of an isotropic tangent taken from the in-plane
     * one: C_tttt = C_xxxx, C_ttkk = C_xxyy (exact for isotropic
     * elasticity; a preconditioner's estimate for anisotropic or plastic
     * tangents, whose hoop entries the in-plane tangent does not hold).
     */
    template <int dim>
    void
    add_hoop_stiffness(const double         *N,
                       const Tensor<1, dim> *grad_N,
                       const unsigned int    stencil,
                       const unsigned short *nodes,
                       const Tensor<4, dim> &C,
                       const double          volume,
                       const double          r,
                       FullMatrix<double>   &K_cell)
    {
      const double c_hoop = C[0][0][0][0], c_cross = C[0][0][1][1];
      for (unsigned int v = 0; v < stencil; ++v)
        for (unsigned int w = 0; w < stencil; ++w)
          {
            const unsigned int row = nodes[v] * dim, column = nodes[w] * dim;
            K_cell(row, column) += volume * c_hoop * N[v] * N[w] / (r * r);
            for (unsigned int b = 0; b < dim; ++b)
              {
                K_cell(row, column + b) +=
                  volume * c_cross * N[v] / r * grad_N[w][b];
                K_cell(row + b, column) +=
                  volume * c_cross * grad_N[v][b] * N[w] / r;
              }
          }
    }



    /**
     * add_hoop_stiffness() with the hoop entries of a 3D tangent @p C
     * (index 2 the hoop direction; the consistent tangent of a plastic
     * point at an iterate; at finite strain with the geometric term in
     * C_2222, the gradients Delta F^{-T} grad_n N and r Delta F_tt):
     *
     *   K_(v,a),(w,b) += Omega [C_2222 N_v N_w / r^2 delta_a0 delta_b0
     *                    + N_v / r delta_a0 C_22bl dN_w/dx_l
     *                    + dN_v/dx_k C_ak22 N_w / r delta_b0].
     */
    template <int dim>
    void
    add_full_hoop_stiffness(const double         *N,
                            const Tensor<1, dim> *grad_N,
                            const unsigned int    stencil,
                            const unsigned short *nodes,
                            const Tensor<4, 3>   &C,
                            const double          volume,
                            const double          r,
                            FullMatrix<double>   &K_cell)
    {
      for (unsigned int v = 0; v < stencil; ++v)
        for (unsigned int w = 0; w < stencil; ++w)
          {
            const unsigned int row = nodes[v] * dim, column = nodes[w] * dim;
            K_cell(row, column) +=
              volume * C[2][2][2][2] * N[v] * N[w] / (r * r);
            for (unsigned int b = 0; b < dim; ++b)
              {
                double hoop_row = 0., hoop_column = 0.;
                for (unsigned int l = 0; l < dim; ++l)
                  {
                    hoop_row += C[2][2][b][l] * grad_N[w][l];
                    hoop_column += grad_N[v][l] * C[b][l][2][2];
                  }
                K_cell(row, column + b) += volume * N[v] / r * hoop_row;
                K_cell(row + b, column) += volume * hoop_column * N[w] / r;
              }
          }
    }



    /**
     * K_(v,a),(w,b) += Omega sum_kl dN_v/dx_k C_akbl dN_w/dx_l of one point,
     * as G^v_abl = Omega sum_k dN_v/dx_k C_akbl once per node v, then
     * sum_l G^v_abl dN_w/dx_l: dim^4 + stencil dim^3 multiply-adds per v
     * instead of stencil dim^4: in 3D 2,376 per point instead of 5,184
     * (timings in doc/example_polycrystal.md). 2D keeps the direct sum of
     * TangentAssembler::assemble() (192 against 256 per point), and with it
     * the last digits of the paper's compact-tension runs.
     */
    template <int dim>
    void
    add_point_stiffness_factored(const Tensor<1, dim> *grad_N,
                                 const unsigned int    stencil,
                                 const unsigned short *nodes,
                                 const Tensor<4, dim> &C,
                                 const double          volume,
                                 FullMatrix<double>   &K_cell)
    {
      for (unsigned int v = 0; v < stencil; ++v)
        {
          double G[dim][dim][dim];
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              for (unsigned int l = 0; l < dim; ++l)
                {
                  double sum = 0;
                  for (unsigned int k = 0; k < dim; ++k)
                    sum += grad_N[v][k] * C[a][k][b][l];
                  G[a][b][l] = volume * sum;
                }
          const unsigned int row = nodes[v] * dim;
          for (unsigned int w = 0; w < stencil; ++w)
            {
              const unsigned int column = nodes[w] * dim;
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  {
                    double sum = 0;
                    for (unsigned int l = 0; l < dim; ++l)
                      sum += G[a][b][l] * grad_N[w][l];
                    K_cell(row + a, column + b) += sum;
                  }
            }
        }
    }
  } // namespace



  template <int dim>
  void
  TangentAssembler<dim>::reinit(const BackgroundGrid<dim> &grid,
                                const bool                 gimp)
  {
    // Displacement conditions only fix values, but periodicity constraints
    // couple the nodes of opposite faces: condensing them adds the slave's
    // couplings to its master's row.
    periodicity.clear();
    periodicity.reinit(grid.locally_relevant_dofs());
    grid.make_periodicity_constraints(periodicity);
    periodicity.close();
    writable_rows = grid.locally_relevant_dofs();
    for (const auto &line : periodicity.get_lines())
      for (const auto &entry : line.entries)
        writable_rows.add_index(entry.first);
    writable_rows.compress();
    pattern_per_step = gimp;
    if (gimp)
      return;

    // Linear shape functions: the cell couplings serve every step.
    // With room for the 3^dim nodes a node couples with on a regular grid
    // (none on a rank that owns no rows: deal.II 9.4 then stops, reporting
    // more than 2^31 entries).
    const unsigned int row_length =
      grid.locally_owned_dofs().n_elements() > 0 ?
        grid.n_node_dofs() * Utilities::fixed_power<dim>(3u) :
        0;
    TrilinosWrappers::SparsityPattern pattern(grid.locally_owned_dofs(),
                                              grid.locally_owned_dofs(),
                                              writable_rows,
                                              grid.get_communicator(),
                                              row_length);
    // Periodicity constraints add the couplings across the period, which
    // DoFTools condenses into the masters' rows.
    if (periodicity.n_constraints() == 0)
      add_node_couplings(grid, pattern);
    else
      DoFTools::make_sparsity_pattern(grid.get_dof_handler(),
                                      pattern,
                                      periodicity,
                                      /*keep_constrained_dofs=*/true,
                                      dealii::Utilities::MPI::this_mpi_process(
                                        grid.get_communicator()));
    pattern.compress();
    K.reinit(pattern);
    ++n_patterns;
    // The rows of the pattern, which grew one by one while it was built,
    // are freed now that K holds them in one array.
    Utils::release_free_heap();
  }



  template <int dim>
  void
  TangentAssembler<dim>::make_step_pattern(
    const BackgroundGrid<dim> &grid,
    const ShapeCache<dim>     &cache,
    const GhostPenalty<dim>   *ghost_penalty)
  {
    // GIMP: the couplings of the nodes that the points of each cell reach
    // in this step. A pattern with every node of the 3^dim cells around
    // each cell would do for all steps, but it stores many zeros, which
    // AMG and its smoothers then treat as couplings.
    TrilinosWrappers::SparsityPattern    pattern(grid.locally_owned_dofs(),
                                              grid.locally_owned_dofs(),
                                              writable_rows,
                                              grid.get_communicator());
    std::vector<types::global_dof_index> dofs;
    const unsigned int                   n_node_dofs = grid.n_node_dofs();
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        if (n_node_dofs == dim)
          dofs.assign(cache.global_dofs(c),
                      cache.global_dofs(c) + cache.n_dofs(c));
        else
          {
            // Several bodies: the contact ties of a step couple a node's
            // dofs of all bodies (a node's dofs are consecutive, dim per
            // body), so every group couples its nodes' dofs of all bodies.
            dofs.clear();
            const types::global_dof_index *group = cache.global_dofs(c);
            const unsigned int             body  = cache.cell(c).body;
            for (unsigned int k = 0; k < cache.n_dofs(c); k += dim)
              for (unsigned int i = 0; i < n_node_dofs; ++i)
                dofs.push_back(group[k] - body * dim + i);
          }
        periodicity.add_entries_local_to_global(dofs,
                                                pattern,
                                                /*keep_constrained=*/true);
      }
    if (ghost_penalty != nullptr)
      ghost_penalty->add_couplings(periodicity, pattern);
    // Every row has its diagonal (nodes without points get one below).
    for (const auto dof : grid.locally_owned_dofs())
      pattern.add(dof, dof);
    pattern.compress();
    K.reinit(pattern);
    ++n_patterns;
  }



  template <int dim>
  void
  TangentAssembler<dim>::assemble(const BackgroundGrid<dim>       &grid,
                                  const MaterialPointSet<dim>     &points,
                                  const ShapeCache<dim>           &cache,
                                  const AffineConstraints<double> &constraints,
                                  const GhostPenalty<dim>      *ghost_penalty,
                                  const AdditionalTerm         &additional_term,
                                  const Tangent                 kind,
                                  const IterateKinematics<dim> *iterate,
                                  const bool                    fbar_terms)
  {
    CellTangents<dim> cell_tangents(points, kind, fbar_terms);

    if (pattern_per_step || ghost_penalty != nullptr)
      make_step_pattern(grid, cache, ghost_penalty);
    K = 0;
    FullMatrix<double>                       K_cell;
    std::vector<types::global_dof_index>     dofs;
    typename ShapeCache<dim>::GradientBuffer buffer;
    typename ShapeCache<dim>::ValueBuffer    values;
    typename ShapeCache<dim>::GradientBuffer spatial;
    const bool axisymmetric = points.get_formulation().axisymmetric;
    // F-bar: the stiffness of the mean volume change (FbarTerms), if asked
    // for; in axisymmetric problems with the 3D tangents' hoop entries,
    // which the matrix then takes in full.
    const bool     full_hoop = axisymmetric && fbar_terms;
    const bool     fbar      = fbar_terms && points.get_formulation().fbar();
    FbarTerms<dim> mean_volume_terms;
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        const unsigned int n_dofs = cache.n_dofs(c);
        K_cell.reinit(n_dofs, n_dofs);
        const auto &range = cache.cell(c);
        cell_tangents.reinit(cache, c, iterate);
        if (fbar)
          mean_volume_terms.reinit(cache, c, !cell_tangents.is_finite_strain());
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const unsigned int    i       = p - range.first_point;
            const unsigned int    stencil = cache.stencil_size(p);
            const Tensor<1, dim> *grad_N  = cell_tangents.spatial_gradients(
              i, cache.gradients(c, p, buffer), stencil, spatial.data());
            const unsigned short *nodes  = cache.nodes(p);
            const Tensor<4, dim> &C      = cell_tangents.C(i);
            const double          volume = cell_tangents.volume(i);
            if constexpr (dim == 3)
              add_point_stiffness_factored(
                grad_N, stencil, nodes, C, volume, K_cell);
            else
              // K_(v,a),(w,b) = Omega sum_kl dN_v/dx_k C_akbl dN_w/dx_l
              for (unsigned int v = 0; v < stencil; ++v)
                for (unsigned int w = 0; w < stencil; ++w)
                  for (unsigned int a = 0; a < dim; ++a)
                    for (unsigned int b = 0; b < dim; ++b)
                      {
                        double sum = 0;
                        for (unsigned int k = 0; k < dim; ++k)
                          for (unsigned int l = 0; l < dim; ++l)
                            sum += grad_N[v][k] * C[a][k][b][l] * grad_N[w][l];
                        K_cell(nodes[v] * dim + a, nodes[w] * dim + b) +=
                          volume * sum;
                      }
            const double *N =
              axisymmetric ? cache.values(c, p, values) : nullptr;
            const double r =
              axisymmetric ?
                cell_tangents.hoop_radius(i, cache.position(p)[0]) :
                0.;
            if (full_hoop)
              add_full_hoop_stiffness(N,
                                      grad_N,
                                      stencil,
                                      nodes,
                                      cell_tangents.hoop_tangent(i),
                                      volume,
                                      r,
                                      K_cell);
            else if (axisymmetric)
              add_hoop_stiffness(
                N, grad_N, stencil, nodes, C, volume, r, K_cell);
            // The point's weight in the mean: its volume at the step's
            // start, at a finite-strain iterate times det Delta F.
            const double weight =
              cache.properties(p)[points.get_offsets().volume] *
              cell_tangents.volume_ratio(i);
            if (fbar && full_hoop)
              {
                const Tensor<2, 3> tau =
                  cell_tangents.is_finite_strain() ?
                    cell_tangents.kirchhoff_stress_3d(i) :
                    Tensor<2, 3>();
                mean_volume_terms.add_point_axisymmetric(
                  N,
                  grad_N,
                  stencil,
                  nodes,
                  cell_tangents.hoop_tangent(i),
                  cell_tangents.is_finite_strain() ? &tau : nullptr,
                  r,
                  volume,
                  weight,
                  K_cell);
              }
            else if (fbar)
              mean_volume_terms.add_point(grad_N,
                                          stencil,
                                          nodes,
                                          C,
                                          cell_tangents.is_finite_strain() ?
                                            &cell_tangents.kirchhoff_stress(i) :
                                            nullptr,
                                          volume,
                                          weight,
                                          K_cell);
          }
        if (fbar)
          mean_volume_terms.add_cell(K_cell);
        dofs.assign(cache.global_dofs(c), cache.global_dofs(c) + n_dofs);
        constraints.distribute_local_to_global(K_cell, dofs, K);
      }
    if (ghost_penalty != nullptr)
      ghost_penalty->add_to(constraints, K);
    if (additional_term)
      additional_term(constraints, K);
    K.compress(VectorOperation::add);

    // Constrained dofs outside every cell with points (nodes without points)
    // got no entry at all: give them a diagonal of the matrix's scale.
    double diagonal_sum = 0, n_diagonal = 0;
    for (const auto dof : grid.locally_owned_dofs())
      if (!constraints.is_constrained(dof))
        {
          diagonal_sum += K.diag_element(dof);
          n_diagonal += 1;
        }
    diagonal_sum =
      dealii::Utilities::MPI::sum(diagonal_sum, grid.get_communicator());
    n_diagonal =
      dealii::Utilities::MPI::sum(n_diagonal, grid.get_communicator());
    const double scale = n_diagonal > 0 ? diagonal_sum / n_diagonal : 1.;
    for (const auto dof : grid.locally_owned_dofs())
      if (constraints.is_constrained(dof) && K.diag_element(dof) == 0.)
        K.set(dof, dof, scale);
    K.compress(VectorOperation::insert);
  }



  template <int dim>
  void
  TangentAssembler<dim>::assemble_diagonal(
    const MaterialPointSet<dim>   &points,
    const ShapeCache<dim>         &cache,
    TrilinosWrappers::MPI::Vector &diagonal)
  {
    CellTangents<dim> cell_tangents(points);

    diagonal = 0.;
    std::vector<double> cell_diagonal(ShapeCache<dim>::max_dofs_per_group);
    typename ShapeCache<dim>::GradientBuffer buffer;
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        std::fill(cell_diagonal.begin(),
                  cell_diagonal.begin() + cache.n_dofs(c),
                  0.);
        const auto &range = cache.cell(c);
        cell_tangents.reinit(cache, c);
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const Tensor<1, dim> *grad_N = cache.gradients(c, p, buffer);
            const unsigned short *nodes  = cache.nodes(p);
            const Tensor<4, dim> &C = cell_tangents.C(p - range.first_point);
            const double volume = cell_tangents.volume(p - range.first_point);
            // K_(v,a),(v,a) = Omega sum_kl dN_v/dx_k C_akal dN_v/dx_l
            for (unsigned int v = 0; v < cache.stencil_size(p); ++v)
              for (unsigned int a = 0; a < dim; ++a)
                {
                  double sum = 0;
                  for (unsigned int k = 0; k < dim; ++k)
                    for (unsigned int l = 0; l < dim; ++l)
                      sum += grad_N[v][k] * C[a][k][a][l] * grad_N[v][l];
                  cell_diagonal[nodes[v] * dim + a] += volume * sum;
                }
          }
        diagonal.add(cache.n_dofs(c),
                     cache.global_dofs(c),
                     cell_diagonal.data());
      }
    diagonal.compress(VectorOperation::add);
  }



  template <int dim>
  const TrilinosWrappers::SparseMatrix &
  TangentAssembler<dim>::matrix() const
  {
    return K;
  }



  template class TangentAssembler<2>;
  template class TangentAssembler<3>;
} // namespace qsmpm
