// The finite-strain hyperelastic models Hencky (tau = D : 1/2 ln b) and
// neo-Hookean (tau = mu (b - I) + lambda ln J I), in 2D (plane strain) and
// 3D, single points, against independent closed forms:
//
// - the tensor logarithm and its derivative (TensorFunctions) against
//   spectral closed forms, finite differences and log1p;
// - uniaxial stretch F = diag(s, 1, 1): tau_xx, tau_yy (, tau_zz) in closed
//   form;
// - objectivity tau(Q F) = Q tau(F) Q^T and isotropy tau(F Q) = tau(F) for a
//   general (non-symmetric) F;
// - the Kirchhoff tangent (d tau = c : d l, d l = d(Delta F) Delta F^{-1})
//   against central finite differences, including b = I and b with
//   repeated and nearly repeated eigenvalues;
// - the small-strain limit tau / eps -> C : sym(G) at F = I + eps G;
// - the small-strain interface: sigma = sigma_old + C : d eps, tangent C;
// - creation through the registry by name and parameters;
// - a small-strain-only model (linear elastic) refuses the finite-strain
//   interface with a message.
//
// Tolerances: closed forms and exact properties of tau (|tau| ~ 0.3 E)
// 1e-10 E: the spectral decomposition and logarithm leave round-off of
// 1e-16 ... 1e-15 E (measured; QSMPM_VERBOSE prints the values), and a
// wrong formula is off by O(|tau|). Tangents against central differences
// with h = 1e-6: 1e-6 relative, far above the difference quotient's own
// error (truncation O(h^2) = 1e-12, round-off eps / h = 1e-10; measured
// 1e-11 ... 6e-10) and far below a missing term (the geometric terms of
// the Kirchhoff tangent are O(|tau| / |c|) ~ 0.1).
#include "tests.h"

#include <deal.II/physics/transformations.h>
#include <qsmpm/base/tensor_functions.h>
#include <qsmpm/materials/hencky.h>
#include <qsmpm/materials/linear_elastic.h>
#include <qsmpm/materials/neo_hookean.h>

using namespace qsmpm;

namespace
{
  const double E = 1e6, nu = 0.3;
  const double lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
  const double mu     = E / (2. * (1. + nu));

  /// The first dim x dim block of a 3x3 matrix given by rows.
  template <int dim>
  Tensor<2, dim>
  matrix(const double (&m)[3][3])
  {
    Tensor<2, dim> A;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        A[i][j] = m[i][j];
    return A;
  }

  template <int dim>
  Tensor<2, dim>
  diagonal(const double a0, const double a1, const double a2)
  {
    const double   a[3] = {a0, a1, a2};
    Tensor<2, dim> D;
    for (unsigned int i = 0; i < dim; ++i)
      D[i][i] = a[i];
    return D;
  }

  /// A rotation by @p angle (about a fixed oblique axis in 3D).
  template <int dim>
  Tensor<2, dim>
  rotation(const double angle, const double axis_tilt = 0.4)
  {
    if constexpr (dim == 2)
      return Physics::Transformations::Rotations::rotation_matrix_2d(angle);
    else
      {
        Point<3> axis(std::cos(axis_tilt), 0.6, std::sin(axis_tilt) + 0.3);
        axis /= axis.norm();
        return Physics::Transformations::Rotations::rotation_matrix_3d(axis,
                                                                       angle);
      }
  }

  // A general deformation: stretch + shear (not symmetric), then rotated.
  const double A_rows[3][3] = {{1.25, 0.30, -0.10},
                               {0.05, 0.85, 0.20},
                               {-0.15, 0.10, 1.10}};
  const double B_rows[3][3] = {{1.10, -0.20, 0.05},
                               {0.15, 0.95, 0.10},
                               {0.00, -0.05, 0.90}};

  template <int dim>
  Tensor<2, dim>
  general_F()
  {
    return rotation<dim>(0.7) * matrix<dim>(A_rows);
  }

  template <int dim>
  Tensor<2, dim>
  general_delta_F()
  {
    return rotation<dim>(-0.35, 1.1) * matrix<dim>(B_rows);
  }

  template <int dim>
  PointState<dim>
  point_state()
  {
    return {SymmetricTensor<2, dim>(),
            SymmetricTensor<2, dim>(),
            ArrayView<const double>(),
            1.};
  }

  /// tau at F = delta_F F_old.
  template <int dim>
  SymmetricTensor<2, dim>
  kirchhoff(const ConstitutiveModel<dim> &model,
            const Tensor<2, dim>         &F_old,
            const Tensor<2, dim>         &delta_F)
  {
    const FiniteStrainKinematics<dim> k{F_old, delta_F, delta_F * F_old};
    SymmetricTensor<2, dim>           tau;
    model.update_kirchhoff_stress(point_state<dim>(),
                                  k,
                                  tau,
                                  ArrayView<double>());
    return tau;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  kirchhoff(const ConstitutiveModel<dim> &model, const Tensor<2, dim> &F)
  {
    return kirchhoff(model, Tensor<2, dim>(unit_symmetric_tensor<dim>()), F);
  }

  /// Isotropic linear elasticity C : eps with the Lame constants above.
  template <int dim>
  SymmetricTensor<2, dim>
  hooke(const SymmetricTensor<2, dim> &eps)
  {
    return lambda * trace(eps) * unit_symmetric_tensor<dim>() + 2. * mu * eps;
  }

  /**
   * Max over s and components of |tau - tau_exact| / E for the uniaxial
   * stretch F = diag(s, 1, 1); tau_exact_xx and tau_exact_other are the
   * closed forms.
   */
  template <int dim, typename Exact>
  double
  uniaxial_error(const ConstitutiveModel<dim> &model, const Exact &exact)
  {
    double error = 0.;
    for (const double s : {0.5, 0.7, 1.3, 2.})
      {
        const SymmetricTensor<2, dim> tau =
          kirchhoff(model, diagonal<dim>(s, 1., 1.));
        const std::pair<double, double> tau_exact = exact(s);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            {
              const double t =
                i != j ? 0. : (i == 0 ? tau_exact.first : tau_exact.second);
              error = std::max(error, std::abs(tau[i][j] - t) / E);
            }
      }
    return error;
  }

  /**
   * Relative Frobenius error of the Kirchhoff tangent against central
   * differences of tau in the directions d l = h E_kl, i.e.
   * Delta F -> Delta F + h E_kl Delta F.
   */
  template <int dim>
  double
  tangent_error(const ConstitutiveModel<dim> &model,
                const Tensor<2, dim>         &F_old,
                const Tensor<2, dim>         &delta_F)
  {
    const FiniteStrainKinematics<dim> kinematics{F_old,
                                                 delta_F,
                                                 delta_F * F_old};
    const Tensor<4, dim>              c =
      model.kirchhoff_tangent(point_state<dim>(), kinematics);
    const double h      = 1e-6;
    double       error2 = 0.;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int l = 0; l < dim; ++l)
        {
          Tensor<2, dim> E_kl;
          E_kl[k][l]                          = 1.;
          const Tensor<2, dim>          plus  = delta_F + h * E_kl * delta_F;
          const Tensor<2, dim>          minus = delta_F - h * E_kl * delta_F;
          const SymmetricTensor<2, dim> fd =
            (kirchhoff(model, F_old, plus) - kirchhoff(model, F_old, minus)) /
            (2. * h);
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              error2 += std::pow(fd[i][j] - c[i][j][k][l], 2);
        }
    return std::sqrt(error2) / c.norm();
  }

  template <int dim>
  void
  check_model(const ConstitutiveModel<dim> &model, const bool is_hencky)
  {
    const std::string prefix =
      "  " + std::to_string(dim) + "D " + model.name() + ": ";
    check_that(prefix + "supports finite strain",
               model.supports_finite_strain());

    // Uniaxial stretch, closed form.
    const auto exact = [&](const double s) -> std::pair<double, double> {
      const double ln_s = std::log(s);
      if (is_hencky)
        return {(lambda + 2. * mu) * ln_s, lambda * ln_s};
      else
        return {mu * (s * s - 1.) + lambda * ln_s, lambda * ln_s};
    };
    check(prefix + "uniaxial stretch s = 0.5, 0.7, 1.3, 2: "
                   "max |tau - tau_exact| / E",
          uniaxial_error(model, exact),
          1e-10);

    // Objectivity and isotropy at a general F.
    const Tensor<2, dim> F = general_F<dim>();
    const double         J = determinant(F);
    check_that(prefix + "general F: 0.6 <= det F <= 1.5", J >= 0.6 && J <= 1.5);
    const Tensor<2, dim>          Q   = rotation<dim>(1.9, -0.8);
    const SymmetricTensor<2, dim> tau = kirchhoff(model, F);
    const Tensor<2, dim>          rotated =
      Q * static_cast<Tensor<2, dim>>(tau) * transpose(Q);
    check(prefix + "objectivity: |tau(Q F) - Q tau(F) Q^T| / E",
          (static_cast<Tensor<2, dim>>(
             kirchhoff(model, Tensor<2, dim>(Q * F))) -
           rotated)
              .norm() /
            E,
          1e-10);
    check(prefix + "isotropy: |tau(F Q) - tau(F)| / E",
          (kirchhoff(model, Tensor<2, dim>(F * Q)) - tau).norm() / E,
          1e-10);
    check_at_least(prefix + "(the test is not trivial) |tau(F)| / E",
                   tau.norm() / E,
                   0.1);

    // Tangent against finite differences.
    const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
    check(prefix + "tangent, general F_old and Delta F: relative error",
          tangent_error(model, F, general_delta_F<dim>()),
          1e-6);
    check(prefix + "tangent, F_old = Delta F = I (b = I): relative error",
          tangent_error(model, I, I),
          1e-6);
    check(prefix + "tangent, rotations F_old, Delta F (b = I + round-off): "
                   "relative error",
          tangent_error(model, rotation<dim>(0.3), rotation<dim>(-1.2, 2.)),
          1e-6);
    check(prefix + "tangent, b with a repeated eigenvalue: relative error",
          tangent_error(model,
                        rotation<dim>(0.3) * (dim == 2 ?
                                                diagonal<dim>(1.1, 1.1, 1.) :
                                                diagonal<dim>(1.2, 0.9, 0.9)),
                        rotation<dim>(-1.2, 2.)),
          1e-6);
    for (const double gap : {1e-7, 1e-9})
      {
        std::ostringstream what;
        what << prefix << "tangent, eigenvalues of b apart by " << gap
             << " (relative): relative error";
        const double   a    = dim == 2 ? 1.1 : 0.9;
        Tensor<2, dim> U    = diagonal<dim>(1.2, 0.9, 0.9);
        U[dim - 2][dim - 2] = a;
        U[dim - 1][dim - 1] = a * std::sqrt(1. + gap);
        check(what.str(),
              tangent_error(model,
                            rotation<dim>(0.3) * U,
                            rotation<dim>(-1.2, 2.)),
              1e-6);
      }

    // Continuity across coincident eigenvalues: the tangents at eigenvalue
    // gaps 1e-10 and 0 differ by O(1e-10) (a naive divided difference
    // (ln a - ln b)/(a - b) would be off by O(1e-6)).
    {
      const Tensor<2, dim> U0 = diagonal<dim>(1.2, 0.9, 0.9);
      Tensor<2, dim>       U1 = U0;
      U1[dim - 1][dim - 1] *= std::sqrt(1. + 1e-10);
      const Tensor<2, dim>              R  = rotation<dim>(0.3);
      const Tensor<2, dim>              dF = rotation<dim>(-1.2, 2.);
      const FiniteStrainKinematics<dim> k0{R * U0, dF, dF * R * U0},
        k1{R * U1, dF, dF * R * U1};
      const Tensor<4, dim> c0 = model.kirchhoff_tangent(point_state<dim>(), k0);
      check(prefix + "tangent at eigenvalue gaps 1e-10 and 0: "
                     "relative difference",
            (model.kirchhoff_tangent(point_state<dim>(), k1) - c0).norm() /
              c0.norm(),
            1e-8);
    }

    // Small-strain limit.
    {
      const double                  eps = 1e-7;
      const Tensor<2, dim>          G   = matrix<dim>(B_rows) - I;
      const SymmetricTensor<2, dim> lin = hooke(symmetrize(G));
      const SymmetricTensor<2, dim> t   = kirchhoff(model, I + eps * G) / eps;
      check(prefix + "small-strain limit, F = I + 1e-7 G: "
                     "|tau / 1e-7 - C : sym G| / |C : sym G|",
            (t - lin).norm() / lin.norm(),
            1e-5);
    }

    // The small-strain interface.
    {
      PointState<dim> old = point_state<dim>();
      old.stress          = 1e-3 * E * symmetrize(matrix<dim>(A_rows));
      const SymmetricTensor<2, dim> d_eps =
        2e-3 * symmetrize(matrix<dim>(B_rows));
      SymmetricTensor<2, dim> sigma;
      model.update_stress(old, d_eps, sigma, ArrayView<double>());
      const SymmetricTensor<2, dim> expected = old.stress + hooke(d_eps);
      check(prefix + "small strain: |sigma - (sigma_old + C : d eps)| / "
                     "|sigma|",
            (sigma - expected).norm() / expected.norm(),
            1e-12);
      const SymmetricTensor<4, dim> C =
        lambda * outer_product(unit_symmetric_tensor<dim>(),
                               unit_symmetric_tensor<dim>()) +
        2. * mu * identity_tensor<dim>();
      check(prefix + "small strain: |tangent() - C| / |C|",
            (model.tangent(old) - C).norm() / C.norm(),
            1e-12);
    }
  }

  /// The tensor logarithm and its derivative.
  template <int dim>
  void
  check_tensor_functions()
  {
    const std::string       prefix = "  " + std::to_string(dim) + "D: ";
    const Tensor<2, dim>    R      = rotation<dim>(0.8);
    const double            lam[3] = {2.5, 0.4, 1.3};
    SymmetricTensor<2, dim> b, log_b;
    for (unsigned int a = 0; a < dim; ++a)
      {
        const Tensor<1, dim> q = R[a];
        b += lam[a] * symmetrize(outer_product(q, q));
        log_b += std::log(lam[a]) * symmetrize(outer_product(q, q));
      }
    check("" + prefix + "|ln b - sum ln(lambda_a) q_a (x) q_a|",
          (TensorFunctions::log(b) - log_b).norm(),
          1e-14);

    const SymmetricTensor<2, dim> db = symmetrize(matrix<dim>(A_rows));
    const double                  h  = 1e-5;
    const SymmetricTensor<2, dim> fd =
      (TensorFunctions::log(SymmetricTensor<2, dim>(b + h * db)) -
       TensorFunctions::log(SymmetricTensor<2, dim>(b - h * db))) /
      (2. * h);
    const SymmetricTensor<2, dim> d =
      TensorFunctions::log_directional_derivative(b, db);
    check(prefix + "d ln b [db] against central differences, relative",
          (d - fd).norm() / fd.norm(),
          1e-8);
    check(prefix + "|L : db - d ln b [db]| / |d ln b [db]|",
          (TensorFunctions::log_derivative(b) * db - d).norm() / d.norm(),
          1e-14);
  }
} // namespace

int
main()
{
  initlog();

  deallog << "Tensor logarithm" << std::endl;
  {
    // (ln x - ln y)/(x - y) with y = x (1 + delta) equals
    // log1p(delta) / (x delta), for nearly equal and distant x, y.
    double error = 0.;
    for (const double x : {0.3, 1., 4.})
      for (const double delta : {1e-14, 1e-11, 1e-9, 1e-7, 1e-4, 0.3, 3.})
        {
          const double y      = x * (1. + delta);
          const double d      = (y - x) / x; // delta as represented
          const double exact  = std::log1p(d) / (x * d);
          const double result = TensorFunctions::log_divided_difference(x, y);
          error = std::max(error, std::abs(result - exact) / exact);
          error =
            std::max(error,
                     std::abs(TensorFunctions::log_divided_difference(y, x) -
                              exact) /
                       exact);
        }
    check("  (ln x - ln y)/(x - y), y/x - 1 = 1e-14 ... 3: relative error",
          error,
          1e-14);
    check("  (ln x - ln x)/(x - x) := 1/x",
          TensorFunctions::log_divided_difference(0.8, 0.8) - 1. / 0.8,
          0.);
  }
  check_tensor_functions<2>();
  check_tensor_functions<3>();

  deallog << "Models" << std::endl;
  check_model<2>(Hencky<2>(E, nu), true);
  check_model<3>(Hencky<3>(E, nu), true);
  check_model<2>(NeoHookean<2>(E, nu), false);
  check_model<3>(NeoHookean<3>(E, nu), false);

  deallog << "Inverted deformation (det F < 0)" << std::endl;
  {
    const Tensor<2, 3> F = diagonal<3>(-1., 1., 1.);
    check_that("  hencky and neo-Hookean: tau is not finite",
               !std::isfinite(kirchhoff(Hencky<3>(E, nu), F).norm()) &&
                 !std::isfinite(kirchhoff(NeoHookean<3>(E, nu), F).norm()));
  }

  deallog << "Registry" << std::endl;
  for (const std::string name : {"hencky", "neo-Hookean"})
    {
      ParameterHandler prm;
      ConstitutiveModelFactory<3>::declare_parameters(prm);
      prm.enter_subsection("Material");
      prm.set("Model", name);
      prm.enter_subsection(name);
      prm.set("Young's modulus", "2e6");
      prm.set("Poisson's ratio", "0.25");
      prm.leave_subsection();
      prm.leave_subsection();
      const auto model = ConstitutiveModelFactory<3>::create(prm);
      check_that("  <" + name + ">: created, name() and finite strain",
                 model->name() == name && model->supports_finite_strain());
      // tau_yy = lambda ln s for both models under uniaxial stretch.
      const double l = 2e6 * 0.25 / (1.25 * 0.5), s = 1.4;
      check("  <" + name +
              ">: E = 2e6, nu = 0.25 from the parameters: "
              "|tau_yy - lambda ln s| / E",
            (kirchhoff(*model, diagonal<3>(s, 1., 1.))[1][1] -
             l * std::log(s)) /
              2e6,
            1e-12);
    }

  deallog << "Small-strain only models" << std::endl;
  {
    const LinearElastic<2> elastic(E, nu);
    bool                   thrown = false;
    try
      {
        SymmetricTensor<2, 2> tau;
        elastic.update_kirchhoff_stress(point_state<2>(),
                                        {unit_symmetric_tensor<2>(),
                                         unit_symmetric_tensor<2>(),
                                         unit_symmetric_tensor<2>()},
                                        tau,
                                        ArrayView<double>());
      }
    catch (const std::exception &e)
      {
        thrown =
          std::string(e.what()).find("small-strain only") != std::string::npos;
      }
    check_that("  linear elastic: update_kirchhoff_stress throws "
               "\"small-strain only\"",
               thrown && !elastic.supports_finite_strain());
  }

  // The models' eigen decompositions (Hencky's logarithm, the principal
  // stresses of Mohr-Coulomb): a tensor that is not finite, as a line
  // search's trial far from the solution can give, has NaN eigenvalues,
  // so that the residual is not finite and the step is cut back; the QL
  // method threw there and stopped the run (the Mohr-Coulomb footing at
  // a/h = 16 with the preconditioner updated in every Newton iteration).
  deallog << "Eigen decomposition" << std::endl;
  {
    SymmetricTensor<2, 3> a;
    a[0][0]          = 3.;
    a[1][1]          = -1.;
    a[2][2]          = 2.;
    a[0][1]          = 0.5;
    a[1][2]          = -0.25;
    const auto eigen = TensorFunctions::eigen_decomposition(a);
    const auto exact = eigenvalues(a);
    double     error = 0.;
    for (unsigned int k = 0; k < 3; ++k)
      error = std::max(error, std::abs(eigen[k].first - exact[k]));
    check("  a finite tensor: |lambda - eigenvalues()|", error, 1e-13);
    a[1][2]          = std::numeric_limits<double>::quiet_NaN();
    bool nan_values  = true;
    bool thrown_here = false;
    try
      {
        for (const auto &pair : TensorFunctions::eigen_decomposition(a))
          nan_values = nan_values && std::isnan(pair.first);
      }
    catch (const std::exception &)
      {
        thrown_here = true;
      }
    check_that("  a tensor with a NaN entry: NaN eigenvalues, no exception",
               nan_values && !thrown_here);
  }
}
