#include <Epetra_BlockMap.h>
#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/fe/fe_poly.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/particles/shape_cache.h>

namespace qsmpm
{
  namespace
  {
    // Phi(xi) = int_{-inf}^{xi} hat(s) ds for the hat function
    // hat(s) = max(0, 1 - |s|) of a node of a uniform 1D grid.
    inline double
    hat_integral(const double xi)
    {
      if (xi <= -1.)
        return 0.;
      if (xi <= 0.)
        return 0.5 * (1. + xi) * (1. + xi);
      if (xi <= 1.)
        return 1. - 0.5 * (1. - xi) * (1. - xi);
      return 1.;
    }

    inline double
    hat(const double xi)
    {
      return std::max(0., 1. - std::abs(xi));
    }

    /**
     * 1D GIMP weight of a node at distance d = x_p - X_i from the point, for
     * the domain [x_p - l, x_p + l] and spacing h: the average of the hat
     * function over the domain, and its derivative with respect to x_p.
     */
    inline void
    gimp_weight_1d(const double d,
                   const double l,
                   const double h,
                   double      &value,
                   double      &derivative)
    {
      const double upper = (d + l) / h, lower = (d - l) / h;
      value      = h / (2. * l) * (hat_integral(upper) - hat_integral(lower));
      derivative = (hat(upper) - hat(lower)) / (2. * l);
    }

    /// The diagonal of the stretch U of F = R U.
    template <int dim>
    Tensor<1, dim>
    stretch_diagonal(const Tensor<2, dim> &F)
    {
      const SymmetricTensor<2, dim> C =
        symmetrize(Tensor<2, dim>(transpose(F) * F));
      const auto     eigen = eigenvectors(C);
      Tensor<1, dim> U;
      for (unsigned int a = 0; a < dim; ++a)
        {
          const double stretch = std::sqrt(std::max(eigen[a].first, 0.));
          for (unsigned int d = 0; d < dim; ++d)
            U[d] += stretch * eigen[a].second[d] * eigen[a].second[d];
        }
      return U;
    }
  } // namespace



  template <int dim>
  void
  ShapeCache<dim>::reinit(const BackgroundGrid<dim>           &grid,
                          MaterialPointSet<dim>               &points,
                          const TrilinosWrappers::MPI::Vector &ghosted)
  {
    [[maybe_unused]] const FESystem<dim> &fe          = grid.get_fe();
    const unsigned int                    n_node_dofs = grid.n_node_dofs();
    for (unsigned int v = 0; v < n_vertices; ++v)
      for (unsigned int c = 0; c < n_node_dofs; ++c)
        Assert(fe.system_to_component_index(v * n_node_dofs + c).first == c &&
                 fe.system_to_component_index(v * n_node_dofs + c).second == v,
               ExcInternalError());
    const unsigned int n_bodies = grid.n_bodies();
    AssertThrow(n_bodies == 1 || body_of_material.size() > 0,
                ExcMessage("A grid of several bodies needs the body of each "
                           "material id (ShapeCache::set_bodies())."));
    material_id_offset = points.get_offsets().material_id;

    const bool         gimp             = points.get_formulation().gimp();
    auto              &particle_handler = points.get_particle_handler();
    const unsigned int n_local_points =
      particle_handler.n_locally_owned_particles();

    ++generation_count;
    point_set = &points;
    stencil   = gimp ? max_stencil_size : n_vertices;
    cells.clear();
    affine_cells.clear();
    cell_is_affine.clear();
    dof_offsets.assign(1, 0);
    cell_local_dofs.clear();
    cell_global_dofs.clear();
    shape_offsets.clear();
    // GIMP stores every point's stencil; with linear shape functions only
    // the points of cells that are not affine are stored (add_linear_cell()).
    stencil_nodes.resize(gimp ? n_local_points * stencil : 0);
    shape_values.resize(gimp ? n_local_points * stencil : 0);
    shape_gradients.resize(gimp ? n_local_points * stencil : 0);
    point_stencil_sizes.assign(n_local_points, stencil);
    point_properties.resize(n_local_points);
    point_positions.resize(n_local_points);
    point_reference_locations.resize(gimp ? 0 : n_local_points);

    const Epetra_BlockMap &map = ghosted.trilinos_vector().Map();
    unsigned int           p   = 0;
    for (const auto &dof_cell : grid.get_dof_handler().active_cell_iterators())
      if (dof_cell->is_locally_owned())
        {
          const typename Triangulation<dim>::active_cell_iterator cell(
            dof_cell);
          const auto particles = particle_handler.particles_in_cell(cell);
          if (particles.begin() == particles.end())
            continue;
          // One group per body in the cell, bodies in order.
          std::array<unsigned int, max_bodies> count{};
          if (n_bodies == 1)
            count[0] = particle_handler.n_particles_in_cell(cell);
          else
            for (const auto &particle : particles)
              ++count[body_of(particle.get_properties().data())];
          for (unsigned int b = 0; b < n_bodies; ++b)
            if (count[b] > 0)
              {
                const unsigned int group_first = p;
                if (gimp)
                  {
                    shape_offsets.push_back(group_first);
                    add_gimp_cell(
                      dof_cell, grid, points, map, p, particle_handler, b);
                    affine_cells.emplace_back();
                    cell_is_affine.push_back(false);
                  }
                else
                  add_linear_cell(
                    dof_cell, grid, map, p, particle_handler, b, count[b]);
                cells.push_back({cell, group_first, p, b});
                dof_offsets.push_back(cell_local_dofs.size());
              }
        }
    affine_cell_count =
      std::count(cell_is_affine.begin(), cell_is_affine.end(), 1);
    AssertThrow(p == n_local_points,
                ExcMessage("Some locally owned material points were not found "
                           "in locally owned cells."));
  }



  template <int dim>
  void
  ShapeCache<dim>::set_bodies(const std::vector<unsigned int> &body_of)
  {
    for (const unsigned int b : body_of)
      AssertThrow(b == numbers::invalid_unsigned_int || b < max_bodies,
                  ExcMessage("At most " + std::to_string(max_bodies) +
                             " bodies can be in contact."));
    body_of_material = body_of;
  }



  template <int dim>
  unsigned int
  ShapeCache<dim>::body_of(const double *data) const
  {
    if (body_of_material.empty())
      return 0;
    const auto id = static_cast<unsigned int>(data[material_id_offset]);
    AssertThrow(id < body_of_material.size() &&
                  body_of_material[id] != numbers::invalid_unsigned_int,
                ExcMessage("Contact between bodies: material id " +
                           std::to_string(id) +
                           " belongs to none of the bodies (Contact between "
                           "bodies/Bodies)."));
    return body_of_material[id];
  }



  template <int dim>
  void
  ShapeCache<dim>::clear()
  {
    ++generation_count;
    // swap() with empty vectors: clear() alone keeps the capacity.
    std::vector<CellRange>().swap(cells);
    std::vector<AffineQ1Cell<dim>>().swap(affine_cells);
    std::vector<unsigned char>().swap(cell_is_affine);
    affine_cell_count = 0;
    std::vector<unsigned int>().swap(dof_offsets);
    std::vector<unsigned int>().swap(shape_offsets);
    std::vector<int>().swap(cell_local_dofs);
    std::vector<types::global_dof_index>().swap(cell_global_dofs);
    std::vector<unsigned short>().swap(stencil_nodes);
    std::vector<unsigned char>().swap(point_stencil_sizes);
    std::vector<double>().swap(shape_values);
    std::vector<Tensor<1, dim>>().swap(shape_gradients);
    std::vector<double *>().swap(point_properties);
    std::vector<Point<dim>>().swap(point_positions);
    std::vector<Point<dim>>().swap(point_reference_locations);
    point_set = nullptr;
  }



  template <int dim>
  void
  ShapeCache<dim>::add_linear_cell(
    const typename DoFHandler<dim>::active_cell_iterator &dof_cell,
    const BackgroundGrid<dim>                            &grid,
    const Epetra_BlockMap                                &map,
    unsigned int                                         &p,
    Particles::ParticleHandler<dim>                      &particle_handler,
    const unsigned int                                    body,
    const unsigned int                                    n_points)
  {
    const typename Triangulation<dim>::active_cell_iterator cell(dof_cell);
    for (unsigned int v = 0; v < n_vertices; ++v)
      for (unsigned int c = 0; c < dim; ++c)
        {
          const types::global_dof_index dof =
            dof_cell->vertex_dof_index(v, body * dim + c);
          const int lid =
            map.LID(static_cast<TrilinosWrappers::types::int_type>(dof));
          AssertThrow(lid >= 0, ExcInternalError());
          cell_local_dofs.push_back(lid);
          cell_global_dofs.push_back(dof);
        }

    // On a cell that is not affine: deal.II's FE_Q(1) evaluated at the
    // points' reference locations, all shape functions in one call of its
    // polynomial space (FE_Poly's shape_value(v, xi) is that space's v-th
    // polynomial); shape function v belongs to vertex v.
    const auto &q1 =
      dynamic_cast<const FE_Poly<dim> &>(grid.get_fe().base_element(0));
    const ScalarPolynomialsBase<dim> &polynomials = q1.get_poly_space();
    q1_values.resize(n_vertices);
    q1_gradients.resize(n_vertices);
    // On an affine cell (every cell of a Cartesian grid) the Jacobian of
    // the Q1 map is the same at all points: inverted once per cell, and
    // kept for AffineQ1Cell.
    Tensor<2, dim> affine_jacobian;
    const bool     affine = grid.affine_map(cell, affine_jacobian);
    affine_cells.push_back(
      {affine ? invert(affine_jacobian) : Tensor<2, dim>()});
    cell_is_affine.push_back(affine);
    // On an affine cell only the reference locations are kept (see
    // values()); otherwise the values and gradients, appended.
    const unsigned int first  = p;
    const unsigned int offset = shape_values.size() / stencil;
    if (affine)
      shape_offsets.push_back(numbers::invalid_unsigned_int);
    else
      {
        shape_offsets.push_back(offset);
        shape_values.resize((offset + n_points) * stencil);
        shape_gradients.resize((offset + n_points) * stencil);
      }
    const bool one_body = body_of_material.empty();
    for (const auto &particle : particle_handler.particles_in_cell(cell))
      {
        if (!one_body && body_of(particle.get_properties().data()) != body)
          continue;
        const Point<dim> xi = particle.get_reference_location();
        if (!affine)
          {
            const unsigned int i = (offset + p - first) * stencil;
            polynomials.evaluate(xi,
                                 q1_values,
                                 q1_gradients,
                                 q1_unused_2,
                                 q1_unused_3,
                                 q1_unused_4);
            // The Jacobian of the Q1 map at the point: exact for any
            // (bi/tri)linear cell.
            Tensor<2, dim> jacobian;
            for (unsigned int v = 0; v < n_vertices; ++v)
              jacobian += outer_product(cell->vertex(v), q1_gradients[v]);
            const Tensor<2, dim> inverse_transpose =
              transpose(invert(jacobian));
            for (unsigned int v = 0; v < n_vertices; ++v)
              {
                shape_values[i + v]    = q1_values[v];
                shape_gradients[i + v] = inverse_transpose * q1_gradients[v];
              }
          }
        // ParticleAccessor::get_properties() is not const, but the
        // pointer stays valid until particles are added or sorted.
        point_properties[p] =
          const_cast<double *>(particle.get_properties().data());
        point_positions[p]           = particle.get_location();
        point_reference_locations[p] = xi;
        ++p;
      }
  }



  template <int dim>
  void
  ShapeCache<dim>::add_gimp_cell(
    const typename DoFHandler<dim>::active_cell_iterator &dof_cell,
    const BackgroundGrid<dim>                            &grid,
    const MaterialPointSet<dim>                          &points,
    const Epetra_BlockMap                                &map,
    unsigned int                                         &p,
    Particles::ParticleHandler<dim>                      &particle_handler,
    const unsigned int                                    body)
  {
    constexpr unsigned int n_block = BackgroundGrid<dim>::n_block_nodes;
    const typename Triangulation<dim>::active_cell_iterator cell(dof_cell);
    grid.node_block_dofs(dof_cell, block_dofs, body);
    const bool           one_body    = body_of_material.empty();
    const Tensor<1, dim> h           = grid.cell_size();
    const double         h_min       = grid.min_cell_size();
    const Point<dim>     corner      = cell->vertex(0);
    const auto          &offsets     = points.get_offsets();
    const Formulation   &formulation = points.get_formulation();
    const bool stretch = formulation.shape_functions == ShapeFunctions::cpgimp;
    // Where the grid ends beside this cell (a face at the boundary that is
    // not periodic) a domain that reaches across is cut at that face. The
    // part beyond would weigh nodes that do not exist: the weights would no
    // longer sum to one and the gradients to zero, and part of the point's
    // load and internal force would leave through the edge. Averaged over
    // the part inside, both sums hold (the hat functions of the grid's nodes
    // sum to one everywhere inside it).
    std::array<bool, dim> cut_lower, cut_upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        cut_lower[d] =
          cell->at_boundary(2 * d) && !cell->has_periodic_neighbor(2 * d);
        cut_upper[d] = cell->at_boundary(2 * d + 1) &&
                       !cell->has_periodic_neighbor(2 * d + 1);
      }

    // Block node of each stencil entry; compacted after all points are seen.
    std::array<bool, n_block> touched;
    touched.fill(false);
    const unsigned int first = p;
    for (const auto &particle : particle_handler.particles_in_cell(cell))
      {
        double *data = const_cast<double *>(particle.get_properties().data());
        if (!one_body && body_of(data) != body)
          continue;
        const Point<dim> x = particle.get_location();

        // The point's current half-lengths.
        Tensor<1, dim> l;
        for (unsigned int d = 0; d < dim; ++d)
          l[d] = data[offsets.initial_half_length + d];
        if (stretch)
          {
            Tensor<1, dim> U;
            if (formulation.finite_strain())
              {
                U = stretch_diagonal(
                  Utils::read_tensor<dim>(data + offsets.deformation_gradient));
              }
            else
              {
                const SymmetricTensor<2, dim> eps =
                  Utils::read_symmetric<dim>(data + offsets.strain);
                for (unsigned int d = 0; d < dim; ++d)
                  U[d] = 1. + eps[d][d];
              }
            for (unsigned int d = 0; d < dim; ++d)
              l[d] *= U[d];
          }

        // 1D weights of the three nodes s_d, s_d + 1, s_d + 2 of the 4-node
        // row of the block in each direction, for the domain [lower, upper]
        // (cell coordinates) cut at the grid's edge.
        std::array<unsigned int, dim>          start;
        std::array<std::array<double, 3>, dim> w, dw;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double half =
              std::min(std::max(l[d], 1e-6 * h[d]), 0.5 * h[d]);
            const double local = x[d] - corner[d];
            const double lower =
              cut_lower[d] ? std::max(local - half, 0.) : local - half;
            const double upper =
              cut_upper[d] ? std::min(local + half, h[d]) : local + half;
            const double centre = 0.5 * (lower + upper);
            const double cut    = 0.5 * (upper - lower);
            start[d]            = std::min(
              1, std::max(0, static_cast<int>(std::floor(lower / h[d])) + 1));
            for (unsigned int a = 0; a < 3; ++a)
              {
                const double node =
                  (static_cast<double>(start[d] + a) - 1.) * h[d];
                gimp_weight_1d(centre - node, cut, h[d], w[d][a], dw[d][a]);
              }
          }

        // Only the entries with a non-zero value or gradient are kept, at
        // the front of the point's stencil: a point whose domain lies inside
        // its cell costs as much as with linear shape functions.
        unsigned int n_kept = 0;
        for (unsigned int k = 0; k < stencil; ++k)
          {
            unsigned int   rest = k, node = 0, stride = 1;
            double         value = 1.;
            Tensor<1, dim> gradient;
            for (unsigned int e = 0; e < dim; ++e)
              gradient[e] = 1.;
            for (unsigned int d = 0; d < dim; ++d, rest /= 3, stride *= 4)
              {
                const unsigned int a = rest % 3;
                node += (start[d] + a) * stride;
                value *= w[d][a];
                for (unsigned int e = 0; e < dim; ++e)
                  gradient[e] *= (e == d) ? dw[d][a] : w[d][a];
              }
            // Entries at round-off level (a domain edge on a cell face, or a
            // node beyond the grid's edge, where the domain is cut) are
            // dropped too.
            if (std::abs(value) <= 1e-12 && gradient.norm() * h_min <= 1e-12)
              continue;
            AssertThrow(block_dofs[node * dim] != numbers::invalid_dof_index,
                        ExcInternalError());
            touched[node] = true;
            // Block node for now; replaced by the group's index below.
            stencil_nodes[p * stencil + n_kept]   = node;
            shape_values[p * stencil + n_kept]    = value;
            shape_gradients[p * stencil + n_kept] = gradient;
            ++n_kept;
          }
        point_stencil_sizes[p] = n_kept;
        point_properties[p]    = data;
        point_positions[p]     = x;
        ++p;
      }

    // The group's nodes: the touched block nodes, in block order.
    std::array<unsigned short, n_block> group_index;
    unsigned short                      n_nodes = 0;
    for (unsigned int node = 0; node < n_block; ++node)
      if (touched[node])
        {
          group_index[node] = n_nodes++;
          for (unsigned int c = 0; c < dim; ++c)
            {
              const types::global_dof_index dof = block_dofs[node * dim + c];
              const int                     lid =
                map.LID(static_cast<TrilinosWrappers::types::int_type>(dof));
              AssertThrow(lid >= 0, ExcInternalError());
              cell_local_dofs.push_back(lid);
              cell_global_dofs.push_back(dof);
            }
        }
    for (unsigned int q = first; q < p; ++q)
      for (unsigned int k = 0; k < point_stencil_sizes[q]; ++k)
        {
          unsigned short &node = stencil_nodes[q * stencil + k];
          node                 = group_index[node];
        }
  }



  template <int dim>
  IndexSet
  ShapeCache<dim>::dofs_without_points(const BackgroundGrid<dim> &grid,
                                       const unsigned int         volume_offset,
                                       const double min_nodal_volume,
                                       const bool   per_radian) const
  {
    // Count, for every degree of freedom, the cells with points around it
    // (or, with a threshold, the material volume sum_p Omega_p N_i(x_p) in
    // its support); the sum over ranks tells which nodes are inactive
    // everywhere.
    if (min_nodal_volume > 0.)
      return grid.dofs_at_most(nodal_volumes(grid, volume_offset, per_radian),
                               min_nodal_volume);
    TrilinosWrappers::MPI::Vector count(grid.locally_owned_dofs(),
                                        grid.get_communicator());
    std::vector<double>           ones(max_dofs_per_group, 1.);
    for (unsigned int c = 0; c < n_cells(); ++c)
      count.add(n_dofs(c), global_dofs(c), ones.data());
    count.compress(VectorOperation::add);
    return grid.dofs_at_most(count, 0.);
  }



  template <int dim>
  TrilinosWrappers::MPI::Vector
  ShapeCache<dim>::nodal_volumes(const BackgroundGrid<dim> &grid,
                                 const unsigned int         volume_offset,
                                 const bool                 per_radian) const
  {
    TrilinosWrappers::MPI::Vector volumes(grid.locally_owned_dofs(),
                                          grid.get_communicator());
    std::vector<double>           volume(max_dofs_per_group);
    ValueBuffer                   buffer;
    for (unsigned int c = 0; c < n_cells(); ++c)
      {
        std::fill(volume.begin(), volume.begin() + n_dofs(c), 0.);
        const auto &range = cell(c);
        for (unsigned int p = range.first_point; p < range.end_point; ++p)
          {
            const double omega =
              properties(p)[volume_offset] / (per_radian ? position(p)[0] : 1.);
            const double         *N    = values(c, p, buffer);
            const unsigned short *node = nodes(p);
            for (unsigned int k = 0; k < stencil_size(p); ++k)
              for (unsigned int d = 0; d < dim; ++d)
                volume[node[k] * dim + d] += omega * N[k];
          }
        volumes.add(n_dofs(c), global_dofs(c), volume.data());
      }
    volumes.compress(VectorOperation::add);
    return volumes;
  }



  template <int dim>
  Tensor<1, dim>
  ShapeCache<dim>::interpolate(const unsigned int c,
                               const unsigned int p,
                               const double      *local_values) const
  {
    ValueBuffer           buffer;
    const int            *dofs  = local_dofs(c);
    const double         *N     = values(c, p, buffer);
    const unsigned short *nodes = this->nodes(p);
    Tensor<1, dim>        result;
    for (unsigned int k = 0; k < stencil_size(p); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        result[d] += N[k] * local_values[dofs[nodes[k] * dim + d]];
    return result;
  }



  template class ShapeCache<2>;
  template class ShapeCache<3>;
} // namespace qsmpm
