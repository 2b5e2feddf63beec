// The set-up shared by the tests of Prandtl's smooth strip footing on a
// weightless c-phi soil (footing_drucker_prager, footing_dilatancy): half
// of the soil (x >= 0), 6 a wide and 4 a deep, a/h = 4 (24 x 16 cells),
// 2 x 2 points per cell, the footing the top nodes with x <= a pushed down
// by 0.02 a, rollers on the sides, the base fixed. Wider than
// tests/footing_plasticity since the mechanism of a c-phi soil is (its
// passive wedge reaches the surface at x = 6.1 a for phi = 20 degrees,
// against 3 a for phi = 0).
#ifndef qsmpm_tests_c_phi_footing_h
#define qsmpm_tests_c_phi_footing_h

#include "tests.h"

#include <deal.II/base/function.h>
#include <functional>
#include <qsmpm/core/quasi_static_problem.h>

namespace c_phi_footing
{
  using namespace qsmpm;

  /// The footing's half-width, the soil's cohesion and its elasticity.
  const double a = 1., c = 100., E = 1e6, nu = 0.3;

  /// Prandtl-Reissner: q_u = c N_c, N_c = (N_q - 1) cot phi,
  /// N_q = exp(pi tan phi) tan^2(pi/4 + phi/2).
  inline double
  bearing_factor(const double phi_degrees)
  {
    const double phi = phi_degrees * numbers::PI / 180.;
    const double Nq  = std::exp(numbers::PI * std::tan(phi)) *
                      std::pow(std::tan(numbers::PI / 4. + phi / 2.), 2);
    return (Nq - 1.) / std::tan(phi);
  }

  /**
   * The .prm text of the tests: 2D, 2 x 2 points per cell with @p locking
   * (and the entries @p points_extra), the model @p model with E, nu, c,
   * phi = psi = @p phi_degrees, no hardening (and the entries
   * @p model_extra), 20 steps, Newton tolerance 1e-9 with 8 line-search
   * steps, no output but into @p directory.
   */
  inline std::string
  prm_text(const std::string &model,
           const std::string &locking,
           const double       phi_degrees,
           const std::string &directory,
           const std::string &points_extra = "",
           const std::string &model_extra  = "")
  {
    std::ostringstream text;
    text << "set Dimension = 2\n"
         << "subsection Material points\n"
         << "  set Points per cell per direction = 2\n"
         << points_extra << "  set Volumetric locking = " << locking
         << "\nend\n"
         << "subsection Material\n  set Model = " << model << "\n"
         << "  subsection " << model << "\n"
         << "    set Young's modulus = " << E << "\n"
         << "    set Poisson's ratio = " << nu << "\n"
         << "    set Cohesion = " << c << "\n"
         << "    set Friction angle = " << phi_degrees << "\n"
         << "    set Dilatancy angle = " << phi_degrees << "\n"
         << "    set Hardening modulus = 0\n"
         << model_extra << "  end\nend\n"
         << "subsection Load stepping\n  set Number of steps = 20\nend\n"
         << "subsection Nonlinear solver\n"
         << "  set Tolerance = 1e-9\n  set Line search steps = 8\nend\n"
         << "subsection Output\n  set Interval = 0\n"
         << "  set Directory = " << directory << "\nend\n";
    return text.str();
  }

  struct Result
  {
    bool completed = false;
    /// The footing's mean pressure over c after each step.
    std::vector<double> pressure_over_c;
    std::string         message;
  };

  /**
   * The footing with the problem's entries @p prm_text (a .prm text of
   * QuasiStaticProblem's parameters; "Dimension" is declared here) on
   * @p comm in 20 steps; @p inspect, if given, sees the problem after a
   * completed run.
   */
  inline Result
  run(const MPI_Comm                                      comm,
      const std::string                                  &prm_text,
      const std::function<void(QuasiStaticProblem<2> &)> &inspect = {})
  {
    ParameterHandler prm;
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
    QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
    prm.parse_input_from_string(prm_text);

    QuasiStaticProblem<2> problem(comm);
    problem.pcout().set_condition(false);
    problem.parameters().parse_parameters(prm);
    problem.grid().make_box(Point<2>(), Point<2>(6., 4.), {{24, 16}});
    problem.set_model(ConstitutiveModelFactory<2>::create(prm));
    problem.points().fill([](const Point<2> &) { return true; },
                          2,
                          MaterialPointSet<2>::Placement::regular);
    auto      &bcs  = problem.boundary_conditions();
    const auto zero = std::make_shared<Functions::ZeroFunction<2>>(2);
    bcs.add_dirichlet_boundary(0, {}, zero, true);
    bcs.add_dirichlet_boundary(1, {}, zero, true);
    bcs.add_dirichlet_boundary(2, {{true, true}}, zero);
    bcs.add_dirichlet_nodes(
      "footing",
      [](const Point<2> &x) { return x[0] <= a + 1e-10 && x[1] > 4. - 1e-10; },
      {{false, true}},
      qsmpm_tests::downward_motion(0.02));

    Result result;
    problem.set_step_callback([&](const QuasiStaticProblem<2>::StepReport &) {
      result.pressure_over_c.push_back(-problem.reactions()[3][1] / a / c);
      return true;
    });
    try
      {
        problem.run();
        result.completed = true;
      }
    catch (const std::exception &exc)
      {
        result.message = exc.what();
        return result;
      }
    if (inspect)
      inspect(problem);
    return result;
  }

  /// The pressure over c after the last step, NaN without steps.
  inline double
  last(const Result &r)
  {
    return r.pressure_over_c.empty() ?
             std::numeric_limits<double>::quiet_NaN() :
             r.pressure_over_c.back();
  }
} // namespace c_phi_footing

#endif
