// Tractions that follow the body (issue 35): a traction on the body's own
// surface, carried by its surface points.
//
// A block of length L = 6 and height (and depth) 1 in a grid of cells of
// size h = 1 that leaves room ahead of it, 2 points per cell and direction,
// on rollers at x = 0, y = 0 (and z = 0), pulled at its end x = 6 by a
// surface traction (Boundary conditions/Surface traction region = x > 5.99)
// in 10 steps. Hencky, E = 1000, nu = 0.3. The deformation is homogeneous:
// a stretch lambda along x and lambda_t = lambda^(-nu') across, with
// nu' = nu / (1 - nu) in plane strain and nu' = nu in 3D, and Kirchhoff
// stress tau_xx = E' ln(lambda), E' = E / (1 - nu^2) in plane strain, E in
// 3D. The load decides lambda:
//  - dead (a force per unit initial area t0 t, fixed along x): the nominal
//    stress P_xx = tau_xx / lambda = t0 t, i.e. E' ln(lambda) / lambda =
//    t0 t; Cauchy sigma_xx = t0 t / lambda_t^(dim - 1).
//  - pressure (a follower: -p on the current surface, p = -p0 t pulls):
//    sigma_xx = p0 t, i.e. E' ln(lambda) = J p0 t with J = lambda
//    lambda_t^(dim - 1).
// The references solve these scalar equations by bisection (independent of
// the code); t0 is chosen so that lambda = 1.5 at the end: the end moves by
// 3 cells, across three rows of nodes that had no material at the start.
// Checks every step: the applied load is the resultant of the traction
// (t0 t A0, or p0 t times the current area) to 1e-6 (a pressure acts on the
// current area, as accurate as the solution); the rollers' reaction balances it
// to 1e-6 (the Newton tolerance); the points' displacements are the homogeneous
// field to 1e-5 of the end's displacement and the stress to 1e-5 relative (a
// homogeneous field is reproduced by cpGIMP up to the solver tolerance; the
// Newton tolerance is 1e-6 of each step's first residual).
//
// Further: small strain (linear elastic, dead, plane strain) gives
// sigma_xx = t0 and u_x = t0 (1 - nu^2) x / E, u_y = -nu (1 + nu) t0 y / E;
// with linear shape functions (whose cell crossing spoils the homogeneous field
// at this stretch, so only the loads are checked) the load is kept at the body;
// a region that selects no face of the body stops the run with a message naming
// it.
//
// The same checks pass on 1 and 2 ranks.
#include "tests.h"

#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <sstream>
#include <vector>

namespace
{
  constexpr double E = 1000., nu = 0.3, L = 6.;

  /// @p x with all its digits, for a parameter file.
  std::string
  exact_string(const double x, const int digits)
  {
    std::ostringstream s;
    s << std::setprecision(digits) << x;
    return s.str();
  }

  /// The root of @p f on [a, b] (f(a) < 0 < f(b)) by bisection.
  double
  bisect(const std::function<double(double)> &f, double a, double b)
  {
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double m      = 0.5 * (a + b);
        (f(m) < 0. ? a : b) = m;
      }
    return 0.5 * (a + b);
  }

  template <int dim>
  struct Uniaxial
  {
    double E_eff  = dim == 2 ? E / (1. - nu * nu) : E;
    double nu_eff = dim == 2 ? nu / (1. - nu) : nu;

    double
    transverse(const double lambda) const
    {
      return std::pow(lambda, -nu_eff);
    }

    double
    J(const double lambda) const
    {
      return lambda * std::pow(transverse(lambda), dim - 1);
    }

    /// lambda under the dead nominal stress P.
    double
    dead(const double P) const
    {
      return bisect([&](double l) { return E_eff * std::log(l) / l - P; },
                    1.,
                    std::exp(1.));
    }

    /// lambda under the Cauchy stress sigma.
    double
    follower(const double sigma) const
    {
      return bisect(
        [&](double l) { return E_eff * std::log(l) - J(l) * sigma; }, 1., 10.);
    }
  };

  template <int dim>
  std::string
  block(const std::string &model,
        const std::string &kinematics,
        const std::string &shape_functions,
        const std::string &region,
        const std::string &type,
        const std::string &traction)
  {
    const std::string c = dim == 2 ? "" : ",0";
    return "subsection Geometry\n"
           "  set Lower corner = 0,0" +
           c + "\n  set Upper corner = 10,2" + (dim == 2 ? "" : ",2") +
           "\n  set Subdivisions = 10,2" + (dim == 2 ? "" : ",2") +
           "\nend\n"
           "subsection Material points\n"
           "  set Region lower corner = 0,0" +
           c + "\n  set Region upper corner = 6,1" + (dim == 2 ? "" : ",1") +
           "\n  set Points per cell per direction = 2\n"
           "  set Kinematics = " +
           kinematics + "\n  set Shape functions = " + shape_functions +
           "\nend\n"
           "subsection Material\n"
           "  set Model = " +
           model + "\n  subsection " + model +
           "\n    set Young's modulus = 1000\n"
           "    set Poisson's ratio = 0.3\n"
           "  end\n"
           "end\n"
           "subsection Boundary conditions\n"
           "  set Dirichlet boundaries = 0:x, 2:y" +
           (dim == 2 ? "" : ", 4:z") +
           "\n  set Surface traction region = " + region +
           "\n  set Surface traction type = " + type +
           "\n  subsection Surface traction\n"
           "    set Function expression = " +
           traction + (dim == 2 ? "; 0" : "; 0; 0") +
           "\n  end\n"
           "end\n"
           "subsection Load stepping\n"
           "  set Number of steps = 10\n"
           "end\n"
           "subsection Output\n"
           "  set Interval = 0\n"
           "  set Directory = surface-traction-out\n"
           "end\n";
  }

  /// What a run gave per step.
  template <int dim>
  struct Outcome
  {
    bool                stopped = false;
    std::string         message;
    std::vector<double> t, applied, reaction, imbalance;
    /// The largest |u - u_exact| and |sigma_xx - exact| of each step.
    std::vector<double> u_error, stress_error;
  };

  /// Run @p input; @p exact gives (lambda, lambda_t, sigma_xx) at t.
  template <int dim>
  Outcome<dim>
  run(const std::string                                  &what,
      const std::string                                  &input,
      const std::function<std::array<double, 3>(double)> &exact)
  {
    ParameterHandler prm;
    qsmpm::QuasiStaticProblem<dim>::Parameters::declare_parameters(prm);
    Outcome<dim> outcome;
    try
      {
        prm.parse_input_from_string(input);
        qsmpm::QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
        problem.pcout().set_condition(false);
        problem.initialize(prm);
        problem.set_step_callback([&](const qsmpm::StepReport &report) {
          const auto &balance = problem.equilibrium();
          outcome.t.push_back(report.load_factor);
          outcome.applied.push_back(balance.applied[0]);
          outcome.reaction.push_back(balance.reactions[0][0]);
          outcome.imbalance.push_back(balance.imbalance());
          const auto [lambda, lambda_t, sigma] = exact(report.load_factor);
          const auto &offsets                  = problem.points().get_offsets();
          double      u_error = 0., stress_error = 0.;
          for (const auto &particle : problem.points().get_particle_handler())
            {
              const auto       data = particle.get_properties();
              const Point<dim> x    = particle.get_location();
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const double u = data[offsets.displacement + d];
                  const double X = x[d] - u;
                  const double u_exact =
                    ((d == 0 ? lambda : lambda_t) - 1.) * X;
                  u_error = std::max(u_error, std::abs(u - u_exact));
                }
              stress_error =
                std::max(stress_error, std::abs(data[offsets.stress] - sigma));
            }
          outcome.u_error.push_back(
            Utilities::MPI::max(u_error, MPI_COMM_WORLD));
          outcome.stress_error.push_back(
            Utilities::MPI::max(stress_error, MPI_COMM_WORLD));
          return true;
        });
        problem.run();
      }
    catch (const std::exception &exc)
      {
        outcome.stopped = true;
        outcome.message = qsmpm::Utils::error_message(exc);
      }
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << what << ": "
                << (outcome.stopped ? "stopped: " : "ran to the end")
                << outcome.message << std::endl;
    return outcome;
  }

  /// The load checks of every step: the applied load is @p resultant(t)
  /// and the rollers carry it, both to 1e-6 (the Newton tolerance: a
  /// pressure acts on the current area, which is as accurate as the
  /// solution).
  template <int dim>
  void
  check_loads(const Outcome<dim>                  &outcome,
              const std::function<double(double)> &resultant)
  {
    check_that("  runs 10 steps", !outcome.stopped && outcome.t.size() == 10);
    // A run that stopped early fails every check (NaN).
    const double none    = outcome.t.size() == 10 ? 0. : std::nan("");
    double       applied = none, balance = none;
    for (unsigned int i = 0; i < outcome.t.size(); ++i)
      {
        const double R = resultant(outcome.t[i]);
        applied = std::max(applied, std::abs(outcome.applied[i] - R) / R);
        balance =
          std::max(balance,
                   std::abs(outcome.applied[i] + outcome.reaction[i]) / R);
        balance = std::max(balance, outcome.imbalance[i]);
      }
    check("  max over steps |applied - resultant| / resultant", applied, 1e-6);
    check("  max over steps |applied + reaction| / resultant", balance, 1e-6);
  }

  /// The field checks of every step.
  template <int dim>
  void
  check_field(const Outcome<dim> &outcome,
              const double        end_displacement,
              const double        stress)
  {
    const double none = outcome.u_error.size() == 10 ? 0. : std::nan("");
    double       u = none, s = none;
    for (unsigned int i = 0; i < outcome.u_error.size(); ++i)
      {
        u = std::max(u, outcome.u_error[i] / end_displacement);
        s = std::max(s, outcome.stress_error[i] / stress);
      }
    check("  max |u - u_exact| / end displacement", u, 1e-5);
    check("  max |sigma_xx - exact| / final sigma_xx", s, 1e-5);
  }

  template <int dim>
  void
  finite_strain(const std::string &shape_functions)
  {
    const Uniaxial<dim> bar;
    const double        lambda = 1.5;
    // Dead: P = t0 t with lambda(1) = 1.5.
    const double t0 = bar.E_eff * std::log(lambda) / lambda;
    deallog << dim << "D, finite strain, " << shape_functions
            << ", dead traction (the end moves by 3 cells)" << std::endl;
    const auto dead =
      run<dim>("dead",
               block<dim>("hencky",
                          "finite strain",
                          shape_functions,
                          "x > 5.99",
                          "dead",
                          exact_string(t0, 17) + "*t"),
               [&](double t) -> std::array<double, 3> {
                 const double l = bar.dead(t0 * t);
                 return {{l,
                          bar.transverse(l),
                          t0 * t / std::pow(bar.transverse(l), dim - 1)}};
               });
    check_loads(dead, [&](double t) { return t0 * t; });
    check_field(dead,
                (lambda - 1.) * L,
                t0 / std::pow(bar.transverse(1.5), dim - 1));

    // Pressure: sigma = p0 t with lambda(1) = 1.5.
    const double p0 = bar.E_eff * std::log(lambda) / bar.J(lambda);
    deallog << dim << "D, finite strain, " << shape_functions
            << ", pressure (a follower load)" << std::endl;
    const auto pressure =
      run<dim>("pressure",
               block<dim>("hencky",
                          "finite strain",
                          shape_functions,
                          "x > 5.99",
                          "pressure",
                          "-" + exact_string(p0, 17) + "*t"),
               [&](double t) -> std::array<double, 3> {
                 const double l = bar.follower(p0 * t);
                 return {{l, bar.transverse(l), p0 * t}};
               });
    check_loads(pressure, [&](double t) {
      // The current area of the end: lambda_t^(dim - 1) A0, A0 = 1.
      return p0 * t * std::pow(bar.transverse(bar.follower(p0 * t)), dim - 1);
    });
    check_field(pressure, (lambda - 1.) * L, p0);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  finite_strain<2>("cpGIMP");
  finite_strain<3>("cpGIMP");

  deallog << "2D, small strain, linear, dead traction" << std::endl;
  {
    // A load small enough (strain 1e-6) that the paper's incremental
    // small-strain update on the moving points (relative differences of
    // the order of the strain) is the linear solution to 1e-5.
    const double t0     = 1e-3;
    const double strain = t0 * (1. - nu * nu) / E;
    const auto   small  = run<2>(
      "small strain",
      block<2>("linear elastic",
               "small strain",
               "linear",
               "x > 5.99",
               "dead",
               "1e-3*t"),
      [&](double t) -> std::array<double, 3> {
        return {{1. + strain * t, 1. - nu * (1. + nu) * t0 * t / E, t0 * t}};
      });
    check_loads(small, [&](double t) { return t0 * t; });
    check_field(small, strain * L, t0);
  }

  deallog << "2D, finite strain, linear, dead traction: the load stays"
          << std::endl;
  {
    const Uniaxial<2> bar;
    const double      t0     = bar.E_eff * std::log(1.2) / 1.2;
    const auto        linear = run<2>("linear",
                               block<2>("hencky",
                                        "finite strain",
                                        "linear",
                                        "x > 5.99",
                                        "dead",
                                        exact_string(t0, 17) + "*t"),
                               [](double) -> std::array<double, 3> {
                                 return {{1., 1., 0.}};
                               });
    check_loads(linear, [&](double t) { return t0 * t; });
  }

  deallog << "A region that selects no face of the body" << std::endl;
  {
    const auto none = run<2>(
      "no face",
      block<2>("hencky", "finite strain", "cpGIMP", "x > 8", "dead", "1"),
      [](double) -> std::array<double, 3> {
        return {{1., 1., 0.}};
      });
    check_that("  stops", none.stopped);
    check_that("  the message names the entry",
               none.message.find("selects no face") != std::string::npos);
  }
}
