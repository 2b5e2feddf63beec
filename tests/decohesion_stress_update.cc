// Single-point stress updates of the elastic-decohesive model (paper eqs.
// 3.1-3.2) in 2D plane stress, against closed-form values:
//
// - uniaxial strain in x (eps_yy = 0, sigma = C:(eps - (w/L_c) x(x)x)):
//   elastic until sigma_xx = tau_nf (initiation), then on the softening line
//   sigma_xx = tau_nf (1 - w/u0) with w = (M eps - tau_nf)/(M/L_c -
//   tau_nf/u0); unloading and reloading elastic at the current opening;
//   complete failure at w = u0, after which sigma_xx <= 0 for good; the
//   preconditioner's stiffness tangent() of a softening point is the secant
//   of the band, sigma_xx / eps_xx, and loading_tangent() predicts the
//   stress increment of a further opening exactly (linear softening) and
//   is the secant once the crack has unloaded below the softening line;
// - a stress state with principal directions at 30 degrees: with the
//   principal-stress normal the crack normal is (cos 30, sin 30) and
//   L_c = h cos 30; with the normal fixed to x the same state has
//   sigma_xx = 1.2 cos^2 30 - 0.3 sin^2 30 = 0.825 tau_nf and does not crack;
// - one increment gives the same state as many small ones (closed form);
// - points outside the cracking region stay elastic;
// - the local stability limit L_c < M u0 / tau_nf is enforced;
// - linear shear retention: the shear traction is (1 - w/u0) mu gamma
//   whether shear or opening comes first, independent of the increments,
//   zero at complete failure (and close to zero just before it, where
//   abrupt retention still carries mu gamma); the dissipation summed to
//   complete failure is G_f / L_c plus the elastic shear energy
//   mu gamma^2 / 2; the preconditioner's shear stiffness is beta mu; a
//   completely failed crack closes without traction down to w = u0
//   (contact), the abrupt one keeps its opening.
//
// Tolerance 1e-12 (relative to tau_nf, u0 or h): the updates are closed
// form, so only round-off remains (measured <= 6e-14; strains of order
// tau_nf / M = 1e-3 times M cost three digits), while a wrong formula or
// smearing length is off by 1e-2 or more.
#include "tests.h"

#include <qsmpm/materials/decohesion.h>

using namespace qsmpm;

namespace
{
  const double E = 1000., nu = 0.2, tau = 1., G_f = 0.05, h = 0.1;
  const double u0 = 2. * G_f / tau;

  /// A material point: committed strain, stress and state.
  struct MaterialPoint
  {
    SymmetricTensor<2, 2> strain, stress;
    std::vector<double>   state;
  };

  /// Apply the strain increment d_eps to @p p (and commit).
  void
  step(const Decohesion<2>         &model,
       MaterialPoint               &p,
       const SymmetricTensor<2, 2> &d_eps)
  {
    std::vector<double>   new_state(p.state.size());
    SymmetricTensor<2, 2> stress;
    model.update_stress(
      {p.strain, p.stress, ArrayView<const double>(p.state), 1.},
      d_eps,
      stress,
      ArrayView<double>(new_state));
    p.strain += d_eps;
    p.stress = stress;
    p.state  = new_state;
  }

  MaterialPoint
  make_point(const Decohesion<2> &model, const dealii::Point<2> &x)
  {
    MaterialPoint p;
    p.state.resize(model.n_state_components());
    model.initialize_state(x, ArrayView<double>(p.state));
    return p;
  }

  SymmetricTensor<2, 2>
  uniaxial(const double e)
  {
    SymmetricTensor<2, 2> d;
    d[0][0] = e;
    return d;
  }

  /// Offsets of the model's fields by name, as the library finds them.
  unsigned int
  offset(const Decohesion<2> &model, const std::string &name)
  {
    unsigned int o = 0;
    for (const auto &f : model.state_fields())
      {
        if (f.name == name)
          return o;
        o += f.n_components;
      }
    return numbers::invalid_unsigned_int;
  }
} // namespace

int
main()
{
  initlog();
  Tensor<1, 2> x_normal;
  x_normal[0] = 1.;
  Decohesion<2> model(E, nu, true, tau, G_f, x_normal, h);
  const double  M        = E / (1. - nu * nu);
  const double  L        = h;
  const auto    w_offset = offset(model, Decohesion<2>::crack_opening_name);
  const auto    n_offset = offset(model, Decohesion<2>::crack_normal_name);
  const double  eps_i    = tau / M;
  // The opening on the softening line at total strain eps.
  const auto w_softening = [&](const double eps) {
    return (M * eps - tau) / (M / L - tau / u0);
  };

  deallog << "Uniaxial strain in x, fixed normal x" << std::endl;
  MaterialPoint p = make_point(model, dealii::Point<2>());
  // Elastic up to 0.99 eps_i.
  for (unsigned int i = 0; i < 99; ++i)
    step(model, p, uniaxial(0.01 * eps_i));
  check("  elastic: |sigma_xx - M eps| / tau_nf",
        (p.stress[0][0] - M * p.strain[0][0]) / tau,
        1e-12);
  check_that("  elastic: no crack below tau_nf",
             p.state[w_offset] == 0. && p.state[n_offset] == 0.);
  // Initiation within the next increment.
  step(model, p, uniaxial(0.02 * eps_i));
  check_that("  initiation: crack with normal x",
             p.state[n_offset] == 1. && p.state[n_offset + 1] == 0.);
  double eps = p.strain[0][0];
  check("  initiation: |w - w_exact| / u0",
        (p.state[w_offset] - w_softening(eps)) / u0,
        1e-12);
  // Softening.
  for (unsigned int i = 0; i < 20; ++i)
    step(model, p, uniaxial(0.5 * u0 / L / 20));
  eps             = p.strain[0][0];
  const double w1 = p.state[w_offset];
  check("  softening: |w - w_exact| / u0", (w1 - w_softening(eps)) / u0, 1e-12);
  check("  softening: |sigma_xx - tau_nf (1 - w/u0)| / tau_nf",
        (p.stress[0][0] - tau * (1. - w1 / u0)) / tau,
        1e-12);
  check("  softening: |sigma_xx - M (eps - w/L_c)| / tau_nf",
        (p.stress[0][0] - M * (eps - w1 / L)) / tau,
        1e-12);
  check("  softening: |sigma_yy - nu sigma_xx| / tau_nf",
        (p.stress[1][1] - nu * p.stress[0][0]) / tau,
        1e-12);
  // The stiffness for the preconditioner: across a softening crack the
  // secant of the band, here sigma_xx / eps_xx of the committed state.
  check(
    "  softening: |tangent_xxxx - sigma_xx / eps_xx| / M (secant)",
    (model.tangent(
       {p.strain, p.stress, ArrayView<const double>(p.state), 1.})[0][0][0][0] -
     p.stress[0][0] / eps) /
      M,
    1e-12);
  // The stiffness for a factorizing preconditioner, loading_tangent(): the
  // crack keeps opening. On the linear softening line with a fixed normal
  // the stress is linear in the strain increment, so loading_tangent : d eps
  // is the stress increment of update_stress() for any increment that
  // opens the crack further, to round-off (relative to d sigma, which is
  // 1e-2 of sigma: two digits lost). The secant's normal stress increment
  // has the wrong sign (its normal stiffness is positive, the slope's
  // negative).
  {
    SymmetricTensor<2, 2> d_eps;
    d_eps[0][0] = 0.01 * eps_i;
    d_eps[1][1] = 0.003 * eps_i;
    d_eps[0][1] = 0.002 * eps_i;
    const PointState<2>   old{p.strain,
                            p.stress,
                            ArrayView<const double>(p.state),
                            1.};
    std::vector<double>   new_state(p.state.size());
    SymmetricTensor<2, 2> stress;
    model.update_stress(old, d_eps, stress, new_state);
    const SymmetricTensor<2, 2> d_sigma = stress - p.stress;
    check_that("  softening, further opening: w grows",
               new_state[w_offset] > w1);
    check("  softening: |loading_tangent : d eps - d sigma| / |d sigma|",
          (model.loading_tangent(old) * d_eps - d_sigma).norm() /
            d_sigma.norm(),
          1e-10);
    check_at_least("  softening: |(tangent : d eps)_xx - d sigma_xx| / "
                   "|d sigma_xx| (the secant, of the other sign)",
                   std::abs((model.tangent(old) * d_eps)[0][0] -
                            d_sigma[0][0]) /
                     std::abs(d_sigma[0][0]),
                   1.);
  }
  // Unloading, into compression.
  const double sigma1 = p.stress[0][0];
  step(model, p, uniaxial(-2. * sigma1 / M));
  check("  unloading: opening unchanged, |w - w_before| / u0",
        (p.state[w_offset] - w1) / u0,
        0.);
  {
    // Below the softening line the crack has unloaded: loading_tangent()
    // keeps the secant.
    const PointState<2> unloaded{p.strain,
                                 p.stress,
                                 ArrayView<const double>(p.state),
                                 1.};
    check("  unloaded: |loading_tangent - tangent| / M (the secant)",
          (model.loading_tangent(unloaded) - model.tangent(unloaded)).norm() /
            M,
          1e-12);
  }
  check("  unloading: |sigma_xx + sigma_before| / tau_nf (elastic)",
        (p.stress[0][0] + sigma1) / tau,
        1e-12);
  // Reloading to the softening line: elastic, then softening again.
  step(model, p, uniaxial(2. * sigma1 / M));
  check("  reloading to the previous strain: |w - w_before| / u0",
        (p.state[w_offset] - w1) / u0,
        1e-12);
  check("  reloading: |sigma_xx - sigma_before| / tau_nf",
        (p.stress[0][0] - sigma1) / tau,
        1e-12);
  step(model, p, uniaxial(0.1 * u0 / L));
  check("  reloading beyond: |w - w_exact| / u0",
        (p.state[w_offset] - w_softening(p.strain[0][0])) / u0,
        1e-12);
  // Complete failure and beyond.
  step(model, p, uniaxial(2. * u0 / L));
  check("  complete failure: |sigma_xx| / tau_nf", p.stress[0][0] / tau, 1e-12);
  check("  complete failure: |w - L_c eps| / u0",
        (p.state[w_offset] - L * p.strain[0][0]) / u0,
        1e-12);
  check_at_least("  complete failure: w / u0", p.state[w_offset] / u0, 1.);
  const double w2 = p.state[w_offset];
  step(model, p, uniaxial(-0.1 * u0 / L));
  check_that("  after failure, closing: sigma_xx < 0, w unchanged",
             p.stress[0][0] < 0 && p.state[w_offset] == w2);
  step(model, p, uniaxial(0.3 * u0 / L));
  check("  after failure, reopening: |sigma_xx| / tau_nf (traction free)",
        p.stress[0][0] / tau,
        1e-12);

  deallog << "One increment = many increments (closed form)" << std::endl;
  {
    MaterialPoint a = make_point(model, dealii::Point<2>()), b = a;
    step(model, a, uniaxial(0.7 * u0 / L));
    for (unsigned int i = 0; i < 70; ++i)
      step(model, b, uniaxial(0.01 * u0 / L));
    check("  |w_one - w_many| / u0",
          (a.state[w_offset] - b.state[w_offset]) / u0,
          1e-12);
    check("  |sigma_one - sigma_many| / tau_nf",
          (a.stress - b.stress).norm() / tau,
          1e-12);
  }

  deallog << "Principal directions at 30 degrees" << std::endl;
  {
    const double angle = numbers::PI / 6, c = std::cos(angle),
                 s = std::sin(angle);
    Tensor<1, 2> e1, e2;
    e1[0] = c;
    e1[1] = s;
    e2[0] = -s;
    e2[1] = c;
    // sigma = 1.2 tau e1(x)e1 - 0.3 tau e2(x)e2, reached by a strain
    // increment C^{-1}:sigma from the stress-free state.
    SymmetricTensor<2, 2> sigma =
      1.2 * tau * symmetrize(outer_product(e1, e1)) -
      0.3 * tau * symmetrize(outer_product(e2, e2));
    const SymmetricTensor<2, 2> d_eps = invert(model.stiffness()) * sigma;
    Decohesion<2> principal(E, nu, true, tau, G_f, Tensor<1, 2>(), h);
    MaterialPoint q = make_point(principal, dealii::Point<2>());
    step(principal, q, d_eps);
    Tensor<1, 2> n;
    n[0] = q.state[n_offset];
    n[1] = q.state[n_offset + 1];
    check("  principal normal: 1 - |n . e1|", 1. - std::abs(n * e1), 1e-12);
    check("  principal normal: |L_c - h cos 30| / h",
          (principal.smearing_length(n) - h * c) / h,
          1e-12);
    const double w     = q.state[w_offset];
    const double tau_n = n * q.stress * n;
    check("  principal normal: |tau_n - tau_nf (1 - w/u0)| / tau_nf",
          (tau_n - tau * (1. - w / u0)) / tau,
          1e-12);
    check_that("  principal normal: cracked (w > 0)", w > 0.);
    // With the normal fixed to x the criterion sees tau_n = sigma_xx =
    // 1.2 cos^2 30 - 0.3 sin^2 30 = 0.9 - 0.075 = 0.825 tau_nf < tau_nf.
    MaterialPoint r = make_point(model, dealii::Point<2>());
    step(model, r, d_eps);
    check("  normal fixed to x: |sigma_xx - 0.825 tau_nf| / tau_nf",
          (r.stress[0][0] - (1.2 * c * c - 0.3 * s * s) * tau) / tau,
          1e-12);
    check_that("  normal fixed to x: sigma_xx = 0.825 tau_nf does not crack",
               r.state[w_offset] == 0. && r.state[n_offset] == 0.);
  }

  deallog << "Cracking region" << std::endl;
  {
    Decohesion<2> band(E, nu, true, tau, G_f, x_normal, h);
    band.set_crack_region(
      [](const dealii::Point<2> &x) { return std::abs(x[0]) < 0.05; });
    MaterialPoint inside  = make_point(band, dealii::Point<2>(0.01, 0.));
    MaterialPoint outside = make_point(band, dealii::Point<2>(0.2, 0.));
    step(band, inside, uniaxial(3. * eps_i));
    step(band, outside, uniaxial(3. * eps_i));
    check_that("  inside cracks, outside stays elastic",
               inside.state[w_offset] > 0. && outside.state[w_offset] == 0. &&
                 std::abs(outside.stress[0][0] - 3. * tau) < 1e-12);
  }

  deallog << "Local stability limit" << std::endl;
  {
    const double limit  = M * u0 / tau;
    bool         thrown = false;
    try
      {
        Decohesion<2> unstable(E, nu, true, tau, G_f, x_normal, 1.01 * limit);
      }
    catch (const std::exception &e)
      {
        thrown =
          std::string(e.what()).find("locally unstable") != std::string::npos;
      }
    check_that("  L_c > M u0 / tau_nf is rejected with a message", thrown);
    check("  stability_limit() = M u0 / tau_nf, relative error",
          (model.stability_limit() - limit) / limit,
          1e-12);
  }

  deallog << "Linear shear retention" << std::endl;
  {
    // Shear retention = linear: the shear traction across the crack is
    // t_s = beta mu gamma, beta = max(0, 1 - w/u0), with gamma the band's
    // engineering shear strain (2 eps_xy), whatever the order in which
    // shear and opening were applied; abrupt retention keeps mu gamma until
    // complete failure.
    Decohesion<2> linear(E, nu, true, tau, G_f, x_normal, h);
    linear.set_shear_retention(Decohesion<2>::ShearRetention::linear);
    const double          mu    = E / (2. * (1. + nu));
    const double          gamma = 0.5 * eps_i;
    SymmetricTensor<2, 2> shear;
    shear[0][1]      = 0.5 * gamma;
    const auto w_lin = offset(linear, Decohesion<2>::crack_opening_name);
    const auto D     = [&](const MaterialPoint &a, const MaterialPoint &b) {
      return linear.dissipation(
        {a.strain, a.stress, ArrayView<const double>(a.state), 1.},
        ArrayView<const double>(b.state));
    };

    // Shear first (elastic), then opening in ten steps to complete failure
    // (w / u0 = 0.15 after the first).
    MaterialPoint a = make_point(linear, dealii::Point<2>());
    step(linear, a, shear);
    double dissipated = 0.;
    for (unsigned int i = 0; i < 10; ++i)
      {
        MaterialPoint before = a;
        step(linear, a, uniaxial(eps_i + 0.15 * u0 / L));
        dissipated += D(before, a);
        if (i == 0)
          {
            const double beta = 1. - a.state[w_lin] / u0;
            check("  shear, then opening: |sigma_xy - beta mu gamma| / tau_nf",
                  (a.stress[0][1] - beta * mu * gamma) / tau,
                  1e-12);
            check("  opening unaffected: |sigma_xx - tau_nf beta| / tau_nf",
                  (a.stress[0][0] - tau * beta) / tau,
                  1e-12);
          }
      }
    check_at_least("  the crack has failed completely: w / u0",
                   a.state[w_lin] / u0,
                   1.);
    check("  after complete failure: |sigma_xy| / tau_nf",
          a.stress[0][1] / tau,
          1e-12);
    // All of the fracture energy and all of the elastic shear energy.
    const double expected = G_f / L + 0.5 * mu * gamma * gamma;
    check("  sum of dissipation() = G_f / L_c + mu gamma^2 / 2, relative",
          (dissipated - expected) / expected,
          1e-12);
    // A completely failed crack closes without traction (w falls back by
    // the closing times L_c, nothing dissipated), down to w = u0, where it
    // is in contact and compressed elastically. (The paper's abrupt model
    // keeps w: "after failure, closing" above.)
    const double  w2     = a.state[w_lin];
    MaterialPoint before = a;
    step(linear, a, uniaxial(-0.1 * u0 / L));
    check("  failed, closing: |sigma| / tau_nf (traction free)",
          a.stress.norm() / tau,
          1e-12);
    check("  failed, closing: |w - (w_before - 0.1 u0)| / u0",
          (a.state[w_lin] - (w2 - 0.1 * u0)) / u0,
          1e-12);
    check("  failed, closing: dissipation / (G_f / L_c)",
          D(before, a) / (G_f / L),
          1e-12);
    const double w3 = a.state[w_lin];
    step(linear, a, uniaxial(-((w3 - u0) / L + 0.2 * u0 / L)));
    check("  closed to contact: |w / u0 - 1|", a.state[w_lin] / u0 - 1., 1e-12);
    check("  in contact: |sigma_xx + M 0.2 u0 / L_c| / tau_nf",
          (a.stress[0][0] + M * 0.2 * u0 / L) / tau,
          1e-12);

    // Opening first, then shear in one or in 50 increments.
    MaterialPoint b = make_point(linear, dealii::Point<2>()), c;
    step(linear, b, uniaxial(eps_i + 0.3 * u0 / L));
    c = b;
    step(linear, b, shear);
    for (unsigned int i = 0; i < 50; ++i)
      step(linear, c, shear / 50.);
    const double beta = 1. - b.state[w_lin] / u0;
    check("  opening, then shear: |sigma_xy - beta mu gamma| / tau_nf",
          (b.stress[0][1] - beta * mu * gamma) / tau,
          1e-12);
    check("  one shear increment = 50: |sigma_one - sigma_many| / tau_nf",
          (b.stress - c.stress).norm() / tau,
          1e-12);
    // Continuity at complete failure: just before it the traction is
    // (1 - w/u0) mu gamma, small; abrupt retention still carries mu gamma.
    MaterialPoint e = make_point(linear, dealii::Point<2>());
    MaterialPoint f = make_point(model, dealii::Point<2>());
    step(linear, e, shear);
    step(model, f, shear);
    // The strain at which w = 0.995 u0 on the softening line.
    const SymmetricTensor<2, 2> near_failure =
      uniaxial((0.995 * u0 * (M / L - tau / u0) + tau) / M);
    step(linear, e, near_failure);
    step(model, f, near_failure);
    check_that("  near failure (w / u0 in (0.99, 1)): linear carries "
               "|sigma_xy| <= 0.01 mu gamma, abrupt mu gamma",
               e.state[w_lin] / u0 > 0.99 && e.state[w_lin] / u0 < 1. &&
                 std::abs(e.stress[0][1]) <= 0.01 * mu * gamma &&
                 std::abs(f.stress[0][1] - mu * gamma) < 1e-12 * tau);
    // The preconditioner's tangent: the secant shear stiffness beta mu.
    const auto T = linear.tangent(
      {b.strain, b.stress, ArrayView<const double>(b.state), 1.});
    check("  tangent: |C_xyxy - beta mu| / mu",
          (T[0][1][0][1] - beta * mu) / mu,
          1e-12);
  }
}
