// Contact between deformable bodies (BodyContact) together with loads
// that act through the material points on their own body's field: a rigid
// body and a traction on the body's own surface. The blocks, their
// material and the motion are those of test contact_two_blocks
// (two_blocks.h).
//
// 1. A rigid body: the two elastic blocks of test contact_two_blocks
// (plane strain, grid [0, 2] x [0, 0.5], h = 0.125, 2 x 2 points per
// cell, E = 1000, nu = 0.3, small strain; block A [0, 1], material id 0,
// block B [1 + g, 2], id 1, g = h / 2), but B is moved by a rigid plate instead
// of a displacement condition on the grid's face: a half-space x > 2 (outward
// normal -x), `tied` (it holds the points that touch it, in tension as in
// compression), moved by u(t) along x:
//   t in [0, 0.4]: -g t / 0.4 (B slides to A, no force),
//   t in [0.4, 0.7]: further by -c (t - 0.4) / 0.3, c = 0.006,
//   t in [0.7, 1]: back to -g + s at t = 1, s = 0.01 (the blocks come
//     apart).
// Known answers (as in contact_two_blocks, whose tolerances these are):
//  - while the gap closes the plate's force is zero: below 1e-8 of the
//    peak (Newton's tolerance is 1e-10);
//  - in compression the two blocks are one: a single block [0, 2 - g] on
//    one field without contact, pressed by the same tied plate from
//    x = 2 - g by u(t) + g from t = 0.4 on, carries the same force at
//    every step to 1e-6 (the figure; measured 2.6e-8 with linear
//    functions, 3.8e-8 with cpGIMP). The plate's penalty scales with the
//    mean stiffness of the grid's nodes, which on two fields sums each
//    node's stiffness over the fields. Counted per dof of each field (the
//    nodes at x = 1 twice, each with part of their stiffness), the mean
//    was a few percent lower than on one field, and the forces differed
//    by 3.2e-5 and 5.5e-5 (the plate's compliance takes 7e-4 of the
//    force).
//    A plate that pushed on the wrong field would be off by O(1);
//  - the peak force is that of uniaxial strain of the closed blocks,
//    M c W / (2 - g), to 1e-2 (measured -6.6e-4: the plate's compliance);
//  - after separation (t = 0.9, 1.0) the plate's force is zero: below
//    1e-8 of the peak;
//  - at every step the plate's force balances the reaction of the held
//    face x = 0 to 1e-6 of the peak.
// Linear shape functions and cpGIMP; frictionless and rough contact
// between the blocks. Before, a run with bodies and a rigid body stopped
// at once ("Rigid bodies cannot be used with several bodies yet"); with
// only that check lifted, the plate pushed on every body's field at the
// nodes its points touch.
//
// 2. A traction on the body's own surface (SurfaceTractions): two elastic
// blocks side by side on a multi-field grid, A [0, 1] (material id 0) and B [1,
// 2] (id 1), touching, grid [0, 2.25] x [0, 0.5] (room beyond B's free face),
// h = 0.125, 2 x 2 points per cell, E = 1000, nu = 0.3, plane strain,
// small strain. A is held at x = 0, both are on rollers at y = 0 and
// y = 0.5, and B's free face x = 2 carries the dead traction (-p t, 0),
// p = 10, in 4 steps: B presses on A.
// Known answers: pressed together the two blocks are one (the issue's
// criterion for contact between bodies): every point's stress equals that
// of the same point of one block [0, 2] on one field without contact,
// loaded the same way, to 1e-6 of p (Newton's tolerance is 1e-10); the
// reaction of the held face equals p W to 1e-6. Frictionless and rough
// contact between the blocks, linear shape functions and cpGIMP. (The one
// block's stress itself is not compared with p here: with points that
// move and volumes that follow the strain of -0.74 % it differs from p at
// first order in the strain; test surface_traction verifies surface
// tractions.) Before, a run with bodies and a surface traction stopped at
// once ("Surface tractions cannot be used with several bodies yet"); with only
// that check lifted, the load of a point went to every body's field at its
// cell's nodes (its components indexed past dim).
//
// 3. Loads on grid faces and nodes (ExternalForceAssembler divides a grid
// node's force among the bodies' fields in proportion to their material
// there): A [0, 1] (id 0) and B [1, 2] (id 1) fill the grid [0, 2] x [0, W],
// h = 0.125, linear shape functions; A is held at x = 0 along x, both are
// on rollers at y = 0.
// One load step, from the points' regular places, where the one block's
// stress under the tractions below is uniform (later steps move the points
// off the grid's symmetry, and the stress is uniform only to the order of
// the strain, with a shear along x = 1 that frictionless contact releases:
// 1.5e-3 p after 4 steps).
// a) Tractions on grid faces: (-p t, 0) on x = 2 (B's face only) and
//    (0, -q t) on y = W, p = 10, q = 5; frictionless contact.
//    The top face's node at x = 1 belongs to both blocks, and its vertical
//    force divides between them; frictionless, they would slide along each
//    other if it went to one field only. Known answer: every point's stress
//    equals that of one block [0, 2] on one field under the same loads, to
//    1e-6 of p; the reactions equal p W at x = 0 and q 2 at y = 0 to 1e-6.
//    Before, such a run stopped at once ("Tractions on grid faces cannot be
//    used with several bodies yet").
// b) The top a rigid plate (add_rigid_plate(), loaded by the traction on
//    it), which carries the load q t over B's half of the top only, rough
//    contact: the plate's nodes move as one on both blocks' fields, and
//    spread the load over A as well. Known answer: every point's stress that
//    of one block under the same plate, to 1e-6 of p, and the reaction at
//    y = 0 that of the load, q. (With the plate on the first field only,
//    B's top would bend under its load: the stress differs by 0.44 p.)
//    Before, such a run stopped at once ("Rigid plates cannot be used with
//    several bodies yet").
// c) A point load (-P t, 0), P = 1, at the node (2, W / 2) of B's face,
//    rough contact: the same against one block to 1e-6 of P / h, and
//    the reaction at x = 0 equals P. On A's field (where the first field
//    of a node took it) the load would be lost: B has the node's material.
//
// 4. A rigid body driven by a force (RigidBody::load_direction): A [0, 1]
// and B [1, 2] side by side, touching, grid [0, 2.25] x [0, W], held and on
// rollers as in part 2, frictionless contact between them; a frictionless
// half-space x > 2 (outward normal -x) pushes on B's end with the force
// F t = p W t along -x, its motion along x unknown, 4 steps. Known answer:
// pressed together the blocks are one: every point's stress that of one
// block [0, 2] on one field pushed by the same body, to 1e-6 of p, and the
// material's force on the body and the reaction at x = 0 equal F, to 1e-6.
// Before, such a run stopped at once ("Rigid bodies driven by a force
// (Load direction) cannot be used with several bodies yet").
#include "tests.h"
#include "two_blocks.h"

#include <limits>
#include <map>
#include <qsmpm/base/utilities.h>

using namespace qsmpm;
using namespace two_blocks;

namespace
{
  using Friction = BodyContact<2>::Parameters::Friction;

  /// The grid [0, @p length] x [0, W] of cells h, held at x = 0 along x,
  /// on rollers at y = 0 and y = W.
  void
  make_grid(QuasiStaticProblem<2> &problem, const double length)
  {
    problem.grid().make_box(Point<2>(),
                            Point<2>(length, W),
                            {{static_cast<unsigned int>(length / h + 0.5),
                              static_cast<unsigned int>(W / h + 0.5)}});
    auto      &bcs  = problem.boundary_conditions();
    const auto zero = std::make_shared<Functions::ZeroFunction<2>>(2);
    bcs.add_dirichlet_boundary(0, {{true, false}}, zero);
    bcs.add_dirichlet_boundary(2, {{false, true}}, zero);
    bcs.add_dirichlet_boundary(3, {{false, true}}, zero);
  }

  // Part 1: two_blocks::motion() along x.
  class PlateMotion : public Function<2>
  {
  public:
    explicit PlateMotion(const bool single)
      : Function<2>(2)
      , single(single)
    {
    }
    double
    value(const Point<2> &, const unsigned int component) const override
    {
      return component == 0 ? motion(get_time(), single) : 0.;
    }

  private:
    const bool single;
  };

  struct Forces
  {
    std::vector<double> plate, held;
  };

  // Part 1: the material's force on the plate and the reaction of the held
  // face x = 0 (both along x) at every step.
  Forces
  plate_run(const bool           two_bodies,
            const Friction       friction,
            const ShapeFunctions shape_functions)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    set_up(
      problem, two_bodies, friction, shape_functions, 10, "bodies-loads-out");
    make_grid(problem, 2.);
    RigidBody<2> plate;
    plate.name      = "plate";
    plate.shape     = RigidBody<2>::Shape::half_space;
    plate.point     = Point<2>(two_bodies ? 2. : 2. - g, 0.);
    plate.normal[0] = -1.;
    plate.friction  = RigidBody<2>::Friction::tied;
    plate.motion    = std::make_shared<PlateMotion>(!two_bodies);
    problem.boundary_conditions().add_rigid_body(plate);
    if (two_bodies)
      make_points(
        problem,
        [](const Point<2> &x) { return x[0] < 1. || x[0] > 1. + g; },
        true);
    else
      make_points(
        problem, [](const Point<2> &x) { return x[0] < 2. - g; }, false);

    Forces forces;
    problem.set_step_callback([&](const QuasiStaticProblem<2>::StepReport &) {
      forces.plate.push_back(problem.rigid_body_loads().at(0).force[0]);
      forces.held.push_back(problem.reactions().at(0)[0]);
      return true;
    });
    problem.run();
    return forces;
  }

  // Part 2.
  const double p = 10.;

  struct TractionRun
  {
    Stresses stress;
    double   reaction  = 0.;
    bool     all_steps = false;
  };

  TractionRun
  traction_run(const bool           two_bodies,
               const Friction       friction,
               const ShapeFunctions shape_functions)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    set_up(
      problem, two_bodies, friction, shape_functions, 4, "bodies-loads-out");
    make_grid(problem, 2.25);
    auto traction = std::make_shared<FunctionParser<2>>(2);
    traction->initialize("x,y,t", "-p*t; 0", {{"p", p}}, true);
    problem.boundary_conditions().add_surface_traction(
      "end", [](const Point<2> &x) { return x[0] > 2. - 1e-9; }, traction);
    make_points(
      problem, [](const Point<2> &x) { return x[0] < 2.; }, two_bodies);
    const unsigned int steps = run_counting_steps(problem);

    TractionRun result;
    result.stress    = point_stresses(problem);
    result.reaction  = problem.reactions().at(0)[0];
    result.all_steps = steps == 4;
    return result;
  }

  // Part 3.
  const double q = 5., P = 1.;

  struct GridLoadRun
  {
    Stresses     stress;
    Tensor<1, 2> held, floor;
    bool         all_steps = false;
  };

  GridLoadRun
  grid_load_run(const bool     two_bodies,
                const Friction friction,
                const bool     point,
                const bool     plate = false)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    set_up(problem,
           two_bodies,
           friction,
           ShapeFunctions::linear,
           1,
           "bodies-loads-out");
    problem.grid().make_box(Point<2>(),
                            Point<2>(2., W),
                            {{static_cast<unsigned int>(2. / h + 0.5),
                              static_cast<unsigned int>(W / h + 0.5)}});
    auto      &bcs  = problem.boundary_conditions();
    const auto zero = std::make_shared<Functions::ZeroFunction<2>>(2);
    bcs.add_dirichlet_boundary(0, {{true, false}}, zero);
    bcs.add_dirichlet_boundary(2, {{false, true}}, zero);
    if (point)
      bcs.add_point_load(Point<2>(2., W / 2.), Tensor<1, 2>({-P, 0.}));
    else
      {
        auto traction = std::make_shared<FunctionParser<2>>(2);
        // Under the plate, the load of B's half only.
        traction->initialize("x,y,t",
                             std::string("x > 2 - 1e-9 ? -p*t : 0; ") +
                               (plate ? "y > W - 1e-9 && x > 1 ? -q*t : 0" :
                                        "y > W - 1e-9 ? -q*t : 0"),
                             {{"p", p}, {"q", q}, {"W", W}},
                             true);
        bcs.add_traction(1, traction);
        bcs.add_traction(3, traction);
        if (plate)
          bcs.add_rigid_plate(3);
      }
    make_points(
      problem, [](const Point<2> &) { return true; }, two_bodies);
    const unsigned int steps = run_counting_steps(problem);

    GridLoadRun result;
    result.stress    = point_stresses(problem);
    result.held      = problem.reactions().at(0);
    result.floor     = problem.reactions().at(1);
    result.all_steps = steps == 1;
    return result;
  }

  // Part 4: the stresses, the reaction at x = 0 and the body's force.
  struct PushRun
  {
    Stresses stress;
    double   reaction = 0., body_force = 0.;
    bool     all_steps = false;
  };

  PushRun
  push_run(const bool two_bodies)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    set_up(problem,
           two_bodies,
           Friction::frictionless,
           ShapeFunctions::linear,
           4,
           "bodies-loads-out");
    make_grid(problem, 2.25);
    RigidBody<2> pusher;
    pusher.name              = "pusher";
    pusher.shape             = RigidBody<2>::Shape::half_space;
    pusher.point             = Point<2>(2., 0.);
    pusher.normal[0]         = -1.;
    pusher.load_direction[0] = -1.;
    auto load                = std::make_shared<FunctionParser<2>>(1);
    load->initialize("x,y,t", "F*t", {{"F", p * W}}, true);
    pusher.load = load;
    problem.boundary_conditions().add_rigid_body(pusher);
    make_points(
      problem, [](const Point<2> &x) { return x[0] < 2.; }, two_bodies);
    const unsigned int steps = run_counting_steps(problem);

    PushRun result;
    result.stress     = point_stresses(problem);
    result.reaction   = problem.reactions().at(0)[0];
    result.body_force = problem.rigid_body_loads().at(0).force[0];
    result.all_steps  = steps == 4;
    return result;
  }

} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  const std::pair<ShapeFunctions, const char *> shape_functions[] = {
    {ShapeFunctions::linear, "linear shape functions"},
    {ShapeFunctions::cpgimp, "cpGIMP"}};
  const std::pair<Friction, const char *> frictions[] = {
    {Friction::frictionless, "frictionless"}, {Friction::rough, "rough"}};

  deallog << "1. A tied rigid plate moves B" << std::endl;
  for (const auto &[functions, name] : shape_functions)
    {
      deallog << name << std::endl;
      const Forces single = plate_run(false, Friction::frictionless, functions);
      check_that("single block: 10 steps", single.plate.size() == 10);
      for (const auto &[friction, friction_name] : frictions)
        {
          deallog << friction_name << " contact between the blocks"
                  << std::endl;
          const Forces two = plate_run(true, friction, functions);
          check_that("  two blocks: 10 steps", two.plate.size() == 10);
          double peak = 0.;
          for (const double f : two.plate)
            peak = std::max(peak, std::abs(f));
          double closing = 0., apart = 0., difference = 0., balance = 0.;
          for (unsigned int k = 0; k < two.plate.size(); ++k)
            {
              if (k < 4)
                closing = std::max(closing, std::abs(two.plate[k]));
              else if (k < 8)
                difference = std::max(difference,
                                      std::abs(two.plate[k] - single.plate[k]));
              else
                apart = std::max(apart, std::abs(two.plate[k]));
              balance = std::max(balance, std::abs(two.plate[k] - two.held[k]));
            }
          // Uniaxial strain of the closed blocks, length 2 - g, by c.
          const double M = E * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
          check("  peak force / (M c W / (2 - g)) - 1",
                peak / (M * c * W / (2. - g)) - 1.,
                1e-2);
          check("  max |F| while the gap closes / peak", closing / peak, 1e-8);
          check("  max |F_two - F_single| / peak in compression",
                difference / peak,
                1e-6);
          check("  max |F| after separation / peak", apart / peak, 1e-8);
          check("  max |F_plate - F_held| / peak", balance / peak, 1e-6);
        }
    }

  deallog << "2. A surface traction presses B onto A" << std::endl;
  for (const auto &[functions, name] : shape_functions)
    {
      deallog << name << std::endl;
      const TractionRun single =
        traction_run(false, Friction::frictionless, functions);
      check_that("  one block: 4 steps", single.all_steps);
      for (const auto &[friction, friction_name] : frictions)
        {
          deallog << "  " << friction_name << " contact" << std::endl;
          const TractionRun r = traction_run(true, friction, functions);
          check_that("    4 steps", r.all_steps);
          check("    max |stress - one block's| / p",
                largest_stress_difference(r.stress, single.stress) / p,
                1e-6);
          check("    |reaction at x = 0| / (p W) - 1",
                std::abs(r.reaction) / (p * W) - 1.,
                1e-6);
        }
    }

  deallog << "3. Loads on grid faces and nodes" << std::endl;
  {
    const GridLoadRun one = grid_load_run(false, Friction::frictionless, false);
    const GridLoadRun two = grid_load_run(true, Friction::frictionless, false);
    check_that("  tractions: 1 step, one block and two",
               one.all_steps && two.all_steps);
    check("  max |stress - one block's| / p",
          largest_stress_difference(two.stress, one.stress) / p,
          1e-6);
    check("  |reaction at x = 0| / (p W) - 1",
          std::abs(two.held[0]) / (p * W) - 1.,
          1e-6);
    check("  |reaction at y = 0| / (2 q) - 1",
          std::abs(two.floor[1]) / (2. * q) - 1.,
          1e-6);
  }
  {
    const GridLoadRun one = grid_load_run(false, Friction::rough, false, true);
    const GridLoadRun two = grid_load_run(true, Friction::rough, false, true);
    check_that("  the top a rigid plate: 1 step, one block and two",
               one.all_steps && two.all_steps);
    check("  max |stress - one block's| / p",
          largest_stress_difference(two.stress, one.stress) / p,
          1e-6);
    check("  |reaction at y = 0| / q - 1",
          std::abs(two.floor[1]) / q - 1.,
          1e-6);
  }
  {
    const GridLoadRun one = grid_load_run(false, Friction::rough, true);
    const GridLoadRun two = grid_load_run(true, Friction::rough, true);
    check_that("  point load: 1 step, one block and two",
               one.all_steps && two.all_steps);
    check("  max |stress - one block's| / (P / h)",
          largest_stress_difference(two.stress, one.stress) / (P / h),
          1e-6);
    check("  |reaction at x = 0| / P - 1",
          std::abs(two.held[0]) / P - 1.,
          1e-6);
  }

  deallog << "4. A rigid body driven by a force pushes B onto A" << std::endl;
  {
    const PushRun one = push_run(false);
    const PushRun two = push_run(true);
    check_that("  4 steps, one block and two", one.all_steps && two.all_steps);
    check("  max |stress - one block's| / p",
          largest_stress_difference(two.stress, one.stress) / p,
          1e-6);
    check("  |force on the body| / F - 1",
          std::abs(two.body_force) / (p * W) - 1.,
          1e-6);
    check("  |reaction at x = 0| / F - 1",
          std::abs(two.reaction) / (p * W) - 1.,
          1e-6);
  }
}
