// Consistent tangents of the elastoplastic models VonMises and
// DruckerPrager against central finite differences of their stress
// updates, in 2D (plane strain) and 3D, with hardening and perfectly
// plastic, at elastic and plastic trial states (Drucker-Prager: smooth cone
// and apex):
//
// - small strain: consistent_tangent(old, d eps) against
//   (sigma(d eps + h A) - sigma(d eps - h A)) / 2h over a basis of
//   symmetric directions A, h = 1e-6 eps_y;
// - finite strain: kirchhoff_tangent(old, kinematics) against central
//   differences of tau under Delta F -> Delta F + h E_kl Delta F (i.e.
//   d l = h E_kl), h = 1e-7, at a plastic committed state with a large
//   deformation behind it;
// - tangent() of a point that yielded in its last step is the continuum
//   tangent: it equals the consistent tangent of a vanishing further plastic
//   increment (to O(increment)); of a virgin point it is the elastic D.
//
// The relative Frobenius error |C - C_fd| / |C| is checked against 1e-6 (it
// is typically 1e-9 ... 1e-11).
#include "tests.h"

#include <cstdlib>
#include <deal.II/physics/transformations.h>
#include <iostream>
#include <memory>
#include <qsmpm/materials/drucker_prager.h>
#include <qsmpm/materials/von_mises.h>
#include <vector>

using namespace qsmpm;

namespace
{
  /// With QSMPM_VERBOSE set, measured errors go to stdout (not to the
  /// compared output).
  void
  report(const std::string &what, const double value)
  {
    if (std::getenv("QSMPM_VERBOSE") != nullptr)
      std::cout << what << ": " << value << std::endl;
  }

  void
  check_v(const std::string &what, const double value, const double tolerance)
  {
    report(what, value);
    check(what, value, tolerance);
  }

  const double E = 1e6, nu = 0.3, sigma_y0 = 1e3, c0 = 1e3;
  const double eps_y = sigma_y0 / E;

  template <int dim>
  PointState<dim>
  point(const std::vector<double> &state)
  {
    return {SymmetricTensor<2, dim>(),
            SymmetricTensor<2, dim>(),
            ArrayView<const double>(state.data(), state.size()),
            1.};
  }

  template <int dim>
  SymmetricTensor<2, dim>
  sym(const double (&m)[3][3])
  {
    SymmetricTensor<2, dim> t;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        t[i][j] = m[i][j];
    return t;
  }

  template <int dim>
  Tensor<2, dim>
  identity_plus(const double scale, const double (&m)[3][3])
  {
    Tensor<2, dim> t = unit_symmetric_tensor<dim>();
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        t[i][j] += scale * m[i][j];
    return t;
  }

  template <int dim>
  Tensor<2, dim>
  rotation(const double angle)
  {
    if constexpr (dim == 2)
      return Physics::Transformations::Rotations::rotation_matrix_2d(angle);
    else
      {
        Point<3> axis(0.3, -0.5, 0.8);
        axis /= axis.norm();
        return Physics::Transformations::Rotations::rotation_matrix_3d(axis,
                                                                       angle);
      }
  }

  const double A_rows[3][3] = {{0.8, 0.5, -0.2},
                               {0.5, -0.6, 0.3},
                               {-0.2, 0.3, 0.4}};
  const double B_rows[3][3] = {{-0.3, 0.9, 0.4},
                               {0.9, 0.5, -0.7},
                               {0.4, -0.7, 0.2}};
  const double C_rows[3][3] = {{0.1, 0.6, -0.3},
                               {-0.4, -0.2, 0.5},
                               {0.2, 0.1, 0.3}};

  /// The committed state after one small-strain step d from zero.
  template <int dim>
  std::vector<double>
  state_after(const IsotropicPlasticity<dim> &model,
              const SymmetricTensor<2, dim>  &d)
  {
    std::vector<double>     zero(8, 0.), s(8);
    SymmetricTensor<2, dim> sigma;
    model.update_stress(point<dim>(zero), d, sigma, make_array_view(s));
    return s;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  stress(const IsotropicPlasticity<dim> &model,
         const std::vector<double>      &old,
         const SymmetricTensor<2, dim>  &d,
         std::vector<double>            &s)
  {
    s.resize(8);
    SymmetricTensor<2, dim> sigma;
    model.update_stress(point<dim>(old), d, sigma, make_array_view(s));
    return sigma;
  }

  /// Which branch the trial state takes: elastic, plastic, apex.
  template <int dim>
  std::string
  branch(const IsotropicPlasticity<dim> &model,
         const std::vector<double>      &old,
         const SymmetricTensor<2, dim>  &d)
  {
    std::vector<double> s;
    stress(model, old, d, s);
    const ArrayView<const double> v(s.data(), s.size());
    if (IsotropicPlasticity<dim>::plastic_increment(v) == 0.)
      return "elastic";
    const SymmetricTensor<2, 3> sigma = model.stress_3d(v);
    if (deviator(sigma).norm() <= 1e-12 * std::abs(trace(sigma)))
      return "apex";
    return "plastic";
  }

  template <int dim>
  double
  small_strain_error(const IsotropicPlasticity<dim> &model,
                     const std::vector<double>      &old,
                     const SymmetricTensor<2, dim>  &d)
  {
    const SymmetricTensor<4, dim> C =
      model.consistent_tangent(point<dim>(old), d);
    const double        h      = 1e-6 * eps_y;
    double              error2 = 0., norm2 = 0.;
    std::vector<double> s;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int l = k; l < dim; ++l)
        {
          SymmetricTensor<2, dim> A;
          A[k][l] = 1.; // both kl and lk
          const SymmetricTensor<2, dim> fd =
            (stress(model, old, SymmetricTensor<2, dim>(d + h * A), s) -
             stress(model, old, SymmetricTensor<2, dim>(d - h * A), s)) /
            (2. * h);
          const SymmetricTensor<2, dim> exact = C * A;
          error2 += std::pow((fd - exact).norm(), 2);
          norm2 += std::pow(exact.norm(), 2);
        }
    // The apex tangent of perfect plasticity vanishes: then relative to D.
    const double scale =
      norm2 > 0. ?
        std::sqrt(norm2) :
        IsotropicPlasticity<dim>::extract(model.elastic_stiffness()).norm();
    return std::sqrt(error2) / scale;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  kirchhoff(const IsotropicPlasticity<dim> &model,
            const std::vector<double>      &old,
            const Tensor<2, dim>           &F_old,
            const Tensor<2, dim>           &dF,
            std::vector<double>            &s)
  {
    s.resize(8);
    SymmetricTensor<2, dim> tau;
    model.update_kirchhoff_stress(point<dim>(old),
                                  {F_old, dF, Tensor<2, dim>(dF * F_old)},
                                  tau,
                                  make_array_view(s));
    return tau;
  }

  template <int dim>
  double
  finite_strain_error(const IsotropicPlasticity<dim> &model,
                      const std::vector<double>      &old,
                      const Tensor<2, dim>           &F_old,
                      const Tensor<2, dim>           &dF)
  {
    const Tensor<4, dim> c =
      model.kirchhoff_tangent(point<dim>(old),
                              {F_old, dF, Tensor<2, dim>(dF * F_old)});
    const double        h      = 1e-7;
    double              error2 = 0.;
    std::vector<double> s;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int l = 0; l < dim; ++l)
        {
          Tensor<2, dim> E_kl;
          E_kl[k][l] = 1.;
          const SymmetricTensor<2, dim> fd =
            (kirchhoff(
               model, old, F_old, Tensor<2, dim>(dF + h * E_kl * dF), s) -
             kirchhoff(
               model, old, F_old, Tensor<2, dim>(dF - h * E_kl * dF), s)) /
            (2. * h);
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              error2 += std::pow(fd[i][j] - c[i][j][k][l], 2);
        }
    return std::sqrt(error2) / c.norm();
  }

  /// The branch of a finite-strain trial state.
  template <int dim>
  std::string
  finite_branch(const IsotropicPlasticity<dim> &model,
                const std::vector<double>      &old,
                const Tensor<2, dim>           &F_old,
                const Tensor<2, dim>           &dF)
  {
    std::vector<double> s;
    kirchhoff(model, old, F_old, dF, s);
    const ArrayView<const double> v(s.data(), s.size());
    if (IsotropicPlasticity<dim>::plastic_increment(v) == 0.)
      return "elastic";
    const SymmetricTensor<2, 3> sigma = model.stress_3d(v);
    if (deviator(sigma).norm() <= 1e-12 * std::abs(trace(sigma)))
      return "apex";
    return "plastic";
  }

  template <int dim>
  void
  check_small_strain(const std::string              &name,
                     const IsotropicPlasticity<dim> &model,
                     const SymmetricTensor<2, dim>  &first,
                     const SymmetricTensor<2, dim>  &plastic,
                     const SymmetricTensor<2, dim>  &elastic,
                     const std::string              &plastic_branch)
  {
    const std::string prefix =
      "  " + std::to_string(dim) + "D " + name + ", small strain, ";
    const std::vector<double> old = state_after(model, first);
    check_that(prefix + "committed state: yielded",
               IsotropicPlasticity<dim>::plastic_increment(
                 ArrayView<const double>(old.data(), old.size())) > 0.);
    for (const auto &[what, d, expected] :
         {std::make_tuple("virgin point", first, plastic_branch),
          std::make_tuple("plastic trial", plastic, plastic_branch),
          std::make_tuple("elastic trial (unloading)",
                          elastic,
                          std::string("elastic"))})
      {
        const std::vector<double> from = std::string(what) == "virgin point" ?
                                           std::vector<double>(8, 0.) :
                                           old;
        check_that(prefix + what + ": branch " + expected,
                   branch(model, from, d) == expected);
        check_v(prefix + what + ": |C - C_fd| / |C|",
                small_strain_error(model, from, d),
                1e-6);
      }
    // The continuum tangent of the yielded point = the consistent tangent
    // of a vanishing further plastic increment.
    const SymmetricTensor<2, dim> tiny = 1e-7 * first;
    if (plastic_branch == "plastic")
      {
        check_that(prefix + "a further 1e-7 of the first increment: plastic",
                   branch(model, old, tiny) == "plastic");
        const ArrayView<const double> view(old.data(), old.size());
        const SymmetricTensor<4, dim> C0 = IsotropicPlasticity<dim>::extract(
          model.continuum_tangent(
            model.stress_3d(view),
            IsotropicPlasticity<dim>::equivalent_plastic_strain(view)));
        check_v(prefix + "continuum tangent of the yielded point vs consistent "
                         "tangent of a 1e-7 further increment: relative",
                (C0 - model.consistent_tangent(point<dim>(old), tiny)).norm() /
                  C0.norm(),
                1e-5);
        check_at_least(prefix + "(the test is not trivial) |continuum - D| "
                                "/ |D|",
                       (C0 - IsotropicPlasticity<dim>::extract(
                               model.elastic_stiffness()))
                           .norm() /
                         model.elastic_stiffness().norm(),
                       1e-2);
        check_v(prefix + "consistent_tangent() at a zero increment = "
                         "tangent() = D (the preconditioner's)",
                (model.consistent_tangent(point<dim>(old),
                                          SymmetricTensor<2, dim>()) -
                 IsotropicPlasticity<dim>::extract(model.elastic_stiffness()))
                    .norm(),
                0.);
      }
    const std::vector<double> virgin(8, 0.);
    check_v(prefix + "tangent() of a virgin point = D",
            (model.tangent(point<dim>(virgin)) -
             IsotropicPlasticity<dim>::extract(model.elastic_stiffness()))
              .norm(),
            0.);
  }

  template <int dim>
  void
  check_finite_strain(const std::string              &name,
                      const IsotropicPlasticity<dim> &model,
                      const double                    pre_scale,
                      const double                    scale,
                      const std::string              &plastic_branch)
  {
    const std::string prefix =
      "  " + std::to_string(dim) + "D " + name + ", finite strain, ";
    // A large deformation behind the committed state.
    const Tensor<2, dim> F_old =
      rotation<dim>(0.4) * identity_plus<dim>(pre_scale, A_rows);
    std::vector<double> old(8, 0.), s;
    kirchhoff(
      model, old, Tensor<2, dim>(unit_symmetric_tensor<dim>()), F_old, s);
    old = s;
    check_that(prefix + "committed state: yielded",
               IsotropicPlasticity<dim>::plastic_increment(
                 ArrayView<const double>(old.data(), old.size())) > 0.);

    const Tensor<2, dim> plastic =
      rotation<dim>(-0.3) * identity_plus<dim>(scale, C_rows);
    check_that(prefix + "plastic trial: branch " + plastic_branch,
               finite_branch(model, old, F_old, plastic) == plastic_branch);
    check_v(prefix + "plastic trial: |c - c_fd| / |c|",
            finite_strain_error(model, old, F_old, plastic),
            1e-6);

    // Elastic: a rotation with a little unloading of the last deformation.
    const Tensor<2, dim> unload = invert(identity_plus<dim>(pre_scale, A_rows));
    const Tensor<2, dim> elastic =
      rotation<dim>(0.7) *
      Tensor<2, dim>(unit_symmetric_tensor<dim>() +
                     1e-4 * (unload - unit_symmetric_tensor<dim>()) /
                       pre_scale);
    check_that(prefix + "elastic trial (rotation, unloading): branch elastic",
               finite_branch(model, old, F_old, elastic) == "elastic");
    check_v(prefix + "elastic trial: |c - c_fd| / |c|",
            finite_strain_error(model, old, F_old, elastic),
            1e-6);

    // Virgin point, elastic Hencky-like response at a large rotation.
    const std::vector<double> virgin(8, 0.);
    const Tensor<2, dim>      small =
      rotation<dim>(1.1) * identity_plus<dim>(0.2 * eps_y, B_rows);
    check_that(prefix + "virgin point, rotation and small strain: elastic",
               finite_branch(model,
                             virgin,
                             Tensor<2, dim>(unit_symmetric_tensor<dim>()),
                             small) == "elastic");
    check_v(prefix + "virgin point, rotation and small strain: |c - c_fd| / "
                     "|c|",
            finite_strain_error(model,
                                virgin,
                                Tensor<2, dim>(unit_symmetric_tensor<dim>()),
                                small),
            1e-6);

    // At Delta F = I the tangent uses the continuum tangent of the yielded
    // point: compare with the consistent tangent at Delta F = I + 1e-9 G in
    // the loading direction.
    if (plastic_branch == "plastic")
      {
        const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
        const Tensor<4, dim> c0 =
          model.kirchhoff_tangent(point<dim>(old), {F_old, I, F_old});
        const Tensor<2, dim> tiny =
          I + 1e-9 / pre_scale * (identity_plus<dim>(pre_scale, A_rows) - I);
        check_that(prefix + "Delta F = I + 1e-9 (loading direction): "
                            "plastic",
                   finite_branch(model, old, F_old, tiny) == "plastic");
        const Tensor<4, dim> c1 =
          model.kirchhoff_tangent(point<dim>(old),
                                  {F_old, tiny, Tensor<2, dim>(tiny * F_old)});
        // At Delta F = I the tangent is the preconditioner's (elastic);
        // the consistent one at Delta F = I + 1e-9 G is elastoplastic.
        check_at_least(prefix + "consistent tangent at Delta F = I + 1e-9 G "
                                "differs from the one at Delta F = I",
                       (c0 - c1).norm() / c0.norm(),
                       1e-2);
      }
  }
} // namespace

int
main()
{
  initlog();

  using DP2                      = DruckerPrager<2>;
  using DP3                      = DruckerPrager<3>;
  const SymmetricTensor<2, 2> A2 = sym<2>(A_rows), B2 = sym<2>(B_rows);
  const SymmetricTensor<2, 3> A3 = sym<3>(A_rows), B3 = sym<3>(B_rows);
  const SymmetricTensor<2, 2> I2 = unit_symmetric_tensor<2>();
  const SymmetricTensor<2, 3> I3 = unit_symmetric_tensor<3>();

  deallog << "von Mises" << std::endl;
  for (const double H : {0., 5e4})
    {
      const std::string name = "von Mises H = " + format(H);
      check_small_strain<2>(name,
                            VonMises<2>(E, nu, sigma_y0, H),
                            3. * eps_y * A2,
                            2. * eps_y * B2,
                            -0.3 * eps_y * A2,
                            "plastic");
      check_small_strain<3>(name,
                            VonMises<3>(E, nu, sigma_y0, H),
                            3. * eps_y * A3,
                            2. * eps_y * B3,
                            -0.3 * eps_y * A3,
                            "plastic");
      check_finite_strain<2>(
        name, VonMises<2>(E, nu, sigma_y0, H), 0.3, 0.05, "plastic");
      check_finite_strain<3>(
        name, VonMises<3>(E, nu, sigma_y0, H), 0.3, 0.05, "plastic");
    }

  deallog << "Drucker-Prager, smooth cone" << std::endl;
  // Shear with compression: smooth cone; psi < phi (non-associative).
  for (const double H : {0., 5e4})
    {
      const std::string name =
        "Drucker-Prager phi = 30, psi = 10, H = " + format(H);
      check_small_strain<2>(
        name,
        DP2(E, nu, c0, 30., 10., H, DP2::Matching::outer_cone),
        3. * eps_y * (A2 - 0.3 * I2),
        2. * eps_y * (B2 - 0.3 * I2),
        -0.3 * eps_y * (A2 - 0.3 * I2),
        "plastic");
      check_small_strain<3>(
        name,
        DP3(E, nu, c0, 30., 10., H, DP3::Matching::outer_cone),
        3. * eps_y * (A3 - 0.3 * I3),
        2. * eps_y * (B3 - 0.3 * I3),
        -0.3 * eps_y * (A3 - 0.3 * I3),
        "plastic");
      check_finite_strain<2>(
        name,
        DP2(E, nu, c0, 30., 10., H, DP2::Matching::plane_strain),
        0.3,
        0.05,
        "plastic");
      check_finite_strain<3>(
        name,
        DP3(E, nu, c0, 30., 10., H, DP3::Matching::inner_cone),
        0.3,
        0.05,
        "plastic");
    }

  deallog << "Drucker-Prager, apex" << std::endl;
  // Hydrostatic tension beyond the apex with a little shear.
  for (const double H : {0., 5e4})
    for (const double psi : {0., 20.})
      {
        const std::string name =
          "Drucker-Prager apex, psi = " + format(psi) + ", H = " + format(H);
        check_small_strain<2>(
          name,
          DP2(E, nu, c0, 30., psi, H, DP2::Matching::plane_strain),
          5. * eps_y * I2 + 0.1 * eps_y * A2,
          4. * eps_y * I2 + 0.1 * eps_y * B2,
          -2. * eps_y * I2,
          "apex");
        check_small_strain<3>(
          name,
          DP3(E, nu, c0, 30., psi, H, DP3::Matching::plane_strain),
          5. * eps_y * I3 + 0.1 * eps_y * A3,
          4. * eps_y * I3 + 0.1 * eps_y * B3,
          -2. * eps_y * I3,
          "apex");
      }
}
