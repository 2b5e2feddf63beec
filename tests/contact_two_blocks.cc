// Contact between deformable bodies (issue 30, item 2): two elastic blocks
// on a multi-field grid (BodyContact), meeting across a gap, compressed,
// then pulled apart. Grid [0, 2] x [0, 0.5], h = 0.125, 2 x 2 points per
// cell, linear elastic (E = 1000, nu = 0.3, plane strain), small strain.
// Block A fills [0, 1] (material id 0), block B [1 + g, 2] (id 1), with
// g = h / 2: the blocks share the grid nodes at x = 1 from the start (B's
// first points lie in the cell [1, 1 + h]), and only the gap tells that
// they do not touch. The left face holds u_x = 0, top and bottom u_y = 0
// (uniaxial strain: a 1D problem), the right face moves B by u(t):
//   t in [0, 0.4]: -g t / 0.4 (4 steps: B slides to A, no force),
//   t in [0.4, 0.7]: further by -c (t - 0.4) / 0.3, c = 0.006
//     (3 steps of compression),
//   t in [0.7, 1]: back to -g + s at t = 1, s = 0.01 (3 steps: the blocks
//     unload, come apart at t = 0.82 and separate).
// Known answers:
//  - while closing (t <= 0.4) the force on the right face is zero (B moves
//    freely): below 1e-8 of the peak (the Newton tolerance is 1e-10);
//  - in compression, the two blocks are one: a single block [0, 2 - g]
//    (its points where A's and B's are when the gap has closed), loaded
//    from t = 0.4 by u(t) + g, carries the same force at every step to
//    1e-6 (the figure; frictionless and rough contact);
//  - after separation (t = 0.9, 1.0) the force is zero: below 1e-8 of the
//    peak.
// The single block is computed on one field, without contact: a different
// path through the code. All of it with linear shape functions and with
// cpGIMP (whose points reach the nodes of the neighbouring cells; with
// 2 x 2 points per cell the two blocks still share only the nodes at
// x = 1, so the tied blocks are again the single block). (Its force is no
// closed form: the grid's edge at x = 2 lies h / 2 beyond the material, in a
// cell that the points fill only half.)
// The same axisymmetric (Axisymmetric = true), the blocks stacked along the
// axis: grid [0, 0.5] x [0, 2] in (r, z), A a cylinder z in [0, 1], B one
// z in [1 + g, 2], the axis and the outer face on rollers (u_r = 0:
// uniaxial strain again), the base held, the top moved by u(t) along z.
// Rigid motion along the axis strains nothing, so the known answers are
// the same; the bodies' normals and the points' boxes there come from the
// area r dA / r, not from the volume per radian (with the volume, whose
// growth with r tilts the normals and shrinks the boxes, the blocks were
// found in contact from the first step and carried 0.79-0.96 of the peak
// force while the gap closed).
#include "tests.h"
#include "two_blocks.h"

using namespace qsmpm;
using namespace two_blocks;

namespace
{
  // two_blocks::motion() along the direction @p axis.
  class MovingFace : public Function<2>
  {
  public:
    MovingFace(const bool single, const unsigned int axis)
      : Function<2>(2)
      , single(single)
      , axis(axis)
    {
    }
    double
    value(const Point<2> &, const unsigned int component) const override
    {
      return component == axis ? motion(get_time(), single) : 0.;
    }

  private:
    const bool         single;
    const unsigned int axis;
  };

  // The force on the moving face (its component along the blocks) at every
  // step; the blocks lie along x, or along the axis (y) if axisymmetric.
  std::vector<double>
  run(const bool           two_bodies,
      const std::string   &friction,
      const ShapeFunctions shape_functions,
      const bool           axisymmetric)
  {
    // The direction along the blocks, and the face that moves (boundary id).
    const unsigned int    a = axisymmetric ? 1 : 0, moving = 2 * a + 1;
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    set_up(problem,
           two_bodies,
           friction == "rough" ?
             BodyContact<2>::Parameters::Friction::rough :
             BodyContact<2>::Parameters::Friction::frictionless,
           shape_functions,
           10,
           "two-blocks-out");
    problem.parameters().material_points.formulation.axisymmetric =
      axisymmetric;
    if (axisymmetric)
      problem.grid().make_box(Point<2>(), Point<2>(W, 2.), {{4, 16}});
    else
      problem.grid().make_box(Point<2>(), Point<2>(2., W), {{16, 4}});
    // Along the blocks: the far face (2 a) held, the moving face (2 a + 1)
    // moved; across them, rollers on both faces.
    auto      &bcs  = problem.boundary_conditions();
    const auto zero = std::make_shared<Functions::ZeroFunction<2>>(2);
    const std::array<bool, 2> along{{a == 0, a == 1}}, across{{a == 1, a == 0}};
    bcs.add_dirichlet_boundary(2 * a, along, zero);
    bcs.add_dirichlet_boundary(2 * (1 - a), across, zero);
    bcs.add_dirichlet_boundary(2 * (1 - a) + 1, across, zero);
    bcs.add_dirichlet_boundary(moving,
                               along,
                               std::make_shared<MovingFace>(!two_bodies, a));
    if (two_bodies)
      make_points(
        problem,
        [a](const Point<2> &x) { return x[a] < 1. || x[a] > 1. + g; },
        true,
        a);
    else
      // Where A's and B's points are once the gap has closed: B's moved
      // by -g, which keeps them on the same lattice of spacing h / 2.
      make_points(
        problem, [a](const Point<2> &x) { return x[a] < 2. - g; }, false, a);

    std::vector<double> force;
    problem.set_step_callback([&](const QuasiStaticProblem<2>::StepReport &) {
      // The reaction of the moving face (the last condition): the force
      // the face applies, negative in compression.
      force.push_back(problem.reactions().at(3)[a]);
      return true;
    });
    problem.run();
    return force;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  for (const bool axisymmetric : {false, true})
    for (const auto &[shape_functions, name] :
         {std::make_pair(ShapeFunctions::linear, "linear shape functions"),
          std::make_pair(ShapeFunctions::cpgimp, "cpGIMP")})
      {
        deallog << (axisymmetric ? "axisymmetric, " : "") << name << std::endl;
        const auto single =
          run(false, "frictionless", shape_functions, axisymmetric);
        check_that("single block: 10 steps", single.size() == 10);
        for (const std::string friction : {"frictionless", "rough"})
          {
            deallog << friction << " contact" << std::endl;
            const auto two = run(true, friction, shape_functions, axisymmetric);
            check_that("  two blocks: 10 steps", two.size() == 10);
            double peak = 0.;
            for (const double f : two)
              peak = std::max(peak, std::abs(f));
            double closing = 0., apart = 0., difference = 0.;
            for (unsigned int k = 0; k < 4; ++k)
              closing = std::max(closing, std::abs(two[k]));
            for (unsigned int k = 4; k < 8; ++k)
              difference =
                std::max(difference, std::abs(two[k] - single[k]) / peak);
            for (unsigned int k = 8; k < 10; ++k)
              apart = std::max(apart, std::abs(two[k]));
            check("  max |F| while the gap closes / peak",
                  closing / peak,
                  1e-8);
            check("  max |F_two - F_single| / peak in compression",
                  difference,
                  1e-6);
            check("  max |F| after separation / peak", apart / peak, 1e-8);
          }
      }
}
