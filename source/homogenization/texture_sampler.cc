#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/symmetric_tensor.h>
#include <numeric>
#include <qsmpm/base/rotation.h>
#include <qsmpm/homogenization/texture_sampler.h>
#include <random>

namespace qsmpm
{
  TextureSampler::TextureSampler(const unsigned int n_elementary_volumes,
                                 const double       threshold,
                                 const unsigned int max_seed_trials)
    : n_u(n_elementary_volumes)
    , threshold(threshold)
    , max_seed_trials(max_seed_trials)
  {
    AssertThrow(n_u >= 1,
                ExcMessage("Texture: the number of elementary volumes must "
                           "be at least 1."));
    AssertThrow(threshold > 0,
                ExcMessage("Texture: the disorientation threshold must be "
                           "positive."));
  }



  std::vector<unsigned int>
  TextureSampler::sample(const OrientationDistribution &odf,
                         const std::uint64_t            seed) const
  {
    std::mt19937_64           rng(seed);
    const auto               &F = odf.cumulative();
    std::vector<unsigned int> cells(n_u);
    for (auto &c : cells)
      {
        const double x = (rng() >> 11) * 0x1.0p-53;
        // The cell i with F(i-1) <= x < F(i); empty cells are never hit.
        c = std::min<unsigned int>(std::upper_bound(F.begin(), F.end(), x) -
                                     F.begin(),
                                   F.size() - 1);
      }
    return cells;
  }



  std::vector<double>
  TextureSampler::histogram(const std::vector<Tensor<2, 3>> &g,
                            const std::vector<double>       &w)
  {
    std::vector<double> h(OrientationDistribution::n_cells, 0.);
    for (unsigned int n = 0; n < g.size(); ++n)
      {
        const auto cells = OrientationDistribution::cells_of(g[n]);
        for (const unsigned int c : cells)
          h[c] += w[n] / cells.size();
      }
    return h;
  }



  TextureSampler::Result
  TextureSampler::assign(const OrientationDistribution &odf,
                         const std::vector<double>     &grain_volumes,
                         const std::uint64_t            seed) const
  {
    const unsigned int n_grains = grain_volumes.size();
    AssertThrow(n_grains >= 1, ExcMessage("Texture: no grains."));
    AssertThrow(n_u >= n_grains,
                ExcMessage("Texture: fewer elementary volumes (" +
                           std::to_string(n_u) + ") than grains (" +
                           std::to_string(n_grains) + ")."));
    Result result;
    result.sampled_cells = sample(odf, seed);

    // Misfit of the sampled list: its histogram against the ODF's cells.
    constexpr unsigned int n_cells = OrientationDistribution::n_cells;
    std::vector<double>    counts_d(n_cells, 0.);
    for (const unsigned int c : result.sampled_cells)
      counts_d[c] += 1.;
    result.misfit_sampled = odf.misfit(counts_d);

    // N_G by largest remainders, at least one per grain of positive
    // volume; grains of zero volume (no material point) get none.
    const double total_volume =
      std::accumulate(grain_volumes.begin(), grain_volumes.end(), 0.);
    AssertThrow(total_volume > 0, ExcMessage("Texture: zero grain volume."));
    unsigned int n_occupied = 0;
    result.n_elementary.assign(n_grains, 0);
    for (unsigned int g = 0; g < n_grains; ++g)
      if (grain_volumes[g] > 0)
        {
          result.n_elementary[g] = 1;
          ++n_occupied;
        }
    {
      const unsigned int  free = n_u - n_occupied;
      std::vector<double> remainder(n_grains, -1.);
      unsigned int        given = 0;
      for (unsigned int g = 0; g < n_grains; ++g)
        if (grain_volumes[g] > 0)
          {
            const double share =
              std::max(0., n_u * grain_volumes[g] / total_volume - 1.);
            const unsigned int whole =
              std::min<unsigned int>(std::floor(share), free - given);
            result.n_elementary[g] += whole;
            given += whole;
            remainder[g] = share - whole;
          }
      std::vector<unsigned int> order(n_grains);
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(), [&](unsigned a, unsigned b) {
        return remainder[a] > remainder[b];
      });
      for (unsigned int k = 0; given < free; k = (k + 1) % n_occupied, ++given)
        ++result.n_elementary[order[k]];
    }

    // The remaining list, as counts per cell (orientations are cell
    // centres).
    std::vector<unsigned int> remaining(n_cells, 0);
    for (const unsigned int c : result.sampled_cells)
      ++remaining[c];
    unsigned int n_remaining = n_u;

    std::vector<Tensor<2, 3>> centre(n_cells);
    for (unsigned int c = 0; c < n_cells; ++c)
      centre[c] = OrientationDistribution::cell_orientation(c);

    // Cells within the threshold of a seed cell, nearest first (cached).
    std::vector<std::vector<std::pair<double, unsigned int>>> neighbours(
      n_cells);
    std::vector<bool> has_neighbours(n_cells, false);
    auto              near = [&](const unsigned int s)
      -> const std::vector<std::pair<double, unsigned int>> & {
      if (!has_neighbours[s])
        {
          for (unsigned int c = 0; c < n_cells; ++c)
            if (remaining[c] > 0 || c == s)
              {
                const double a =
                  Rotation::disorientation(centre[s], centre[c], threshold);
                if (a < threshold)
                  neighbours[s].emplace_back(a, c);
              }
          std::sort(neighbours[s].begin(), neighbours[s].end());
          has_neighbours[s] = true;
        }
      return neighbours[s];
    };
    auto available = [&](const unsigned int s) {
      unsigned int n = 0;
      for (const auto &[a, c] : near(s))
        n += remaining[c];
      return n;
    };

    std::mt19937_64           rng(seed ^ 0x9e3779b97f4a7c15ull);
    std::vector<unsigned int> grains(n_grains);
    std::iota(grains.begin(), grains.end(), 0);
    std::stable_sort(grains.begin(), grains.end(), [&](unsigned a, unsigned b) {
      return grain_volumes[a] > grain_volumes[b];
    });

    result.orientations.assign(n_grains,
                               Tensor<2, 3>(unit_symmetric_tensor<3>()));
    for (const unsigned int G : grains)
      {
        const unsigned int N_G = result.n_elementary[G];
        if (N_G == 0)
          continue;
        int seed_cell = -1;
        // Random seeds: a random remaining elementary volume.
        for (unsigned int trial = 0; trial < max_seed_trials && seed_cell < 0;
             ++trial)
          {
            unsigned long k = (rng() >> 11) % n_remaining;
            unsigned int  c = 0;
            while (k >= remaining[c])
              k -= remaining[c++];
            if (available(c) >= N_G)
              seed_cell = c;
          }
        // Then every remaining orientation, the one with most neighbours.
        unsigned int best_count = 0, best_cell = 0;
        if (seed_cell < 0)
          for (unsigned int c = 0; c < n_cells && seed_cell < 0; ++c)
            if (remaining[c] > 0)
              {
                const unsigned int n = available(c);
                if (n >= N_G)
                  seed_cell = c;
                else if (n > best_count)
                  {
                    best_count = n;
                    best_cell  = c;
                  }
              }

        // Collect N_G orientations, nearest to the seed first.
        std::vector<std::pair<double, unsigned int>> candidates;
        bool                                         fallback = seed_cell < 0;
        if (!fallback)
          candidates = near(seed_cell);
        else
          {
            // Fallback: all remaining cells by disorientation to the best
            // seed.
            seed_cell = best_cell;
            for (unsigned int c = 0; c < n_cells; ++c)
              if (remaining[c] > 0)
                candidates.emplace_back(
                  Rotation::disorientation(centre[seed_cell], centre[c]), c);
            std::sort(candidates.begin(), candidates.end());
          }
        std::vector<Tensor<2, 3>> chosen;
        std::vector<double>       weights;
        chosen.push_back(centre[seed_cell]);
        weights.push_back(0.);
        unsigned int needed = N_G;
        double       widest = 0;
        for (const auto &[a, c] : candidates)
          {
            if (needed == 0)
              break;
            const unsigned int take = std::min(needed, remaining[c]);
            if (take == 0)
              continue;
            chosen.push_back(centre[c]);
            weights.push_back(take);
            remaining[c] -= take;
            n_remaining -= take;
            needed -= take;
            widest = std::max(widest, a);
          }
        AssertThrow(needed == 0, ExcInternalError());
        if (fallback)
          {
            ++result.n_fallback;
            result.max_fallback_angle =
              std::max(result.max_fallback_angle, widest);
          }
        result.orientations[G] = Rotation::mean(chosen, weights);
      }

    std::vector<double> w(n_grains);
    for (unsigned int g = 0; g < n_grains; ++g)
      w[g] = grain_volumes[g];
    result.misfit_grains = odf.misfit(histogram(result.orientations, w));
    return result;
  }
} // namespace qsmpm
