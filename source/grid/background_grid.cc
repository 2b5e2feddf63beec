#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/grid/background_grid.h>

namespace qsmpm
{
  template <int dim>
  void
  BackgroundGrid<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.add_parameter("Lower corner",
                        lower_corner,
                        "Lower corner of the background grid box.",
                        Patterns::List(Patterns::Double(), dim, dim));
      prm.add_parameter("Upper corner",
                        upper_corner,
                        "Upper corner of the background grid box.",
                        Patterns::List(Patterns::Double(), dim, dim));
      prm.add_parameter("Subdivisions",
                        subdivisions,
                        "Number of grid cells in each coordinate direction. "
                        "The box is made of n_d / 2^k coarse cells refined "
                        "k times, with k as large as all n_d allow; each "
                        "MPI rank holds the coarse cells and its share of "
                        "the fine ones, so numbers with a common factor "
                        "2^k (e.g. 96 or 108 rather than 101) keep the "
                        "memory of every rank in proportion to its share.",
                        Patterns::List(Patterns::Integer(1), dim, dim));
      prm.add_parameter("Periodic directions",
                        periodic,
                        "Directions in which the box is periodic, as letters "
                        "(e.g. xy); empty for none. The displacement is then "
                        "periodic up to the macroscopic jump of <Boundary "
                        "conditions> (homogenization); with every direction "
                        "periodic one corner node is held.",
                        Patterns::Anything());
    }
    prm.leave_subsection();
  }



  template <int dim>
  BackgroundGrid<dim>::Parameters::Parameters()
  {
    for (unsigned int d = 0; d < dim; ++d)
      {
        upper_corner[d] = 1.;
        subdivisions[d] = 8;
      }
  }



  template <int dim>
  std::vector<unsigned int>
  BackgroundGrid<dim>::Parameters::periodic_directions() const
  {
    std::vector<unsigned int> directions;
    const std::string         letters = std::string("xyz").substr(0, dim);
    for (const char c : periodic)
      {
        const auto d = letters.find(c);
        AssertThrow(d != std::string::npos,
                    ExcMessage("Geometry: <Periodic directions> = <" +
                               periodic + ">: use letters from " + letters +
                               "."));
        if (std::find(directions.begin(), directions.end(), d) ==
            directions.end())
          directions.push_back(d);
      }
    return directions;
  }



  template <int dim>
  void
  BackgroundGrid<dim>::Parameters::check() const
  {
    periodic_directions();
    for (unsigned int d = 0; d < dim; ++d)
      AssertThrow(upper_corner[d] > lower_corner[d],
                  ExcMessage("Geometry: <Upper corner> must be larger than "
                             "<Lower corner> in every coordinate."));
  }



  template <int dim>
  BackgroundGrid<dim>::BackgroundGrid(const MPI_Comm communicator)
    : communicator(communicator)
    , triangulation(communicator)
    , fe(std::make_unique<FESystem<dim>>(FE_Q<dim>(1), dim))
    , dof_handler(triangulation)
  {
  }



  template <int dim>
  void
  BackgroundGrid<dim>::set_n_bodies(const unsigned int n)
  {
    AssertThrow(n >= 1, ExcMessage("A grid needs at least one body."));
    AssertThrow(triangulation.n_active_cells() == 0,
                ExcMessage("BackgroundGrid::set_n_bodies() must come before "
                           "make_box()."));
    bodies = n;
    fe     = std::make_unique<FESystem<dim>>(FE_Q<dim>(1), dim * n);
  }



  template <int dim>
  void
  BackgroundGrid<dim>::make_box(
    const Point<dim>                    &lower_corner,
    const Point<dim>                    &upper_corner,
    const std::array<unsigned int, dim> &subdivisions)
  {
    box_lower        = lower_corner;
    box_upper        = upper_corner;
    box_subdivisions = subdivisions;
    periodic.clear();
    build();
  }



  template <int dim>
  void
  BackgroundGrid<dim>::build()
  {
    // Every rank of a parallel::distributed::Triangulation holds the whole
    // coarse mesh (and p4est its connectivity), so a box made of its n^dim
    // cells directly costs every rank about a kilobyte per cell of the
    // whole grid: more than the points of a rank at 10^7 points on two
    // ranks, and all of a rank's memory on a large machine. The box is
    // therefore made of as few coarse cells as the subdivisions allow,
    // n_d / 2^k in direction d, refined k times: the same cells, vertices
    // and boundary ids, each rank holding only its share. A periodic
    // direction keeps at least two coarse cells, so that no coarse cell is
    // its own periodic neighbour.
    const auto halves = [this](const unsigned int k) {
      for (unsigned int d = 0; d < dim; ++d)
        {
          const unsigned int n = box_subdivisions[d] >> k;
          const bool         periodic_d =
            std::find(periodic.begin(), periodic.end(), d) != periodic.end();
          if (n % 2 != 0 || (periodic_d && n < 4))
            return false;
        }
      return true;
    };
    unsigned int k = 0;
    while (halves(k))
      ++k;
    std::vector<unsigned int> coarse(dim);
    for (unsigned int d = 0; d < dim; ++d)
      coarse[d] = box_subdivisions[d] >> k;

    triangulation.clear();
    GridGenerator::subdivided_hyper_rectangle(
      triangulation, coarse, box_lower, box_upper, /*colorize=*/true);
    // Periodic faces are identified in the coarse mesh, before refinement
    // (p4est's connectivity).
    if (!periodic.empty())
      {
        std::vector<GridTools::PeriodicFacePair<
          typename Triangulation<dim>::cell_iterator>>
          pairs;
        for (const unsigned int d : periodic)
          GridTools::collect_periodic_faces(
            triangulation, 2 * d, 2 * d + 1, d, pairs);
        triangulation.add_periodicity(pairs);
      }
    triangulation.refine_global(k);
    distribute_dofs();
  }



  template <int dim>
  void
  BackgroundGrid<dim>::make_box(const Parameters &parameters)
  {
    make_box(parameters.lower_corner,
             parameters.upper_corner,
             parameters.subdivisions);
    if (!parameters.periodic.empty())
      make_periodic(parameters.periodic_directions());
  }



  template <int dim>
  void
  BackgroundGrid<dim>::make_periodic(
    const std::vector<unsigned int> &directions)
  {
    AssertThrow(triangulation.n_active_cells() > 0,
                ExcMessage("Create the grid (make_box) before making it "
                           "periodic."));
    for (const unsigned int d : directions)
      {
        AssertThrow(d < dim,
                    ExcMessage("Periodic direction " + std::to_string(d) +
                               " does not exist in " + std::to_string(dim) +
                               "D."));
        if (std::find(periodic.begin(), periodic.end(), d) != periodic.end())
          continue;
        // A periodic direction needs two cells across the period, or a
        // node would be tied to itself.
        AssertThrow(box_subdivisions[d] >= 2,
                    ExcMessage("Geometry: the periodic direction " +
                               std::string(1, "xyz"[d]) +
                               " needs at least two cells across the box "
                               "(<Subdivisions>), got " +
                               std::to_string(box_subdivisions[d]) + "."));
        periodic.push_back(d);
      }
    std::sort(periodic.begin(), periodic.end());
    // The same box again, with the periodic faces identified in its coarse
    // mesh (see build()).
    build();
  }



  template <int dim>
  const std::vector<unsigned int> &
  BackgroundGrid<dim>::periodic_directions() const
  {
    return periodic;
  }



  template <int dim>
  void
  BackgroundGrid<dim>::make_periodicity_constraints(
    AffineConstraints<double> &constraints) const
  {
    for (const unsigned int d : periodic)
      DoFTools::make_periodicity_constraints(
        dof_handler, 2 * d, 2 * d + 1, d, constraints);
  }



  template <int dim>
  void
  BackgroundGrid<dim>::distribute_dofs()
  {
    dof_handler.distribute_dofs(*fe);
    owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_dofs);
  }



  template <int dim>
  const parallel::distributed::Triangulation<dim> &
  BackgroundGrid<dim>::get_triangulation() const
  {
    return triangulation;
  }



  template <int dim>
  parallel::distributed::Triangulation<dim> &
  BackgroundGrid<dim>::get_triangulation()
  {
    return triangulation;
  }



  template <int dim>
  const DoFHandler<dim> &
  BackgroundGrid<dim>::get_dof_handler() const
  {
    return dof_handler;
  }



  template <int dim>
  const FESystem<dim> &
  BackgroundGrid<dim>::get_fe() const
  {
    return *fe;
  }



  template <int dim>
  const MappingQ1<dim> &
  BackgroundGrid<dim>::get_mapping() const
  {
    return mapping;
  }



  template <int dim>
  typename DoFHandler<dim>::active_cell_iterator
  BackgroundGrid<dim>::dof_cell(
    const typename Triangulation<dim>::active_cell_iterator &cell) const
  {
    return typename DoFHandler<dim>::active_cell_iterator(&triangulation,
                                                          cell->level(),
                                                          cell->index(),
                                                          &dof_handler);
  }



  template <int dim>
  std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>
  BackgroundGrid<dim>::find_cell_around(
    const Point<dim>                                        &x,
    const typename Triangulation<dim>::active_cell_iterator &hint) const
  {
    if (!locator)
      locator = std::make_unique<GridTools::Cache<dim>>(triangulation, mapping);
    std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>
      found;
    try
      {
        found = GridTools::find_active_cell_around_point(*locator, x, hint);
      }
    catch (...)
      {
        found.first = typename Triangulation<dim>::active_cell_iterator();
      }
    if (found.first.state() == IteratorState::valid &&
        found.first->is_artificial())
      found.first = typename Triangulation<dim>::active_cell_iterator();
    return found;
  }



  template <int dim>
  const IndexSet &
  BackgroundGrid<dim>::locally_owned_dofs() const
  {
    return owned_dofs;
  }



  template <int dim>
  const IndexSet &
  BackgroundGrid<dim>::locally_relevant_dofs() const
  {
    return relevant_dofs;
  }



  template <int dim>
  IndexSet
  BackgroundGrid<dim>::dofs_at_most(const TrilinosWrappers::MPI::Vector &sums,
                                    const double threshold) const
  {
    TrilinosWrappers::MPI::Vector ghosted(owned_dofs,
                                          relevant_dofs,
                                          get_communicator());
    ghosted = sums;
    IndexSet result(dof_handler.n_dofs());
    for (const auto dof : relevant_dofs)
      if (ghosted(dof) <= threshold)
        result.add_index(dof);
    result.compress();
    return result;
  }



  template <int dim>
  MPI_Comm
  BackgroundGrid<dim>::get_communicator() const
  {
    return communicator;
  }



  template <int dim>
  const Point<dim> &
  BackgroundGrid<dim>::lower_corner() const
  {
    return box_lower;
  }



  template <int dim>
  const Point<dim> &
  BackgroundGrid<dim>::upper_corner() const
  {
    return box_upper;
  }



  template <int dim>
  Tensor<1, dim>
  BackgroundGrid<dim>::cell_size() const
  {
    Tensor<1, dim> h;
    for (unsigned int d = 0; d < dim; ++d)
      h[d] = (box_upper[d] - box_lower[d]) / box_subdivisions[d];
    return h;
  }



  template <int dim>
  double
  BackgroundGrid<dim>::min_cell_size() const
  {
    const Tensor<1, dim> h     = cell_size();
    double               h_min = h[0];
    for (unsigned int d = 1; d < dim; ++d)
      h_min = std::min(h_min, h[d]);
    return h_min;
  }



  template <int dim>
  std::vector<Point<dim>>
  BackgroundGrid<dim>::local_vertices(const std::size_t max_count) const
  {
    std::vector<bool>       seen(triangulation.n_vertices(), false);
    std::vector<Point<dim>> vertices;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          if (!seen[cell->vertex_index(v)])
            {
              seen[cell->vertex_index(v)] = true;
              vertices.push_back(cell->vertex(v));
            }
    const std::size_t stride = 1 + vertices.size() / max_count;
    if (stride > 1)
      {
        std::size_t n = 0;
        for (std::size_t i = 0; i < vertices.size(); i += stride)
          vertices[n++] = vertices[i];
        vertices.resize(n);
      }
    return vertices;
  }



  template <int dim>
  void
  BackgroundGrid<dim>::node_block_dofs(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    std::vector<types::global_dof_index>                 &dofs,
    const unsigned int                                    body) const
  {
    using Iterator = typename DoFHandler<dim>::cell_iterator;
    // One step from c in direction d (-1 or +1), across periodic faces
    // too; an invalid iterator where the grid ends.
    const auto step = [](const Iterator &c, const unsigned int d, const int s) {
      const unsigned int face = 2 * d + (s > 0 ? 1 : 0);
      if (!c->at_boundary(face))
        return Iterator(c->neighbor(face));
      if (c->has_periodic_neighbor(face))
        return Iterator(c->periodic_neighbor(face));
      return Iterator();
    };

    constexpr unsigned int              n_block_cells = dim == 2 ? 9 : 27;
    std::array<Iterator, n_block_cells> block;
    // Block cell (o_0, o_1[, o_2]), o_d = 0..2 for offsets -1..1: first
    // along the last direction, then the rows along the earlier ones.
    for (unsigned int b = 0; b < n_block_cells; ++b)
      {
        Iterator             c    = cell;
        unsigned int         rest = b;
        std::array<int, dim> offset;
        for (unsigned int d = 0; d < dim; ++d, rest /= 3)
          offset[d] = static_cast<int>(rest % 3) - 1;
        for (int d = dim - 1; d >= 0 && c.state() == IteratorState::valid; --d)
          if (offset[d] != 0)
            c = step(c, d, offset[d]);
        if (c.state() == IteratorState::valid)
          {
            Assert(c->is_active() && !c->is_artificial(),
                   ExcMessage("GIMP needs a uniform grid whose ghost layer "
                              "holds every vertex neighbour."));
          }
        block[b] = c;
      }

    // Fill the nodes, nearest cells first (fewest non-zero offsets).
    dofs.assign(n_block_nodes * dim, numbers::invalid_dof_index);
    for (unsigned int distance = 0; distance <= dim; ++distance)
      for (unsigned int b = 0; b < n_block_cells; ++b)
        {
          unsigned int         rest = b, n_offsets = 0;
          std::array<int, dim> o;
          for (unsigned int d = 0; d < dim; ++d, rest /= 3)
            {
              o[d] = rest % 3;
              n_offsets += (o[d] != 1);
            }
          if (n_offsets != distance || block[b].state() != IteratorState::valid)
            continue;
          const typename DoFHandler<dim>::active_cell_iterator c(block[b]);
          for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell;
               ++v)
            {
              unsigned int node = 0, stride = 1;
              for (unsigned int d = 0; d < dim; ++d, stride *= 4)
                node += (o[d] + ((v >> d) & 1)) * stride;
              if (dofs[node * dim] != numbers::invalid_dof_index)
                continue;
              for (unsigned int comp = 0; comp < dim; ++comp)
                dofs[node * dim + comp] =
                  c->vertex_dof_index(v, body * dim + comp);
            }
        }
  }



  template <int dim>
  bool
  BackgroundGrid<dim>::affine_map(
    const typename Triangulation<dim>::cell_iterator &cell,
    Tensor<2, dim>                                   &jacobian)
  {
    const Point<dim> &origin = cell->vertex(0);
    for (unsigned int d = 0; d < dim; ++d)
      for (unsigned int e = 0; e < dim; ++e)
        jacobian[e][d] = cell->vertex(1U << d)[e] - origin[e];
    // The affine map through vertices 0 and 2^d must reproduce the others.
    const double tolerance = 1e-12 * jacobian.norm();
    for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell; ++v)
      {
        Tensor<1, dim> predicted;
        for (unsigned int d = 0; d < dim; ++d)
          if ((v >> d) & 1U)
            for (unsigned int e = 0; e < dim; ++e)
              predicted[e] += jacobian[e][d];
        if ((origin + predicted - cell->vertex(v)).norm() > tolerance)
          return false;
      }
    return true;
  }



  template class BackgroundGrid<2>;
  template class BackgroundGrid<3>;
} // namespace qsmpm
