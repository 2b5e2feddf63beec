// Prandtl's smooth strip footing as prescribed grid nodes, the set-up of
// the footing tests of small-strain plasticity (footing_plasticity,
// footing_drucker_prager, footing_dilatancy): half of the soil (x >= 0),
// 4 a deep and a given width, a/h = 4, 2 x 2 points per cell, the footing
// the top nodes with x <= a pushed down by 0.02 a, rollers on the sides,
// the base fixed.
#ifndef qsmpm_tests_nodal_footing_h
#define qsmpm_tests_nodal_footing_h

#include "tests.h"

#include <deal.II/base/function.h>
#include <functional>
#include <qsmpm/core/quasi_static_problem.h>

namespace nodal_footing
{
  using namespace qsmpm;

  /// The footing's half-width.
  const double a = 1.;

  struct Result
  {
    bool completed = false;
    /// The footing's mean pressure over c after each step.
    std::vector<double> pressure_over_c;
    std::string         message;
  };

  /**
   * The footing on a soil @p width a wide with the problem's entries
   * @p prm_text (a .prm text of QuasiStaticProblem's parameters with the
   * points per cell, the model, the steps and the solver; "Dimension" is
   * declared here) on @p comm; the pressure is given over @p c.
   * @p inspect, if given, sees the problem after a completed run. With
   * @p radius > 0 the soil is the ring r in [radius, radius + width] of an
   * axisymmetric problem (the entries must set Axisymmetric = true), the
   * footing the ring r <= radius + a, and the pressure its force per
   * radian over its area per radian, a (radius + a / 2).
   */
  inline Result
  run(const MPI_Comm                                      comm,
      const std::string                                  &prm_text,
      const double                                        width,
      const double                                        c,
      const std::function<void(QuasiStaticProblem<2> &)> &inspect = {},
      const double                                        radius  = 0.)
  {
    ParameterHandler prm;
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
    QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
    prm.parse_input_from_string(prm_text);

    QuasiStaticProblem<2> problem(comm);
    problem.pcout().set_condition(false);
    problem.parameters().parse_parameters(prm);
    problem.grid().make_box(Point<2>(radius, 0.),
                            Point<2>(radius + width, 4.),
                            {{static_cast<unsigned int>(4. * width + 0.5),
                              16}});
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
      [radius](const Point<2> &x) {
        return x[0] <= radius + a + 1e-10 && x[1] > 4. - 1e-10;
      },
      {{false, true}},
      qsmpm_tests::downward_motion(0.02));

    Result result;
    problem.set_step_callback([&](const QuasiStaticProblem<2>::StepReport &) {
      const double area = radius > 0. ? a * (radius + a / 2.) : a;
      result.pressure_over_c.push_back(-problem.reactions()[3][1] / area / c);
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
} // namespace nodal_footing

#endif
