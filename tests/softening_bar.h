// The one-dimensional softening bar of decohesion_bar and
// path_following_bar (doc/references.md#one-dimensional-bar): a row of
// n_cells square cells of length L, one band cell in the middle that may
// crack (fixed normal x, nu = 0, plane stress), the left end held in x,
// every node held in y, the right end pulled in x by u = t.
#ifndef qsmpm_tests_softening_bar_h
#define qsmpm_tests_softening_bar_h

#include <cmath>
#include <deal.II/base/function.h>
#include <memory>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/decohesion.h>

namespace qsmpm_tests
{
  /// u_x = t.
  class Pull : public dealii::Function<2>
  {
  public:
    Pull()
      : dealii::Function<2>(2)
    {
    }
    double
    value(const dealii::Point<2> &, const unsigned int c) const override
    {
      return c == 0 ? get_time() : 0.;
    }
  };

  /**
   * Grid, model, points (points_per_direction^2 per cell, regular) and
   * supports of the bar in @p problem; returns the index of the pulled
   * condition among the displacement conditions (its reaction is the load).
   */
  inline unsigned int
  make_softening_bar(qsmpm::QuasiStaticProblem<2> &problem,
                     const double                  E,
                     const double                  tau,
                     const double                  G_f,
                     const double                  L,
                     const unsigned int            n_cells,
                     const unsigned int            points_per_direction)
  {
    using namespace dealii;
    const double h = L / n_cells;
    problem.grid().make_box(Point<2>(), Point<2>(L, h), {{n_cells, 1}});
    Tensor<1, 2> x_normal;
    x_normal[0] = 1.;
    auto model  = std::make_unique<qsmpm::Decohesion<2>>(
      E, 0., true, tau, G_f, x_normal, h);
    const double x_band = (n_cells / 2 + 0.5) * h;
    model->set_crack_region(
      [=](const Point<2> &x) { return std::abs(x[0] - x_band) < 0.5 * h; });
    problem.set_model(std::move(model));
    problem.points().fill([](const Point<2> &) { return true; },
                          points_per_direction,
                          qsmpm::MaterialPointSet<2>::Placement::regular);

    auto               &bcs = problem.boundary_conditions();
    std::array<bool, 2> x_only{{true, false}}, y_only{{false, true}};
    const auto          zero = std::make_shared<Functions::ZeroFunction<2>>(2);
    bcs.add_dirichlet_boundary(0, x_only, zero);
    bcs.add_dirichlet_nodes(
      "all y", [](const Point<2> &) { return true; }, y_only, zero);
    const unsigned int right = bcs.dirichlet_conditions().size();
    bcs.add_dirichlet_boundary(1, x_only, std::make_shared<Pull>());
    return right;
  }
} // namespace qsmpm_tests

#endif
