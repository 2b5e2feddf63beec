// Contact between deformable bodies together with a traction on the
// body's own surface (SurfaceTractions): two elastic blocks side by side
// on a multi-field grid, A [0, 1] (material id 0) and B [1, 2] (id 1),
// touching, grid [0, 2.25] x [0, 0.5] (room beyond B's free face),
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
// tractions.) Before, a run with bodies and a surface
// traction stopped at once ("Surface tractions cannot be used with
// several bodies yet"); with only that check lifted, the load of a point
// went to every body's field at its cell's nodes (its components indexed
// past dim).
#include "tests.h"

#include <limits>
#include <map>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>

using namespace qsmpm;

namespace
{
  const double E = 1000., nu = 0.3, W = 0.5, p = 10.;

  struct Result
  {
    /// Each point's stress (xx, yy, xy), by its initial position.
    std::map<types::particle_index, std::array<double, 3>> stress;
    double                                                 reaction  = 0.;
    bool                                                   all_steps = false;
  };

  Result
  run(const bool                                 two_bodies,
      const BodyContact<2>::Parameters::Friction friction,
      const ShapeFunctions                       shape_functions)
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    problem.pcout().set_condition(false);
    auto &prm                                       = problem.parameters();
    prm.material_points.formulation.shape_functions = shape_functions;
    prm.load_stepping.n_steps                       = 4;
    prm.nonlinear_solver.tolerance                  = 1e-10;
    prm.output.interval                             = 0;
    prm.output.directory                            = "bodies-traction-out";
    BodyContact<2>::Parameters contact;
    contact.bodies   = "0; 1";
    contact.friction = friction;
    if (two_bodies)
      problem.set_body_contact(contact);
    problem.grid().make_box(Point<2>(), Point<2>(2.25, W), {{18, 4}});
    auto      &bcs  = problem.boundary_conditions();
    const auto zero = std::make_shared<Functions::ZeroFunction<2>>(2);
    bcs.add_dirichlet_boundary(0, {{true, false}}, zero);
    bcs.add_dirichlet_boundary(2, {{false, true}}, zero);
    bcs.add_dirichlet_boundary(3, {{false, true}}, zero);
    auto traction = std::make_shared<FunctionParser<2>>(2);
    traction->initialize("x,y,t", "-p*t; 0", {{"p", p}}, true);
    bcs.add_surface_traction(
      "end", [](const Point<2> &x) { return x[0] > 2. - 1e-9; }, traction);

    LinearElastic<2>::Parameters material;
    material.elasticity.young_modulus = E;
    material.elasticity.poisson_ratio = nu;
    problem.set_model(std::make_unique<LinearElastic<2>>(material));
    problem.points().fill([](const Point<2> &x) { return x[0] < 2.; },
                          MaterialPointSet<2>::reference_rule(
                            MaterialPointSet<2>::Placement::regular, {{2, 2}}),
                          [](const Point<2> &x) {
                            return x[0] < 1. ? 0u : 1u;
                          });
    unsigned int steps = 0;
    problem.set_step_callback([&](const QuasiStaticProblem<2>::StepReport &) {
      ++steps;
      return true;
    });
    problem.run();

    Result      result;
    const auto &offsets = problem.points().get_offsets();
    for (const auto &particle : problem.points().get_particle_handler())
      {
        const SymmetricTensor<2, 2> s = qsmpm::Utils::read_symmetric<2>(
          &particle.get_properties()[offsets.stress]);
        result.stress[particle.get_id()] = {{s[0][0], s[1][1], s[0][1]}};
      }
    result.reaction  = problem.reactions().at(0)[0];
    result.all_steps = steps == 4;
    return result;
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
      const Result single =
        run(false,
            BodyContact<2>::Parameters::Friction::frictionless,
            shape_functions);
      check_that("  one block: 4 steps", single.all_steps);
      for (const auto &[friction, friction_name] :
           {std::make_pair(BodyContact<2>::Parameters::Friction::frictionless,
                           "frictionless"),
            std::make_pair(BodyContact<2>::Parameters::Friction::rough,
                           "rough")})
        {
          deallog << "  " << friction_name << " contact" << std::endl;
          const Result r = run(true, friction, shape_functions);
          check_that("    4 steps", r.all_steps);
          // Each point's stress against the one block's at the same place
          // (this rank's points; the partition is the same in both runs).
          double difference = 0.;
          for (const auto &[id, s] : r.stress)
            {
              const auto found = single.stress.find(id);
              if (found == single.stress.end())
                difference = std::numeric_limits<double>::infinity();
              else
                for (unsigned int k = 0; k < 3; ++k)
                  difference =
                    std::max(difference, std::abs(s[k] - found->second[k]));
            }
          difference = Utilities::MPI::max(difference, MPI_COMM_WORLD) / p;
          check("    max |stress - one block's| / p", difference, 1e-6);
          check("    |reaction at x = 0| / (p W) - 1",
                std::abs(r.reaction) / (p * W) - 1.,
                1e-6);
        }
    }
}
