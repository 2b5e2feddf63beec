// Friction between deformable bodies (issue 30, item 2): an elastic block B
// pressed onto a wider elastic block A and pushed along it, with
// frictionless, rough and Coulomb contact (BodyContact). Grid [0, 2] x
// [0, 1], h = 0.125, 2 x 2 points per cell, linear elastic (E = 1000,
// nu = 0.3, plane strain), small strain. A fills [0.25, 1.75] x [0, 0.5]
// (material id 0), B [0.5, 1.5] x [0.5 + g, 1] (id 1), g = h / 2: the blocks
// share the grid nodes at y = 0.5 from the start, and only the gap tells
// that they do not touch. The bottom face holds A (u = 0); the top face
// moves B by u(t) in 14 steps:
//   steps 1-2: u_y to -g (B moves onto A, no force),
//   steps 3-4: u_y further by -p, p = 0.005 (pressed),
//   steps 5-14: u_x by s / 10 per step, s = 0.01, u_y held (pushed along).
// The force on the top face, H (along x) and V (along y), is the force
// between the blocks: B carries nothing else. Known answers:
//  - rough contact (no slip) is one body: a single block, A and B where
//    they are once the gap has closed (B's points moved by -g, on the same
//    lattice), loaded from step 3 by u(t) + g in y, carries the same H and
//    V at every step to 1e-6 of the peak (the two_blocks test's figure);
//  - frictionless contact transmits no tangential force: |H| / |V| while B
//    slides below 1e-3 (the normals, from the bodies' volume gradients,
//    tilt by up to 0.006 where A's points are compressed unevenly under B;
//    a sticking or locking interface gives 0.1 and more);
//  - Coulomb contact with mu = 0.3: H / V = mu while B slides (the last
//    three steps; the rough interface then carries H / V = 0.45-0.53), to
//    1 % (the figure); |H| / |V| <= mu (to 1 %) at every step;
//  - Coulomb contact with mu = 10 never slips here: it is rough contact
//    (to 1e-6); with mu = 0 it is frictionless contact (to 1e-6).
//  - Coulomb contact with mu = 0.3 and block A across the whole grid:
//    all 14 steps, and H / V = mu while B slides, to 1 %.
// All of it with linear shape functions and with cpGIMP, where rough
// contact is the glued block to 1e-3 only: Poisson's expansion stretches
// the cpGIMP domains of B's side columns past B's sides, to nodes beside B
// whose gap, measured between the points' unstretched boxes, is open
// (4.2e-4 measured).
#include "tests.h"

#include <optional>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>

using namespace qsmpm;

namespace
{
  const double E = 1000., nu = 0.3, h = 0.125, g = 0.5 * h, p = 0.005, s = 0.01;
  const unsigned int n_steps = 14;

  using Friction = BodyContact<2>::Parameters::Friction;

  // u(t) of the top face; single = true: the single block's, 0 until step
  // 2, then u(t) + g in y.
  class TopFace : public Function<2>
  {
  public:
    explicit TopFace(const bool single)
      : Function<2>(2)
      , single(single)
    {
    }
    double
    value(const Point<2> &, const unsigned int component) const override
    {
      const double k = get_time() * n_steps;
      if (component == 0)
        return k <= 4. ? 0. : s * (k - 4.) / (n_steps - 4);
      const double u =
        k <= 2. ? -g * k / 2. : (k <= 4. ? -g - p * (k - 2.) / 2. : -g - p);
      return single ? (k <= 2. ? 0. : u + g) : u;
    }

  private:
    const bool single;
  };

  struct Forces
  {
    std::vector<double> H, V;
  };

  // The force on the top face at every step; without @p friction one
  // block on one field.
  Forces
  run(const ShapeFunctions          shape_functions,
      const std::optional<Friction> friction,
      const double                  mu            = 0.,
      const bool                    a_across_grid = false)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    problem.pcout().set_condition(false);
    auto &prm                                       = problem.parameters();
    prm.material_points.formulation.shape_functions = shape_functions;
    prm.load_stepping.n_steps                       = n_steps;
    prm.nonlinear_solver.tolerance                  = 1e-10;
    prm.output.interval                             = 0;
    prm.output.directory                            = "friction-blocks-out";
    if (friction)
      {
        BodyContact<2>::Parameters contact;
        contact.bodies               = "0; 1";
        contact.friction             = *friction;
        contact.friction_coefficient = mu;
        problem.set_body_contact(contact);
      }
    problem.grid().make_box(Point<2>(), Point<2>(2., 1.), {{16, 8}});
    auto &bcs = problem.boundary_conditions();
    bcs.add_dirichlet_boundary(2,
                               {{true, true}},
                               std::make_shared<Functions::ZeroFunction<2>>(2));
    bcs.add_dirichlet_boundary(3,
                               {{true, true}},
                               std::make_shared<TopFace>(!friction));

    LinearElastic<2>::Parameters material;
    material.elasticity.young_modulus = E;
    material.elasticity.poisson_ratio = nu;
    problem.set_model(std::make_unique<LinearElastic<2>>(material));
    const auto rule = MaterialPointSet<2>::reference_rule(
      MaterialPointSet<2>::Placement::regular, {{2, 2}});
    const double bottom_of_b = friction ? 0.5 + g : 0.5,
                 top_of_b    = friction ? 1. : 1. - g;
    problem.points().fill(
      [&](const Point<2> &x) {
        return (x[1] < 0.5 &&
                (a_across_grid || (x[0] > 0.25 && x[0] < 1.75))) ||
               (x[1] > bottom_of_b && x[1] < top_of_b && x[0] > 0.5 &&
                x[0] < 1.5);
      },
      rule,
      [](const Point<2> &x) { return x[1] < 0.5 ? 0u : 1u; });

    Forces forces;
    problem.set_step_callback([&](const QuasiStaticProblem<2>::StepReport &) {
      // The reaction of the top face (condition 1).
      forces.H.push_back(problem.reactions().at(1)[0]);
      forces.V.push_back(problem.reactions().at(1)[1]);
      return true;
    });
    try
      {
        problem.run();
      }
    catch (const std::exception &exc)
      {
        // A run that stops has fewer than n_steps rows: the checks of the
        // step count fail.
        print_value("stopped: " + Utils::error_message(exc), 0.);
      }
    return forces;
  }

  // max_k (|a_k - b_k|) / peak over steps [first, n_steps), H and V.
  double
  difference(const Forces &a, const Forces &b, const unsigned int first)
  {
    double peak = 0., largest = 0.;
    for (unsigned int k = first; k < n_steps; ++k)
      {
        peak    = std::max({peak, std::abs(b.H[k]), std::abs(b.V[k])});
        largest = std::max(
          {largest, std::abs(a.H[k] - b.H[k]), std::abs(a.V[k] - b.V[k])});
      }
    return largest / peak;
  }

  // max ||H_k| / |V_k| / mu - 1| over the last 3 steps, where B slides; 1
  // (a failure) for a run that stopped before its last step.
  double
  sliding_misfit(const Forces &forces, const double mu)
  {
    if (forces.H.size() != n_steps)
      return 1.;
    double off = 0.;
    for (unsigned int k = n_steps - 3; k < n_steps; ++k)
      off =
        std::max(off, std::abs(std::abs(forces.H[k] / forces.V[k]) / mu - 1.));
    return off;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  for (const auto &[shape_functions, name] :
       {std::make_pair(ShapeFunctions::linear, "linear shape functions"),
        std::make_pair(ShapeFunctions::cpgimp, "cpGIMP")})
    {
      deallog << name << std::endl;
      const double mu           = 0.3;
      const auto   single       = run(shape_functions, {});
      const auto   rough        = run(shape_functions, Friction::rough);
      const auto   frictionless = run(shape_functions, Friction::frictionless);
      const auto   coulomb      = run(shape_functions, Friction::coulomb, mu);
      for (const auto *forces : {&single, &rough, &frictionless, &coulomb})
        check_that(std::to_string(n_steps) + " steps",
                   forces->H.size() == n_steps);

      check("rough: max |F_rough - F_single| / peak, steps 3-14",
            difference(rough, single, 2),
            shape_functions == ShapeFunctions::linear ? 1e-6 : 1e-3);

      double sliding = 0.;
      for (unsigned int k = 4; k < n_steps; ++k)
        sliding =
          std::max(sliding, std::abs(frictionless.H[k] / frictionless.V[k]));
      check("frictionless: max |H| / |V| while B slides", sliding, 1e-3);

      for (unsigned int k = 0; k < n_steps; ++k)
        print_value("Coulomb: H / V / mu, step " + std::to_string(k + 1),
                    coulomb.H[k] / coulomb.V[k] / mu);
      double above = 0.;
      for (unsigned int k = 2; k < n_steps; ++k)
        above =
          std::max(above, std::abs(coulomb.H[k] / coulomb.V[k]) / mu - 1.);
      check("Coulomb mu = 0.3: max (|H| / |V|) / mu - 1, steps 3-14",
            std::max(above, 0.),
            1e-2);
      check("Coulomb mu = 0.3: max ||H| / |V| / mu - 1| while sliding",
            sliding_misfit(coulomb, mu),
            1e-2);
      check_at_least("rough: |H| / |V| / mu at the last step",
                     std::abs(rough.H.back() / rough.V.back()) / mu,
                     1.05);

      check("Coulomb mu = 10: max |F - F_rough| / peak",
            difference(run(shape_functions, Friction::coulomb, 10.), rough, 0),
            1e-6);
      check("Coulomb mu = 0: max |F - F_frictionless| / peak",
            difference(run(shape_functions, Friction::coulomb, 0.),
                       frictionless,
                       0),
            1e-6);

      // Block A across the whole grid: B's cpGIMP domains reach the nodes
      // of A's top one cell beyond B's ends with a normal force of a few
      // 1e-6 of the largest. Without the stick tolerance of
      // BodyContact::update() such a node alternates between stick and
      // slip in every solve, and with cpGIMP the run stops in step 7.
      const auto across = run(shape_functions, Friction::coulomb, mu, true);
      check_that("Coulomb mu = 0.3, A across the grid: " +
                   std::to_string(n_steps) + " steps",
                 across.H.size() == n_steps);
      check("Coulomb mu = 0.3, A across the grid: max ||H| / |V| / mu - 1| "
            "while sliding",
            sliding_misfit(across, mu),
            1e-2);
    }
}
