#ifndef qsmpm_homogenization_columnar_voronoi_h
#define qsmpm_homogenization_columnar_voronoi_h

#include <array>
#include <cstdint>
#include <deal.II/base/point.h>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * A columnar grain structure (paper Section 4.2, Fig. 5): N generating
   * points, uniformly distributed in the rectangle [x0, x1] x [y0, y1] of the
   * film plane, and their planar Voronoi cells extruded through the
   * thickness. A point belongs to the grain of its nearest generator (with
   * the periodic option: nearest over the periodic images, so that the
   * tessellation tiles the plane periodically).
   *
   * Generators come from a std::mt19937_64 seeded with the given seed and
   * converted to doubles without std::uniform_real_distribution, so the
   * grains are identical on every MPI rank, compiler and library: every rank
   * builds the tessellation redundantly.
   */
  class ColumnarVoronoi
  {
  public:
    ColumnarVoronoi(const unsigned int          n_grains,
                    const std::array<double, 2> lower,
                    const std::array<double, 2> upper,
                    const std::uint64_t         seed,
                    const bool                  periodic = false);

    unsigned int
    n_grains() const;

    /// The grain of the in-plane position (x, y).
    unsigned int
    grain(const double x, const double y) const;

    /// The grain of a point (its first two coordinates are the film plane).
    template <int dim>
    unsigned int
    grain(const Point<dim> &p) const
    {
      return grain(p[0], p[1]);
    }

    /**
     * In-plane area of every grain, counted on the lattice of the centres of
     * an nx x ny subdivision of the rectangle (the in-plane positions of
     * regularly placed material points), so that grain volumes are those the
     * points represent. Rank-independent.
     */
    std::vector<double>
    areas(const unsigned int nx, const unsigned int ny) const;

    /// The generating points.
    const std::vector<std::array<double, 2>> &
    generators() const;

  private:
    std::array<double, 2>              lower, upper;
    bool                               periodic;
    std::vector<std::array<double, 2>> points;
    /// Bucket grid for the nearest-generator search.
    unsigned int                           n_buckets;
    std::vector<std::vector<unsigned int>> buckets;
  };
} // namespace qsmpm

#endif
