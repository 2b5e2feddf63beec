// The rotated pre-stressed block of the tests finite_strain_rotation
// (Hencky) and umat_finite_strain (a UMAT): see finite_strain_rotation.cc
// for what it does and checks.
#ifndef qsmpm_tests_rotated_block_h
#define qsmpm_tests_rotated_block_h

#include "tests.h"

#include <algorithm>
#include <deal.II/base/function.h>
#include <functional>
#include <map>
#include <memory>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>

using namespace qsmpm;

namespace rotated_block_test
{
  const double       angle_step       = 9. * M_PI / 180.;
  const unsigned int n_rotation_steps = 10;

  template <int dim>
  Tensor<2, dim>
  stretch()
  {
    const double   s[3] = {1.1, 0.95, 1.05};
    Tensor<2, dim> F0;
    for (unsigned int d = 0; d < dim; ++d)
      F0[d][d] = s[d];
    return F0;
  }

  /// The rotation by @p angle in the x-y plane (about z in 3D).
  template <int dim>
  Tensor<2, dim>
  rotation(const double angle)
  {
    Tensor<2, dim> R;
    for (unsigned int d = 0; d < dim; ++d)
      R[d][d] = 1.;
    R[0][0] = R[1][1] = std::cos(angle);
    R[0][1]           = -std::sin(angle);
    R[1][0]           = std::sin(angle);
    return R;
  }

  template <int dim>
  Point<dim>
  centre()
  {
    Point<dim> c;
    for (unsigned int d = 0; d < dim; ++d)
      c[d] = 0.05 * (d + 1);
    return c;
  }

  /**
   * g(x, t): t (F0 - I)(x - c) for t <= 1, then
   * (F0 - I)(x - c) + (t - 1)(R - I)(x - c), so that the increment of a
   * step from t = k to k + 1 is (F0 - I)(x - c) for k = 0 and
   * (R - I)(x - c) for k >= 1.
   */
  template <int dim>
  class StretchThenRotate : public Function<dim>
  {
  public:
    StretchThenRotate()
      : Function<dim>(dim)
    {
    }

    void
    vector_value(const Point<dim> &x, Vector<double> &values) const override
    {
      const double         t  = this->get_time();
      const Tensor<2, dim> I  = unit_symmetric_tensor<dim>();
      const Tensor<1, dim> dx = x - centre<dim>();
      Tensor<1, dim>       g  = std::min(t, 1.) * ((stretch<dim>() - I) * dx);
      if (t > 1.)
        g += (t - 1.) * ((rotation<dim>(angle_step) - I) * dx);
      for (unsigned int d = 0; d < dim; ++d)
        values[d] = g[d];
    }
  };

  template <int dim>
  Tensor<2, dim>
  read_F(const double *data, const unsigned int offset)
  {
    Tensor<2, dim> F;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        F[i][j] = data[offset + i * dim + j];
    return F;
  }

  /// What a point carries after the stretch step.
  template <int dim>
  struct State
  {
    Point<dim>              X;
    SymmetricTensor<2, dim> stress;
  };

  template <int dim>
  std::array<double, dim>
  principal(const SymmetricTensor<2, dim> &s)
  {
    auto values = eigenvalues(s);
    std::sort(values.begin(), values.end());
    return values;
  }

  /**
   * lambda tr(ln F0) I + 2 mu ln F0 for a diagonal F0 and the Lame
   * constants of E, nu: the Kirchhoff stress of Hencky's model, and the
   * Cauchy stress of a hypoelastic UMAT given the logarithmic strain (in
   * 2D the in-plane part of the 3D formula, ln F0_zz = 0).
   */
  template <int dim>
  SymmetricTensor<2, dim>
  log_strain_stress(const Tensor<2, dim> &F0, const double E, const double nu)
  {
    const double            mu     = E / (2. * (1. + nu));
    const double            lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
    SymmetricTensor<2, dim> ln_U;
    for (unsigned int d = 0; d < dim; ++d)
      ln_U[d][d] = std::log(F0[d][d]);
    return lambda * trace(ln_U) * unit_symmetric_tensor<dim>() + 2. * mu * ln_U;
  }

  /**
   * The test for the model @p model. @p closed_form is the Cauchy stress the
   * model gives for the stretch F0 applied in one step from the
   * unstressed state.
   */
  template <int dim>
  void
  rotated_block(
    const ShapeFunctions                    shape_functions,
    const std::string                      &name,
    std::unique_ptr<ConstitutiveModel<dim>> model,
    const std::function<SymmetricTensor<2, dim>(const Tensor<2, dim> &)>
      &closed_form)
  {
    QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
    problem.pcout().set_condition(false);

    // Grid [-1, 1]^dim with 8 cells per direction, block [-0.5, 0.5]^dim
    // (2^dim points per cell): stretched and rotated, it stays well inside.
    std::array<unsigned int, dim> n;
    n.fill(8);
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = -1.;
        upper[d] = 1.;
      }
    problem.grid().make_box(lower, upper, n);

    auto &prm                                       = problem.parameters();
    prm.material_points.formulation.kinematics      = Kinematics::finite_strain;
    prm.material_points.formulation.shape_functions = shape_functions;
    prm.load_stepping.n_steps                       = 1 + n_rotation_steps;
    prm.load_stepping.final_load_factor             = 1. + n_rotation_steps;
    prm.nonlinear_solver.tolerance                  = 1e-12;
    prm.nonlinear_solver.residual_floor             = 0.;
    // Every increment is prescribed, so Newton has nothing to solve. In 2D
    // the default AMG set-up on the (all-constrained) tangent is kept as a
    // check that this case works; in 3D it would dominate the run time
    // (about 1.5 s per step with the 27-node GIMP stencil).
    if (dim == 3)
      prm.nonlinear_solver.preconditioner = "none";
    prm.output.directory = "results";
    prm.output.interval  = 0;

    problem.set_model(std::move(model));
    problem.points().fill(
      [](const Point<dim> &x) {
        for (unsigned int d = 0; d < dim; ++d)
          if (std::abs(x[d]) > 0.5)
            return false;
        return true;
      },
      2,
      MaterialPointSet<dim>::Placement::regular);
    std::array<bool, dim> all;
    all.fill(true);
    problem.boundary_conditions().add_dirichlet_nodes(
      "all nodes",
      [](const Point<dim> &) { return true; },
      all,
      std::make_shared<StretchThenRotate<dim>>());

    const auto          &offsets = problem.points().get_offsets();
    const auto          &handler = problem.points().get_particle_handler();
    const Tensor<2, dim> F0      = stretch<dim>();
    const Tensor<2, dim> Q       = rotation<dim>(n_rotation_steps * angle_step);
    const Point<dim>     c       = centre<dim>();
    const double         det_F0  = determinant(F0);

    std::map<types::particle_index, State<dim>> initial;
    for (const auto &particle : handler)
      initial[particle.get_id()] = {particle.get_location(), {}};

    const SymmetricTensor<2, dim> sigma_exact = closed_form(F0);

    // After step 1: record the stress, check the stretched state.
    double stretch_F = 0, stretch_J = 0, stretch_stress = 0, stretch_x = 0;
    problem.set_step_callback([&](const auto &report) {
      if (report.step != 1)
        return true;
      for (const auto &particle : handler)
        {
          const double *data  = particle.get_properties().data();
          State<dim>   &state = initial.at(particle.get_id());
          state.stress = Utils::read_symmetric<dim>(data + offsets.stress);
          stretch_F    = std::max(
            stretch_F,
            (read_F<dim>(data, offsets.deformation_gradient) - F0).norm());
          stretch_J =
            std::max(stretch_J, std::abs(data[offsets.J] - det_F0) / det_F0);
          stretch_stress =
            std::max(stretch_stress,
                     (state.stress - sigma_exact).norm() / sigma_exact.norm());
          const Point<dim> x_exact = c + F0 * (state.X - c);
          stretch_x =
            std::max(stretch_x, particle.get_location().distance(x_exact));
        }
      return true;
    });

    problem.run();

    bool converged = problem.step_reports().size() == 1 + n_rotation_steps;
    for (const auto &report : problem.step_reports())
      converged = converged && report.cut_backs == 0 && report.newton.converged;

    double principal_error = 0, stress_error = 0, F_error = 0, J_error = 0,
           x_error = 0, u_error = 0;
    for (const auto &particle : handler)
      {
        const double                 *data  = particle.get_properties().data();
        const State<dim>             &state = initial.at(particle.get_id());
        const SymmetricTensor<2, dim> sigma =
          Utils::read_symmetric<dim>(data + offsets.stress);
        const double scale = state.stress.norm();

        const auto p0 = principal(state.stress), p = principal(sigma);
        for (unsigned int d = 0; d < dim; ++d)
          principal_error =
            std::max(principal_error,
                     std::abs(p[d] - p0[d]) /
                       std::max(std::abs(p0[0]), std::abs(p0[dim - 1])));

        const Tensor<2, dim> rotated =
          Q * Tensor<2, dim>(state.stress) * transpose(Q);
        stress_error =
          std::max(stress_error,
                   (Tensor<2, dim>(sigma) - rotated).norm() / scale);
        F_error = std::max(
          F_error,
          (read_F<dim>(data, offsets.deformation_gradient) - Q * F0).norm());
        J_error =
          std::max(J_error, std::abs(data[offsets.J] - det_F0) / det_F0);

        const Point<dim> x_exact = c + Q * (F0 * (state.X - c));
        x_error = std::max(x_error, particle.get_location().distance(x_exact));
        Tensor<1, dim> u;
        for (unsigned int d = 0; d < dim; ++d)
          u[d] = data[offsets.displacement + d];
        u_error = std::max(u_error, (u - (x_exact - state.X)).norm());
      }

    deallog << dim << "D, " << name << " shape functions, "
            << problem.points().n_global_points() << " points, "
            << problem.step_reports().size() << " steps" << std::endl;
    check_that("  all steps converged without cut-backs", converged);
    deallog << "  after the stretch F0:" << std::endl;
    check("    max |F - F0|", stretch_F, 1e-10);
    check("    max |J - det F0| / det F0", stretch_J, 1e-10);
    check("    max |sigma - closed form| / |sigma|", stretch_stress, 1e-10);
    check("    max |x - (c + F0 (X - c))|", stretch_x, 1e-10);
    deallog << "  after the rotation Q by 90 degrees in " << n_rotation_steps
            << " steps:" << std::endl;
    check("    max principal stress change / max |principal stress|",
          principal_error,
          1e-8);
    check("    max |sigma - Q sigma_1 Q^T| / |sigma_1|", stress_error, 1e-8);
    check("    max |F - Q F0|", F_error, 1e-10);
    check("    max |J - det F0| / det F0", J_error, 1e-10);
    check("    max |x - (c + Q F0 (X - c))|", x_error, 1e-10);
    check("    max |u - (c + Q F0 (X - c) - X)|", u_error, 1e-10);
  }
} // namespace rotated_block_test

#endif
