#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <qsmpm/base/rotation.h>
#include <qsmpm/homogenization/orientation_distribution.h>
#include <set>
#include <sstream>

namespace qsmpm
{
  namespace
  {
    constexpr double degree = M_PI / 180.;

    unsigned int
    node_index(const unsigned int i1,
               const unsigned int iP,
               const unsigned int i2)
    {
      constexpr unsigned int n = OrientationDistribution::n_nodes_per_dir;
      return (i1 * n + iP) * n + i2;
    }
  } // namespace



  OrientationDistribution::OrientationDistribution(const std::string &filename)
  {
    // An ifstream opens a directory without complaint (and then reads
    // nothing), so say what is wrong before "found 0 grid nodes".
    AssertThrow(!std::filesystem::is_directory(filename),
                ExcMessage("ODF file <" + filename +
                           ">: is a directory, not a file."));
    std::ifstream in(filename);
    AssertThrow(in,
                ExcMessage("ODF file <" + filename +
                           ">: cannot be opened (missing or unreadable)."));
    constexpr unsigned int n = n_nodes_per_dir;
    nodes.assign(n * n * n, 0.);
    std::vector<bool> seen(nodes.size(), false);
    std::string       line;
    unsigned int      line_number = 0, n_read = 0;
    while (std::getline(in, line))
      {
        ++line_number;
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#' ||
            line[first] == '%')
          continue;
        std::istringstream s(line);
        double             a[3], value;
        if (!(s >> a[0] >> a[1] >> a[2] >> value))
          {
            // A header line before the data is allowed, but not a line that
            // starts with a number: that is a data line with a bad value
            // (e.g. "0 0 0 nan", which operator>> does not read), and
            // skipping it would only be reported as a missing node.
            std::istringstream first_word(line);
            double             number;
            AssertThrow(n_read == 0 && !(first_word >> number),
                        ExcMessage("ODF file <" + filename + ">, line " +
                                   std::to_string(line_number) +
                                   ": expected \"phi1 Phi phi2 value\" "
                                   "(four numbers), got <" +
                                   line + ">."));
            continue;
          }
        unsigned int index[3];
        for (unsigned int d = 0; d < 3; ++d)
          {
            const double k = a[d] / step_degrees;
            AssertThrow(std::abs(k - std::round(k)) < 1e-6 && k > -0.5 &&
                          k < n - 0.5,
                        ExcMessage("ODF file <" + filename + ">, line " +
                                   std::to_string(line_number) +
                                   ": the angles must lie on the 5 degree "
                                   "grid in [0, 90] degrees (Bunge angles "
                                   "in degrees), got <" +
                                   line + ">."));
            index[d] = static_cast<unsigned int>(std::lround(k));
          }
        AssertThrow(std::isfinite(value),
                    ExcMessage("ODF file <" + filename + ">, line " +
                               std::to_string(line_number) +
                               ": the value is not a finite number."));
        const unsigned int i = node_index(index[0], index[1], index[2]);
        AssertThrow(!seen[i],
                    ExcMessage("ODF file <" + filename + ">, line " +
                               std::to_string(line_number) + ": the node <" +
                               line + "> appears a second time."));
        seen[i]  = true;
        nodes[i] = value;
        ++n_read;
      }
    AssertThrow(n_read == nodes.size(),
                ExcMessage("ODF file <" + filename + ">: found " +
                           std::to_string(n_read) + " grid nodes, expected " +
                           std::to_string(nodes.size()) +
                           " (19^3: phi1, Phi, phi2 = 0, 5, ..., 90 "
                           "degrees)."));
    const double max_value = *std::max_element(nodes.begin(), nodes.end());
    AssertThrow(max_value > 0,
                ExcMessage("ODF file <" + filename +
                           ">: all values are zero (or negative); an ODF "
                           "must be positive somewhere."));
    for (double &v : nodes)
      {
        AssertThrow(v >= -1e-6 * max_value,
                    ExcMessage("ODF file <" + filename + ">: negative value " +
                               std::to_string(v) +
                               "; an ODF is a non-negative density."));
        v = std::max(v, 0.);
      }
    compute_cells();
  }



  OrientationDistribution::OrientationDistribution(
    const std::function<double(double, double, double)> &f)
  {
    constexpr unsigned int n = n_nodes_per_dir;
    nodes.resize(n * n * n);
    for (unsigned int i1 = 0; i1 < n; ++i1)
      for (unsigned int iP = 0; iP < n; ++iP)
        for (unsigned int i2 = 0; i2 < n; ++i2)
          nodes[node_index(i1, iP, i2)] = f(i1 * step_degrees * degree,
                                            iP * step_degrees * degree,
                                            i2 * step_degrees * degree);
    AssertThrow(*std::max_element(nodes.begin(), nodes.end()) > 0,
                ExcMessage("ODF: all values are zero."));
    compute_cells();
  }



  void
  OrientationDistribution::write(const std::string &filename,
                                 const std::string &comment) const
  {
    std::ofstream out(filename);
    AssertThrow(out, ExcMessage("Cannot write <" + filename + ">."));
    out << "% " << comment << "\n"
        << "% Bunge angles in degrees (cubic crystal, orthorhombic sample), "
           "5 degree grid\n"
        << "% phi1 Phi phi2 value\n";
    constexpr unsigned int n = n_nodes_per_dir;
    out << std::setprecision(8);
    for (unsigned int i2 = 0; i2 < n; ++i2)
      for (unsigned int iP = 0; iP < n; ++iP)
        for (unsigned int i1 = 0; i1 < n; ++i1)
          out << i1 * step_degrees << ' ' << iP * step_degrees << ' '
              << i2 * step_degrees << ' ' << nodes[node_index(i1, iP, i2)]
              << '\n';
  }



  unsigned int
  OrientationDistribution::cell_index(const unsigned int i1,
                                      const unsigned int iP,
                                      const unsigned int i2)
  {
    return (i1 * n_cells_per_dir + iP) * n_cells_per_dir + i2;
  }



  std::array<double, 3>
  OrientationDistribution::cell_centre(const unsigned int i)
  {
    const unsigned int i2 = i % n_cells_per_dir;
    const unsigned int iP = (i / n_cells_per_dir) % n_cells_per_dir;
    const unsigned int i1 = i / (n_cells_per_dir * n_cells_per_dir);
    return {{(i1 + 0.5) * step_degrees * degree,
             (iP + 0.5) * step_degrees * degree,
             (i2 + 0.5) * step_degrees * degree}};
  }



  Tensor<2, 3>
  OrientationDistribution::cell_orientation(const unsigned int i)
  {
    const auto a = cell_centre(i);
    return Rotation::from_bunge(a[0], a[1], a[2]);
  }



  const std::vector<double> &
  OrientationDistribution::cell_measures()
  {
    static const std::vector<double> measures = [] {
      std::vector<double> m(n_cells);
      const double        h     = step_degrees * degree;
      double              total = 0;
      for (unsigned int i = 0; i < n_cells; ++i)
        {
          const unsigned int iP = (i / n_cells_per_dir) % n_cells_per_dir;
          // int sin Phi dPhi over the cell, exactly.
          m[i] = h * h * (std::cos(iP * h) - std::cos((iP + 1) * h));
          total += m[i];
        }
      for (double &v : m)
        v /= total;
      return m;
    }();
    return measures;
  }



  void
  OrientationDistribution::compute_cells()
  {
    fractions.resize(n_cells);
    const auto &measure = cell_measures();
    double      total   = 0;
    for (unsigned int i1 = 0; i1 < n_cells_per_dir; ++i1)
      for (unsigned int iP = 0; iP < n_cells_per_dir; ++iP)
        for (unsigned int i2 = 0; i2 < n_cells_per_dir; ++i2)
          {
            double mean = 0;
            for (unsigned int c = 0; c < 8; ++c)
              mean += nodes[node_index(
                i1 + (c & 1), iP + ((c >> 1) & 1), i2 + ((c >> 2) & 1))];
            const unsigned int i = cell_index(i1, iP, i2);
            fractions[i]         = mean / 8. * measure[i];
            total += fractions[i];
          }
    AssertThrow(total > 0,
                ExcMessage("ODF: zero in every cell of the Euler box."));
    F.resize(n_cells);
    double sum = 0;
    for (unsigned int i = 0; i < n_cells; ++i)
      {
        fractions[i] /= total;
        sum += fractions[i];
        F[i] = sum;
      }
    F.back() = 1.;
  }



  const std::vector<double> &
  OrientationDistribution::cell_fractions() const
  {
    return fractions;
  }



  const std::vector<double> &
  OrientationDistribution::cumulative() const
  {
    return F;
  }



  std::vector<unsigned int>
  OrientationDistribution::cells_of(const Tensor<2, 3> &g)
  {
    std::set<unsigned int> cells;
    const double           h   = step_degrees * degree;
    const double           top = 90. * degree + 1e-9;
    for (const auto &Sc : Rotation::cubic_symmetry())
      for (const auto &Ss : Rotation::orthorhombic_symmetry())
        {
          const auto a = Rotation::to_bunge(Sc * g * Ss);
          // phi1 or phi2 of 2 pi - tiny is 0.
          double angles[3] = {a[0] > 2 * M_PI - 1e-9 ? 0. : a[0],
                              a[1],
                              a[2] > 2 * M_PI - 1e-9 ? 0. : a[2]};
          bool inside = true;
          for (double &x : angles)
            inside = inside && x <= top;
          if (!inside)
            continue;
          unsigned int k[3];
          for (unsigned int d = 0; d < 3; ++d)
            k[d] = std::min(n_cells_per_dir - 1,
                            static_cast<unsigned int>(angles[d] / h));
          cells.insert(cell_index(k[0], k[1], k[2]));
        }
    return {cells.begin(), cells.end()};
  }



  double
  OrientationDistribution::misfit(
    const std::vector<double> &reconstructed) const
  {
    AssertThrow(reconstructed.size() == n_cells,
                ExcMessage("misfit: one value per cell is needed."));
    double total = 0;
    for (const double r : reconstructed)
      total += r;
    AssertThrow(total > 0, ExcMessage("misfit: empty reconstruction."));
    // Densities relative to the uniform ODF: f = fraction / measure.
    const auto &measure = cell_measures();
    double      num = 0, den = 0;
    for (unsigned int i = 0; i < n_cells; ++i)
      {
        const double f     = fractions[i] / measure[i];
        const double f_rec = reconstructed[i] / total / measure[i];
        num += (f - f_rec) * (f - f_rec) * measure[i];
        den += f * f * measure[i];
      }
    return num / den;
  }
} // namespace qsmpm
