#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/porous/pore_pressure_solver.h>
#include <tuple>

namespace qsmpm
{
  template <int dim>
  void
  PorePressureSolver<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Pore fluid");
    {
      prm.add_parameter("Enabled",
                        enabled,
                        "Saturated porous body: a pore pressure p on the "
                        "grid, Darcy flow, effective stress sigma = sigma' - "
                        "b p I (the material model is the skeleton's). The "
                        "load factor is the time (s): each load step is a "
                        "time step of implicit Euler. Small or finite strain, "
                        "linear or GIMP shape functions.",
                        Patterns::Bool());
      prm.add_parameter("Biot coefficient",
                        biot_coefficient,
                        "b in (0, 1]; 1 for incompressible grains.",
                        Patterns::Double(0.));
      prm.add_parameter("Biot modulus",
                        biot_modulus,
                        "M (stress): 1/M = n/K_f + (b - n)/K_s, the storage "
                        "of the pore space per unit pressure. 0: "
                        "incompressible grains and fluid (1/M = 0).",
                        Patterns::Double(0.));
      prm.add_parameter("Mobility",
                        mobility,
                        "kappa = k / mu_f (area / (stress time)): the "
                        "permeability over the fluid's viscosity, or the "
                        "hydraulic conductivity over the fluid's unit "
                        "weight; Darcy flux q = -kappa grad p.",
                        Patterns::Double(0.));
      prm.add_parameter(
        "Mobility by material id",
        mobility_by_material_id,
        "Mobilities of particular material ids (Material points/<Material "
        "id>), as 'id: mobility, id: mobility', e.g. '0: 1e-9, 1: 1e-5' "
        "for a clay (id 0) under a sand (id 1); points of other ids have "
        "<Mobility>. Each is multiplied by <Mobility factor> as <Mobility> "
        "is.",
        Patterns::Map(Patterns::Integer(0),
                      Patterns::Double(0.),
                      0,
                      Patterns::Map::max_int_value,
                      ",",
                      ":"));
      prm.add_parameter(
        "Mobility factor",
        mobility_factor,
        "f(J): the mobility of a point is <Mobility> times this expression "
        "in J, the point's volume ratio det F (V / V_0) at the start of "
        "the step, so that the permeability follows the compaction at "
        "finite strain; e.g. Kozeny-Carman with the initial porosity n0 = "
        "0.4, n = 1 - (1 - n0) / J: '(1 - 0.6/J)^3 / (0.6/J)^2 * 0.36 / "
        "0.064'. It must be positive at every point. 1: a constant "
        "mobility.",
        Patterns::Anything());
      prm.add_parameter("Initial pore pressure",
                        initial_pressure,
                        "p of every point at the start (stress units).",
                        Patterns::Double());
      prm.add_parameter("Drained boundaries",
                        drained_boundaries,
                        "Boundary ids of the grid where p is prescribed, as "
                        "<Boundary pore pressure> (box: 0/1 = x min/max, 2/3 "
                        "= y, 4/5 = z). Boundaries that are neither drained "
                        "nor in <Flux boundaries> are impermeable; nodes of "
                        "the grid without material have p = 0.",
                        Patterns::List(Patterns::Integer(0)));
      prm.add_parameter("Boundary pore pressure",
                        boundary_pressure,
                        "p on the drained boundaries: an expression in x, y "
                        "(z) and the time t.",
                        Patterns::Anything());
      prm.add_parameter(
        "Drained surface region",
        drained_surface_region,
        "Where the body's own surface is drained, at the pressure "
        "<Boundary pore pressure>: an expression in x, y (z), non-zero on "
        "the drained part of the initial surface (found from the points as "
        "for Boundary conditions/Surface traction region), e.g. 'y > 9.99'. "
        "The surface follows the body, at small and finite strain: a free "
        "surface inside the grid, or one that settles away from a grid "
        "face. The pressure is held there by a penalty (<Drained surface "
        "penalty>). Empty: none.",
        Patterns::Anything());
      prm.add_parameter(
        "Drained surface penalty",
        drained_surface_penalty,
        "f of the penalty gamma = f kappa / h of the drained surface: the "
        "surface passes the flux gamma (p - p_b), so that p exceeds p_b by "
        "the flux times h / (f kappa), 1/f of a cell's pressure drop.",
        Patterns::Double(0.));
      prm.add_parameter("Flux boundaries",
                        flux_boundaries,
                        "Boundary ids of the grid through which the fluid "
                        "flows at the rate <Boundary flux>.",
                        Patterns::List(Patterns::Integer(0)));
      prm.add_parameter("Boundary flux",
                        boundary_flux,
                        "q.n on the flux boundaries, the volume of fluid "
                        "that leaves per unit area and time (negative: "
                        "inflow): an expression in x, y (z) and t.",
                        Patterns::Anything());
      prm.add_parameter("Stabilization factor",
                        stabilization_factor,
                        "f of the stabilization beta = f h^2 / M_c of the "
                        "equal-order pressure (Rodrigo et al. 2016; M_c the "
                        "constrained modulus of the skeleton, h the cell "
                        "size); 1/4 removes the overshoot of the pressure "
                        "after a sudden load on Terzaghi's column; 0 "
                        "switches it off.",
                        Patterns::Double(0.));
      prm.add_parameter(
        "Coupling",
        coupling,
        "How a step couples the displacement and the pressure. "
        "fixed-stress: the fixed-stress split, flow and displacement "
        "solved in turn until the pressure stops changing (Coupling "
        "tolerance). monolithic: Newton-Krylov on both fields at once, "
        "GMRES preconditioned block-triangularly with the displacement's "
        "preconditioner and one AMG cycle of the fixed-stress Schur "
        "complement (its L from Fixed-stress factor); its stopping test is "
        "Nonlinear solver/Tolerance. Same answers; monolithic took "
        "0.6-0.85 of the time on the consolidation problems of "
        "doc/example_consolidation.md (1 and 2 ranks) and converges where "
        "the split needs a larger Fixed-stress factor, but 1.6 times as "
        "long for an undrained footing loaded to collapse.",
        Patterns::Selection("fixed-stress|monolithic"));
      prm.add_parameter(
        "Fixed-stress factor",
        fixed_stress_factor,
        "f >= 1 of the fixed-stress split: each point's pore volume "
        "responds to the pressure change of an iteration with f b^2 / K, K "
        "the drained bulk modulus of the skeleton's tangent at the start "
        "of the step (the elastic one for the plastic models). 1 is the "
        "classical choice; a skeleton that compacts plastically is softer "
        "than that K, and the iteration then needs more: Modified Cam Clay "
        "undrained (doc/example_triaxial.md) diverges with 1 and takes 8 "
        "iterations per step with 2.",
        Patterns::Double(1.));
      prm.add_parameter(
        "Coupling tolerance",
        coupling_tolerance,
        "The fixed-stress iteration of a step stops when no "
        "nodal pressure changes by more than this times the "
        "largest nodal pressure or stress component at the "
        "start of the step, whichever is larger (the stress the loads have "
        "added: without Material points/Initial stress and its Cam Clay "
        "-p0 I). Each displacement solve after the step's first reduces "
        "the forces of the pressure change by 1e-2, down to 1e-12 of the "
        "forces in the body, so that this may be far below Nonlinear "
        "solver/Tolerance (1e-8 converges on Terzaghi's column). The "
        "remainders add up over the steps: many short steps need a "
        "smaller value. With Coupling = monolithic there is no such "
        "iteration; the Newton solve of a step then stops at Nonlinear "
        "solver/Tolerance, but not below 1e-2 of this times the forces in "
        "the body.",
        Patterns::Double(0.));
      prm.add_parameter("Maximum coupling iterations",
                        max_coupling_iterations,
                        "Fixed-stress iterations of a step before it counts "
                        "as not converged (and is cut back).",
                        Patterns::Integer(1));
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  PorePressureSolver<dim>::Parameters::check() const
  {
    if (!enabled)
      return;
    AssertThrow(biot_coefficient > 0. && biot_coefficient <= 1.,
                ExcMessage("Pore fluid: <Biot coefficient> must lie in (0, "
                           "1]."));
    AssertThrow(mobility > 0.,
                ExcMessage("Pore fluid: <Mobility> must be positive (an "
                           "impermeable body is undrained: give a small "
                           "mobility or no pore fluid)."));
    for (const auto &[id, value] : mobility_by_material_id)
      AssertThrow(value > 0.,
                  ExcMessage("Pore fluid: <Mobility by material id> gives "
                             "material id " +
                             std::to_string(id) + " the mobility " +
                             std::to_string(value) + "; it must be positive."));
    AssertThrow(coupling_tolerance > 0.,
                ExcMessage("Pore fluid: <Coupling tolerance> must be "
                           "positive."));
    for (const unsigned int id : flux_boundaries)
      {
        AssertThrow(id < 2 * dim,
                    ExcMessage("Pore fluid: <Flux boundaries> lists " +
                               std::to_string(id) + ", but a box in " +
                               std::to_string(dim) +
                               "D has the boundary ids 0 to " +
                               std::to_string(2 * dim - 1) + "."));
        AssertThrow(std::find(drained_boundaries.begin(),
                              drained_boundaries.end(),
                              id) == drained_boundaries.end(),
                    ExcMessage("Pore fluid: boundary " + std::to_string(id) +
                               " is in both <Drained boundaries> and <Flux "
                               "boundaries>."));
      }
    for (const unsigned int id : drained_boundaries)
      AssertThrow(id < 2 * dim,
                  ExcMessage("Pore fluid: <Drained boundaries> lists " +
                             std::to_string(id) + ", but a box in " +
                             std::to_string(dim) +
                             "D has the boundary ids 0 "
                             "to " +
                             std::to_string(2 * dim - 1) + "."));
  }



  template <int dim>
  PorePressureSolver<dim>::PorePressureSolver(const Parameters &parameters,
                                              const MPI_Comm    comm)
    : parameters(parameters)
    , communicator(comm)
    , fe(1)
  {
    try
      {
        mobility_factor.initialize("J", parameters.mobility_factor, {});
        mobility_factor.value(Point<1>(1.));
      }
    catch (const std::exception &exc)
      {
        AssertThrow(false,
                    ExcMessage("Pore fluid: <Mobility factor> = <" +
                               parameters.mobility_factor +
                               ">: " + Utils::error_message(exc)));
      }
    const std::string variables = dim == 2 ? "x,y,t" : "x,y,z,t";
    for (const auto &[function, expression, entry] :
         {std::make_tuple(&boundary_pressure,
                          parameters.boundary_pressure,
                          "Boundary pore pressure"),
          std::make_tuple(&boundary_flux,
                          parameters.boundary_flux,
                          "Boundary flux")})
      try
        {
          function->initialize(variables, expression, {}, true);
          function->value(Point<dim>());
        }
      catch (const std::exception &exc)
        {
          AssertThrow(false,
                      ExcMessage(std::string("Pore fluid: <") + entry +
                                 "> = <" + expression +
                                 ">: " + Utils::error_message(exc)));
        }
  }



  namespace
  {
    /// sum_ij C_iijj / dim^2: the drained bulk modulus of the tangent (in 2D
    /// the plane-strain one, lambda + mu).
    template <int dim>
    double
    bulk_modulus(const SymmetricTensor<4, dim> &C)
    {
      double K = 0.;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          K += C[i][i][j][j];
      return K / (dim * dim);
    }

    /// The mean of C_dddd: the constrained modulus (lambda + 2 mu).
    template <int dim>
    double
    constrained_modulus(const SymmetricTensor<4, dim> &C)
    {
      double M = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        M += C[d][d][d][d];
      return M / dim;
    }
  } // namespace



  template <int dim>
  void
  PorePressureSolver<dim>::begin_step(const BackgroundGrid<dim>   &grid,
                                      const ShapeCache<dim>       &cache,
                                      MaterialPointSet<dim>       &points,
                                      const PoroelasticModel<dim> &model,
                                      const double                 t_old,
                                      const double                 t_new)
  {
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;

    dt = t_new - t_old;
    AssertThrow(dt >= 0.,
                ExcMessage("Pore fluid: the load factor is the time and must "
                           "not decrease."));
    b            = model.biot_coefficient();
    state_offset = points.get_offsets().state + model.pressure_offset();
    initial_stress_offset =
      points.get_offsets().state + model.initial_stress_offset();

    const auto &tria = grid.get_triangulation();
    dof_handler.reinit(tria);
    dof_handler.distribute_dofs(fe);
    owned    = dof_handler.locally_owned_dofs();
    relevant = DoFTools::extract_locally_relevant_dofs(dof_handler);

    // The nodes whose support holds material on some rank.
    TrilinosWrappers::MPI::Vector        has_material(owned, communicator);
    std::vector<types::global_dof_index> dofs(n_vertices);
    const unsigned int                   n_points = cache.n_points();
    volume.resize(n_points);
    mobility.resize(n_points);
    fixed_stress.resize(n_points);
    stabilization.resize(n_points);
    finite_strain                  = points.get_formulation().finite_strain();
    axisymmetric                   = points.get_formulation().axisymmetric;
    const bool   constant_mobility = parameters.mobility_factor == "1";
    const double h                 = grid.min_cell_size();
    cell_size                      = h;
    stress_scale                   = 0.;
    double largest_modulus         = 0.;

    const auto                                 &offsets = points.get_offsets();
    const typename PointStateBatch<dim>::Layout layout{
      offsets.strain,
      offsets.stress,
      offsets.volume,
      offsets.material_id,
      offsets.state,
      model.n_state_components()};
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        const auto                &range = cache.cell(c);
        const PointStateBatch<dim> batch(layout,
                                         cache.property_arrays(
                                           range.first_point),
                                         &cache.position(range.first_point),
                                         range.end_point - range.first_point);
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            double                       *data = cache.properties(p, points);
            const SymmetricTensor<4, dim> C =
              model.tangent(batch[p - range.first_point]);
            const double K  = bulk_modulus(C);
            const double Mc = constrained_modulus(C);
            AssertThrow(K > 0. && Mc > 0.,
                        ExcMessage("Pore fluid: the skeleton's tangent has no "
                                   "positive bulk modulus."));
            // The stress the loads have added: a geostatic stress far
            // above the load's would otherwise set the scale, and the
            // iteration would stop with the load's pressures still moving
            // (a Cam Clay column at p0 = 200 dq consolidated 6 % of dq
            // away from Terzaghi's).
            for (unsigned int k = 0;
                 k < SymmetricTensor<2, dim>::n_independent_components;
                 ++k)
              stress_scale =
                std::max(stress_scale,
                         std::abs(data[offsets.stress + k] -
                                  data[initial_stress_offset + k]));
            stress_scale = std::max(stress_scale, std::abs(data[state_offset]));
            volume[p]    = data[offsets.volume];
            mobility[p]  = parameters.mobility;
            if (!parameters.mobility_by_material_id.empty())
              {
                const auto found = parameters.mobility_by_material_id.find(
                  static_cast<unsigned int>(data[offsets.material_id]));
                if (found != parameters.mobility_by_material_id.end())
                  mobility[p] = found->second;
              }
            if (!constant_mobility)
              {
                const double J = data[offsets.J];
                const double f = mobility_factor.value(Point<1>(J));
                AssertThrow(f > 0. && std::isfinite(f),
                            ExcMessage("Pore fluid: <Mobility factor> = <" +
                                       parameters.mobility_factor + "> is " +
                                       std::to_string(f) +
                                       " at J = " + std::to_string(J) +
                                       "; it must be positive."));
                mobility[p] *= f;
              }
            fixed_stress[p]  = parameters.fixed_stress_factor * b * b / K;
            stabilization[p] = parameters.stabilization_factor * h * h / Mc;
            largest_modulus  = std::max(largest_modulus, Mc);
            // The iteration starts from the committed pressure (also after
            // a cut-back).
            double *state = data + state_offset;
            state[1]      = state[0];
            for (unsigned int d = 0; d < dim; ++d)
              state[2 + dim + d] = state[2 + d];
          }
      }
    stress_scale = Utilities::MPI::max(stress_scale, communicator);
    modulus_scale =
      Utilities::MPI::max(largest_modulus, communicator) / cell_size;
    forces = stress_scale * std::pow(h, dim - 1) *
             std::sqrt(static_cast<double>(grid.get_dof_handler().n_dofs()));
    collect_group_dofs(grid, cache);
    // Ghost nodes of other ranks' cells reach the owner by the sum.
    {
      TrilinosWrappers::MPI::Vector sums;
      sums.reinit(owned, relevant, communicator, true);
      for (const auto dof : group_dofs)
        sums(dof) += 1.;
      sums.compress(VectorOperation::add);
      has_material = sums;
    }
    TrilinosWrappers::MPI::Vector material_ghosted(owned,
                                                   relevant,
                                                   communicator);
    material_ghosted = has_material;

    constraints.clear();
    constraints.reinit(relevant);
    for (const auto dof : relevant)
      if (material_ghosted(dof) == 0.)
        constraints.add_line(dof);
    for (const unsigned int id : parameters.drained_boundaries)
      {
        // A drained boundary that no material touches drains nothing: a
        // wrong id, or a body that has left that side of the grid.
        std::map<types::global_dof_index, double> values;
        boundary_pressure.set_time(t_new);
        VectorTools::interpolate_boundary_values(dof_handler,
                                                 id,
                                                 boundary_pressure,
                                                 values);
        double touched = 0.;
        for (const auto &[dof, value] : values)
          if (material_ghosted(dof) > 0.)
            {
              touched = 1.;
              if (!constraints.is_constrained(dof))
                {
                  constraints.add_line(dof);
                  constraints.set_inhomogeneity(dof, value);
                }
            }
        AssertThrow(Utilities::MPI::max(touched, communicator) > 0.,
                    ExcMessage("Pore fluid: <Drained boundaries> lists " +
                               std::to_string(id) +
                               ", but no material touches that boundary of "
                               "the grid."));
      }
    constraints.close();

    TrilinosWrappers::SparsityPattern pattern(owned,
                                              owned,
                                              relevant,
                                              communicator);
    DoFTools::make_sparsity_pattern(dof_handler, pattern, constraints, false);
    // GIMP couples the nodes of the 3^dim cells around a point's cell.
    if (cache.stencil_size() != n_vertices)
      for (unsigned int c = 0; c < cache.n_cells(); ++c)
        {
          dofs.assign(group_dofs.begin() + group_offsets[c],
                      group_dofs.begin() + group_offsets[c + 1]);
          constraints.add_entries_local_to_global(dofs, pattern, false);
        }
    pattern.compress();
    matrix.reinit(pattern);

    // The matrix of the step (storage, fixed-stress and stabilization terms
    // and the conductance) and the part of the right-hand side that stays
    // the same in all its iterations: the fluxes and, through the matrix,
    // the prescribed pressures.
    // With linear shape functions a group's nodes are its cell's vertices
    // in deal.II's order, so that the fluxes of the cell's faces join the
    // group's right-hand side; with GIMP they are added on their own.
    boundary_rhs.reinit(owned, communicator);
    const bool         vertex_groups = cache.stencil_size() == n_vertices;
    FullMatrix<double> local_matrix;
    Vector<double>     local_rhs, flux_rhs(n_vertices);
    std::vector<types::global_dof_index> vertex_dofs(n_vertices);
    const QGauss<dim - 1>                face_quadrature(2);
    FEFaceValues<dim>                    face_values(fe,
                                  face_quadrature,
                                  update_values | update_quadrature_points |
                                    update_JxW_values);
    boundary_flux.set_time(t_new);
    boundary_pressure.set_time(t_new);
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        const auto &range = cache.cell(c);
        const typename DoFHandler<dim>::active_cell_iterator cell(
          &tria, range.cell->level(), range.cell->index(), &dof_handler);
        dofs.assign(group_dofs.begin() + group_offsets[c],
                    group_dofs.begin() + group_offsets[c + 1]);
        group_matrix(cache, c, local_matrix);
        local_rhs.reinit(dofs.size());
        if (vertex_groups)
          add_boundary_flux(cell, face_values, local_rhs);
        constraints.distribute_local_to_global(
          local_matrix, local_rhs, dofs, matrix, boundary_rhs);
        if (!vertex_groups)
          {
            flux_rhs = 0.;
            add_boundary_flux(cell, face_values, flux_rhs);
            if (flux_rhs.l2_norm() > 0.)
              {
                cell->get_dof_indices(vertex_dofs);
                constraints.distribute_local_to_global(flux_rhs,
                                                       vertex_dofs,
                                                       boundary_rhs);
              }
          }
      }
    if (drained_surface != numbers::invalid_unsigned_int)
      add_drained_surface(cache, points);
    matrix.compress(VectorOperation::add);
    boundary_rhs.compress(VectorOperation::add);

    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    data.smoother_sweeps       = 2;
    amg.initialize(matrix, data);

    p_owned.reinit(owned, communicator);
    rhs.reinit(owned, communicator);
    p_ghosted.reinit(owned, relevant, communicator);
    ghost_import =
      std::make_unique<Epetra_Import>(p_ghosted.trilinos_vector().Map(),
                                      p_owned.trilinos_vector().Map());

    // Where each group node's pressure lives in the relevant set, found
    // once per step instead of looking the global index up for every
    // point: the position in p_ghosted's local array too (its map lists
    // the relevant set in order) and in the sums of assemble_rhs().
    group_relevant_entry.resize(group_dofs.size());
    for (unsigned int k = 0; k < group_dofs.size(); ++k)
      {
        group_relevant_entry[k] = relevant.index_within_set(group_dofs[k]);
        Assert(p_ghosted.trilinos_partitioner().LID(
                 static_cast<TrilinosWrappers::types::int_type>(
                   group_dofs[k])) == static_cast<int>(group_relevant_entry[k]),
               ExcInternalError());
      }
    relevant_sums.assign(relevant.n_elements(), 0.);
    relevant_owned_entry.assign(relevant.n_elements(), -1);
    ghost_entries.clear();
    ghost_dofs.clear();
    for (unsigned int k = 0; k < relevant.n_elements(); ++k)
      {
        const types::global_dof_index dof = relevant.nth_index_in_set(k);
        if (owned.is_element(dof))
          relevant_owned_entry[k] = rhs.trilinos_partitioner().LID(
            static_cast<TrilinosWrappers::types::int_type>(dof));
        else
          {
            ghost_entries.push_back(k);
            ghost_dofs.push_back(dof);
          }
      }
    ghost_sums.resize(ghost_entries.size());

    // What the committed state contributes to the flow's right-hand side,
    // sum_p Omega_p (p_n / M N_i + beta_p grad N_i . grad p_n): the same in
    // every evaluation of the step.
    {
      const double inverse_M = parameters.inverse_biot_modulus();
      typename ShapeCache<dim>::ValueBuffer    N_buffer;
      typename ShapeCache<dim>::GradientBuffer grad_buffer;
      step_sums.assign(relevant.n_elements(), 0.);
      for (unsigned int c = 0; c < cache.n_cells(); ++c)
        {
          const auto         &range = cache.cell(c);
          const unsigned int *entry = &group_relevant_entry[group_offsets[c]];
          for (unsigned int p = range.first_point; p < range.end_point; ++p)
            {
              const double         *N     = cache.values(c, p, N_buffer);
              const Tensor<1, dim> *gradN = cache.gradients(c, p, grad_buffer);
              const unsigned short *nodes = cache.nodes(p);
              const double         *state = cache.properties(p) + state_offset;
              Tensor<1, dim>        grad_p_n;
              for (unsigned int d = 0; d < dim; ++d)
                grad_p_n[d] = state[2 + d];
              for (unsigned int i = 0; i < cache.stencil_size(p); ++i)
                step_sums[entry[nodes[i]]] +=
                  volume[p] * (inverse_M * state[0] * N[i] +
                               stabilization[p] * (gradN[i] * grad_p_n));
            }
        }
    }
  }



  template <int dim>
  void
  PorePressureSolver<dim>::collect_group_dofs(const BackgroundGrid<dim> &grid,
                                              const ShapeCache<dim>     &cache)
  {
    // Node k of a group is the node of its displacement dofs k dim, ...,
    // k dim + dim - 1 (ShapeCache): the pressure dof of a group node is
    // found through the vertex that both dofs belong to. On a multi-field
    // grid (Contact between bodies) each body's field has its own dofs at
    // a vertex (body b's first direction is the vertex's dof b dim), and
    // all of them lead to the vertex's one pressure: the bodies share
    // their pore fluid.
    relevant_displacement             = grid.locally_relevant_dofs();
    const IndexSet &displacement_dofs = relevant_displacement;
    pressure_at.assign(displacement_dofs.n_elements(),
                       numbers::invalid_dof_index);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          const auto displacement_cell = grid.dof_cell(cell);
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int b = 0; b < grid.n_bodies(); ++b)
              pressure_at[displacement_dofs.index_within_set(
                displacement_cell->vertex_dof_index(v, b * dim))] =
                cell->vertex_dof_index(v, 0);
        }

    group_offsets.resize(cache.n_cells() + 1);
    group_offsets[0] = 0;
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      group_offsets[c + 1] = group_offsets[c] + cache.n_dofs(c) / dim;
    group_dofs.resize(group_offsets.back());
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        const types::global_dof_index *displacement = cache.global_dofs(c);
        for (unsigned int k = 0; k < group_offsets[c + 1] - group_offsets[c];
             ++k)
          {
            const types::global_dof_index dof =
              pressure_at[displacement_dofs.index_within_set(
                displacement[k * dim])];
            AssertThrow(dof != numbers::invalid_dof_index, ExcInternalError());
            group_dofs[group_offsets[c] + k] = dof;
          }
      }
  }



  template <int dim>
  void
  PorePressureSolver<dim>::group_matrix(const ShapeCache<dim> &cache,
                                        const unsigned int     c,
                                        FullMatrix<double>    &matrix) const
  {
    const double inverse_M = parameters.inverse_biot_modulus();
    typename ShapeCache<dim>::ValueBuffer    N_buffer;
    typename ShapeCache<dim>::GradientBuffer grad_buffer;
    const auto                              &range = cache.cell(c);
    const unsigned int n_nodes = group_offsets[c + 1] - group_offsets[c];
    matrix.reinit(n_nodes, n_nodes);
    for (unsigned int p = range.first_point; p < range.end_point; ++p)
      {
        const double         *N     = cache.values(c, p, N_buffer);
        const Tensor<1, dim> *gradN = cache.gradients(c, p, grad_buffer);
        const unsigned short *nodes = cache.nodes(p);
        const unsigned int    n     = cache.stencil_size(p);
        const double storage        = volume[p] * (inverse_M + fixed_stress[p]);
        const double conductance =
          volume[p] * (dt * mobility[p] + stabilization[p]);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            matrix(nodes[i], nodes[j]) +=
              storage * N[i] * N[j] + conductance * (gradN[i] * gradN[j]);
      }
  }



  template <int dim>
  void
  PorePressureSolver<dim>::add_drained_surface(
    const ShapeCache<dim>       &cache,
    const MaterialPointSet<dim> &points)
  {
    // SurfaceTractions has found each point's faces' centre x_f and the Q1
    // values there, on the displacement dofs of the cell that carries its
    // load; its component-0 dofs are the cell's vertices.
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    const unsigned int     area_offset =
      points.get_offsets().surface_load + drained_surface * (2 * dim + 1);
    FullMatrix<double>                   local_matrix(n_vertices, n_vertices);
    Vector<double>                       local_rhs(n_vertices);
    std::vector<types::global_dof_index> dofs(n_vertices);
    std::array<double, n_vertices>       N;
    surface_tractions->for_each_load(
      drained_surface,
      [&](const unsigned int             p,
          const Point<dim>              &x_f,
          const types::global_dof_index *displacement,
          const double                  *values,
          const unsigned int            *components) {
        unsigned int v = 0;
        for (unsigned int i = 0; i < n_vertices * dim; ++i)
          if (components[i] == 0)
            {
              dofs[v] = pressure_at[relevant_displacement.index_within_set(
                displacement[i])];
              N[v]    = values[i];
              ++v;
            }
        // The current area |n da| (A_0 at small strain).
        const double  *data = cache.properties(p);
        Tensor<1, dim> a;
        for (unsigned int d = 0; d < dim; ++d)
          a[d] = data[area_offset + 1 + d];
        const double area  = finite_strain ? a.norm() : data[area_offset];
        const double gamma = parameters.drained_surface_penalty * mobility[p] /
                             cell_size * dt * area;
        const double p_b = boundary_pressure.value(x_f);
        for (unsigned int i = 0; i < n_vertices; ++i)
          {
            local_rhs(i) = gamma * N[i] * p_b;
            for (unsigned int j = 0; j < n_vertices; ++j)
              local_matrix(i, j) = gamma * N[i] * N[j];
          }
        constraints.distribute_local_to_global(
          local_matrix, local_rhs, dofs, matrix, boundary_rhs);
      });
  }



  template <int dim>
  void
  PorePressureSolver<dim>::add_boundary_flux(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    FEFaceValues<dim>                                    &face_values,
    Vector<double>                                       &cell_rhs) const
  {
    if (parameters.flux_boundaries.empty() || !cell->at_boundary())
      return;
    for (const unsigned int f : cell->face_indices())
      if (cell->at_boundary(f) && std::find(parameters.flux_boundaries.begin(),
                                            parameters.flux_boundaries.end(),
                                            cell->face(f)->boundary_id()) !=
                                    parameters.flux_boundaries.end())
        {
          face_values.reinit(cell, f);
          for (const unsigned int q : face_values.quadrature_point_indices())
            {
              const Point<dim> &x    = face_values.quadrature_point(q);
              const double      flux = boundary_flux.value(x);
              // Axisymmetric: per radian, r dGamma.
              const double area =
                face_values.JxW(q) * (axisymmetric ? x[0] : 1.);
              for (unsigned int i = 0; i < cell_rhs.size(); ++i)
                cell_rhs(i) -= dt * flux * face_values.shape_value(i, q) * area;
            }
        }
  }



  template <int dim>
  void
  PorePressureSolver<dim>::assemble_rhs(
    const ShapeCache<dim>               &cache,
    const TrilinosWrappers::MPI::Vector &du_ghosted,
    const bool                           coupling_only,
    TrilinosWrappers::MPI::Vector       &vector) const
  {
    typename ShapeCache<dim>::ValueBuffer    N_buffer;
    typename ShapeCache<dim>::GradientBuffer grad_buffer;
    const double *du = du_ghosted.trilinos_vector()[0];

    // The sums over the points, per locally relevant node, then into the
    // owners' entries (the ghost nodes' through the vector's exchange);
    // the right-hand side starts from the step's part.
    if (coupling_only)
      std::fill(relevant_sums.begin(), relevant_sums.end(), 0.);
    else
      relevant_sums = step_sums;
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        const auto         &range = cache.cell(c);
        const int          *local = cache.local_dofs(c);
        const unsigned int *entry = &group_relevant_entry[group_offsets[c]];
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const double         *N     = cache.values(c, p, N_buffer);
            const Tensor<1, dim> *gradN = cache.gradients(c, p, grad_buffer);
            const unsigned short *nodes = cache.nodes(p);
            const unsigned int    n     = cache.stencil_size(p);
            // The volume change of the step over the volume at its start:
            // tr(grad du) at small strain, det(I + grad du) - 1 at finite
            // strain (and its linearization at du = 0, tr(grad du), for
            // the coupling alone). Axisymmetric, the hoop strain du_r / r
            // joins the trace, the hoop stretch 1 + du_r / r the
            // determinant (r the point's radius at the step's start, as in
            // QuasiStaticResidual).
            double hoop = 0.;
            if (axisymmetric)
              {
                for (unsigned int k = 0; k < n; ++k)
                  hoop += N[k] * du[local[nodes[k] * dim]];
                hoop /= cache.position(p)[0];
              }
            double eps_v = 0.;
            if (finite_strain && !coupling_only)
              {
                Tensor<2, dim> delta_F = unit_symmetric_tensor<dim>();
                for (unsigned int k = 0; k < n; ++k)
                  for (unsigned int d = 0; d < dim; ++d)
                    delta_F[d] += du[local[nodes[k] * dim + d]] * gradN[k];
                eps_v = determinant(delta_F) * (1. + hoop) - 1.;
              }
            else
              {
                eps_v = hoop;
                for (unsigned int k = 0; k < n; ++k)
                  for (unsigned int d = 0; d < dim; ++d)
                    eps_v += gradN[k][d] * du[local[nodes[k] * dim + d]];
              }
            // The coupling B du, or the iterate's fixed-stress storage
            // less the skeleton's volume change.
            const double source =
              coupling_only ?
                volume[p] * b * eps_v :
                volume[p] *
                  (fixed_stress[p] * (cache.properties(p) + state_offset)[1] -
                   b * eps_v);
            for (unsigned int i = 0; i < n; ++i)
              relevant_sums[entry[nodes[i]]] += source * N[i];
          }
      }
    // Every owned vector of the step has the layout of rhs (the entries
    // relevant_owned_entry points to).
    AssertDimension(vector.locally_owned_size(), owned.n_elements());
    vector         = 0.;
    double *values = vector.trilinos_vector()[0];
    for (unsigned int k = 0; k < relevant_sums.size(); ++k)
      if (relevant_owned_entry[k] >= 0)
        values[relevant_owned_entry[k]] += relevant_sums[k];
    for (unsigned int g = 0; g < ghost_entries.size(); ++g)
      ghost_sums[g] = relevant_sums[ghost_entries[g]];
    vector.add(ghost_dofs, ghost_sums);
    vector.compress(VectorOperation::add);
    // The constrained rows have no equation (as distribute_local_to_global()
    // would have dropped them); the boundary part gives them theirs.
    constraints.set_zero(vector);
    if (!coupling_only)
      vector += boundary_rhs;
  }



  template <int dim>
  void
  PorePressureSolver<dim>::interpolate_to_points(const ShapeCache<dim> &cache,
                                                 MaterialPointSet<dim> &points)
  {
    typename ShapeCache<dim>::ValueBuffer    N_buffer;
    typename ShapeCache<dim>::GradientBuffer grad_buffer;
    std::vector<double>                      nodal;
    for (unsigned int c = 0; c < cache.n_cells(); ++c)
      {
        const auto &range = cache.cell(c);
        nodal.resize(group_offsets[c + 1] - group_offsets[c]);
        const double *ghosted = p_ghosted.trilinos_vector()[0];
        for (unsigned int k = 0; k < nodal.size(); ++k)
          nodal[k] = ghosted[group_relevant_entry[group_offsets[c] + k]];
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const double         *N     = cache.values(c, p, N_buffer);
            const Tensor<1, dim> *gradN = cache.gradients(c, p, grad_buffer);
            const unsigned short *nodes = cache.nodes(p);
            double                value = 0.;
            Tensor<1, dim>        gradient;
            for (unsigned int k = 0; k < cache.stencil_size(p); ++k)
              {
                value += N[k] * nodal[nodes[k]];
                gradient += nodal[nodes[k]] * gradN[k];
              }
            double *state = cache.properties(p, points) + state_offset;
            state[1]      = value;
            for (unsigned int d = 0; d < dim; ++d)
              state[2 + dim + d] = gradient[d];
          }
      }
  }



  template <int dim>
  double
  PorePressureSolver<dim>::update(
    const ShapeCache<dim>               &cache,
    MaterialPointSet<dim>               &points,
    const TrilinosWrappers::MPI::Vector &du_ghosted)
  {
    assemble_rhs(cache, du_ghosted, false, rhs);

    // The previous iterate, for the change.
    TrilinosWrappers::MPI::Vector previous(p_owned);
    SolverControl control(1000, 1e-12 * rhs.l2_norm(), false, false);
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    if (rhs.l2_norm() > 0.)
      cg.solve(matrix, p_owned, rhs, amg);
    else
      p_owned = 0.;
    linear_iterations = control.last_step();
    constraints.distribute(p_owned);
    // The new iterate at the points.
    set_pressure(cache, points, p_owned);

    previous -= p_owned;
    const double change  = previous.linfty_norm();
    const double largest = std::max(p_owned.linfty_norm(), stress_scale);
    return largest > 0. ? change / largest : (change > 0. ? 1. : 0.);
  }



  template <int dim>
  void
  PorePressureSolver<dim>::set_pressure(const ShapeCache<dim> &cache,
                                        MaterialPointSet<dim> &points,
                                        const TrilinosWrappers::MPI::Vector &p)
  {
    const int ierr = p_ghosted.trilinos_vector().Import(p.trilinos_vector(),
                                                        *ghost_import,
                                                        Insert);
    AssertThrow(ierr == 0, ExcTrilinosError(ierr));
    interpolate_to_points(cache, points);
  }



  template <int dim>
  void
  PorePressureSolver<dim>::flow_residual(
    const ShapeCache<dim>               &cache,
    const TrilinosWrappers::MPI::Vector &du_ghosted,
    const TrilinosWrappers::MPI::Vector &p,
    TrilinosWrappers::MPI::Vector       &R) const
  {
    // The right-hand side holds L_p p(x_p) of the points' iterate, which
    // set_pressure() made p: it cancels the fixed-stress term of the
    // matrix, and what remains is the flow equation itself.
    assemble_rhs(cache, du_ghosted, false, R);
    R *= -1.;
    matrix.vmult_add(R, p);
    constraints.set_zero(R);
  }



  template <int dim>
  void
  PorePressureSolver<dim>::coupling_product(
    const ShapeCache<dim>               &cache,
    const TrilinosWrappers::MPI::Vector &du_ghosted,
    TrilinosWrappers::MPI::Vector       &dst) const
  {
    // assemble_rhs() leaves the constrained rows zero.
    assemble_rhs(cache, du_ghosted, true, dst);
  }



  template <int dim>
  void
  PorePressureSolver<dim>::precondition_schur(
    TrilinosWrappers::MPI::Vector       &dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    amg.vmult(dst, src);
    constraints.set_zero(dst);
  }



  template class PorePressureSolver<2>;
  template class PorePressureSolver<3>;
} // namespace qsmpm
