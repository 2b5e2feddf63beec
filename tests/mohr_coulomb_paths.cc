// The Mohr-Coulomb model (MohrCoulomb, issue 31): single-point strain paths
// of its 3D return mapping against closed forms of Mohr-Coulomb plasticity
// (tension positive, sigma_1 >= sigma_2 >= sigma_3; E = 1e4, nu = 0.3,
// c = 10, perfect plasticity unless said):
//
// 1. Drained triaxial compression (lateral stress held at -p0 = -100 by
//    solving for the lateral strain in every step, axial strain decreasing
//    in 400 steps of 1e-4): the return lands on the edge sigma_1 =
//    sigma_2 (the lateral stresses); the limit state satisfies
//      sigma_3 = -(p0 (1 + sin phi) + 2 c cos phi) / (1 - sin phi),
//    and once the stress is at the limit all strain is plastic with the
//    dilatancy of the two planes' flows,
//      d eps_v / d eps_axial = -2 sin psi / (1 - sin psi).
//    For phi = psi = 30 degrees and phi = 30, psi = 10 degrees.
// 2. A strain path with three distinct principal values (d eps = (1, -0.2,
//    -0.8) 1e-4 per step from the same isotropic state): the return lands
//    on the main plane (the order stays strict); Phi = 0 there, and the
//    plastic strain increment in the principal axes is a multiple of the
//    flow direction (1 + sin psi, 0, -(1 - sin psi)).
// 3. Hydrostatic tension (d eps = 1e-4 I per step): the return to the
//    apex, p = c cot(phi), with phi = 30 and psi = 10 degrees.
// 4. Linear hardening of the cohesion (H = 500) on the triaxial path: the
//    limit stress of the current cohesion c(alpha) = c0 + H alpha in every
//    plastic step.
// 5. Finite strain: a stretch F1 from the virgin state gives the return
//    mapping of the trial elastic strain ln F1 (the exponential map), and
//    a rigid rotation R of the yielded state gives R tau R^T without a
//    plastic increment (objectivity).
// 6. Bad parameters: one message each, naming the entry.
//
// Tolerances: the returns are closed form in principal stresses (linear
// systems), so only round-off remains: 1e-10 relative is far above it
// (QSMPM_VERBOSE prints the values) and far below what a wrong flow or
// plane gives (O(sin psi) or O(1)).
#include "plasticity_point.h"
#include "tests.h"

#include <qsmpm/materials/mohr_coulomb.h>

using namespace qsmpm;

namespace
{
  const double E = 1e4, nu = 0.3, c = 10., p0 = 100.;

  PointHistory
  isotropic_state(const MohrCoulomb<3> &model)
  {
    PointHistory point;
    point.elastic_strain =
      -p0 / (3. * model.bulk_modulus()) * unit_symmetric_tensor<3>();
    return point;
  }

  /// The triaxial path; checks the limit and the dilatancy.
  void
  triaxial(const double phi_deg, const double psi_deg, const double H)
  {
    const MohrCoulomb<3> model(E, nu, c, phi_deg, psi_deg, H);
    PointHistory         point         = isotropic_state(model);
    const double         sf            = std::sin(phi_deg * M_PI / 180.),
                 cf                    = std::cos(phi_deg * M_PI / 180.),
                 sp                    = std::sin(psi_deg * M_PI / 180.);
    double                 limit_error = 0., dilatancy_error = 0.;
    double                 edge_error = 0., lateral_error = 0.;
    unsigned int           plastic_steps = 0;
    MohrCoulomb<3>::Return r;
    for (unsigned int n = 0; n < 400; ++n)
      {
        // Axial (z) strain -1e-4; the lateral strain (x and y alike) by
        // Newton on the lateral stress.
        double d_lat = 0.;
        for (unsigned int it = 0; it < 50; ++it)
          {
            r = step(model, point, diagonal(d_lat, d_lat, -1e-4), false);
            const double residual = r.stress[0][0] + p0;
            if (std::abs(residual) < 1e-13 * p0)
              break;
            d_lat -= residual / (r.tangent[0][0][0][0] + r.tangent[0][0][1][1]);
          }
        r = step(model, point, diagonal(d_lat, d_lat, -1e-4));
        lateral_error =
          std::max(lateral_error, std::abs(r.stress[0][0] + p0) / p0);
        if (r.increment > 0.)
          {
            ++plastic_steps;
            const double coh = c + H * r.alpha;
            const double sigma_3 =
              -(p0 * (1. + sf) + 2. * coh * cf) / (1. - sf);
            limit_error =
              std::max(limit_error, std::abs(r.stress[2][2] - sigma_3) / p0);
            edge_error =
              std::max(edge_error,
                       std::abs(r.stress[0][0] - r.stress[1][1]) / p0);
            // At the limit (perfect plasticity, the stress no longer
            // changes) the whole increment is plastic.
            if (H == 0. && n > 300)
              dilatancy_error = std::max(dilatancy_error,
                                         std::abs((2. * d_lat - 1e-4) / -1e-4 -
                                                  (-2. * sp / (1. - sp))) /
                                           (1. + 2. * sp / (1. - sp)));
          }
      }
    std::ostringstream what;
    what << "  phi = " << phi_deg << ", psi = " << psi_deg << ", H = " << H
         << ": ";
    check_that(what.str() + "it yields", plastic_steps > 100);
    check(what.str() + "lateral stress held, |sigma_lat + p0| / p0",
          lateral_error,
          1e-12);
    check(what.str() + "on the edge, |sigma_1 - sigma_2| / p0",
          edge_error,
          1e-12);
    check(what.str() + "limit sigma_3 against the closed form, / p0",
          limit_error,
          1e-10);
    if (H == 0.)
      check(what.str() + "dilatancy d eps_v / d eps_axial",
            dilatancy_error,
            1e-8);
  }
} // namespace

int
main()
{
  initlog();

  deallog << "1. Drained triaxial compression (the edge sigma_1 = sigma_2)"
          << std::endl;
  triaxial(30., 30., 0.);
  triaxial(30., 10., 0.);

  deallog << "2. Three distinct principal strains (the main plane)"
          << std::endl;
  {
    const double                phi = 30., psi = 10.;
    const MohrCoulomb<3>        model(E, nu, c, phi, psi);
    PointHistory                point     = isotropic_state(model);
    const double                sp        = std::sin(psi * M_PI / 180.);
    const SymmetricTensor<2, 3> d_eps     = 1e-4 * diagonal(1., -0.2, -0.8);
    double                      phi_error = 0., flow_error = 0.;
    bool                        strict  = true;
    unsigned int                plastic = 0;
    for (unsigned int n = 0; n < 200; ++n)
      {
        const SymmetricTensor<2, 3> eps_e_old = point.elastic_strain;
        const auto                  r         = step(model, point, d_eps);
        if (!(r.increment > 0.))
          continue;
        ++plastic;
        const double s1 = r.stress[0][0], s2 = r.stress[1][1],
                     s3 = r.stress[2][2];
        strict          = strict && s1 > s2 && s2 > s3;
        phi_error =
          std::max(phi_error,
                   std::abs(model.yield_function(r.stress, r.alpha)) / c);
        // The principal axes are x, y, z throughout (diagonal path).
        const SymmetricTensor<2, 3> d_eps_p =
          d_eps - (r.elastic_strain - eps_e_old);
        const double scale = d_eps_p.norm();
        flow_error         = std::max(
          {flow_error,
                   std::abs(d_eps_p[1][1]) / scale,
                   std::abs(d_eps_p[0][0] * (1. - sp) + d_eps_p[2][2] * (1. + sp)) /
                     scale});
      }
    check_that("  it yields, with sigma_1 > sigma_2 > sigma_3 throughout",
               plastic > 50 && strict);
    check("  |Phi| / c", phi_error, 1e-10);
    check("  plastic increment off the flow direction, relative",
          flow_error,
          1e-10);
  }

  deallog << "3. Hydrostatic tension (the apex)" << std::endl;
  {
    const double         phi = 30., psi = 10.;
    const MohrCoulomb<3> model(E, nu, c, phi, psi);
    PointHistory         point;
    const double         apex    = c / std::tan(phi * M_PI / 180.);
    double               error   = 0.;
    unsigned int         plastic = 0;
    for (unsigned int n = 0; n < 100; ++n)
      {
        const auto r = step(model, point, 1e-4 * unit_symmetric_tensor<3>());
        if (r.increment > 0.)
          {
            ++plastic;
            error =
              std::max(error,
                       (r.stress - apex * unit_symmetric_tensor<3>()).norm() /
                         apex);
          }
      }
    check_that("  it yields", plastic > 10);
    check("  |sigma - c cot(phi) I| / (c cot(phi))", error, 1e-10);
  }

  deallog << "4. Cohesion hardening on the triaxial path" << std::endl;
  triaxial(30., 10., 500.);

  deallog << "5. Finite strain (the exponential map of IsotropicPlasticity)"
          << std::endl;
  {
    const MohrCoulomb<3> model(E, nu, c, 30., 10.);
    std::vector<double>  state(8, 0.), state_1(8), state_2(8);
    const Tensor<2, 3>   I = unit_symmetric_tensor<3>();
    Tensor<2, 3>         F1;
    F1[0][0] = 0.98;
    F1[1][1] = 1.004;
    F1[2][2] = 1.001;
    const PointState<3>   virgin{SymmetricTensor<2, 3>(),
                               SymmetricTensor<2, 3>(),
                               ArrayView<const double>(state),
                               1.};
    SymmetricTensor<2, 3> tau_1, tau_2;
    model.update_kirchhoff_stress(virgin,
                                  {I, F1, F1},
                                  tau_1,
                                  make_array_view(state_1));
    // A stretch from the virgin state: the trial elastic strain is ln F1.
    SymmetricTensor<2, 3> ln_F1;
    for (unsigned int d = 0; d < 3; ++d)
      ln_F1[d][d] = std::log(F1[d][d]);
    MohrCoulomb<3>::Return r;
    model.return_map(ln_F1, 0., false, r);
    check_that("  the stretch yields", r.increment > 0.);
    check("  |tau - return map of ln F| / |tau|",
          (tau_1 - r.stress).norm() / r.stress.norm(),
          1e-12);
    // Then a rigid rotation by 30 degrees about (1, 2, 3).
    Tensor<1, 3> axis({1., 2., 3.});
    axis /= axis.norm();
    const double a = M_PI / 6.;
    Tensor<2, 3> R = std::cos(a) * I +
                     std::sin(a) * Tensor<2, 3>({{0., -axis[2], axis[1]},
                                                 {axis[2], 0., -axis[0]},
                                                 {-axis[1], axis[0], 0.}}) +
                     (1. - std::cos(a)) * outer_product(axis, axis);
    const PointState<3> yielded{SymmetricTensor<2, 3>(),
                                tau_1 / determinant(F1),
                                ArrayView<const double>(state_1),
                                1.};
    model.update_kirchhoff_stress(yielded,
                                  {F1, R, R * F1},
                                  tau_2,
                                  make_array_view(state_2));
    check(
      "  rotated: |tau - R tau_1 R^T| / |tau_1|",
      (Tensor<2, 3>(tau_2) - R * Tensor<2, 3>(tau_1) * transpose(R)).norm() /
        tau_1.norm(),
      1e-12);
    check("  rotated: no plastic increment",
          IsotropicPlasticity<3>::plastic_increment(
            ArrayView<const double>(state_2)),
          0.);
  }

  deallog << "6. Bad parameters" << std::endl;
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
  check_that("  dilatancy above friction names 'Dilatancy angle'",
             message([] {
               MohrCoulomb<3>(E, nu, c, 20., 30.);
             }).find("Dilatancy angle") != std::string::npos);
  check_that("  Tresca without cohesion names 'Cohesion'",
             message([] {
               MohrCoulomb<3>(E, nu, 0., 0., 0.);
             }).find("Cohesion") != std::string::npos);
  check_that("  negative hardening names 'Hardening modulus'",
             message([] {
               MohrCoulomb<3>(E, nu, c, 30., 0., -1.);
             }).find("Hardening modulus") != std::string::npos);
}
