// Rigid contact of a GIMP point whose box is sheared far beyond its GIMP
// domain (issue 30; the cone of doc/axisymmetry.md pushed beyond 3 R).
//
// A point touches a rigid body at the surface point of its box, deformed
// with it (RigidContact), and that contact point moves with the Q1
// functions of the cell that holds it. The point's cpGIMP domain is an
// axis-parallel box at most a cell wide; the sheared box whose surface the
// contact sees can reach a cell beside the point's cell that no point of
// its cell reaches. The contact stiffness then couples nodes that the
// stiffness's pattern does not: the cone stopped at 3.14 R with "error
// number 2 occurred while calling a Trilinos function". Such a point must
// take the functions of its own cell (extrapolated) instead.
//
// The set-up makes that cell: grid [0, 2]^2, h = 0.25, 2 x 2 points per
// cell, cpGIMP, small strain, linear elastic (E = 1000, nu = 0.3); the
// body [0, 1.25]^2 without its corner cell D = [1, 1.25]^2, its base held;
// a rigid box [1, 2]^2 in that corner, pushed diagonally into the notch
// by 1e-3 in x and y in one step. The point of cell C = [0.75, 1]^2
// nearest to D is given the strain eps_xy = 3 (its stress stays zero: the
// linear elastic model adds stress increments, and the strain only shapes
// the box): F = I + eps shears its box towards D, whose corner then lies
// in D, 0.16 inside the box. D touches C at a vertex; its nodes (1.25, 1)
// and (1, 1.25) belong to the cells beside C, and no cell's points reach
// both. Checks:
// 1. The step converges (with the contact point in D: the Trilinos error).
// 2. The supports carry the box's force to 1e-4 of it: no load lost
//    (measured 2e-5: in the first step, Newton's tolerance 1e-6 is relative
//    to the step's first residual, which the penalty forces of the box's
//    motion make larger than the box's force).
// 3. The same force on 1 and on all ranks (to 1e-8 of it).
#include "tests.h"

#include <deal.II/base/function.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>

using namespace qsmpm;

namespace
{
  class Push : public Function<2>
  {
  public:
    Push()
      : Function<2>(2)
    {
    }
    double
    value(const Point<2> &, const unsigned int) const override
    {
      return -1e-3 * get_time();
    }
  };

  struct Result
  {
    bool         completed = false;
    Tensor<1, 2> force;
    double       imbalance = 0.;
    std::string  message;
    unsigned int sheared = 0;
  };

  Result
  run(const MPI_Comm comm)
  {
    const std::string text = "set Dimension = 2\n"
                             "subsection Material points\n"
                             "  set Points per cell per direction = 2\n"
                             "  set Shape functions = cpGIMP\nend\n"
                             "subsection Material\n"
                             "  set Model = linear elastic\n"
                             "  subsection linear elastic\n"
                             "    set Young's modulus = 1000\n"
                             "    set Poisson's ratio = 0.3\n  end\nend\n"
                             "subsection Load stepping\n"
                             "  set Number of steps = 1\nend\n"
                             "subsection Output\n  set Interval = 0\n"
                             "  set Directory = sheared-out\nend\n";
    ParameterHandler  prm;
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
    QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
    prm.parse_input_from_string(text);

    QuasiStaticProblem<2> problem(comm);
    problem.pcout().set_condition(false);
    problem.parameters().parse_parameters(prm);
    problem.grid().make_box(Point<2>(0., 0.), Point<2>(2., 2.), {{8, 8}});
    auto &bcs = problem.boundary_conditions();
    bcs.add_dirichlet_nodes(
      "base",
      [](const Point<2> &x) { return x[1] <= 1e-10; },
      {{true, true}},
      std::make_shared<Functions::ZeroFunction<2>>(2));
    RigidBody<2> box;
    box.name         = "box";
    box.shape        = RigidBody<2>::Shape::box;
    box.point        = Point<2>(1., 1.);
    box.upper_corner = Point<2>(2., 2.);
    box.motion       = std::make_shared<Push>();
    bcs.add_rigid_body(box);
    problem.set_model(ConstitutiveModelFactory<2>::create(prm));
    problem.points().fill(
      [](const Point<2> &x) {
        return x[0] < 1.25 && x[1] < 1.25 && !(x[0] > 1. && x[1] > 1.);
      },
      2,
      MaterialPointSet<2>::Placement::regular);

    // The point of C at (0.9375, 0.9375), on whichever rank holds it.
    Result             result;
    const unsigned int strain = problem.points().get_offsets().strain;
    for (auto &particle : problem.points().get_particle_handler())
      if (particle.get_location().distance(Point<2>(0.9375, 0.9375)) < 1e-10)
        {
          SymmetricTensor<2, 2> eps;
          eps[0][1] = 3.;
          Utils::write_symmetric(eps,
                                 particle.get_properties().data() + strain);
          ++result.sheared;
        }
    result.sheared = Utilities::MPI::sum(result.sheared, comm);

    problem.set_step_callback([&](const QuasiStaticProblem<2>::StepReport &) {
      result.force = problem.rigid_body_loads().front().force;
      Tensor<1, 2> supports;
      for (const auto &reaction : problem.reactions())
        supports += reaction;
      result.imbalance = (supports - result.force).norm() / result.force.norm();
      return true;
    });
    try
      {
        problem.run();
        result.completed = true;
      }
    catch (const std::exception &exc)
      {
        result.message = Utils::error_message(exc);
      }
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  const Result r = run(MPI_COMM_WORLD);
  check_that("one point sheared", r.sheared == 1);
  check_that("the step converged", r.completed);
  if (!r.completed)
    {
      deallog << "  run stopped: " << r.message << std::endl;
      return 0;
    }
  check_that("the box is pushed back (force along (1, 1))",
             r.force[0] > 0. && r.force[1] > 0.);
  check("|supports - box force| / |box force|", r.imbalance, 1e-4);

  const Result alone = run(MPI_COMM_SELF);
  check_that("1 rank: the step converged", alone.completed);
  check("1 rank against all: |force difference| / |force|",
        (alone.force - r.force).norm() / r.force.norm(),
        1e-8);
}
