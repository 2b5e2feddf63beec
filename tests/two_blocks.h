// The two elastic blocks of the tests of contact between deformable bodies
// (contact_two_blocks, contact_bodies_loads): E = 1000, nu = 0.3, plane
// strain (or axisymmetric), small strain, cells of h = 0.125 and 2 x 2
// points per cell, block A (material id 0) below x_a = 1 and block B (id 1)
// beyond, a the direction along the blocks.
#ifndef qsmpm_tests_two_blocks_h
#define qsmpm_tests_two_blocks_h

#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <limits>
#include <map>
#include <memory>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>
#include <string>

namespace two_blocks
{
  using namespace dealii;
  using namespace qsmpm;

  /// The material, the cell size, the blocks' width across, the gap g
  /// between them, and the compression c and separation s of motion().
  const double E = 1000., nu = 0.3, h = 0.125, W = 0.5, g = 0.5 * h, c = 0.006,
               s = 0.01;

  /// The motion of B's far end along the blocks: t in [0, 0.4], -g t / 0.4
  /// (B slides to A); t in [0.4, 0.7], further by -c (t - 0.4) / 0.3
  /// (compression); t in [0.7, 1], back to -g + s at t = 1 (the blocks
  /// come apart). @p single: that of one block [0, 2 - g] in the closed
  /// blocks' place, 0 until t = 0.4, then u(t) + g.
  inline double
  motion(const double t, const bool single)
  {
    double u = 0.;
    if (t <= 0.4)
      u = -g * t / 0.4;
    else if (t <= 0.7)
      u = -g - c * (t - 0.4) / 0.3;
    else
      u = -g - c + (c + s) * (t - 0.7) / 0.3;
    return single ? (t <= 0.4 ? 0. : u + g) : u;
  }

  /// The solver (Newton to 1e-10), no output into @p directory, @p n_steps
  /// load steps, @p shape_functions, and, if @p two_bodies, contact
  /// between the bodies of material ids 0 and 1 with @p friction.
  inline void
  set_up(QuasiStaticProblem<2>                     &problem,
         const bool                                 two_bodies,
         const BodyContact<2>::Parameters::Friction friction,
         const ShapeFunctions                       shape_functions,
         const unsigned int                         n_steps,
         const std::string                         &directory)
  {
    problem.pcout().set_condition(false);
    auto &prm                                       = problem.parameters();
    prm.material_points.formulation.shape_functions = shape_functions;
    prm.load_stepping.n_steps                       = n_steps;
    prm.nonlinear_solver.tolerance                  = 1e-10;
    prm.output.interval                             = 0;
    prm.output.directory                            = directory;
    if (two_bodies)
      {
        BodyContact<2>::Parameters contact;
        contact.bodies   = "0; 1";
        contact.friction = friction;
        problem.set_body_contact(contact);
      }
  }

  /// The linear elastic model and 2 x 2 points per cell where @p inside
  /// is true: material id 0 below x_a = 1 and, if @p two_bodies, 1 beyond
  /// (otherwise 0 everywhere).
  template <typename Inside>
  inline void
  make_points(QuasiStaticProblem<2> &problem,
              const Inside          &inside,
              const bool             two_bodies,
              const unsigned int     a = 0)
  {
    LinearElastic<2>::Parameters material;
    material.elasticity.young_modulus = E;
    material.elasticity.poisson_ratio = nu;
    problem.set_model(std::make_unique<LinearElastic<2>>(material));
    problem.points().fill(inside,
                          MaterialPointSet<2>::reference_rule(
                            MaterialPointSet<2>::Placement::regular, {{2, 2}}),
                          [two_bodies, a](const Point<2> &x) {
                            return two_bodies && x[a] >= 1. ? 1u : 0u;
                          });
  }

  /// Run @p problem; the number of load steps it accepted.
  inline unsigned int
  run_counting_steps(QuasiStaticProblem<2> &problem)
  {
    unsigned int steps = 0;
    problem.set_step_callback([&](const QuasiStaticProblem<2>::StepReport &) {
      ++steps;
      return true;
    });
    problem.run();
    return steps;
  }

  /// Each point's stress (xx, yy, xy), by particle id (this rank's points).
  using Stresses = std::map<types::particle_index, std::array<double, 3>>;

  /// The stresses of the points of @p problem.
  inline Stresses
  point_stresses(const QuasiStaticProblem<2> &problem)
  {
    Stresses    result;
    const auto &offsets = problem.points().get_offsets();
    for (const auto &particle : problem.points().get_particle_handler())
      {
        const SymmetricTensor<2, 2> s = qsmpm::Utils::read_symmetric<2>(
          &particle.get_properties()[offsets.stress]);
        result[particle.get_id()] = {{s[0][0], s[1][1], s[0][1]}};
      }
    return result;
  }

  /// The largest difference of a point's stress component between two
  /// runs (all ranks; the partition is the same in both): infinite if a
  /// point of @p a is not among those of @p b.
  inline double
  largest_stress_difference(const Stresses &a, const Stresses &b)
  {
    double difference = 0.;
    for (const auto &[id, s] : a)
      {
        const auto found = b.find(id);
        if (found == b.end())
          difference = std::numeric_limits<double>::infinity();
        else
          for (unsigned int k = 0; k < 3; ++k)
            difference =
              std::max(difference, std::abs(s[k] - found->second[k]));
      }
    return Utilities::MPI::max(difference, MPI_COMM_WORLD);
  }
} // namespace two_blocks

#endif
