// The Modified Cam Clay model (ModifiedCamClay, issue 31): single-point
// paths against the closed forms of critical-state soil mechanics (Wood,
// Soil Behaviour and Critical State Soil Mechanics, CUP 1990, ch. 6-7;
// soil signs: p, v > 0 in compression). Parameters: G = 3000, kappa = 0.01,
// lambda = 0.05, M = 1.2, p0 = 100 (kPa), so that p_c = p_c0 exp(alpha /
// (lambda - kappa)) and p = p0 exp(v_e / kappa).
//
// The closed forms, with theta = lambda - kappa:
// 1. Isotropic compression on the normal consolidation line (p_c0 = p0):
//    v = lambda ln(p / p0), at small strain (v = -tr eps) and at finite
//    strain (v = -ln J, the Kirchhoff pressure); unloading on the swelling
//    line, v - v_max = kappa ln(p / p_max).
// 2. Undrained triaxial compression (v = 0), p_c0 / p0 = 1, 1.5 (wet side)
//    and 4 (dry side: the pressure rises and the strength softens to the
//    critical state):
//    elastic at p = p0 until q = M p0 sqrt(p_c0 / p0 - 1), then on the
//    surface with kappa ln(p / p0) + theta ln(p_c / p_c0) = 0, i.e.
//      q(p) = M p sqrt(p_c(p) / p - 1),  p_c(p) = p_c0 (p0 / p)^(kappa/theta).
// 3. Drained triaxial compression (the lateral stress held at -p0 by
//    solving for the lateral strain with the consistent tangent), p_c0 =
//    p0: q = 3 (p - p0) and on the surface
//      v(p) = kappa ln(p / p0) + theta ln(p_c / p_c0),
//      p_c = p + q^2 / (M^2 p).
//    For 2 and 3 the shear strain eps_s = 2/3 |eps_a - eps_r| against
//      eps_s(p) = q / (3 G) + int 2 eta / (M^2 - eta^2) d alpha,
//    eta = q / p, d alpha the plastic compaction (undrained: -kappa dp / p;
//    drained: theta d ln p_c), by composite 5-point Gauss quadrature (2000
//    panels, to round-off): this is the one path-dependent quantity, so the
//    backward-Euler error shows in it, with order 1 in the step.
// 4. The algorithmic tangent against central differences of the return
//    (3D return map, the 2D plane-strain consistent_tangent(), and the
//    finite-strain kirchhoff_tangent()).
// 5. Bad parameters: one message each, naming the entry; the model made by
//    name from a parameter file.
// 7. `Overconsolidation ratio`: the yield surface through the initial
//    stress, scaled by OCR. Normally consolidated at p_i != p0, isotropic
//    compression follows the normal consolidation line through p_i,
//    v = lambda ln(p / p_i), from the first step; p_c of a K0 start is
//    OCR (p + q^2 / (M^2 p)) (all to 1e-10 or 1e-12, functions of the
//    state as above).
//
// Tolerances: the volumetric relations and p_c are functions of the state,
// exact for any step size, so only the return's Newton tolerance (1e-14 of
// the scaled residual) and round-off remain: 1e-10 is far above them and
// far below what a wrong hardening law or elastic law gives (O(1)). The
// tangents: a central difference with a relative step 1e-6 is accurate to
// about 1e-8; 1e-6 is checked. The shear strain: the order between 0.9 and
// 1.1, the error at 2000 steps below 3e-3 (measured 6e-4 to 1.7e-3), and
// Richardson's extrapolation from 1000 and 2000 steps within 3e-5
// (measured 1e-6 to 9e-6): far below the O(1) of a wrong G or flow rule.
#include "cam_clay_closed_forms.h"
#include "plasticity_point.h"
#include "tests.h"

#include <deal.II/base/parameter_handler.h>
#include <qsmpm/materials/constitutive_model.h>
#include <qsmpm/materials/modified_cam_clay.h>

using namespace qsmpm;

namespace
{
  const double G = 3000., kappa = 0.01, lambda_ = 0.05, M = 1.2, p0 = 100.;

  template <int dim = 3>
  typename ModifiedCamClay<dim>::Parameters
  parameters(const double pc0)
  {
    typename ModifiedCamClay<dim>::Parameters p;
    p.shear_modulus             = G;
    p.swelling_index            = kappa;
    p.compression_index         = lambda_;
    p.critical_state_slope      = M;
    p.initial_pressure          = p0;
    p.preconsolidation_pressure = pc0;
    return p;
  }

  double
  pressure(const SymmetricTensor<2, 3> &s)
  {
    return -trace(s) / 3.;
  }

  double
  deviatoric_stress(const SymmetricTensor<2, 3> &s)
  {
    return std::sqrt(1.5) * deviator(s).norm();
  }

  CamClayTriaxial
  soil(const double pc0)
  {
    return {G, kappa, lambda_, M, p0, pc0};
  }

  /// Undrained path in n steps to the shear strain eps_s; returns the
  /// relative error of eps_s against the closed form at the final p, and
  /// the largest error of the stress path q(p).
  std::pair<double, double>
  undrained(const double pc0, const unsigned int n, const double eps_s)
  {
    const ModifiedCamClay<3> model(parameters(pc0));
    PointHistory             point;
    // eps = eps_a diag(1, -1/2, -1/2): eps_s = 2/3 |eps_a - eps_r| = |eps_a|.
    const double               d          = -eps_s / n;
    double                     path_error = 0., elastic_error = 0.;
    const double               q_yield = M * p0 * std::sqrt(pc0 / p0 - 1.);
    ModifiedCamClay<3>::Return r;
    for (unsigned int i = 1; i <= n; ++i)
      {
        r              = step(model, point, diagonal(-0.5 * d, -0.5 * d, d));
        const double p = pressure(r.stress), q = deviatoric_stress(r.stress);
        if (r.increment == 0.)
          elastic_error =
            std::max(elastic_error,
                     std::abs(p - p0) / p0 +
                       std::abs(q - 3. * G * i * std::abs(d)) / q_yield);
        else
          path_error =
            std::max(path_error, std::abs(q - soil(pc0).undrained_q(p)) / p0);
      }
    path_error     = std::max(path_error, elastic_error);
    const double p = pressure(r.stress);
    return {(eps_s - soil(pc0).undrained_shear_strain(p)) / eps_s, path_error};
  }

  struct DrainedResult
  {
    double shear_error, path_error, volume_error, lateral_error, eta;
  };

  /// Drained path (p_c0 = p0) in n steps of the axial strain to eps_a.
  DrainedResult
  drained(const unsigned int n, const double eps_a)
  {
    const ModifiedCamClay<3>   model(parameters(p0));
    PointHistory               point;
    const double               d       = eps_a / n;
    double                     lateral = 0.;
    DrainedResult              result{0., 0., 0., 0., 0.};
    ModifiedCamClay<3>::Return r;
    for (unsigned int i = 1; i <= n; ++i)
      {
        // The lateral strain increment (x and y alike) by Newton's method
        // on the lateral stress, with the consistent tangent.
        double d_lat = 0.;
        for (unsigned int it = 0; it < 50; ++it)
          {
            r = step(model, point, diagonal(d_lat, d_lat, d), false);
            const double residual = r.stress[0][0] + p0;
            if (std::abs(residual) < 1e-13 * p0)
              break;
            d_lat -= residual / (r.tangent[0][0][0][0] + r.tangent[0][0][1][1]);
          }
        r = step(model, point, diagonal(d_lat, d_lat, d));
        lateral += d_lat;
        result.lateral_error =
          std::max(result.lateral_error, std::abs(r.stress[0][0] + p0) / p0);
        const double p = pressure(r.stress), q = deviatoric_stress(r.stress);
        const double pc = soil(p0).drained_pc(p);
        const double v  = -(i * d + 2. * lateral);
        result.path_error =
          std::max(result.path_error, std::abs(q - 3. * (p - p0)) / p0);
        result.volume_error =
          std::max(result.volume_error,
                   std::abs(v - soil(p0).drained_volumetric_strain(p)) /
                     lambda_);
        // The model's own p_c against the one of the closed form.
        result.path_error =
          std::max(result.path_error,
                   std::abs(model.preconsolidation_pressure(point.alpha) - pc) /
                     p0);
        result.eta = q / p;
      }
    const double eps_s = 2. / 3. * std::abs(eps_a - lateral);
    result.shear_error =
      (eps_s - soil(p0).drained_shear_strain(pressure(r.stress))) / eps_s;
    return result;
  }

  /// The largest entry of a - b over the largest of b.
  template <typename T>
  double
  relative_difference(const T &a, const T &b)
  {
    return (a - b).norm() / b.norm();
  }
} // namespace



int
main()
{
  initlog();

  deallog << "1. Isotropic compression: the normal consolidation line"
          << std::endl;
  {
    const ModifiedCamClay<3> model(parameters(p0));
    PointHistory             point;
    double                   error = 0.;
    for (unsigned int i = 1; i <= 100; ++i)
      {
        const auto   r = step(model, point, -1e-3 * unit_symmetric_tensor<3>());
        const double v = 3e-3 * i;
        error =
          std::max(error,
                   std::abs(pressure(r.stress) - p0 * std::exp(v / lambda_)) /
                     (p0 * std::exp(v / lambda_)));
      }
    check("  small strain: |p - p0 exp(v / lambda)| / p", error, 1e-10);
    const double p_max = p0 * std::exp(0.3 / lambda_);
    error              = 0.;
    bool elastic       = true;
    for (unsigned int i = 1; i <= 20; ++i)
      {
        const auto r = step(model, point, 1e-3 * unit_symmetric_tensor<3>());
        elastic      = elastic && r.increment == 0.;
        const double p_exact = p_max * std::exp(-3e-3 * i / kappa);
        error =
          std::max(error, std::abs(pressure(r.stress) - p_exact) / p_exact);
      }
    check_that("  unloading is elastic", elastic);
    check("  unloading: |p - p_max exp((v - v_max) / kappa)| / p",
          error,
          1e-10);

    // Finite strain: F = J^(1/3) I in 30 steps to J = 0.7; v = -ln J.
    const ConstitutiveModel<3> &base = model;
    std::vector<double>   state(base.n_state_components(), 0.), next(state);
    Tensor<2, 3>          F_old = unit_symmetric_tensor<3>();
    SymmetricTensor<2, 3> tau;
    error = 0.;
    for (unsigned int i = 1; i <= 30; ++i)
      {
        const double       J = 1. - 0.01 * i;
        const Tensor<2, 3> F =
          std::cbrt(J) * Tensor<2, 3>(unit_symmetric_tensor<3>());
        const PointState<3> old{SymmetricTensor<2, 3>(),
                                SymmetricTensor<2, 3>(),
                                ArrayView<const double>(state),
                                1.};
        base.update_kirchhoff_stress(old,
                                     {F_old, F * invert(F_old), F},
                                     tau,
                                     make_array_view(next));
        state                = next;
        F_old                = F;
        const double p_exact = p0 * std::pow(J, -1. / lambda_);
        error = std::max(error, std::abs(pressure(tau) - p_exact) / p_exact);
      }
    check("  finite strain: |p_Kirchhoff - p0 J^(-1/lambda)| / p",
          error,
          1e-10);
  }

  deallog << "2. Undrained triaxial compression" << std::endl;
  for (const double ocr : {1., 1.5, 4.})
    {
      std::ostringstream what;
      what << "  p_c0 / p0 = " << ocr << ": ";
      double last_error = 0., richardson = 0.;
      double order_min = 10., order_max = 0.;
      double path_error = 0.;
      for (const unsigned int n : {250u, 500u, 1000u, 2000u})
        {
          const auto [shear_error, p_error] = undrained(ocr * p0, n, 0.05);
          path_error                        = std::max(path_error, p_error);
          if (last_error != 0.)
            {
              const double order =
                std::log2(std::abs(last_error / shear_error));
              order_min = std::min(order_min, order);
              order_max = std::max(order_max, order);
            }
          richardson = 2. * shear_error - last_error;
          last_error = shear_error;
        }
      check(what.str() + "stress path q(p) against the closed form, / p0",
            path_error,
            1e-10);
      print_value(what.str() + "shear strain order (min)", order_min);
      check_that(what.str() + "shear strain error of order 1 in the step "
                              "(0.9 ... 1.1)",
                 order_min > 0.9 && order_max < 1.1);
      check(what.str() + "shear strain error at 2000 steps", last_error, 3e-3);
      check(what.str() + "Richardson's 2 e_2000 - e_1000", richardson, 3e-5);
    }

  deallog << "3. Drained triaxial compression" << std::endl;
  {
    double last_error = 0., richardson = 0., order_min = 10., order_max = 0.;
    DrainedResult r;
    for (const unsigned int n : {250u, 500u, 1000u, 2000u})
      {
        r = drained(n, -0.1);
        if (last_error != 0.)
          {
            const double order =
              std::log2(std::abs(last_error / r.shear_error));
            order_min = std::min(order_min, order);
            order_max = std::max(order_max, order);
          }
        richardson = 2. * r.shear_error - last_error;
        last_error = r.shear_error;
      }
    print_value("  final eta / M", r.eta / M);
    check("  lateral stress held, |sigma_lat + p0| / p0",
          r.lateral_error,
          1e-12);
    check("  stress path q = 3 (p - p0) and p_c, / p0", r.path_error, 1e-10);
    check("  volumetric strain against v(p), / lambda", r.volume_error, 1e-10);
    print_value("  drained shear strain order (min)", order_min);
    check_that("  shear strain error of order 1 in the step (0.9 ... 1.1)",
               order_min > 0.9 && order_max < 1.1);
    check("  shear strain error at 2000 steps", last_error, 3e-3);
    check("  Richardson's 2 e_2000 - e_1000", richardson, 3e-5);
  }

  deallog << "4. Tangents against central differences" << std::endl;
  {
    const ModifiedCamClay<3> model(parameters(1.5 * p0));
    // A plastic trial state with three distinct principal strains and shear.
    PointHistory point;
    step(model, point, diagonal(-1e-2, 5e-3, 1e-3));
    SymmetricTensor<2, 3> d_eps = diagonal(-1.5e-2, 4e-3, 2e-3);
    d_eps[0][1]                 = 3e-3;
    d_eps[1][2]                 = -2e-3;
    ModifiedCamClay<3>::Return r;
    model.return_map(point.elastic_strain + d_eps, point.alpha, true, r);
    check_that("  the trial state is plastic", r.increment != 0.);
    const double          h = 1e-6 * (point.elastic_strain + d_eps).norm();
    SymmetricTensor<4, 3> fd;
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int l = k; l < 3; ++l)
        {
          SymmetricTensor<2, 3> e;
          e[k][l] = (k == l ? 1. : 0.5); // a symmetric unit perturbation
          ModifiedCamClay<3>::Return plus, minus;
          model.return_map(point.elastic_strain + d_eps + h * e,
                           point.alpha,
                           false,
                           plus);
          model.return_map(point.elastic_strain + d_eps - h * e,
                           point.alpha,
                           false,
                           minus);
          const SymmetricTensor<2, 3> column =
            (plus.stress - minus.stress) / (2. * h);
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = i; j < 3; ++j)
              fd[i][j][k][l] = column[i][j] / (k == l ? 1. : 2. * 0.5);
        }
    check("  3D return map: |D_alg - central difference| / |D_alg|",
          relative_difference(r.tangent, fd),
          1e-6);

    // The same in 2D (plane strain) through the ConstitutiveModel
    // interface, from a committed plastic state.
    {
      const ModifiedCamClay<2>    model_2d(parameters<2>(1.5 * p0));
      const ConstitutiveModel<2> &base = model_2d;
      std::vector<double>   state(base.n_state_components(), 0.), next(state);
      SymmetricTensor<2, 2> stress, inc;
      inc[0][0] = -1e-2;
      inc[1][1] = 5e-3;
      base.update_stress({{}, {}, ArrayView<const double>(state), 1.},
                         inc,
                         stress,
                         make_array_view(next));
      state = next;
      const PointState<2> old{{}, {}, ArrayView<const double>(state), 1.};
      inc[0][0] = -1.5e-2;
      inc[1][1] = 4e-3;
      inc[0][1] = 3e-3;
      base.update_stress(old, inc, stress, make_array_view(next));
      check_that("  2D: the increment is plastic",
                 IsotropicPlasticity<2>::plastic_increment(
                   ArrayView<const double>(next)) != 0.);
      const SymmetricTensor<4, 2> D = base.consistent_tangent(old, inc);
      SymmetricTensor<4, 2>       fd_2d;
      const double                h2 = 1e-6 * inc.norm();
      for (unsigned int k = 0; k < 2; ++k)
        for (unsigned int l = k; l < 2; ++l)
          {
            SymmetricTensor<2, 2> e;
            e[k][l] = 1.; // symmetric: both (k,l) and (l,k)
            SymmetricTensor<2, 2> plus, minus;
            base.update_stress(old, inc + h2 * e, plus, make_array_view(next));
            base.update_stress(old, inc - h2 * e, minus, make_array_view(next));
            const SymmetricTensor<2, 2> column = (plus - minus) / (2. * h2);
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = i; j < 2; ++j)
                fd_2d[i][j][k][l] = column[i][j] / (k == l ? 1. : 2.);
          }
      check("  2D plane strain: |consistent_tangent - central difference| / "
            "|D|",
            relative_difference(D, fd_2d),
            1e-6);
    }

    // Finite strain: d tau / d l against tau of (I + h E_kl) Delta F.
    {
      const ConstitutiveModel<3> &base = model;
      std::vector<double> state(base.n_state_components(), 0.), next(state);
      const Tensor<2, 3>  I = unit_symmetric_tensor<3>();
      Tensor<2, 3> F1({{0.98, 0.02, 0.}, {0., 1.006, 0.}, {0., 0., 1.004}});
      SymmetricTensor<2, 3> tau;
      base.update_kirchhoff_stress({{}, {}, ArrayView<const double>(state), 1.},
                                   {I, F1, F1},
                                   tau,
                                   make_array_view(next));
      state = next;
      const PointState<3> old{{}, {}, ArrayView<const double>(state), 1.};
      Tensor<2, 3>        dF(
        {{0.97, 0.02, 0.}, {-0.01, 1.01, 0.005}, {0., 0.004, 1.008}});
      base.update_kirchhoff_stress(old,
                                   {F1, dF, dF * F1},
                                   tau,
                                   make_array_view(next));
      check_that("  finite strain: the increment is plastic",
                 IsotropicPlasticity<3>::plastic_increment(
                   ArrayView<const double>(next)) != 0.);
      const Tensor<4, 3> c = base.kirchhoff_tangent(old, {F1, dF, dF * F1});
      Tensor<4, 3>       fd_c;
      const double       h3 = 1e-7;
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = 0; l < 3; ++l)
          {
            Tensor<2, 3> E;
            E[k][l] = 1.;
            SymmetricTensor<2, 3> plus, minus;
            const Tensor<2, 3>    dF_plus  = (I + h3 * E) * dF;
            const Tensor<2, 3>    dF_minus = (I - h3 * E) * dF;
            base.update_kirchhoff_stress(old,
                                         {F1, dF_plus, dF_plus * F1},
                                         plus,
                                         make_array_view(next));
            base.update_kirchhoff_stress(old,
                                         {F1, dF_minus, dF_minus * F1},
                                         minus,
                                         make_array_view(next));
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                fd_c[i][j][k][l] = (plus[i][j] - minus[i][j]) / (2. * h3);
          }
      check("  finite strain: |kirchhoff_tangent - central difference| / |c|",
            (c - fd_c).norm() / c.norm(),
            1e-6);
    }
  }

  deallog << "5. Bad parameters" << std::endl;
  const auto message = [](const std::function<void()> &make) {
    try
      {
        make();
      }
    catch (const std::exception &exc)
      {
        return std::string(exc.what());
      }
    return std::string("(no error)");
  };
  const auto bad =
    [&](const std::function<void(ModifiedCamClay<3>::Parameters &)> &change) {
      return message([&] {
        auto p = parameters(p0);
        change(p);
        ModifiedCamClay<3> model(p);
      });
    };
  check_that("  kappa >= lambda names 'Compression index'",
             bad([](auto &p) {
               p.compression_index = 0.5 * kappa;
             }).find("Compression index") != std::string::npos);
  check_that("  p_c0 < p0 names 'Preconsolidation pressure'",
             bad([](auto &p) {
               p.preconsolidation_pressure = 0.5 * p0;
             }).find("Preconsolidation pressure") != std::string::npos);
  check_that("  G = 0 names 'Shear modulus'",
             bad([](auto &p) { p.shear_modulus = 0.; }).find("Shear modulus") !=
               std::string::npos);
  check_that("  OCR = 0.5 names 'Overconsolidation ratio'",
             bad([](auto &p) {
               p.overconsolidation_ratio = 0.5;
             }).find("Overconsolidation ratio") != std::string::npos);

  deallog << "6. Made by name from a parameter file" << std::endl;
  {
    ParameterHandler prm;
    ConstitutiveModelFactory<2>::declare_parameters(prm);
    prm.parse_input_from_string("subsection Material\n"
                                "  set Model = Modified Cam Clay\n"
                                "  subsection Modified Cam Clay\n"
                                "    set Initial pressure = 50\n"
                                "    set Preconsolidation pressure = 80\n"
                                "  end\n"
                                "end\n");
    const auto  model = ConstitutiveModelFactory<2>::create(prm);
    const auto *mcc   = dynamic_cast<const ModifiedCamClay<2> *>(model.get());
    check_that("  'Modified Cam Clay' makes the model", mcc != nullptr);
    std::vector<double> state(model->n_state_components(), 0.);
    check("  an unstrained point: |sigma + p0 I| / p0",
          (mcc->stress_3d(ArrayView<const double>(state)) +
           50. * unit_symmetric_tensor<3>())
              .norm() /
            50.,
          1e-14);
  }

  deallog << "7. The yield surface through the initial stress (OCR)"
          << std::endl;
  {
    // Normally consolidated (OCR = 1) at p_i = 30 kPa, below the elastic
    // law's p0 = 100 and the entry's p_c0 = 100: the point starts on its
    // own normal consolidation line, and isotropic compression follows it
    // from the first step, v = lambda ln(p / p_i) (v from the start).
    auto parameters_nc                    = parameters(p0);
    parameters_nc.overconsolidation_ratio = 1.;
    const ModifiedCamClay<3>    model(parameters_nc);
    const double                p_i = 30.;
    std::vector<double>         state(model.n_state_components(), 0.);
    const SymmetricTensor<2, 3> start = -p_i * unit_symmetric_tensor<3>();
    model.initial_stress(Point<3>(), 0, &start, ArrayView<double>(state));
    PointHistory point{ModifiedCamClay<3>::elastic_strain(state),
                       ModifiedCamClay<3>::equivalent_plastic_strain(state)};
    check("  isotropic start: p_c / p_i - 1",
          model.preconsolidation_pressure(point.alpha) / p_i - 1.,
          1e-12);
    double error   = 0.;
    bool   plastic = true;
    for (unsigned int i = 1; i <= 50; ++i)
      {
        const auto r = step(model, point, -1e-3 * unit_symmetric_tensor<3>());
        plastic      = plastic && r.increment > 0.;
        const double p_exact = p_i * std::exp(3e-3 * i / lambda_);
        error =
          std::max(error, std::abs(pressure(r.stress) - p_exact) / p_exact);
      }
    check_that("  every step of the compression plastic", plastic);
    check("  on the line through p_i: |p - p_i exp(v / lambda)| / p",
          error,
          1e-10);

    // A K0 start (sigma_h = 0.5 sigma_v, p = 40/3, q = 10 kPa), OCR = 1
    // and 2: p_c = OCR (p + q^2 / (M^2 p)), and the point keeps the start's
    // stress.
    for (const double ocr : {1., 2.})
      {
        auto parameters_k0                    = parameters(p0);
        parameters_k0.overconsolidation_ratio = ocr;
        const ModifiedCamClay<3> k0_model(parameters_k0);
        std::fill(state.begin(), state.end(), 0.);
        const SymmetricTensor<2, 3> k0 = diagonal(-10., -20., -10.);
        k0_model.initial_stress(Point<3>(), 0, &k0, ArrayView<double>(state));
        const double p = 40. / 3., q = 10.;
        const double alpha =
          ModifiedCamClay<3>::equivalent_plastic_strain(state);
        check("  K0 start, OCR = " + std::to_string(int(ocr)) +
                ": p_c / (OCR (p + q^2 / (M^2 p))) - 1",
              k0_model.preconsolidation_pressure(alpha) /
                  (ocr * (p + q * q / (M * M * p))) -
                1.,
              1e-12);
        check("  the same: the start's stress kept, |sigma - sigma0| / p",
              (k0_model.stress_3d(ArrayView<const double>(state)) - k0).norm() /
                p,
              1e-12);
      }

    // A start in tension is refused, naming the entry.
    std::fill(state.begin(), state.end(), 0.);
    const SymmetricTensor<2, 3> tension = unit_symmetric_tensor<3>();
    check_that("  a start with p <= 0 names 'Initial stress'",
               message([&] {
                 model.initial_stress(Point<3>(),
                                      0,
                                      &tension,
                                      ArrayView<double>(state));
               }).find("Initial stress") != std::string::npos);
  }
}
