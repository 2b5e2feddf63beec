#include <algorithm>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/grid/field_shape_values.h>
#include <qsmpm/loading/surface_tractions.h>
#include <sstream>
#include <tuple>

namespace qsmpm
{
  namespace
  {
    // The distinct coordinates of the rule's points in direction d, in
    // increasing order, and the weight of each (the sum of the weights of
    // the points with that coordinate: the 1D weight of a tensor-product
    // rule, whose weights sum to one).
    template <int dim>
    std::pair<std::vector<double>, std::vector<double>>
    rule_in_direction(const Quadrature<dim> &rule, const unsigned int d)
    {
      std::vector<double> coordinates;
      for (const auto &point : rule.get_points())
        coordinates.push_back(point[d]);
      std::sort(coordinates.begin(), coordinates.end());
      coordinates.erase(std::unique(coordinates.begin(),
                                    coordinates.end(),
                                    [](const double a, const double b) {
                                      return std::abs(a - b) < 1e-10;
                                    }),
                        coordinates.end());
      std::vector<double> weights(coordinates.size(), 0.);
      for (unsigned int q = 0; q < rule.size(); ++q)
        for (unsigned int i = 0; i < coordinates.size(); ++i)
          if (std::abs(rule.point(q)[d] - coordinates[i]) < 1e-10)
            weights[i] += rule.weight(q);
      return {coordinates, weights};
    }



    // The index of @p x among @p coordinates.
    unsigned int
    index_of(const std::vector<double> &coordinates, const double x)
    {
      for (unsigned int i = 0; i < coordinates.size(); ++i)
        if (std::abs(coordinates[i] - x) < 1e-8)
          return i;
      AssertThrow(false,
                  ExcMessage("Surface tractions: a material point is not at "
                             "a position of the placement rule of its cell; "
                             "the body's surface is found from the points "
                             "as fill() placed them, before the first "
                             "step."));
      return 0;
    }



    // cof(A) = det(A) A^{-T}, written out so that it is defined (and
    // continuous) for every A.
    template <int dim>
    Tensor<2, dim>
    cofactor(const Tensor<2, dim> &A)
    {
      Tensor<2, dim> C;
      if constexpr (dim == 2)
        {
          C[0][0] = A[1][1];
          C[0][1] = -A[1][0];
          C[1][0] = -A[0][1];
          C[1][1] = A[0][0];
        }
      else
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            C[i][j] =
              A[(i + 1) % 3][(j + 1) % 3] * A[(i + 2) % 3][(j + 2) % 3] -
              A[(i + 1) % 3][(j + 2) % 3] * A[(i + 2) % 3][(j + 1) % 3];
      return C;
    }
  } // namespace



  template <int dim>
  SurfaceTractions<dim>::SurfaceTractions(
    const BoundaryDescriptor<dim> &boundary)
    : boundary(boundary)
  {
  }



  template <int dim>
  bool
  SurfaceTractions<dim>::empty() const
  {
    return boundary.surface_tractions().empty();
  }



  template <int dim>
  std::vector<double>
  SurfaceTractions<dim>::mark(const BackgroundGrid<dim> &grid,
                              MaterialPointSet<dim>     &points) const
  {
    const auto         &conditions = boundary.surface_tractions();
    const unsigned int  n          = conditions.size();
    std::vector<double> areas(n, 0.);
    if (n == 0)
      return areas;
    AssertThrow(points.n_surface_loads() == n,
                ExcMessage("Surface tractions: the material points carry the "
                           "areas of " +
                           std::to_string(points.n_surface_loads()) +
                           " surface tractions, but " + std::to_string(n) +
                           " are given; add every surface traction before "
                           "the points are made "
                           "(QuasiStaticProblem::set_model())."));

    const Quadrature<dim>               &rule = points.placement_rule();
    std::array<std::vector<double>, dim> coordinates, weights;
    std::size_t                          n_tensor = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        std::tie(coordinates[d], weights[d]) = rule_in_direction(rule, d);
        n_tensor *= coordinates[d].size();
      }
    AssertThrow(n_tensor == rule.size(),
                ExcMessage("Surface tractions: the points of a cell must sit "
                           "on a tensor-product rule (Material points/"
                           "Placement = regular or gauss)."));

    // The points of the neighbouring cells on other ranks.
    auto &handler = points.get_particle_handler();
    handler.exchange_ghost_particles();

    const unsigned int offset  = points.get_offsets().surface_load;
    const unsigned int initial = points.get_offsets().initial_volume;
    const unsigned int stride  = 2 * dim + 1;
    for (auto &particle : handler)
      {
        const auto        cell = particle.get_surrounding_cell();
        const Point<dim>  xi   = particle.get_reference_location();
        const Point<dim>  X    = particle.get_location();
        ArrayView<double> data = particle.get_properties();
        for (unsigned int d = 0; d < dim; ++d)
          {
            const auto        &x_d = coordinates[d];
            const unsigned int i   = index_of(x_d, xi[d]);
            for (const int s : {-1, 1})
              {
                // The next position of the rule in direction s e_d: in
                // this cell, or the first one of the neighbouring cell.
                Point<dim> xi_next      = xi;
                auto       next_cell    = cell;
                const bool in_this_cell = s > 0 ? i + 1 < x_d.size() : i > 0;
                double     distance     = 0.; // in reference units
                if (in_this_cell)
                  {
                    xi_next[d] = x_d[i + s];
                    distance   = std::abs(xi_next[d] - xi[d]);
                  }
                else
                  {
                    xi_next[d] = s > 0 ? x_d.front() : x_d.back();
                    distance =
                      s > 0 ? 1. - xi[d] + xi_next[d] : xi[d] + 1. - xi_next[d];
                    const unsigned int face = 2 * d + (s > 0 ? 1 : 0);
                    if (cell->at_boundary(face) &&
                        !cell->has_periodic_neighbor(face))
                      next_cell = decltype(cell)();
                    else
                      next_cell = cell->at_boundary(face) ?
                                    cell->periodic_neighbor(face) :
                                    cell->neighbor(face);
                  }
                bool found = false;
                if (next_cell.state() == IteratorState::valid &&
                    !next_cell->is_artificial())
                  for (const auto &other : handler.particles_in_cell(next_cell))
                    if (other.get_reference_location().distance(xi_next) < 1e-8)
                      {
                        found = true;
                        break;
                      }
                if (found)
                  continue;

                // A face of the body's surface, halfway to the missing
                // neighbour.
                const double h_d  = cell->extent_in_direction(d);
                Point<dim>   face = X;
                face[d] += s * 0.5 * distance * h_d;
                const double area    = data[initial] / (weights[d][i] * h_d);
                const double to_face = s * 0.5 * distance * h_d;
                for (unsigned int k = 0; k < n; ++k)
                  if (conditions[k].selector(face))
                    {
                      double *load = data.data() + offset + k * stride;
                      load[0] += area;
                      load[1 + d] += s * area;
                      load[1 + dim + d] += area * to_face;
                      areas[k] += area;
                    }
              }
          }
      }

    // Drop the ghost particles again: the points are moved and sorted by
    // owned particles only, and stale copies would only take memory.
    using CellIterator = typename Triangulation<dim>::active_cell_iterator;
    std::vector<std::tuple<Point<dim>,
                           Point<dim>,
                           types::particle_index,
                           CellIterator,
                           std::vector<double>>>
      owned;
    owned.reserve(handler.n_locally_owned_particles());
    for (const auto &particle : handler)
      {
        const auto properties = particle.get_properties();
        owned.emplace_back(particle.get_location(),
                           particle.get_reference_location(),
                           particle.get_id(),
                           particle.get_surrounding_cell(),
                           std::vector<double>(properties.begin(),
                                               properties.end()));
      }
    handler.clear_particles();
    for (const auto &[location, reference, id, cell, properties] : owned)
      handler.insert_particle(location, reference, id, cell, properties);
    handler.update_cached_numbers();

    const MPI_Comm comm = grid.get_communicator();
    for (unsigned int k = 0; k < n; ++k)
      {
        areas[k] = dealii::Utilities::MPI::sum(areas[k], comm);
        AssertThrow(areas[k] > 0.,
                    ExcMessage("Surface tractions: <" + conditions[k].name +
                               "> selects no face of the body's surface "
                               "(the selector is evaluated at the centres "
                               "of the faces of the surface points' "
                               "domains, in the initial configuration)."));
      }
    return areas;
  }



  template <int dim>
  void
  SurfaceTractions<dim>::reinit_step(const BackgroundGrid<dim>   &grid,
                                     const ShapeCache<dim>       &shape_cache,
                                     const MaterialPointSet<dim> &points,
                                     const VectorType &ghosted_layout,
                                     const double      t)
  {
    cache                          = &shape_cache;
    offset                         = points.get_offsets().surface_load;
    displacement                   = points.get_offsets().displacement;
    finite_strain                  = points.get_formulation().finite_strain();
    const Formulation &formulation = points.get_formulation();
    const bool         gimp        = formulation.gimp();
    const bool ugimp = formulation.shape_functions == ShapeFunctions::ugimp;
    const unsigned int half_length = points.get_offsets().initial_half_length;
    time                           = t;
    pressure                       = false;
    loads.clear();
    load_dofs.clear();
    load_values.clear();
    load_components.clear();
    const auto               &conditions = boundary.surface_tractions();
    const FiniteElement<dim> &fe         = grid.get_fe();
    // On a multi-field grid (Contact between bodies) a point's load acts
    // on its own body's field: dofs_per_cell of the cell's dofs.
    dofs_per_cell = field_dofs_per_cell(fe);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    typename Triangulation<dim>::active_cell_iterator hint;
    std::string                                       error;
    for (unsigned int c = 0; c < cache->n_cells() && error.empty(); ++c)
      {
        const auto &range = cache->cell(c);
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          for (unsigned int k = 0; k < conditions.size(); ++k)
            {
              const double *data = cache->properties(p);
              const double *load = data + offset + k * (2 * dim + 1);
              if (!(load[0] > 0.))
                continue;
              if (conditions[k].type ==
                  BoundaryDescriptor<dim>::SurfaceLoadType::pressure)
                pressure = true;

              // x_f = x_p + F_p D_p.
              Tensor<1, dim> D;
              for (unsigned int d = 0; d < dim; ++d)
                D[d] = load[1 + dim + d] / load[0];
              if (finite_strain)
                D = Utils::read_tensor<dim>(
                      data + points.get_offsets().deformation_gradient) *
                    D;
              // uGIMP: the point's domain keeps its initial size and may
              // no longer reach the surface; the load acts at the edge of
              // the domain, on nodes the point's weights reach.
              if (ugimp)
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    const double l = data[half_length + d];
                    D[d]           = std::max(-l, std::min(l, D[d]));
                  }
              const Point<dim> x_f = cache->position(p) + D;

              // The cell of the point, and that of its load: with GIMP the
              // cell around x_f, whose nodes the point's domain reaches;
              // with linear functions the point's own cell (x_f projected
              // onto it), since only the nodes of cells with points carry
              // the body and the surface may already lie in the next cell.
              auto found = grid.find_cell_around(cache->position(p), hint);
              if (found.first.state() == IteratorState::valid)
                {
                  hint = found.first;
                  if (gimp)
                    found = grid.find_cell_around(x_f, hint);
                  else
                    found.second =
                      grid.get_mapping().transform_real_to_unit_cell(
                        found.first, x_f);
                }
              if (found.first.state() != IteratorState::valid ||
                  found.first->is_artificial())
                {
                  std::ostringstream message;
                  message << "Surface tractions: the load of <"
                          << conditions[k].name << "> at x = (" << x_f
                          << ") lies outside the background grid. Enlarge "
                             "the grid around the body (Geometry/Lower "
                             "corner, Upper corner).";
                  error = message.str();
                  break;
                }
              grid.dof_cell(found.first)->get_dof_indices(dofs);
              const Point<dim> xi =
                GeometryInfo<dim>::project_to_unit_cell(found.second);
              loads.push_back({c, p, k, (unsigned int)load_dofs.size(), x_f});
              append_field_shape_values(fe,
                                        dofs,
                                        xi,
                                        range.body,
                                        load_dofs,
                                        load_components,
                                        load_values);
            }
      }
    Utils::throw_if_any_rank(error, grid.get_communicator());
    pressure =
      dealii::Utilities::MPI::logical_or(pressure,
                                         ghosted_layout.get_mpi_communicator());
    if (pressure)
      {
        du_ghosted.reinit(ghosted_layout);
        forces.reinit(ghosted_layout.locally_owned_elements(),
                      ghosted_layout.get_mpi_communicator());
      }
  }



  template <int dim>
  bool
  SurfaceTractions<dim>::has_pressure() const
  {
    return pressure;
  }



  template <int dim>
  void
  SurfaceTractions<dim>::add_dead_loads(VectorType &f_ext) const
  {
    const auto         &conditions = boundary.surface_tractions();
    Vector<double>      traction(dim);
    std::vector<double> values(dofs_per_cell);
    for (const Load &load : loads)
      if (conditions[load.condition].type ==
          BoundaryDescriptor<dim>::SurfaceLoadType::dead)
        {
          const double *data = cache->properties(load.point);
          conditions[load.condition].traction->set_time(time);
          conditions[load.condition].traction->vector_value(
            initial_position(load.point), traction);
          const double   area = data[offset + load.condition * (2 * dim + 1)];
          Tensor<1, dim> force;
          for (unsigned int d = 0; d < dim; ++d)
            force[d] = traction[d] * area;
          spread(load, force, values, f_ext);
        }
  }



  template <int dim>
  void
  SurfaceTractions<dim>::for_each_load(
    const unsigned int                                         k,
    const std::function<void(const unsigned int             point,
                             const Point<dim>              &x_f,
                             const types::global_dof_index *dofs,
                             const double                  *values,
                             const unsigned int *components)> &action) const
  {
    for (const Load &load : loads)
      if (load.condition == k)
        action(load.point,
               load.face_centre,
               &load_dofs[load.first],
               &load_values[load.first],
               &load_components[load.first]);
  }



  template <int dim>
  void
  SurfaceTractions<dim>::spread(const Load           &load,
                                const Tensor<1, dim> &force,
                                std::vector<double>  &values,
                                VectorType           &f) const
  {
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      values[i] =
        load_values[load.first + i] * force[load_components[load.first + i]];
    f.add(dofs_per_cell, &load_dofs[load.first], values.data());
  }



  template <int dim>
  Point<dim>
  SurfaceTractions<dim>::initial_position(const unsigned int p) const
  {
    const double *data = cache->properties(p);
    Point<dim>    X    = cache->position(p);
    for (unsigned int d = 0; d < dim; ++d)
      X[d] -= data[displacement + d];
    return X;
  }



  template <int dim>
  Tensor<1, dim>
  SurfaceTractions<dim>::current_area(const unsigned int c,
                                      const unsigned int p,
                                      const unsigned int k,
                                      const double      *du_local) const
  {
    const double  *load = cache->properties(p) + offset + k * (2 * dim + 1);
    Tensor<1, dim> a;
    for (unsigned int d = 0; d < dim; ++d)
      a[d] = load[1 + d];
    if (!finite_strain)
      return a;
    // Delta F = I + sum_i du_i (x) grad N_i(x_p).
    Tensor<2, dim>        delta_F = unit_symmetric_tensor<dim>();
    const int            *dofs    = cache->local_dofs(c);
    const unsigned short *nodes   = cache->nodes(p);
    typename ShapeCache<dim>::GradientBuffer buffer;
    const Tensor<1, dim> *gradients = cache->gradients(c, p, buffer);
    for (unsigned int n = 0; n < cache->stencil_size(p); ++n)
      for (unsigned int i = 0; i < dim; ++i)
        {
          const double du = du_local[dofs[nodes[n] * dim + i]];
          for (unsigned int j = 0; j < dim; ++j)
            delta_F[i][j] += du * gradients[n][j];
        }
    return cofactor(delta_F) * a;
  }



  template <int dim>
  void
  SurfaceTractions<dim>::add_pressure_forces(const VectorType &du,
                                             VectorType       &R) const
  {
    if (!pressure)
      return;
    du_ghosted               = du;
    const double *du_local   = du_ghosted.trilinos_vector()[0];
    const auto   &conditions = boundary.surface_tractions();
    forces                   = 0.;
    Vector<double>      value(dim);
    std::vector<double> values(dofs_per_cell);
    for (const Load &load : loads)
      if (conditions[load.condition].type ==
          BoundaryDescriptor<dim>::SurfaceLoadType::pressure)
        {
          conditions[load.condition].traction->set_time(time);
          conditions[load.condition].traction->vector_value(
            initial_position(load.point), value);
          const Tensor<1, dim> force =
            -value[0] *
            current_area(load.group, load.point, load.condition, du_local);
          spread(load, force, values, forces);
        }
    forces.compress(VectorOperation::add);
    R += forces;
  }



  template <int dim>
  void
  SurfaceTractions<dim>::commit(MaterialPointSet<dim> &points,
                                const VectorType      &du_ghosted_step) const
  {
    if (!finite_strain)
      return;
    const double *du_local = du_ghosted_step.trilinos_vector()[0];
    for (const Load &load : loads)
      {
        const Tensor<1, dim> a =
          current_area(load.group, load.point, load.condition, du_local);
        double *data = cache->properties(load.point, points) + offset +
                       load.condition * (2 * dim + 1);
        for (unsigned int d = 0; d < dim; ++d)
          data[1 + d] = a[d];
      }
  }



  template class SurfaceTractions<2>;
  template class SurfaceTractions<3>;
} // namespace qsmpm
