#ifndef qsmpm_homogenization_texture_sampler_h
#define qsmpm_homogenization_texture_sampler_h

#include <cstdint>
#include <deal.II/base/tensor.h>
#include <qsmpm/homogenization/orientation_distribution.h>
#include <vector>

namespace qsmpm
{
  /**
   * Texture discretization for grains of unequal size by the algorithm of
   * Melchior and Delannay as described in paper Section 4.3:
   *
   * 1. N_u elementary volumes: N_u uniform random numbers x, each identified
   *    with the ODF cell i with F(i-1) <= x < F(i) and its centre
   *    orientation g_i (sample()).
   * 2. Grains from the largest to the smallest: grain G of volume V_G gets
   *    N_G = N_u V_G / V elementary volumes (rounded by largest remainders
   *    so that the N_G add up to N_u; at least 1; grains of zero volume,
   *    which no material point represents, get none and keep the identity
   *    orientation). From the remaining list, N_G
   *    orientations are chosen whose disorientation (cubic symmetry) to a
   *    seed orientation of the list is below the threshold (default 7
   *    degrees), nearest to the seed first; their mean orientation is the
   *    grain's. Seeds are tried in random order (a seed is a random
   *    remaining elementary volume, so dense regions of the ODF are tried
   *    more often), at most "max seed trials" times, then every remaining
   *    orientation is tried. The chosen orientations leave the list.
   *
   * Fallback (documented; Melchior and Delannay propose a variant for it):
   * if no seed has N_G orientations within the threshold, the seed with the
   * most neighbours within the threshold is used and the set is completed
   * with the next nearest remaining orientations beyond the threshold. Such
   * grains are counted in Result::n_fallback, with the largest
   * disorientation they needed.
   *
   * All random numbers come from a std::mt19937_64 with the given seed and
   * no std:: distributions, so every MPI rank computes the same result.
   */
  class TextureSampler
  {
  public:
    struct Result
    {
      /// Per grain: orientation (Bunge matrix, sample -> crystal).
      std::vector<Tensor<2, 3>> orientations;
      /// Per grain: number of elementary volumes N_G.
      std::vector<unsigned int> n_elementary;
      /// The N_u sampled ODF cells (step 1).
      std::vector<unsigned int> sampled_cells;
      /// Grains that needed the fallback, and its largest disorientation
      /// (radians).
      unsigned int n_fallback         = 0;
      double       max_fallback_angle = 0.;
      /// Misfit (paper Section 4.3) of the N_u sampled orientations, ODF
      /// reconstructed as a histogram on the 5 degree cells.
      double misfit_sampled = 0.;
      /// Misfit of the grain orientations, each weighted by its grain
      /// volume, reconstructed the same way (counted in all cells that hold
      /// a symmetry equivalent).
      double misfit_grains = 0.;
    };

    /**
     * @p threshold in radians; @p max_seed_trials random seeds before the
     * exhaustive search.
     */
    TextureSampler(const unsigned int n_elementary_volumes = 50000,
                   const double       threshold            = 7. * M_PI / 180.,
                   const unsigned int max_seed_trials      = 50);

    /// Step 1 only: N_u cells sampled from the cumulative distribution.
    std::vector<unsigned int>
    sample(const OrientationDistribution &odf, std::uint64_t seed) const;

    /// Steps 1 and 2 for grains with volumes @p grain_volumes.
    Result
    assign(const OrientationDistribution &odf,
           const std::vector<double>     &grain_volumes,
           std::uint64_t                  seed) const;

    /// The histogram of orientations @p g with weights @p w on the cells.
    static std::vector<double>
    histogram(const std::vector<Tensor<2, 3>> &g, const std::vector<double> &w);

  private:
    unsigned int n_u;
    double       threshold;
    unsigned int max_seed_trials;
  };
} // namespace qsmpm

#endif
