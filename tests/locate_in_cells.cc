// MaterialPointSet::locate_in_cells(), the fast path of the sort after a
// load step: while no point leaves its cell it only updates the points'
// reference locations, and deal.II's full sort must find nothing to do.
//
// On a Cartesian grid (affine cells: the inverse affine map) and on a grid
// whose vertices are moved by a smooth nonlinear map (bilinear/trilinear
// cells: the grid's mapping), every point is moved by up to 0.2 of the cell
// size, which keeps the regularly placed points (at 1/4 and 3/4 of their
// cell) inside. Checks:
//  - locate_in_cells() returns true;
//  - the Q1 map of each new reference location, evaluated here from the
//    cell's vertices and the bilinear (trilinear) shape functions, gives the
//    point's location back (an independent check of the inverse), and the
//    reference location lies in the unit cell;
//  - deal.II's sort afterwards moves no point and changes no reference
//    location by more than the tolerance;
// then one point (on one rank) is moved by a whole cell: locate_in_cells()
// must return false on every rank, and deal.II's sort puts the point into
// its new cell without losing any. Tolerance 1e-10 of the cell size (about
// 1 here): deal.II's Newton iteration for non-affine cells stops at a
// residual of 1e-11 of the cell's diameter (measured: 1.5e-12 in 2D,
// 1.8e-12 in 3D; on the affine cells 1e-15); a point assigned the wrong
// reference location would be off by a good part of the cell.
#include "tests.h"

#include <deal.II/grid/grid_tools.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/materials/linear_elastic.h>
#include <qsmpm/particles/material_point_set.h>

namespace
{
  using namespace qsmpm;

  /// x(xi) = sum_v X_v N_v(xi) of the (bi/tri)linear map of @p cell.
  template <int dim>
  Point<dim>
  q1_map(const typename Triangulation<dim>::active_cell_iterator &cell,
         const Point<dim>                                        &xi)
  {
    Point<dim> x;
    for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell; ++v)
      {
        double N = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          N *= ((v >> d) & 1U) ? xi[d] : 1. - xi[d];
        x += N * cell->vertex(v);
      }
    return x;
  }

  template <int dim>
  void
  test(const bool distorted)
  {
    BackgroundGrid<dim>           grid(MPI_COMM_WORLD);
    Point<dim>                    upper;
    std::array<unsigned int, dim> n;
    for (unsigned int d = 0; d < dim; ++d)
      {
        n[d]     = (d == 1 ? 3 : 4);
        upper[d] = n[d];
      }
    grid.make_box(Point<dim>(), upper, n);
    if (distorted)
      GridTools::transform(
        [](const Point<dim> &x) {
          Point<dim> y = x;
          y[0] += 0.15 * std::sin(x[1]) * x[0];
          y[1] += 0.1 * x[0] * x[1] / 4.;
          return y;
        },
        grid.get_triangulation());

    const LinearElastic<dim> model(1., 0.3);
    MaterialPointSet<dim>    points(grid, model);
    points.fill([](const Point<dim> &) { return true; },
                2,
                MaterialPointSet<dim>::Placement::regular);
    auto &handler = points.get_particle_handler();

    // A deterministic displacement of each point, up to 0.2 of the
    // smallest cell size (about 0.9 here) in each direction.
    for (auto &particle : handler)
      {
        Tensor<1, dim> u;
        for (unsigned int d = 0; d < dim; ++d)
          u[d] = 0.15 * std::sin(1.7 * particle.get_id() + d);
        particle.set_location(particle.get_location() + u);
      }
    const bool located = points.locate_in_cells();

    double                                      map_error = 0.;
    bool                                        in_unit   = true;
    unsigned int                                n_local   = 0;
    std::map<types::particle_index, Point<dim>> reference;
    for (const auto &particle : handler)
      {
        const Point<dim> xi = particle.get_reference_location();
        map_error           = std::max(map_error,
                             q1_map<dim>(particle.get_surrounding_cell(), xi)
                               .distance(particle.get_location()));
        in_unit = in_unit && GeometryInfo<dim>::is_inside_unit_cell(xi);
        reference[particle.get_id()] = xi;
        ++n_local;
      }
    map_error = Utilities::MPI::max(map_error, MPI_COMM_WORLD);
    in_unit   = Utilities::MPI::min(in_unit ? 1 : 0, MPI_COMM_WORLD) == 1;

    // deal.II's sort on the same points: nothing to do.
    const auto lost        = points.sort_into_cells();
    double     sort_change = 0.;
    for (const auto &particle : handler)
      sort_change = std::max(sort_change,
                             particle.get_reference_location().distance(
                               reference.at(particle.get_id())));
    sort_change = Utilities::MPI::max(sort_change, MPI_COMM_WORLD);
    const unsigned int n_after =
      Utilities::MPI::sum(handler.n_locally_owned_particles(), MPI_COMM_WORLD);
    const unsigned int n_before = Utilities::MPI::sum(n_local, MPI_COMM_WORLD);
    const unsigned int moved_ranks = Utilities::MPI::sum(
      handler.n_locally_owned_particles() != n_local ? 1U : 0U, MPI_COMM_WORLD);

    deallog << dim << "D, " << (distorted ? "distorted" : "Cartesian")
            << " grid, " << n_before << " points moved within their cells"
            << std::endl;
    deallog << "  locate_in_cells() = true: " << (located ? "PASS" : "FAIL")
            << std::endl;
    deallog << "  Q1 map of the reference location = location (1e-10): "
            << (map_error < 1e-10 ? "PASS" : "FAIL") << std::endl;
    deallog << "  reference locations in the unit cell: "
            << (in_unit ? "PASS" : "FAIL") << std::endl;
    deallog << "  deal.II's sort then moves no point (1e-10): "
            << (lost == 0 && n_after == n_before && moved_ranks == 0 &&
                    sort_change < 1e-10 ?
                  "PASS" :
                  "FAIL")
            << std::endl;

    // One point, on the first rank with points, moves by one cell in x.
    const unsigned int my_rank =
      Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const unsigned int first_rank =
      Utilities::MPI::min(handler.n_locally_owned_particles() > 0 ? my_rank :
                                                                    1000000U,
                          MPI_COMM_WORLD);
    Point<dim> jumped;
    if (my_rank == first_rank)
      {
        auto       particle = handler.begin();
        Point<dim> x        = particle->get_location();
        // Towards the grid's centre, so that it stays in the grid.
        x[0] += (x[0] < 2. ? 1. : -1.);
        particle->set_location(x);
      }
    const bool located_after_jump = points.locate_in_cells();
    const auto lost_after_jump    = points.sort_into_cells();
    double     jump_error         = 0.;
    for (const auto &particle : handler)
      jump_error = std::max(jump_error,
                            q1_map<dim>(particle.get_surrounding_cell(),
                                        particle.get_reference_location())
                              .distance(particle.get_location()));
    jump_error = Utilities::MPI::max(jump_error, MPI_COMM_WORLD);
    deallog << "  one point moved by a cell: locate_in_cells() = false: "
            << (!located_after_jump ? "PASS" : "FAIL") << std::endl;
    deallog << "  then deal.II's sort keeps all points in the right cells: "
            << (lost_after_jump == 0 &&
                    handler.n_global_particles() == n_before &&
                    jump_error < 1e-10 ?
                  "PASS" :
                  "FAIL")
            << std::endl;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::MPILogInitAll       log;
  test<2>(false);
  test<2>(true);
  test<3>(false);
  test<3>(true);
}
