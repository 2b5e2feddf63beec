// Prandtl's smooth strip footing (half-width a = 1) as a rigid box pushed
// into a weightless von Mises soil (c = 100, nu = 0.3), plane strain,
// F-bar, 2 x 2 points per cell, the soil 3 a deep: the set-up that the
// rigid-footing contact tests share. Each test gives the points'
// formulation, E, the settlement and the grid with its supports.
#ifndef qsmpm_tests_rigid_footing_h
#define qsmpm_tests_rigid_footing_h

#include "tests.h"

#include <deal.II/base/function.h>
#include <qsmpm/core/quasi_static_problem.h>

namespace rigid_footing
{
  using namespace qsmpm;

  const double a = 1., sigma_y = 173.20508075688772;
  const double c = sigma_y / std::sqrt(3.), prandtl = 2. + numbers::PI;
  const double depth = 3.;

  /// The curve q/c against s, and the largest |supports - footing force|
  /// relative to the footing force over the steps.
  struct Result
  {
    bool                completed = false;
    std::vector<double> s, q_over_c;
    double              largest_imbalance = 0.;
    std::string         message;
  };

  /// Push the footing down by @p settlement in @p steps steps on @p comm:
  /// @p points_entries are the lines of subsection Material points beside
  /// 2 x 2 points and F-bar, @p grid_and_supports(problem) makes the grid
  /// and the supports (ids 0-2 carry the reactions). In 3D the soil is a
  /// slab z in [0, @p thickness] (the grid's supports hold it in plane
  /// strain), the footing reaches a thickness beyond it on either side, and
  /// q is the force over a times the thickness.
  template <int dim = 2, typename GridAndSupports>
  Result
  run(const MPI_Comm         comm,
      const std::string     &points_entries,
      const double           youngs_modulus,
      const double           settlement,
      const unsigned int     steps,
      const GridAndSupports &grid_and_supports,
      const double           thickness = 1.)
  {
    std::ostringstream text;
    text << "set Dimension = " << dim << "\n"
         << "subsection Material points\n"
         << "  set Points per cell per direction = 2\n"
         << points_entries << "  set Volumetric locking = F-bar\nend\n"
         << "subsection Material\n  set Model = von Mises\n"
         << "  subsection von Mises\n"
         << "    set Young's modulus = " << youngs_modulus
         << "\n    set Poisson's ratio = 0.3\n"
         << "    set Yield stress = " << std::setprecision(17) << sigma_y
         << "\n    set Hardening modulus = 0\n  end\nend\n"
         << "subsection Load stepping\n  set Number of steps = " << steps
         << "\nend\n"
         << "subsection Nonlinear solver\n  set Line search steps = 8\nend\n"
         << "subsection Output\n  set Interval = 0\n"
         << "  set Directory = rigid-footing-out\nend\n";
    ParameterHandler prm;
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
    QuasiStaticProblem<dim>::Parameters::declare_parameters(prm);
    prm.parse_input_from_string(text.str());

    QuasiStaticProblem<dim> problem(comm);
    problem.pcout().set_condition(false);
    problem.parameters().parse_parameters(prm);
    grid_and_supports(problem);
    RigidBody<dim> footing;
    footing.name            = "footing";
    footing.shape           = RigidBody<dim>::Shape::box;
    footing.point[0]        = -a;
    footing.point[1]        = depth;
    footing.upper_corner[0] = a;
    footing.upper_corner[1] = depth + a;
    if (dim == 3)
      {
        footing.point[dim - 1]        = -thickness;
        footing.upper_corner[dim - 1] = 2. * thickness;
      }
    footing.motion         = downward_motion<dim>(settlement);
    footing.penalty_factor = 10.;
    problem.boundary_conditions().add_rigid_body(footing);
    problem.set_model(ConstitutiveModelFactory<dim>::create(prm));
    problem.points().fill(
      [](const Point<dim> &x) {
        return x[0] > 0. && x[1] > 0. && x[1] < depth;
      },
      2,
      MaterialPointSet<dim>::Placement::regular);

    Result       result;
    const double width = dim == 3 ? a * thickness : a;
    problem.set_step_callback(
      [&](const typename QuasiStaticProblem<dim>::StepReport &report) {
        const double force    = problem.rigid_body_loads().front().force[1];
        double       supports = 0.;
        for (unsigned int k = 0; k < 3; ++k)
          supports += problem.reactions()[k][1];
        result.s.push_back(settlement * report.load_factor);
        result.q_over_c.push_back(force / width / c);
        result.largest_imbalance =
          std::max(result.largest_imbalance,
                   std::abs(supports - force) / std::abs(force));
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

  /// Push the footing down by @p settlement in @p steps steps on @p comm
  /// at finite strain with cpGIMP (Ghost penalty 1e-4), E = 1e5, a/h = 4,
  /// on the grid of examples/footing: x in [-h, 4 a], y in [-h, depth + a]
  /// (17 x 17 cells), a column of cells at x < 0 held in x with the
  /// symmetry line, a row of cells below the soil held in x and y, rollers
  /// on the right. In 3D the same on a slab one cell (h) thick held in z on
  /// both faces: plane strain again.
  template <int dim = 2>
  inline Result
  run_finite_strain_gimp(const MPI_Comm     comm,
                         const double       settlement,
                         const unsigned int steps)
  {
    const double h = a / 4.;
    return run<dim>(
      comm,
      "  set Kinematics = finite strain\n"
      "  set Shape functions = cpGIMP\n"
      "  set Ghost penalty = 1e-4\n",
      1e5,
      settlement,
      steps,
      [h](QuasiStaticProblem<dim> &problem) {
        Point<dim>                    lower, upper;
        std::array<unsigned int, dim> cells;
        lower[0] = lower[1] = -h;
        upper[0]            = 4. * a;
        upper[1]            = depth + a;
        cells[0] = cells[1] = 17;
        if (dim == 3)
          {
            upper[dim - 1] = h;
            cells[dim - 1] = 1;
          }
        problem.grid().make_box(lower, upper, cells);
        auto      &bcs  = problem.boundary_conditions();
        const auto zero = std::make_shared<Functions::ZeroFunction<dim>>(dim);
        std::array<bool, dim> x_only{}, all{};
        x_only[0] = true;
        all.fill(true);
        bcs.add_dirichlet_nodes(
          "symmetry",
          [](const Point<dim> &x) { return x[0] <= 1e-10; },
          x_only,
          zero);
        bcs.add_dirichlet_boundary(1, {}, zero, /*normal_only=*/true);
        bcs.add_dirichlet_nodes(
          "base", [](const Point<dim> &x) { return x[1] <= 1e-10; }, all, zero);
        if (dim == 3)
          for (const unsigned int face : {4u, 5u})
            bcs.add_dirichlet_boundary(face, {}, zero, /*normal_only=*/true);
      },
      h);
  }

  /// Check that the run of @p r completed; print why it stopped if not.
  inline bool
  check_completed(const Result &r)
  {
    check_that("completed", r.completed);
    if (!r.completed)
      deallog << "  run stopped: " << r.message << std::endl;
    return r.completed;
  }

  /// q/c at the settlement @p s of @p r (0 if no step ends there).
  inline double
  q_over_c_at(const Result &r, const double s)
  {
    for (unsigned int k = 0; k < r.s.size(); ++k)
      if (std::abs(r.s[k] - s) < 1e-9)
        return r.q_over_c[k];
    return 0.;
  }

  /// The largest fall of q from one step to the next beyond the settlement
  /// @p from, over (2 + pi) c.
  inline double
  largest_fall(const Result &r, const double from)
  {
    double fall = 0.;
    for (unsigned int k = 1; k < r.s.size(); ++k)
      if (r.s[k] > from)
        fall = std::max(fall, (r.q_over_c[k - 1] - r.q_over_c[k]) / prandtl);
    return fall;
  }

  /// The checks of a footing pushed in by @p settlement at finite strain
  /// (contact_footing_deep and its 3D slab): it got there; from s = 0.05 a
  /// on no step lowers q by more than 2 % of (2 + pi) c (a perfectly
  /// plastic, weightless soil under monotonic penetration); q at the end is
  /// at least q at s = 0.05 a (the embedment only raises the limit load);
  /// the supports carry the footing's force to 1e-4 of it in every step.
  inline void
  check_deep_penetration(const Result &r, const double settlement)
  {
    check_that("the footing reached s = a",
               std::abs(r.s.back() - settlement) < 1e-12);
    check("largest fall of q in one step, s > 0.05 a, / ((2 + pi) c)",
          largest_fall(r, 0.05 * a),
          0.02);
    const double first_limit = q_over_c_at(r, 0.05 * a);
    check_that("q(s = a) >= q(s = 0.05 a) > 0",
               first_limit > 0. && r.q_over_c.back() >= first_limit);
    check("largest |supports - footing force| / footing force",
          r.largest_imbalance,
          1e-4);
  }

  /// Check that @p alone (1 rank) gives the steps of @p r and its q to
  /// 1e-4 of (2 + pi) c.
  inline void
  check_same_on_one_rank(const Result &r, const Result &alone)
  {
    bool   same       = alone.completed && alone.s.size() == r.s.size();
    double difference = 0.;
    for (unsigned int k = 0; same && k < r.s.size(); ++k)
      {
        same = same && std::abs(alone.s[k] - r.s[k]) < 1e-12;
        difference =
          std::max(difference,
                   std::abs(alone.q_over_c[k] - r.q_over_c[k]) / prandtl);
      }
    check_that("1 rank: the same load steps", same);
    check("1 rank against all: largest |q difference| / ((2 + pi) c)",
          difference,
          1e-4);
  }
} // namespace rigid_footing

#endif
