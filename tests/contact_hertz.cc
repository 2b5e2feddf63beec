// Hertz contact in plane strain (doc/contact.md#hertz): a rigid cylinder of
// radius R = 1 pressed into an elastic block (E = 1000, nu = 0.3), the
// .prm route (Boundary conditions/Rigid body, Shape = sphere), frictionless.
//
// Hertz's solution for a cylinder on a half-plane (Johnson, Contact
// Mechanics, 1985, eqs. 4.43-4.45; the complementary problem of an elastic
// cylinder on a rigid plane has the same contact solution with the same
// E*): for the force P per unit length the contact half-width and the peak
// pressure are
//
//   a = sqrt(4 P R / (pi E*)),  p0 = 2 P / (pi a),  E* = E / (1 - nu^2),
//
// and the pressure is p(x) = p0 sqrt(1 - x^2 / a^2). The half-width is
// measured from the points' contact tractions by the second moment of the
// pressure, which for Hertz's ellipse is a^2 / 4: a_m = 2 sqrt(int p x^2 /
// int p), and the peak pressure as the largest traction of a point.
//
// The half block [0, 0.6]^2 (symmetry at x = 0, rollers at x = 0.6, fixed
// base); the cylinder moves down by 0.01, which gives a = 0.088: 3.5, 7
// and 14 cells of the three grids (24, 48 and 96 cells per side); cpGIMP,
// 2 x 2 points per cell, 5 load steps. The block is 6.8 a deep and wide,
// not a half-plane; that part of the error is not separated from the
// discretization's here (it is within what the checks allow).
//
// The penalty factor is 1: with 2 x 2 points per cell there are twice as
// many contact points along the surface as nodes, and a penalty that
// dominates the material's stiffness over-constrains them: the points'
// tractions then alternate from point to point while their sum stays
// right (measured: largest traction +58 % of p0 at a/h = 7 with
// gamma = 100; gamma = 10 gives -0.7 % at a/h = 14). With gamma = 1 the
// penalty's compliance makes a too large and p0 too small, by an error
// that falls with h (epsilon = gamma kbar / h).
//
// Each run writes the points' pressure, x / a and p / p0, to
// pressure-<cells>.csv (the picture in doc/contact.md).
//
// Checks: at the finest grid (a/h = 14) a_m and the peak pressure within
// 3 % of Hertz's (the tolerance); both errors fall under each
// refinement (a/h = 3.5, 7, 14); the cylinder's force equals the base's
// reaction (global equilibrium) to 1e-6.
#include "prm_text.h"
#include "tests.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>

using namespace qsmpm;

namespace
{
  const double E = 1000., nu = 0.3, R = 1., W = 0.6;

  struct Result
  {
    double a_error = 0., p_error = 0., balance = 0., a_over_h = 0.;
  };

  Result
  run(const unsigned int cells)
  {
    std::ostringstream text;
    text << "set Dimension = 2\n"
         << "subsection Geometry\n  set Lower corner = 0,0\n"
         << "  set Upper corner = " << W << "," << W
         << "\n  set Subdivisions = " << cells << "," << cells << "\nend\n"
         << "subsection Material points\n"
         << "  set Points per cell per direction = 2\n"
         << "  set Shape functions = cpGIMP\nend\n"
         << "subsection Material\n  set Model = linear elastic\n"
         << "  subsection linear elastic\n"
         << "    set Young's modulus = " << E << "\n"
         << "    set Poisson's ratio = " << nu << "\n  end\nend\n"
         << "subsection Boundary conditions\n"
         << "  set Dirichlet boundaries = 0:x, 1:x, 2:xy\n"
         << "  subsection Rigid body\n"
         << "    set Shape = sphere\n    set Name = cylinder\n"
         << "    set Point = 0, " << W + R << "\n"
         << "    set Radius = " << R << "\n"
         << "    set Penalty factor = 1\n"
         << "    subsection Motion\n"
         << "      set Function expression = 0; -0.01*t\n"
         << "    end\n  end\nend\n"
         << "subsection Load stepping\n  set Number of steps = 5\nend\n"
         << "subsection Nonlinear solver\n  set Tolerance = 1e-8\nend\n"
         << "subsection Output\n  set Interval = 0\n"
         << "  set Directory = contact-out\nend\n";
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    initialize_from_text(problem, text.str());
    problem.run();

    // Hertz's a and p0 for the force of the whole cylinder (twice the half
    // block's).
    const double h      = W / cells;
    const double P      = 2. * std::abs(problem.rigid_body_loads()[0].force[1]);
    const double E_star = E / (1. - nu * nu);
    const double a      = std::sqrt(4. * P * R / (numbers::PI * E_star));
    const double p0     = 2. * P / (numbers::PI * a);

    // The pressure's moments over the points' contact tractions (a point
    // of the top row stands for the width h / 2 of the surface).
    const auto         &offsets = problem.points().get_offsets();
    double              force = 0., second_moment = 0., peak = 0.;
    std::vector<double> profile; // x / a, p / p0 of each point in contact
    for (const auto &particle : problem.points().get_particle_handler())
      {
        const double p = -particle.get_properties()[offsets.contact + 1];
        if (p <= 0.)
          continue;
        const double x = particle.get_location()[0];
        force += p * h / 2.;
        second_moment += p * h / 2. * x * x;
        peak = std::max(peak, p);
        profile.insert(profile.end(), {x / a, p / p0});
      }
    // The pressure profile for the picture in doc/contact.md (rank 0).
    std::vector<std::pair<double, double>> all;
    for (const auto &part : Utilities::MPI::gather(MPI_COMM_WORLD, profile))
      for (unsigned int i = 0; i + 1 < part.size(); i += 2)
        all.emplace_back(part[i], part[i + 1]);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::sort(all.begin(), all.end());
        std::ofstream csv("pressure-" + std::to_string(cells) + ".csv");
        csv << "x_over_a,p_over_p0\n";
        for (const auto &[x, p] : all)
          csv << x << ',' << p << '\n';
      }
    force         = Utilities::MPI::sum(force, MPI_COMM_WORLD);
    second_moment = Utilities::MPI::sum(second_moment, MPI_COMM_WORLD);
    peak          = Utilities::MPI::max(peak, MPI_COMM_WORLD);

    Result result;
    result.a_over_h = a / h;
    result.a_error  = 2. * std::sqrt(second_moment / force) / a - 1.;
    result.p_error  = peak / p0 - 1.;
    result.balance  = std::abs(problem.rigid_body_loads()[0].force[1] -
                              problem.reactions().at(2)[1]) /
                     (P / 2.);
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::MPILogInitAll       log;

  deallog << "Rigid cylinder R = 1 on an elastic block, plane strain, "
             "against Hertz"
          << std::endl;
  std::vector<Result> results;
  for (const unsigned int cells : {24u, 48u, 96u})
    {
      results.push_back(run(cells));
      const Result &r = results.back();
      deallog << "  " << cells << " x " << cells
              << " cells, a/h = " << std::fixed << std::setprecision(1)
              << r.a_over_h << std::defaultfloat << std::endl;
      check("    cylinder's force = base's reaction (relative)",
            r.balance,
            1e-6);
    }
  const Result &finest = results.back();
  check("a/h = 14: |a_m / a_Hertz - 1|", finest.a_error, 0.03);
  check("a/h = 14: |p_max / p0_Hertz - 1|", finest.p_error, 0.03);
  for (unsigned int i = 1; i < results.size(); ++i)
    {
      check_that("refinement " + std::to_string(i) + ": the error of a falls",
                 std::abs(results[i].a_error) <
                   std::abs(results[i - 1].a_error));
      check_that("refinement " + std::to_string(i) +
                   ": the error of p_max falls",
                 std::abs(results[i].p_error) <
                   std::abs(results[i - 1].p_error));
    }
  deallog << "observed order of a_m's error, last refinement: "
          << std::setprecision(1)
          << std::log2(results[1].a_error / results[2].a_error) << std::endl;
}
