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
//    - the permissions follow the corner test with the three paths;
//    - the smearing lengths follow the band's direction (h = 1): B's is
//      that of the mean of its normal and the first path's, which crosses
//      its cell: L = cos 32.5 + sin 32.5 degrees (its own normal would give
//      cos 35 + sin 35, 0.9 % more); C's, whose cell no path within r
//      crosses, that of its own normal; A's stays that of step 1.
// 3. In 3D (8 x 8 x 8 unit cells, 2 x 2 x 2 points per cell, cracking where
//    x < 6), one crack with its normal at 30 degrees in the xy plane and
//    20 degrees out of it: the permissions by the same test with the eight
//    corners of each cell (the plane crosses the cell), and its path point
//    at its cell's centre.
// 4. `Crack tracking localization` = 0.02 on the 2D grid, one crack as in
//    1.: with its separation on the initial branch (2e-6, the elastic
//    limit is tau_nf / K_0 = 1.2e-5: nothing dissipated) the permissions
//    are those of 1.; with a separation of delta_0 / 2 (the linear law's
//    D = G_f / 2 there, above 0.02 G_f) the body is localized and every
//    point whose cell the path does not cross is held back, far ones too.
// The same output on 1 and 2 ranks (the cracked points are gathered).
#include "tests.h"

#include <qsmpm/fracture/crack_tracking.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/materials/smeared_cracks.h>
#include <qsmpm/particles/material_point_set.h>

namespace
{
  using namespace qsmpm;

  /// A crack's path for the reference: a point on it and its normal.
  template <int dim>
  struct Path
  {
    Point<dim>     anchor;
    Tensor<1, dim> normal;
  };

  /// The unit vector at @p degrees to x in the xy plane and, in 3D,
  /// @p elevation out of it.
  template <int dim>
  Tensor<1, dim>
  unit_at(const double degrees, const double elevation = 0.)
  {
    const double   a = degrees * M_PI / 180., b = elevation * M_PI / 180.;
    Tensor<1, dim> n;
    n[0] = std::cos(a) * std::cos(b);
    n[1] = std::sin(a) * std::cos(b);
    if (dim == 3)
      n[dim - 1] = std::sin(b);
    return n;
  }

  /// Whether the line (plane) of @p path crosses the unit cell with centre
  /// @p c: its corners are not all on one side.
  template <int dim>
  bool
  crosses(const Path<dim> &path, const Point<dim> &c)
  {
    double lowest = 1e300, highest = -1e300;
    for (unsigned int corner = 0; corner < (1U << dim); ++corner)
      {
        Point<dim> x = c;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] += ((corner >> d) & 1U) ? 0.5 : -0.5;
        const double s = (x - path.anchor) * path.normal;
        lowest         = std::min(lowest, s);
        highest        = std::max(highest, s);
      }
    return lowest <= 0. && highest >= 0.;
  }

  template <int dim>
  Point<dim>
  project(const Point<dim> &c, const Path<dim> &path)
  {
    return c - ((c - path.anchor) * path.normal) * path.normal;
  }

  template <int dim>
  Point<dim>
  cell_centre(const Point<dim> &x)
  {
    Point<dim> c;
    for (unsigned int d = 0; d < dim; ++d)
      c[d] = std::floor(x[d]) + 0.5;
    return c;
  }

  template <int dim>
  class Test
  {
  public:
    /// @p n unit cells per direction, cracking where x < @p region_end,
    /// `Crack tracking localization` @p localization.
    Test(const unsigned int n,
         const double       region_end,
         const double       localization = 0.)
      : grid(MPI_COMM_WORLD)
      , region_end(region_end)
    {
      std::array<unsigned int, dim> cells;
      cells.fill(n);
      Point<dim> upper;
      for (unsigned int d = 0; d < dim; ++d)
        upper[d] = n;
      grid.make_box(Point<dim>(), upper, cells);
      typename SmearedCracks<dim>::Parameters parameters;
      parameters.elastic.elasticity.young_modulus = 1.;
      parameters.elastic.elasticity.poisson_ratio = 0.2;
      parameters.tensile_strength                 = 1e-3;
      parameters.fracture_energy                  = 1e-3;
      parameters.crack_band_width                 = 1.;
      parameters.crack_tracking                   = true;
      parameters.tracking_radius                  = 2.;
      parameters.tracking_localization            = localization;
      parameters.cracking_region =
        "x < " + std::to_string(region_end) + " ? 1 : 0";
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
            for (unsigned int d = 0; d < dim; ++d)
              a[d] = data[i + 1 + d];
          }
      for (unsigned int d = 0; d < dim; ++d)
        a[d] = Utilities::MPI::sum(a[d], MPI_COMM_WORLD);
      return a;
    }

    /// The smearing length CrackTracking gave the crack in the point
    /// nearest @p x (all ranks).
    double
    band_length_near(const Point<dim> &x) const
    {
      double L = 0.;
      for (const auto &particle : points->get_particle_handler())
        if (particle.get_location().distance(x) < 0.25)
          L = particle.get_properties()
                .data()[index.at(SmearedCracks<dim>::band_length_name)];
      return Utilities::MPI::sum(L, MPI_COMM_WORLD);
    }

    /// Run the update and compare the permissions with the corner test
    /// (if @p localized, a point off every path's cells is held back even
    /// far from the paths).
    void
    update_and_check(const std::vector<Path<dim>> &paths,
                     const std::string            &step,
                     const bool                    localized = false)
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
          if (particle.get_location()[0] >= region_end)
            {
              outside_changed += (allowed != 0.);
              continue;
            }
          if (data[index.at(SmearedCracks<dim>::count_name)] > 0.)
            continue;
          ++in_region;
          const Point<dim> c    = cell_centre(particle.get_location());
          bool             near = false, crossed = false;
          for (const Path<dim> &path : paths)
            if (c.distance(path.anchor) <= 2.)
              {
                near    = true;
                crossed = crossed || crosses(path, c);
              }
          const bool may = (!near && !localized) || crossed;
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
              << expected_held
              << " of them off the paths' cells and near one (or localized)"
              << std::endl;
      check_that(step + ": every permission as the corner test", wrong == 0);
      check_that(step + ": the number held back returned",
                 held_back == expected_held);
      check_that(step + ": outside the region crack_allowed stays 0",
                 outside_changed == 0);
    }

    BackgroundGrid<dim>                    grid;
    const double                           region_end;
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

  constexpr int dim = 2;
  Test<dim>     test(12, 10.);
  // The points are at 1/4 and 3/4 of each cell.
  const Point<dim> A(5.25, 5.25), B(4.75, 6.25), C(6.25, 5.25);
  test.start_crack(A, unit_at<dim>(30.), 2e-6);
  const Path<dim> first{Point<dim>(5.5, 5.5), unit_at<dim>(30.)};
  test.update_and_check({first}, "one crack");
  check("one crack: |path point - cell centre|",
        test.anchor_near(A).distance(first.anchor),
        1e-12);
  // The smearing length at an angle phi to x, h = 1: cos phi + sin phi.
  const auto length_at = [](const double degrees) {
    return std::cos(degrees * M_PI / 180.) + std::sin(degrees * M_PI / 180.);
  };
  check("one crack: |L - (cos 30 + sin 30)|",
        test.band_length_near(A) - length_at(30.),
        1e-12);

  // B's cell (4,6) is crossed by the first path, C's cell (6,5) is not.
  AssertThrow(crosses(first, cell_centre(B)) && !crosses(first, cell_centre(C)),
              ExcInternalError());
  test.start_crack(B, unit_at<dim>(35.), 2e-6);
  test.start_crack(C, unit_at<dim>(30.), 1e-6);
  const Path<dim> second{project(cell_centre(B), first), unit_at<dim>(35.)};
  // The nearest path whose path point lies within r of C's cell centre.
  const Path<dim> *nearest = nullptr;
  for (const Path<dim> *path : {&first, &second})
    if (cell_centre(C).distance(path->anchor) <= 2. &&
        (nearest == nullptr ||
         std::abs((cell_centre(C) - path->anchor) * path->normal) <
           std::abs((cell_centre(C) - nearest->anchor) * nearest->normal)))
      nearest = path;
  const Path<dim> third{project(cell_centre(C), *nearest), unit_at<dim>(30.)};
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
  check("two more cracks: |L_B - (cos 32.5 + sin 32.5)|",
        test.band_length_near(B) - length_at(32.5),
        1e-12);
  check("two more cracks: |L_C - (cos 30 + sin 30)|",
        test.band_length_near(C) - length_at(30.),
        1e-12);
  check("one crack: |L_A - (cos 30 + sin 30)| after the next step",
        test.band_length_near(A) - length_at(30.),
        1e-12);

  // Localization after 0.02 G_f: tau_nf = G_f = 1e-3, delta_0 = 2.
  for (const double separation : {2e-6, 1.})
    {
      Test<dim> test4(12, 10., 0.02);
      test4.start_crack(A, unit_at<dim>(30.), separation);
      test4.update_and_check({first},
                             separation < 1. ?
                               "localization, the crack on its initial branch" :
                               "localization, the crack at delta_0 / 2",
                             separation == 1.);
    }

  // 3D: a plane crack.
  {
    constexpr int     dim3 = 3;
    Test<dim3>        test3(8, 6.);
    const Point<dim3> P(3.25, 3.25, 3.25);
    const Path<dim3> plane{Point<dim3>(3.5, 3.5, 3.5), unit_at<dim3>(30., 20.)};
    test3.start_crack(P, plane.normal, 2e-6);
    test3.update_and_check({plane}, "3D, one crack");
    check("3D, one crack: |path point - cell centre|",
          test3.anchor_near(P).distance(plane.anchor),
          1e-12);
  }
}
