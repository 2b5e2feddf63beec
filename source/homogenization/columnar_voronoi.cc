#include <cmath>
#include <deal.II/base/exceptions.h>
#include <limits>
#include <qsmpm/homogenization/columnar_voronoi.h>
#include <random>

namespace qsmpm
{
  ColumnarVoronoi::ColumnarVoronoi(const unsigned int          n_grains,
                                   const std::array<double, 2> lower,
                                   const std::array<double, 2> upper,
                                   const std::uint64_t         seed,
                                   const bool                  periodic)
    : lower(lower)
    , upper(upper)
    , periodic(periodic)
  {
    AssertThrow(n_grains >= 1,
                ExcMessage("Voronoi grains: the number of grains must be at "
                           "least 1."));
    AssertThrow(upper[0] > lower[0] && upper[1] > lower[1],
                ExcMessage("Voronoi grains: empty rectangle."));
    std::mt19937_64 rng(seed);
    // 53 random bits -> [0, 1), the same everywhere.
    auto uniform = [&rng]() { return (rng() >> 11) * 0x1.0p-53; };
    points.resize(n_grains);
    for (auto &p : points)
      for (unsigned int d = 0; d < 2; ++d)
        p[d] = lower[d] + uniform() * (upper[d] - lower[d]);

    n_buckets = std::max(1u, static_cast<unsigned int>(std::sqrt(n_grains)));
    buckets.assign(n_buckets * n_buckets, {});
    for (unsigned int g = 0; g < n_grains; ++g)
      {
        unsigned int b[2];
        for (unsigned int d = 0; d < 2; ++d)
          b[d] = std::min(n_buckets - 1,
                          static_cast<unsigned int>((points[g][d] - lower[d]) /
                                                    (upper[d] - lower[d]) *
                                                    n_buckets));
        buckets[b[1] * n_buckets + b[0]].push_back(g);
      }
  }



  unsigned int
  ColumnarVoronoi::n_grains() const
  {
    return points.size();
  }



  unsigned int
  ColumnarVoronoi::grain(const double x, const double y) const
  {
    const double L[2] = {upper[0] - lower[0], upper[1] - lower[1]};
    const double h[2] = {L[0] / n_buckets, L[1] / n_buckets};
    const int    n    = n_buckets;
    const int    bx =
      std::clamp(static_cast<int>((x - lower[0]) / h[0]), 0, n - 1);
    const int by =
      std::clamp(static_cast<int>((y - lower[1]) / h[1]), 0, n - 1);

    double       best_d2 = std::numeric_limits<double>::max();
    unsigned int best    = 0;
    // Search rings of buckets around (bx, by) until no closer generator is
    // possible. Ties go to the lower generator index.
    for (int r = 0;; ++r)
      {
        for (int j = by - r; j <= by + r; ++j)
          for (int i = bx - r; i <= bx + r; ++i)
            {
              if (std::max(std::abs(i - bx), std::abs(j - by)) != r)
                continue;
              int    ii = i, jj = j;
              double shift[2] = {0., 0.};
              if (periodic)
                {
                  const int wi = ((ii % n) + n) % n, wj = ((jj % n) + n) % n;
                  // (ii - wi) is an exact multiple of n.
                  shift[0] = static_cast<double>((ii - wi) / n) * L[0];
                  shift[1] = static_cast<double>((jj - wj) / n) * L[1];
                  ii       = wi;
                  jj       = wj;
                }
              else if (ii < 0 || jj < 0 || ii >= n || jj >= n)
                continue;
              for (const unsigned int g : buckets[jj * n + ii])
                {
                  const double dx = points[g][0] + shift[0] - x;
                  const double dy = points[g][1] + shift[1] - y;
                  const double d2 = dx * dx + dy * dy;
                  if (d2 < best_d2 || (d2 == best_d2 && g < best))
                    {
                      best_d2 = d2;
                      best    = g;
                    }
                }
            }
        // Every generator not yet seen is at least r * min(h) away.
        const double reach = r * std::min(h[0], h[1]);
        if (best_d2 < reach * reach || (!periodic && r > 2 * n) ||
            (periodic && r > n + 1))
          break;
      }
    return best;
  }



  std::vector<double>
  ColumnarVoronoi::areas(const unsigned int nx, const unsigned int ny) const
  {
    std::vector<double> result(points.size(), 0.);
    const double        dx = (upper[0] - lower[0]) / nx;
    const double        dy = (upper[1] - lower[1]) / ny;
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        result[grain(lower[0] + (i + 0.5) * dx, lower[1] + (j + 0.5) * dy)] +=
          dx * dy;
    return result;
  }



  const std::vector<std::array<double, 2>> &
  ColumnarVoronoi::generators() const
  {
    return points;
  }
} // namespace qsmpm
