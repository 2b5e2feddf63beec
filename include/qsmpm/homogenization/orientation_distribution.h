#ifndef qsmpm_homogenization_orientation_distribution_h
#define qsmpm_homogenization_orientation_distribution_h

#include <array>
#include <deal.II/base/tensor.h>
#include <functional>
#include <string>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * An orientation distribution function (ODF) f(g) of cubic crystals in a
   * sample with orthorhombic symmetry, given on the 5 degree grid of Bunge
   * angles 0 <= phi1, Phi, phi2 <= 90 degrees (paper Section 4.1, eq. 4.1),
   * and its discretization into the N = 18^3 cells C_i of that grid (paper
   * Section 4.3):
   *
   *   f_i = int_{C_i} f(g) dg / int f(g) dg,   dg = sin Phi dphi1 dPhi dphi2,
   *
   * with f on a cell the mean of its 8 corner values and the sin Phi volume
   * element integrated exactly over the cell; the cumulative distribution
   * F(M) = sum_{i<=M} f_i; and the misfit of a reconstructed ODF (paper,
   * after the algorithm of Section 4.3).
   *
   * File format (plain text, the plain grid export of texture tools such as
   * MTEX restricted to the 0-90 degree box, or written by any program): one
   * grid node per
   * line, "phi1 Phi phi2 value", angles in degrees, all 19^3 = 6859 nodes
   * of the 5 degree grid exactly once, in any order. Empty lines and lines
   * starting with '#' or '%' are comments; non-numeric lines before the
   * first node (column headers) are skipped. Values are densities in any
   * unit (normalized here); small negative values (above -1e-6 of the
   * maximum, round-off of series expansions) are set to zero.
   */
  class OrientationDistribution
  {
  public:
    /// Grid step (degrees), nodes and cells per angle.
    static constexpr double       step_degrees    = 5.;
    static constexpr unsigned int n_nodes_per_dir = 19;
    static constexpr unsigned int n_cells_per_dir = 18;
    static constexpr unsigned int n_cells =
      n_cells_per_dir * n_cells_per_dir * n_cells_per_dir;

    /// Read an ODF file; throws with a message naming the file and the cause.
    explicit OrientationDistribution(const std::string &filename);

    /// An ODF from a function of the Bunge angles (radians) at the nodes.
    explicit OrientationDistribution(
      const std::function<double(double, double, double)> &f);

    /// Write the node values in the file format above.
    void
    write(const std::string &filename, const std::string &comment) const;

    /// Cell index of the cell numbers (i1, iP, i2) of phi1, Phi, phi2.
    static unsigned int
    cell_index(const unsigned int i1,
               const unsigned int iP,
               const unsigned int i2);

    /// Bunge angles (radians) of the centre of cell @p i.
    static std::array<double, 3>
    cell_centre(const unsigned int i);

    /// Orientation matrix of the centre of cell @p i.
    static Tensor<2, 3>
    cell_orientation(const unsigned int i);

    /// The volume fractions f_i of the cells (sum 1).
    const std::vector<double> &
    cell_fractions() const;

    /// The cumulative distribution F(M) (last entry 1).
    const std::vector<double> &
    cumulative() const;

    /// Measure of cell i in Euler space, int_{C_i} dg, over that of the box.
    static const std::vector<double> &
    cell_measures();

    /**
     * The cells of the 0-90 degree box that hold orientation @p g or one of
     * its symmetry equivalents S_c g S_s (24 cubic S_c, 4 orthorhombic
     * S_s); usually 3 (the box holds the cubic-orthorhombic fundamental
     * zone three times).
     */
    static std::vector<unsigned int>
    cells_of(const Tensor<2, 3> &g);

    /**
     * The misfit of paper Section 4.3,
     *   int (f - f_rec)^2 dg / int f^2 dg,
     * with both ODFs piecewise constant on the cells; f_rec is given by its
     * cell volume fractions @p reconstructed (any positive scale).
     */
    double
    misfit(const std::vector<double> &reconstructed) const;

  private:
    void
    compute_cells();

    /// Node values, index (i1 * 19 + iP) * 19 + i2.
    std::vector<double> nodes;
    std::vector<double> fractions;
    std::vector<double> F;
  };
} // namespace qsmpm

#endif
