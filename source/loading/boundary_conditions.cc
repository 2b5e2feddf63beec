#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <iostream>
#include <map>
#include <qsmpm/base/utilities.h>
#include <qsmpm/loading/boundary_conditions.h>
#include <qsmpm/loading/constraint_checks.h>
#include <sstream>
#include <unordered_map>

namespace qsmpm
{
  namespace
  {
    // The subsections of the three functions of "Boundary conditions", in
    // the order of BoundaryConditions::parsed_expressions.
    const std::array<std::string, 3> function_subsections = {
      {"Displacement", "Traction", "Body force"}};

    // Evaluate @p f at @p point with std::cerr silenced. deal.II compiles an
    // expression at its first evaluation and, for a syntax error or an
    // unknown variable, prints a five-line description to std::cerr before
    // it throws; the exception already holds the reason, and the user should
    // see one line that names the entry (see check_parsed_functions()).
    template <int dim>
    void
    evaluate_quietly(const Function<dim> &f,
                     const Point<dim>    &point,
                     Vector<double>      &values)
    {
      std::ostringstream    swallowed;
      std::streambuf *const original = std::cerr.rdbuf(swallowed.rdbuf());
      try
        {
          f.vector_value(point, values);
        }
      catch (...)
        {
          std::cerr.rdbuf(original);
          throw;
        }
      std::cerr.rdbuf(original);
    }
  } // namespace



  template <int dim>
  void
  BoundaryConditions<dim>::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    {
      prm.declare_entry(
        "Dirichlet boundaries",
        "",
        Patterns::Anything(),
        "Comma-separated list of <boundary id>:<components>, e.g. "
        "\"0:xy, 1:x, 2:n\". Components are letters from x, y, z, or n for "
        "the normal component only (a face free to slide). The prescribed "
        "values come from the function of subsection <Displacement> at the "
        "node positions, with t = load factor. Box boundary ids: 0/1 = x "
        "min/max, 2/3 = y min/max, 4/5 = z min/max.");
      prm.declare_entry("Traction boundaries",
                        "",
                        Patterns::List(Patterns::Integer(0)),
                        "Boundary ids loaded by the function of subsection "
                        "<Traction> (force per area, t = load factor).");
      prm.declare_entry(
        "Macroscopic displacement gradient",
        "",
        Patterns::Anything(),
        "For a grid with <Periodic directions>: the displacement gradient H "
        "(dim x dim numbers, row by row, multiplied by the load factor t), "
        "so that u = t H x + a periodic fluctuation; across a periodic "
        "direction d the displacement jumps by t H L_d e_d. Empty: H = 0.");
      const std::string zero = dim == 2 ? "0; 0" : "0; 0; 0";
      for (const std::string name : {"Displacement", "Traction", "Body force"})
        {
          prm.enter_subsection(name);
          Functions::ParsedFunction<dim>::declare_parameters(prm, dim);
          prm.set("Function expression", zero);
          prm.set("Variable names", dim == 2 ? "x,y,t" : "x,y,z,t");
          prm.leave_subsection();
        }
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  BoundaryConditions<dim>::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    dirichlet            = prm.get("Dirichlet boundaries");
    traction             = prm.get("Traction boundaries");
    macroscopic_gradient = prm.get("Macroscopic displacement gradient");
    prm.leave_subsection();
  }



  template <int dim>
  void
  BoundaryConditions<dim>::parse_parameters(ParameterHandler &prm)
  {
    Parameters parameters;
    parameters.parse_parameters(prm);

    // The three functions. deal.II's own messages for a wrong number of
    // expressions ("The number of components (2) is not equal to the number
    // of expressions (3).") or a malformed constant ("Invalid format") do
    // not say which of the three functions is meant, so we add the
    // subsection and the entries. A first evaluation (at the origin, t = 0)
    // finds syntax errors and unknown variables now rather than in the
    // middle of the first load step.
    prm.enter_subsection("Boundary conditions");
    parsed_displacement = std::make_shared<Functions::ParsedFunction<dim>>(dim);
    parsed_traction     = std::make_shared<Functions::ParsedFunction<dim>>(dim);
    parsed_body_force   = std::make_shared<Functions::ParsedFunction<dim>>(dim);
    const std::array<Functions::ParsedFunction<dim> *, 3> functions = {
      {parsed_displacement.get(),
       parsed_traction.get(),
       parsed_body_force.get()}};
    for (unsigned int i = 0; i < 3; ++i)
      {
        prm.enter_subsection(function_subsections[i]);
        parsed_expressions[i] = prm.get("Function expression");
        const std::string entries =
          "Boundary conditions/" + function_subsections[i] +
          ": <Function expression> = <" + parsed_expressions[i] +
          "> with <Variable names> = <" + prm.get("Variable names") +
          "> and <Function constants> = <" + prm.get("Function constants") +
          ">";
        try
          {
            functions[i]->parse_parameters(prm);
            Vector<double> values(dim);
            evaluate_quietly<dim>(*functions[i], Point<dim>(), values);
          }
        catch (const std::exception &exc)
          {
            AssertThrow(false,
                        ExcMessage(entries + ": " + Utils::error_message(exc) +
                                   " (a function needs " + std::to_string(dim) +
                                   " expressions separated by ';' in the "
                                   "variables of <Variable names>, and "
                                   "constants as name=value, ...)."));
          }
        prm.leave_subsection();
      }
    const bool has_body_force =
      parsed_expressions[2] != (dim == 2 ? "0; 0" : "0; 0; 0");
    prm.leave_subsection();

    for (const auto &entry : Utils::split(parameters.dirichlet, ','))
      {
        const auto parts = Utils::split(entry, ':');
        AssertThrow(parts.size() == 2,
                    ExcMessage("Boundary conditions: the entry <Dirichlet "
                               "boundaries> expects <id>:<components> items, "
                               "got <" +
                               entry + ">."));
        // string_to_int() would stop with "Can't convert <two> to an
        // integer.", which does not name the entry.
        int id = -1;
        try
          {
            id = dealii::Utilities::string_to_int(parts[0]);
          }
        catch (const std::exception &)
          {
            AssertThrow(false,
                        ExcMessage("Boundary conditions: <" + parts[0] +
                                   "> in <Dirichlet boundaries> = <" + entry +
                                   "> is not a boundary id (a box has ids 0 "
                                   "to " +
                                   std::to_string(2 * dim - 1) + ")."));
          }
        AssertThrow(id >= 0 && id < 2 * dim,
                    ExcMessage("Boundary conditions: boundary id <" + parts[0] +
                               "> in <Dirichlet boundaries> does "
                               "not exist; a box has ids 0 to " +
                               std::to_string(2 * dim - 1) + "."));
        bool       normal_only = false;
        const auto components =
          Utils::parse_components<dim>(parts[1],
                                       "Dirichlet boundaries",
                                       normal_only);
        add_dirichlet_boundary(id,
                               components,
                               parsed_displacement,
                               normal_only);
      }
    if (!parameters.macroscopic_gradient.empty())
      {
        const auto entries = Utils::split(parameters.macroscopic_gradient, ',');
        AssertThrow(entries.size() == dim * dim,
                    ExcMessage("Boundary conditions: <Macroscopic displacement "
                               "gradient> needs " +
                               std::to_string(dim * dim) + " numbers, got " +
                               std::to_string(entries.size()) + "."));
        Tensor<2, dim> H;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            {
              const std::string &entry = entries[i * dim + j];
              // string_to_double() would not name the entry.
              try
                {
                  H[i][j] = dealii::Utilities::string_to_double(entry);
                }
              catch (const std::exception &)
                {
                  AssertThrow(false,
                              ExcMessage("Boundary conditions: <" + entry +
                                         "> in <Macroscopic displacement "
                                         "gradient> is not a number."));
                }
              AssertThrow(std::isfinite(H[i][j]),
                          ExcMessage("Boundary conditions: <" + entry +
                                     "> in <Macroscopic displacement "
                                     "gradient> is not a finite number."));
            }
        set_macroscopic_displacement_gradient(
          [H](const double t) { return t * H; });
      }
    // The pattern of the entry admits only non-negative integers, but not
    // only the ids a box has: a traction on id 9 would load nothing.
    for (const auto &entry : Utils::split(parameters.traction, ','))
      {
        const int id = dealii::Utilities::string_to_int(entry);
        AssertThrow(id >= 0 && id < 2 * dim,
                    ExcMessage("Boundary conditions: boundary id <" + entry +
                               "> in <Traction boundaries> does not exist; a "
                               "box has ids 0 to " +
                               std::to_string(2 * dim - 1) + "."));
        add_traction(id, parsed_traction);
      }
    if (has_body_force)
      set_body_force(parsed_body_force);
  }



  template <int dim>
  void
  BoundaryConditions<dim>::add_dirichlet_boundary(
    const types::boundary_id              id,
    const std::array<bool, dim>          &components,
    const std::shared_ptr<Function<dim>> &displacement,
    const bool                            normal_only)
  {
    AssertThrow(displacement && displacement->n_components == dim,
                ExcMessage("A displacement function needs dim components."));
    dirichlet.push_back({"boundary_" + std::to_string(id),
                         id,
                         {},
                         components,
                         normal_only,
                         displacement});
  }



  template <int dim>
  void
  BoundaryConditions<dim>::add_dirichlet_nodes(
    const std::string                             &name,
    const std::function<bool(const Point<dim> &)> &selector,
    const std::array<bool, dim>                   &components,
    const std::shared_ptr<Function<dim>>          &displacement)
  {
    AssertThrow(displacement && displacement->n_components == dim,
                ExcMessage("A displacement function needs dim components."));
    dirichlet.push_back({name,
                         numbers::invalid_boundary_id,
                         selector,
                         components,
                         false,
                         displacement});
  }



  template <int dim>
  void
  BoundaryConditions<dim>::add_traction(
    const types::boundary_id              id,
    const std::shared_ptr<Function<dim>> &traction)
  {
    AssertThrow(traction && traction->n_components == dim,
                ExcMessage("A traction function needs dim components."));
    tractions.emplace_back(id, traction);
  }



  template <int dim>
  void
  BoundaryConditions<dim>::set_body_force(
    const std::shared_ptr<Function<dim>> &force)
  {
    AssertThrow(force && force->n_components == dim,
                ExcMessage("A body force function needs dim components."));
    body_force = force;
  }



  template <int dim>
  void
  BoundaryConditions<dim>::set_macroscopic_displacement_gradient(
    const std::function<Tensor<2, dim>(const double)> &H,
    const Point<dim>                                  &reference)
  {
    macroscopic_gradient  = H;
    macroscopic_reference = reference;
  }



  template <int dim>
  void
  BoundaryConditions<dim>::add_point_load(const Point<dim>     &location,
                                          const Tensor<1, dim> &force)
  {
    point_loads.emplace_back(location, force);
  }



  namespace
  {
    // The coordinate direction normal to an axis-aligned face.
    template <typename FaceIterator>
    unsigned int
    face_normal_direction(const FaceIterator &face, const unsigned int dim)
    {
      for (unsigned int d = 0; d < dim; ++d)
        {
          bool constant = true;
          for (unsigned int v = 1; v < face->n_vertices(); ++v)
            constant =
              constant && std::abs(face->vertex(v)[d] - face->vertex(0)[d]) <=
                            1e-12 * face->diameter();
          if (constant)
            return d;
        }
      AssertThrow(false,
                  ExcMessage("Sliding (normal-component) conditions need "
                             "axis-aligned boundary faces."));
      return 0;
    }
  } // namespace



  template <int dim>
  void
  BoundaryConditions<dim>::make_constraints(
    const BackgroundGrid<dim> &grid,
    const IndexSet            &inactive_dofs,
    const double               t_old,
    const double               t_new,
    AffineConstraints<double> &constraints)
  {
    constraints.clear();
    constraints.reinit(grid.locally_relevant_dofs());
    constrained_dofs.assign(dirichlet.size(), {});
    AssertThrow(!macroscopic_gradient || !grid.periodic_directions().empty(),
                ExcMessage("A macroscopic displacement gradient needs a grid "
                           "with periodic directions (Geometry: <Periodic "
                           "directions>)."));
    if (!grid.periodic_directions().empty())
      add_periodicity_constraints(grid, t_old, t_new, constraints);

    const IndexSet &owned = grid.locally_owned_dofs();
    Vector<double>  g_old(dim), g_new(dim);

    // Per condition: this rank's held nodes that carry material, and the
    // largest prescribed increment; and all held degrees of freedom with
    // material (for the rigid-body check).
    std::vector<unsigned int> n_active(dirichlet.size(), 0);
    std::vector<double>       largest_increment(dirichlet.size(), 0.);
    std::map<types::global_dof_index, std::pair<Point<dim>, unsigned int>> held;

    // Constrain component c of vertex x with global dof index `dof`.
    auto constrain = [&](const unsigned int            condition,
                         const Point<dim>             &x,
                         const types::global_dof_index dof,
                         const unsigned int            c,
                         const double                  increment) {
      if (!constraints.is_constrained(dof))
        {
          constraints.add_line(dof);
          constraints.set_inhomogeneity(dof, increment);
        }
      if (owned.is_element(dof))
        {
          constrained_dofs[condition].emplace_back(dof, c);
          largest_increment[condition] =
            std::max(largest_increment[condition], std::abs(increment));
          if (!inactive_dofs.is_element(dof))
            held.emplace(dof, std::make_pair(x, c));
        }
    };

    for (unsigned int k = 0; k < dirichlet.size(); ++k)
      {
        DirichletCondition &condition = dirichlet[k];
        auto                evaluate  = [&](const Point<dim> &x) {
          condition.displacement->set_time(t_old);
          condition.displacement->vector_value(x, g_old);
          condition.displacement->set_time(t_new);
          condition.displacement->vector_value(x, g_new);
        };

        for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
          {
            if (cell->is_artificial())
              continue;
            if (condition.boundary_id != numbers::invalid_boundary_id)
              {
                for (const unsigned int f : cell->face_indices())
                  if (cell->face(f)->at_boundary() &&
                      cell->face(f)->boundary_id() == condition.boundary_id)
                    {
                      const auto            face = cell->face(f);
                      std::array<bool, dim> mask = condition.components;
                      if (condition.normal_only)
                        {
                          mask.fill(false);
                          mask[face_normal_direction(face, dim)] = true;
                        }
                      for (unsigned int v = 0; v < face->n_vertices(); ++v)
                        {
                          evaluate(face->vertex(v));
                          for (unsigned int c = 0; c < dim; ++c)
                            if (mask[c])
                              constrain(k,
                                        face->vertex(v),
                                        face->vertex_dof_index(v, c),
                                        c,
                                        g_new[c] - g_old[c]);
                        }
                    }
              }
            else
              for (const unsigned int v : cell->vertex_indices())
                if (condition.selector(cell->vertex(v)))
                  {
                    evaluate(cell->vertex(v));
                    for (unsigned int c = 0; c < dim; ++c)
                      if (condition.components[c])
                        constrain(k,
                                  cell->vertex(v),
                                  cell->vertex_dof_index(v, c),
                                  c,
                                  g_new[c] - g_old[c]);
                  }
          }

        auto &dofs = constrained_dofs[k];
        std::sort(dofs.begin(), dofs.end());
        dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
        AssertThrow(dealii::Utilities::MPI::sum(dofs.size(),
                                                grid.get_communicator()) > 0,
                    ExcMessage("The displacement condition <" + condition.name +
                               "> does not select any grid node."));
        for (const auto &[dof, c] : dofs)
          n_active[k] += !inactive_dofs.is_element(dof);
        ConstraintChecks::assert_condition_acts(condition.name,
                                                n_active[k],
                                                largest_increment[k],
                                                t_old,
                                                t_new,
                                                grid.get_communicator());
      }

    // Without periodicity (which holds the body itself) the conditions on
    // nodes with material must prevent every rigid-body motion, or the
    // step's linear systems are singular.
    if (grid.periodic_directions().empty())
      {
        std::vector<std::pair<Point<dim>, unsigned int>> held_nodes;
        held_nodes.reserve(held.size());
        for (const auto &entry : held)
          held_nodes.push_back(entry.second);
        ConstraintChecks::assert_no_rigid_body_motion<dim>(
          held_nodes,
          grid.lower_corner() +
            0.5 * (grid.upper_corner() - grid.lower_corner()),
          grid.lower_corner().distance(grid.upper_corner()),
          grid.get_communicator());
      }

    // Nodes with no point in their support have no equation: fix their
    // increment to zero. It does not influence any point.
    for (const auto dof : inactive_dofs)
      if (!constraints.is_constrained(dof))
        constraints.add_line(dof);

    constraints.close();
  }



  template <int dim>
  void
  BoundaryConditions<dim>::add_periodicity_constraints(
    const BackgroundGrid<dim> &grid,
    const double               t_old,
    const double               t_new,
    AffineConstraints<double> &constraints) const
  {
    grid.make_periodicity_constraints(constraints);
    const Tensor<2, dim> dH = macroscopic_gradient ?
                                Tensor<2, dim>(macroscopic_gradient(t_new) -
                                               macroscopic_gradient(t_old)) :
                                Tensor<2, dim>();

    // Node and component of every locally relevant degree of freedom.
    std::unordered_map<types::global_dof_index,
                       std::pair<Point<dim>, unsigned int>>
      nodes;
    nodes.reserve(grid.locally_relevant_dofs().n_elements());
    for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int c = 0; c < dim; ++c)
            nodes.emplace(cell->vertex_dof_index(v, c),
                          std::make_pair(cell->vertex(v), c));
    auto node = [&](const types::global_dof_index dof) {
      const auto it = nodes.find(dof);
      AssertThrow(it != nodes.end(),
                  ExcMessage("Periodicity constraints: a node tied across "
                             "the period is not in the ghost layer."));
      return it->second;
    };

    // Every line is u_s = u_m between two nodes one period (or, at edges
    // and corners, several) apart: u_s - u_m = H (x_s - x_m).
    std::vector<std::pair<types::global_dof_index, double>> jumps;
    for (const auto &line : constraints.get_lines())
      {
        AssertThrow(line.entries.size() == 1 &&
                      std::abs(line.entries[0].second - 1.) < 1e-12,
                    ExcMessage("Periodicity constraints: expected one node "
                               "tied to one node."));
        const auto [x_s, c]   = node(line.index);
        const auto [x_m, c_m] = node(line.entries[0].first);
        AssertThrow(c == c_m,
                    ExcMessage("Periodicity constraints: components differ."));
        jumps.emplace_back(line.index, (dH * (x_s - x_m))[c]);
      }
    for (const auto &[dof, jump] : jumps)
      constraints.set_inhomogeneity(dof, jump);

    // Fully periodic: hold the free corner node (all corners are tied to it).
    if (grid.periodic_directions().size() < dim)
      return;
    const Point<dim> &lower = grid.lower_corner(), &upper = grid.upper_corner();
    const double      tolerance = 1e-10 * lower.distance(upper);
    for (const auto &[dof, x_c] : nodes)
      {
        bool corner = true;
        for (unsigned int d = 0; d < dim; ++d)
          corner = corner && (std::abs(x_c.first[d] - lower[d]) < tolerance ||
                              std::abs(x_c.first[d] - upper[d]) < tolerance);
        if (corner && !constraints.is_constrained(dof))
          {
            constraints.add_line(dof);
            constraints.set_inhomogeneity(
              dof, (dH * (x_c.first - macroscopic_reference))[x_c.second]);
          }
      }
  }



  template <int dim>
  void
  BoundaryConditions<dim>::assemble_external_force(
    const BackgroundGrid<dim>     &grid,
    const ShapeCache<dim>         &cache,
    const unsigned int             volume_offset,
    const double                   t,
    TrilinosWrappers::MPI::Vector &f_ext) const
  {
    f_ext = 0;
    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  cell_force;

    // Body force, paper eq. (2.11): b_i = sum_p Omega_p b(x_p) N_i(x_p).
    if (body_force)
      {
        body_force->set_time(t);
        Vector<double> b(dim);
        for (unsigned int c = 0; c < cache.n_cells(); ++c)
          {
            cell_force.assign(cache.n_dofs(c), 0.);
            const auto &range = cache.cell(c);
            for (unsigned int p = range.first_point; p < range.end_point; ++p)
              {
                body_force->vector_value(cache.position(p), b);
                const double  volume = cache.properties(p)[volume_offset];
                const double *N      = cache.values(p);
                const unsigned short *nodes = cache.nodes(p);
                for (unsigned int k = 0; k < cache.stencil_size(p); ++k)
                  for (unsigned int d = 0; d < dim; ++d)
                    cell_force[nodes[k] * dim + d] += volume * b[d] * N[k];
              }
            dofs.assign(cache.global_dofs(c),
                        cache.global_dofs(c) + cache.n_dofs(c));
            f_ext.add(dofs, cell_force);
          }
      }

    // Tractions, paper eq. (2.12), on the grid's boundary faces.
    if (!tractions.empty())
      {
        const QGauss<dim - 1> face_quadrature(2);
        FEFaceValues<dim>     fe_face(grid.get_mapping(),
                                  grid.get_fe(),
                                  face_quadrature,
                                  update_values | update_quadrature_points |
                                    update_JxW_values);
        Vector<double>        traction(dim);
        const unsigned int    dofs_per_cell = grid.get_fe().n_dofs_per_cell();
        dofs.resize(dofs_per_cell);
        cell_force.resize(dofs_per_cell);
        for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int f : cell->face_indices())
              for (const auto &[id, function] : tractions)
                if (cell->face(f)->at_boundary() &&
                    cell->face(f)->boundary_id() == id)
                  {
                    fe_face.reinit(cell, f);
                    function->set_time(t);
                    std::fill(cell_force.begin(), cell_force.end(), 0.);
                    for (const unsigned int q :
                         fe_face.quadrature_point_indices())
                      {
                        function->vector_value(fe_face.quadrature_point(q),
                                               traction);
                        for (unsigned int i = 0; i < dofs_per_cell; ++i)
                          {
                            const unsigned int c =
                              grid.get_fe().system_to_component_index(i).first;
                            cell_force[i] += traction[c] *
                                             fe_face.shape_value(i, q) *
                                             fe_face.JxW(q);
                          }
                      }
                    cell->get_dof_indices(dofs);
                    f_ext.add(dofs, cell_force);
                  }
      }

    // Point loads at grid nodes; the owner of the node's dofs adds them.
    for (const auto &[location, force] : point_loads)
      {
        bool found = false;
        for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
          if (!cell->is_artificial() && !found)
            for (const unsigned int v : cell->vertex_indices())
              if (cell->vertex(v).distance(location) < 1e-10 * cell->diameter())
                {
                  found = true;
                  for (unsigned int d = 0; d < dim; ++d)
                    if (grid.locally_owned_dofs().is_element(
                          cell->vertex_dof_index(v, d)))
                      f_ext(cell->vertex_dof_index(v, d)) += t * force[d];
                  break;
                }
        AssertThrow(dealii::Utilities::MPI::max(found ? 1 : 0,
                                                grid.get_communicator()) == 1,
                    ExcMessage("A point load must sit on a grid node."));
      }
    f_ext.compress(VectorOperation::add);
  }



  template <int dim>
  std::vector<Tensor<1, dim>>
  BoundaryConditions<dim>::reactions(
    const TrilinosWrappers::MPI::Vector &residual,
    const MPI_Comm                       communicator) const
  {
    std::vector<Tensor<1, dim>> result(constrained_dofs.size());
    for (unsigned int k = 0; k < constrained_dofs.size(); ++k)
      {
        for (const auto &[dof, c] : constrained_dofs[k])
          result[k][c] -= residual(dof);
        result[k] = dealii::Utilities::MPI::sum(result[k], communicator);
      }
    return result;
  }



  template <int dim>
  const std::vector<typename BoundaryConditions<dim>::DirichletCondition> &
  BoundaryConditions<dim>::dirichlet_conditions() const
  {
    return dirichlet;
  }



  template <int dim>
  void
  BoundaryConditions<dim>::check_parsed_functions(
    const std::vector<Point<dim>> &points,
    const std::vector<double>     &load_factors) const
  {
    const std::array<Functions::ParsedFunction<dim> *, 3> functions = {
      {parsed_displacement.get(),
       parsed_traction.get(),
       parsed_body_force.get()}};
    Vector<double> values(dim);
    for (unsigned int i = 0; i < 3; ++i)
      if (functions[i] != nullptr)
        {
          const double time = functions[i]->get_time();
          for (const double t : load_factors)
            {
              functions[i]->set_time(t);
              for (const auto &point : points)
                {
                  evaluate_quietly<dim>(*functions[i], point, values);
                  for (unsigned int c = 0; c < dim; ++c)
                    if (!std::isfinite(values[c]))
                      {
                        functions[i]->set_time(time);
                        std::ostringstream where;
                        where
                          << "Boundary conditions/" << function_subsections[i]
                          << ": <Function expression> = <"
                          << parsed_expressions[i] << "> gives " << values[c]
                          << " in component " << c << " at x = (" << point
                          << "), t = " << t
                          << "; every value must be a finite number.";
                        AssertThrow(false, ExcMessage(where.str()));
                      }
                }
            }
          functions[i]->set_time(time);
        }
  }



  template <int dim>
  bool
  BoundaryConditions<dim>::has_loads() const
  {
    return body_force || !tractions.empty() || !point_loads.empty();
  }



  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
} // namespace qsmpm
