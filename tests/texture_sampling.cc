// Texture discretization (paper Section 4.3) and the Voigt/Reuss/Hill
// in-plane moduli (paper Table I) against independent references for
// C11, C12, C44 = 249, 155, 114 GPa
// (doc/references.md#nickel-single-crystal-constants-and-bounds):
//
// - for each shipped ODF, N_u = 50,000 orientations sampled from its
//   cumulative distribution reproduce it: misfit < 15 % (the paper's
//   acceptance level; histogram reconstruction on the 5 degree cells);
// - perfect <001> fibre: Reuss / Hill / Voigt = 163.25 / 172.41 / 182.65
//   (Hill here: the harmonic mean of Voigt and Reuss);
// - uniform texture (the shipped uniform ODF's cells):
//   192.77 / 209.73 / 226.30;
// - the shipped electrodeposited-Ni-like ODF has the Hill modulus of the
//   real films, 194.7 GPa (paper Table I): a consistency check of the
//   shipped file only, whose fibre fraction was tuned by bisection to give
//   exactly this value, not a verification of anything;
// - Melchior-Delannay assignment: the N_G add up to N_u, and the grains'
//   orientations keep the texture (Hill modulus of the assigned
//   orientations within 1.5 % of the ODF's);
// - bad ODF files stop with a message naming the cause.
#include "tests.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <qsmpm/base/rotation.h>
#include <qsmpm/homogenization/orientation_distribution.h>
#include <qsmpm/homogenization/stiffness_bounds.h>
#include <qsmpm/homogenization/texture_sampler.h>

using namespace qsmpm;

const std::string odf_directory =
  (std::filesystem::path(__FILE__).parent_path() / ".." / "examples" /
   "polycrystal" / "odf")
    .string();

StiffnessBounds
bounds_of(const OrientationDistribution &odf, const SymmetricTensor<4, 3> &C)
{
  std::vector<Tensor<2, 3>> g;
  std::vector<double>       w;
  for (unsigned int i = 0; i < OrientationDistribution::n_cells; ++i)
    {
      g.push_back(OrientationDistribution::cell_orientation(i));
      w.push_back(odf.cell_fractions()[i]);
    }
  return StiffnessBounds(C, g, w);
}

// A reference value as it is checked, all its digits (format() rounds to
// three).
std::string
reference(const double value)
{
  std::ostringstream s;
  s << std::setprecision(8) << value;
  return s.str();
}

// Hill: E of C_H = (C_V + C_R) / 2 (StiffnessBounds), the reference for
// the uniform texture (from G_Hill); for the fibre the reference Hill value
// is the harmonic mean of the Voigt and Reuss moduli (the Hill average of
// the compliances), so with @p harmonic that is compared instead.
void
check_moduli(const std::string     &name,
             const StiffnessBounds &b,
             const double           R,
             const double           H,
             const double           V,
             const double           tolerance,
             const bool             harmonic = false)
{
  const double E_R = StiffnessBounds::in_plane(b.reuss()).E_in_plane;
  const double E_V = StiffnessBounds::in_plane(b.voigt()).E_in_plane;
  const double E_H = StiffnessBounds::in_plane(b.hill()).E_in_plane;
  std::cout << name << ": Reuss " << E_R << ", Hill " << E_H
            << ", 2 V R / (V + R) " << 2 * E_V * E_R / (E_V + E_R) << ", Voigt "
            << E_V << std::endl;
  check(name + ": Reuss - " + reference(R), E_R - R, tolerance);
  if (harmonic)
    {
      check(name + ": 2 V R / (V + R) - " + reference(H),
            2 * E_V * E_R / (E_V + E_R) - H,
            tolerance);
      check_that(name + ": Reuss < Hill < Voigt", E_R < E_H && E_H < E_V);
    }
  else
    check(name + ": Hill - " + reference(H), E_H - H, tolerance);
  check(name + ": Voigt - " + reference(V), E_V - V, tolerance);
}

void
expect_error(const std::string &what,
             const std::string &file_content,
             const std::string &expected_words)
{
  const std::string name = "bad_odf.txt";
  if (!file_content.empty())
    std::ofstream(name) << file_content;
  try
    {
      OrientationDistribution odf(file_content.empty() ? "missing_odf.txt" :
                                                         name);
      check_that(what + ": stops", false);
    }
  catch (const std::exception &e)
    {
      // deal.II wraps long messages: compare with single spaces.
      std::string message;
      for (const char c : std::string(e.what()))
        if (!std::isspace(c))
          message += c;
        else if (!message.empty() && message.back() != ' ')
          message += ' ';
      check_that(what + ": stops with a message naming the cause",
                 message.find(expected_words) != std::string::npos);
    }
}

int
main()
{
  initlog();
  const auto C = Rotation::cubic_stiffness(249., 155., 114.);

  deallog << "Sampling the shipped ODFs, N_u = 50000" << std::endl;
  const TextureSampler sampler(50000);
  for (const std::string name : {"uniform", "fibre_001", "electrodeposited_ni"})
    {
      const OrientationDistribution odf(odf_directory + "/" + name + ".txt");
      const auto                    cells = sampler.sample(odf, 1);
      std::vector<double>           h(OrientationDistribution::n_cells, 0.);
      for (const unsigned int c : cells)
        h[c] += 1;
      check("  " + name + ": misfit", odf.misfit(h), 0.15);
    }

  deallog << "In-plane moduli (GPa)" << std::endl;
  {
    std::vector<Tensor<2, 3>> g;
    for (unsigned int i = 0; i < 360; ++i)
      g.push_back(Rotation::from_bunge((i + 0.5) * M_PI / 720., 0., 0.));
    check_moduli("  perfect <001> fibre",
                 StiffnessBounds(C, g, std::vector<double>(g.size(), 1.)),
                 163.25,
                 172.41,
                 182.65,
                 0.01,
                 true);
  }
  // 0.5 GPa: the ODF's 5 degree cells (centres weighted with the cell
  // measures) are a quadrature of the orientation average whose error,
  // against the exact uniform-texture values, is at most 0.24 GPa (Voigt;
  // Reuss 0.01, Hill 0.13): the tolerance allows twice that and is far
  // below the 33 GPa between the bounds.
  check_moduli(
    "  uniform (ODF cells)",
    bounds_of(OrientationDistribution(odf_directory + "/uniform.txt"), C),
    192.77,
    209.73,
    226.30,
    0.5);
  const OrientationDistribution ed(odf_directory + "/electrodeposited_ni.txt");
  const double                  ed_hill =
    StiffnessBounds::in_plane(bounds_of(ed, C).hill()).E_in_plane;
  // Not a verification: the fibre fraction of the shipped file was chosen
  // by bisection (polycrystal --make-odfs) so that exactly this value is
  // 194.7 GPa, the measured films' Hill modulus (paper Table I). The check
  // only confirms that the shipped file is still the tuned one (not
  // regenerated with other constants, truncated or replaced). Tolerance
  // 0.05 GPa: half a unit of the paper's last digit, i.e. the file's value
  // rounds to the paper's 194.7 (the file's 8-digit values reproduce the
  // bisection's target far more closely).
  std::cout << "electrodeposited_ni.txt: Hill " << std::setprecision(8)
            << ed_hill << std::setprecision(6) << std::endl;
  check("  electrodeposited_ni.txt (consistency of the shipped file, tuned "
        "to it, not a verification): Hill - 194.7",
        ed_hill - 194.7,
        0.05);

  deallog << "Melchior-Delannay assignment, 300 grains, N_u = 30000"
          << std::endl;
  {
    std::vector<double> volumes(300);
    for (unsigned int g = 0; g < volumes.size(); ++g)
      volumes[g] = 1. + 0.9 * std::sin(1.7 * g); // unequal grains
    const TextureSampler sampler_small(30000);
    const auto           result = sampler_small.assign(ed, volumes, 7);
    unsigned int         sum    = 0;
    for (const unsigned int n : result.n_elementary)
      sum += n;
    check_that("  sum of N_G = N_u", sum == 30000);
    const double hill =
      StiffnessBounds::in_plane(
        StiffnessBounds(C, result.orientations, volumes).hill())
        .E_in_plane;
    std::cout << "assignment: Hill of the grains " << hill << ", of the ODF "
              << ed_hill << std::endl;
    // 1.5 %: 300 grains sample the ODF with a scatter; realizations of
    // 1000 grains scatter by 0.07 % (standard deviation, example_
    // polycrystal.md), i.e. about 0.13 % for 300 grains; 1.5 % is ten times
    // that, and a texture lost in the assignment (uniform: Hill 209.6
    // against 194.7, 7.7 %) fails.
    check("  Hill of the grains / Hill of the ODF - 1",
          hill / ed_hill - 1.,
          0.015);
    check("  misfit of the sampled list", result.misfit_sampled, 0.15);
  }

  deallog << "Bad ODF files" << std::endl;
  expect_error("  missing file", "", "cannot be opened");
  std::string zeros, off_grid = "0 0 0 1\n2.5 0 0 1\n", few = "0 0 0 1\n";
  for (unsigned int i2 = 0; i2 < 19; ++i2)
    for (unsigned int iP = 0; iP < 19; ++iP)
      for (unsigned int i1 = 0; i1 < 19; ++i1)
        zeros += std::to_string(5 * i1) + " " + std::to_string(5 * iP) + " " +
                 std::to_string(5 * i2) + " 0\n";
  expect_error("  all zeros", zeros, "all values are zero");
  expect_error("  off-grid angle", off_grid, "5 degree grid");
  expect_error("  incomplete grid", few, "expected 6859");
  expect_error("  malformed line", "0 0 0 1\n0 0 five 1\n", "four numbers");
}
