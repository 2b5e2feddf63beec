// The rule of CrackTracking (`Crack tracking = true` of the smeared-crack
// model), on a 12 x 12 grid of unit cells with 2 x 2 points per cell,
// cracking allowed where x < 10, tracking radius r = 2 cells. Cracks are
// written into the points' state by hand (by the names of the model's
// fields), then CrackTracking::update() decides. The references are
// geometry computed here, not the rule's own formula:
//
// 1. One crack, normal at 30 degrees to x, in the point nearest (5.3, 5.3):
//    - its path point is its cell's centre (5.5, 5.5) (to 1e-12);
//    - every point without a crack in the cracking region may crack in the
//      next step if and only if its cell's centre lies further than r from
//      the path point, or the crack's line crosses its cell: the signed
//      distances of the cell's four corners from the line do not all have
//      one sign (the rule itself uses |(c - a) . n| <= h (|n_x| + |n_y|) / 2;
//      the two agree at this angle, which puts no corner on the line);
//    - the number of points held back returned equals the count here;
//    - points outside the cracking region keep crack_allowed = 0.
// 2. The next step starts two cracks: B in a cell that the path crosses,
//    ahead of the first (normal at 35 degrees, the larger separation), and
//    C in a cell beside the first cell that the path does not cross
//    (normal at 30 degrees, a smaller separation: two points that crack in
//    the same step):
//    - B's path point is its cell's centre projected onto the first path
//      (to 1e-12): the path runs on from cell to cell;
//    - C's path point is its cell's centre projected onto the nearest of
//      the paths whose path points lie within r (here the first crack's:
//      B's path point is 2.06 cells away), so that points cracking
//      together share a path instead of starting a parallel one;
//    - the permissions follow the corner test with the three paths.
// The same output on 1 and 2 ranks (the cracked points are gathered).
#include "tests.h"

#include <qsmpm/fracture/crack_tracking.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/materials/smeared_cracks.h>
#include <qsmpm/particles/material_point_set.h>

namespace
{
  using namespace qsmpm;
  constexpr int dim = 2;

  /// A crack's path for the reference: a point on it and its normal.
  struct Path
  {
    Point<dim>     anchor;
    Tensor<1, dim> normal;
  };

  Tensor<1, dim>
  unit_at(const double degrees)
  {
    const double a = degrees * M_PI / 180.;
    return Tensor<1, dim>({std::cos(a), std::sin(a)});
  }

  /// Whether the line of @p path crosses the unit cell with centre @p c:
  /// its corners are not all on one side.
  bool
  crosses(const Path &path, const Point<dim> &c)
  {
    double lowest = 1e300, highest = -1e300;
    for (const double dx : {-0.5, 0.5})
      for (const double dy : {-0.5, 0.5})
        {
          const double s =
            (c + Tensor<1, dim>({dx, dy}) - path.anchor) * path.normal;
          lowest  = std::min(lowest, s);
          highest = std::max(highest, s);
        }
    return lowest <= 0. && highest >= 0.;
  }

  Point<dim>
  project(const Point<dim> &c, const Path &path)
  {
    return c - ((c - path.anchor) * path.normal) * path.normal;
  }

  Point<dim>
  cell_centre(const Point<dim> &x)
  {
    return Point<dim>(std::floor(x[0]) + 0.5, std::floor(x[1]) + 0.5);
  }

  class Test
  {
  public:
    Test()
      : grid(MPI_COMM_WORLD)
    {
      grid.make_box(Point<dim>(), Point<dim>(12., 12.), {{12, 12}});
      typename SmearedCracks<dim>::Parameters parameters;
      parameters.elastic.elasticity.young_modulus = 1.;
      parameters.elastic.elasticity.poisson_ratio = 0.2;
      parameters.tensile_strength                 = 1e-3;
      parameters.fracture_energy                  = 1e-3;
      parameters.crack_band_width                 = 1.;
      parameters.crack_tracking                   = true;
      parameters.tracking_radius                  = 2.;
      parameters.cracking_region                  = "x < 10 ? 1 : 0";
      model  = std::make_unique<SmearedCracks<dim>>(parameters);
      points = std::make_unique<MaterialPointSet<dim>>(grid, *model);
      points->fill([](const Point<dim> &) { return true; },
                   2,
                   MaterialPointSet<dim>::Placement::regular);
      unsigned int offset = points->get_offsets().state;
      for (const auto &field : model->state_fields())
        {
          index[field.name] = offset;
          offset += field.n_components;
        }
    }

    /// Start a crack with normal @p n and separation @p separation in the
    /// point nearest @p x (on the rank that owns it).
    void
    start_crack(const Point<dim>     &x,
                const Tensor<1, dim> &n,
                const double          separation)
    {
      for (auto &particle : points->get_particle_handler())
        if (particle.get_location().distance(x) < 0.25)
          {
            double *data = particle.get_properties().data();
            data[index.at(SmearedCracks<dim>::count_name)] = 1.;
            for (unsigned int d = 0; d < dim; ++d)
              data[index.at(SmearedCracks<dim>::normals_name) + d] = n[d];
            data[index.at(SmearedCracks<dim>::separation_name)] = separation;
          }
    }

    /// The path point of the crack in the point nearest @p x (all ranks).
    Point<dim>
    anchor_near(const Point<dim> &x) const
    {
      Point<dim> a;
      for (const auto &particle : points->get_particle_handler())
        if (particle.get_location().distance(x) < 0.25)
          {
            const double      *data = particle.get_properties().data();
            const unsigned int i    = index.at(SmearedCracks<dim>::anchor_name);
            AssertThrow(data[i] == 1., ExcMessage("no path point"));
            a = Point<dim>(data[i + 1], data[i + 2]);
          }
      for (unsigned int d = 0; d < dim; ++d)
        a[d] = Utilities::MPI::sum(a[d], MPI_COMM_WORLD);
      return a;
    }

    /// Run the update and compare the permissions with the corner test.
    void
    update_and_check(const std::vector<Path> &paths, const std::string &step)
    {
      CrackTracking<dim>       tracking(*model);
      const unsigned long long held_back =
        tracking.update(*points, MPI_COMM_WORLD);
      unsigned long long expected_held = 0, wrong = 0, outside_changed = 0,
                         in_region = 0;
      for (const auto &particle : points->get_particle_handler())
        {
          const double *data = particle.get_properties().data();
          const double  allowed =
            data[index.at(SmearedCracks<dim>::allowed_name)];
          if (particle.get_location()[0] >= 10.)
            {
              outside_changed += (allowed != 0.);
              continue;
            }
          if (data[index.at(SmearedCracks<dim>::count_name)] > 0.)
            continue;
          ++in_region;
          const Point<dim> c    = cell_centre(particle.get_location());
          bool             near = false, crossed = false;
          for (const Path &path : paths)
            if (c.distance(path.anchor) <= 2.)
              {
                near    = true;
                crossed = crossed || crosses(path, c);
              }
          const bool may = !near || crossed;
          expected_held += !may;
          wrong +=
            (may != (allowed == 1.)) || (allowed != 1. && allowed != -1.);
        }
      expected_held   = Utilities::MPI::sum(expected_held, MPI_COMM_WORLD);
      wrong           = Utilities::MPI::sum(wrong, MPI_COMM_WORLD);
      in_region       = Utilities::MPI::sum(in_region, MPI_COMM_WORLD);
      outside_changed = Utilities::MPI::sum(outside_changed, MPI_COMM_WORLD);
      deallog << step << ": " << in_region
              << " points without a crack in the cracking region, "
              << expected_held << " of them near a path but off its cells"
              << std::endl;
      check_that(step + ": every permission as the corner test", wrong == 0);
      check_that(step + ": the number held back returned",
                 held_back == expected_held);
      check_that(step + ": outside the region crack_allowed stays 0",
                 outside_changed == 0);
    }

    BackgroundGrid<dim>                    grid;
    std::unique_ptr<SmearedCracks<dim>>    model;
    std::unique_ptr<MaterialPointSet<dim>> points;
    std::map<std::string, unsigned int>    index;
  };
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  Test test;
  // The points are at 1/4 and 3/4 of each cell.
  const Point<dim> A(5.25, 5.25), B(4.75, 6.25), C(6.25, 5.25);
  test.start_crack(A, unit_at(30.), 2e-6);
  const Path first{Point<dim>(5.5, 5.5), unit_at(30.)};
  test.update_and_check({first}, "one crack");
  check("one crack: |path point - cell centre|",
        test.anchor_near(A).distance(first.anchor),
        1e-12);

  // B's cell (4,6) is crossed by the first path, C's cell (6,5) is not.
  AssertThrow(crosses(first, cell_centre(B)) && !crosses(first, cell_centre(C)),
              ExcInternalError());
  test.start_crack(B, unit_at(35.), 2e-6);
  test.start_crack(C, unit_at(30.), 1e-6);
  const Path second{project(cell_centre(B), first), unit_at(35.)};
  // The nearest path whose path point lies within r of C's cell centre.
  const Path *nearest = nullptr;
  for (const Path *path : {&first, &second})
    if (cell_centre(C).distance(path->anchor) <= 2. &&
        (nearest == nullptr ||
         std::abs((cell_centre(C) - path->anchor) * path->normal) <
           std::abs((cell_centre(C) - nearest->anchor) * nearest->normal)))
      nearest = path;
  const Path third{project(cell_centre(C), *nearest), unit_at(30.)};
  test.update_and_check({first, second, third}, "two more cracks");
  check("two more cracks: |B's path point - its cell centre on the first "
        "path|",
        test.anchor_near(B).distance(second.anchor),
        1e-12);
  check("two more cracks: |C's path point - its cell centre on the nearest "
        "path|",
        test.anchor_near(C).distance(third.anchor),
        1e-12);
  check("one crack: its path point unchanged",
        test.anchor_near(A).distance(first.anchor),
        1e-12);
}
