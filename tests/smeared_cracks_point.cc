// Single-point paths of the multi-crack smeared model (SmearedCracks), 2D
// plane stress, E = 1000, nu = 0.2, tau_nf = 1, G_f = 0.005 (delta_0 = 0.01),
// crack band width h = 0.1, against what the model must do whatever its
// implementation:
//
// 1. Uniaxial strain along a direction n at angle theta to x (eps = e n(x)n,
//    e growing in 1000 increments to 1.5 tau_nf / E', then 3000 to beyond
//    complete failure), theta = 0, 15, 30, 45 degrees:
//    - the crack starts when sigma_nn reaches tau_nf, with its normal along
//      n (within 1e-6 rad);
////    - the work of the stress, int sigma : d eps (trapezoidal rule), up to
//      complete failure (where sigma = 0: all elastic energy is released)
//      equals G_f / L with
//      L = h (|cos theta| + |sin theta|) (the projection of the cell onto
//      the normal, the default `Smearing length`),
//      to 1e-3 (the quadrature error of the rule at the kink of the
//      softening law is about 1e-4; a wrong L is off by 3 % or more);
//    - the model's own dissipation summed over the path equals the same
//      G_f / L to 1e-6 (closed form per increment).
// 2. Unloading from the middle of the softening branch to zero strain: the
//    stress returns to zero (secant, damage) to 1e-9 tau_nf, and reloading
//    meets the softening line again at the strain it left it at: the stress
//    there is that of the first loading to 1e-6.
// 3. Closing: after the crack has opened and unloaded, compression across
//    it is carried as by the intact material, sigma_nn = E' eps_nn
//    (uniaxial strain in plane stress, E' = E / (1 - nu^2)) to 1 %
//    (the contact penalty is 1000 M / L).
// 4. A second crack: pulling a cracked point (threshold 60 degrees) along
//    the direction normal to the first crack's plane (90 degrees) starts a
//    second crack (count 2) normal to it; pulling along 30 degrees to the
//    first normal does not (count 1: the first crack takes it in mixed
//    mode).
// 5. Mixed mode = effective separation: slip on a crack that has just
//    started (its opening held): the work of the stresses up to complete
//    failure is G_f / L (the energy of the mixed-mode path, almost all of
//    it in slip, is G_f), to 2e-3.
// 5b. Mixed mode = opening (the default): slip alone does not damage the
//    crack (its history stays exactly), and the crack carries the shear
//    stress: sigma_xy above tau_nf after a shear strain eps_xy = 4 tau_nf / E
//    (elastic: 3.3 tau_nf).
// 7. Damage integration = IMPL-EX (the history of a step extrapolated from
//    the last one): the same pull along 30 degrees reaches the work
//    G_f / L to 1e-2 (first order in the step: 3000 increments over the
//    softening branch; measured 1.4e-4) and the dissipation to 1e-6; the
//    peak overshoots tau_nf by 3.5 % (tolerance 5e-2): a new crack starts
//    with no history increment to extrapolate, and the damage lags the
//    opening until the increments have grown.
// 8. Failed points: a point pulled along n at 30 degrees to complete
//    failure while stretched along the crack plane t by eps_tt =
//    0.5 tau_nf / E (a band that crosses the grid at an angle is stretched
//    so):
//    - at failure the crack carries nothing and the point carries the
//      uniaxial stress sigma_tt = E eps_tt along the crack (its elastic
//      strain is the one that leaves sigma n = 0), to 1e-9;
//    - Failed points = no tension (default): from the next step on the
//      point carries no stress under further stretch along t and in
//      shear (|sigma| <= 1e-12 tau_nf), the switch dissipates the elastic
//      energy sigma_tt^2 / (2 E) to 1e-9, and under a compression with
//      tr eps < 0 it carries the pressure of the 2D bulk modulus,
//      sigma = E / (2 (1 - nu)) tr(eps) I, to 1e-12;
//    - Failed points = keep cracks: the stretch along t is carried,
//      sigma_tt = E eps_tt (the stress that locks an inclined band).
// 9. Softening = bilinear (Petersson 1981): the uniaxial pull along 0 and
//    30 degrees to complete failure. The opening w = L (e - sigma_nn / E')
//    (sigma_nn = E' (e - w / L) for a crack normal to the pull) and the
//    traction sigma_nn follow Petersson's law T(w) = tau_nf (1 - 2/3 w /
//    w_1) up to w_1 = 0.8 G_f / tau_nf, then tau_nf / 3 (w_c - w) / (w_c -
//    w_1) to w_c = 3.6 G_f / tau_nf, to 1e-3 tau_nf at every increment
//    past the peak (the initial branch of the model, w_e = tau_nf / K_0 =
//    1e-6 here, shifts the law by about w_e / w_1 = 2.5e-4); the work and
//    the dissipation up to failure are G_f / L to 1e-3 and 1e-6 as in 1.
// 6. Bad entries: Maximum cracks per point = 3 in 2D and Threshold angle =
//    0 stop with a message naming the entry.
// 10. Crack-parallel softening: the path of 8 (pull along n at 30 degrees,
//    stretch eps_tt = 0.5 tau_nf / E along t). Plane-stress elasticity
//    with sigma n = T n gives the unfaded stress along the crack,
//    E eps_tt + nu sigma_nn; with the entry it is that times T(delta*) /
//    tau_nf, delta* the committed history (the implicit law's secant) and
//    T the linear law written out here (T = tau_nf (delta_0 - delta*) /
//    (delta_0 - delta_e), delta_e = tau_nf / K_0, K_0 = 100 E' / L), at
//    every increment after the crack starts, to 1e-9 tau_nf; the traction
//    across the crack is that of the same run without the entry, to 1e-9
//    tau_nf (sigma_nn is not touched); at failure the point carries less
//    than 1e-3 tau_nf (without the entry E eps_tt = 0.5 tau_nf), and the
//    switch to no tension releases less than 1e-6 of the energy
//    sigma_tt^2 / (2 E) that it releases without the entry (8).
#include "tests.h"

#include <qsmpm/base/utilities.h>
#include <qsmpm/materials/smeared_cracks.h>

using namespace qsmpm;

namespace
{
  const double E = 1000., nu = 0.2, tau = 1., G_f = 0.005, h = 0.1;

  struct MaterialPoint
  {
    SymmetricTensor<2, 2> strain, stress;
    std::vector<double>   state;
    double                dissipated = 0., work = 0.;
  };

  SmearedCracks<2>::Parameters
  parameters(const double threshold = 60.)
  {
    SmearedCracks<2>::Parameters p;
    p.elastic.elasticity.young_modulus = E;
    p.elastic.elasticity.poisson_ratio = nu;
    p.elastic.plane_stress             = true;
    p.tensile_strength                 = tau;
    p.fracture_energy                  = G_f;
    p.crack_band_width                 = h;
    p.max_cracks                       = 2;
    p.threshold_angle                  = threshold;
    return p;
  }

  void
  step(const SmearedCracks<2>      &model,
       MaterialPoint               &p,
       const SymmetricTensor<2, 2> &d_eps)
  {
    std::vector<double>   new_state(p.state.size());
    SymmetricTensor<2, 2> stress;
    const PointState<2>   old{p.strain,
                            p.stress,
                            ArrayView<const double>(p.state),
                            1.};
    model.update_stress(old, d_eps, stress, ArrayView<double>(new_state));
    p.dissipated += model.dissipation(old, ArrayView<const double>(new_state));
    p.work += 0.5 * (p.stress + stress) * d_eps;
    p.strain += d_eps;
    p.stress = stress;
    p.state  = new_state;
  }

  MaterialPoint
  make_point(const SmearedCracks<2> &model)
  {
    MaterialPoint p;
    p.state.resize(model.n_state_components());
    model.initialize_state(Point<2>(), ArrayView<double>(p.state));
    return p;
  }

  /// n (x) n and t (x) t of the direction at @p degrees.
  std::pair<SymmetricTensor<2, 2>, SymmetricTensor<2, 2>>
  directions(const double degrees)
  {
    const double a = degrees * M_PI / 180.;
    Tensor<1, 2> n({std::cos(a), std::sin(a)}), t({-std::sin(a), std::cos(a)});
    return {symmetrize(outer_product(n, n)), symmetrize(outer_product(t, t))};
  }

  /// A uniaxial strain increment d e along the direction at @p degrees.
  SymmetricTensor<2, 2>
  pull(const MaterialPoint &, const double degrees, const double de)
  {
    return de * directions(degrees).first;
  }

  unsigned int
  count(const MaterialPoint &p)
  {
    return static_cast<unsigned int>(p.state[1]);
  }

  Tensor<1, 2>
  first_normal(const MaterialPoint &p)
  {
    return Tensor<1, 2>({p.state[2], p.state[3]});
  }
} // namespace

int
main()
{
  initlog();
  const SmearedCracks<2> model(parameters());

  deallog << "1. Uniaxial pull at an angle to the grid" << std::endl;
  for (const double theta : {0., 15., 30., 45.})
    {
      MaterialPoint p        = make_point(model);
      const auto [nn, tt]    = directions(theta);
      double       sigma_max = 0.;
      bool         started   = false;
      double       angle_err = 1.;
      const double L         = h * (std::abs(std::cos(theta * M_PI / 180.)) +
                            std::abs(std::sin(theta * M_PI / 180.)));
      const double E_plane   = E / (1. - nu * nu);
      const double e_peak    = 1.5 * tau / E_plane;
      const double e_end     = 1.2 * (2. * G_f / tau) / L;
      for (unsigned int i = 0; i < 4000; ++i)
        {
          step(model,
               p,
               pull(p,
                    theta,
                    i < 1000 ? e_peak / 1000. : (e_end - e_peak) / 3000.));
          sigma_max = std::max(sigma_max, p.stress * nn);
          if (!started && count(p) > 0)
            {
              started              = true;
              const Tensor<1, 2> c = first_normal(p);
              angle_err            = std::acos(
                std::min(1.,
                         std::abs(c[0] * std::cos(theta * M_PI / 180.) +
                                  c[1] * std::sin(theta * M_PI / 180.))));
            }
        }
      const std::string at = "  theta = " + std::to_string(int(theta)) + ": ";
      // The peak is that of the last elastic increment or of the first on
      // the softening line, within one increment (1.5e-3 tau_nf).
      check(at + "|peak sigma_nn - tau_nf|", sigma_max - tau, 2e-3);
      check(at + "angle between crack normal and load axis (rad)",
            angle_err,
            1e-6);
      check(at + "|work / (G_f / L) - 1|", p.work / (G_f / L) - 1., 1e-3);
      check(at + "|dissipation / (G_f / L) - 1|",
            p.dissipated / (G_f / L) - 1.,
            1e-6);
      check(at + "|sigma| after failure / tau_nf", p.stress.norm(), 1e-9);
    }

  deallog << "2. Unloading and reloading" << std::endl;
  {
    MaterialPoint       p = make_point(model);
    std::vector<double> e, s;
    const double        de = (tau / E) / 10.;
    for (unsigned int i = 0; i < 300; ++i)
      {
        step(model, p, pull(p, 0., de));
        e.push_back(p.strain[0][0]);
        s.push_back(p.stress[0][0]);
      }
    const double strain_left = p.strain[0][0], stress_left = p.stress[0][0];
    check_at_least("  softening: stress left the peak (1 - sigma/tau)",
                   1. - stress_left / tau,
                   0.05);
    // Unload to zero strain in x (transverse kept stress free).
    const double steps = 100;
    const double back  = strain_left / steps;
    for (unsigned int i = 0; i < steps; ++i)
      step(model, p, pull(p, 0., -back));
    check("  |sigma_xx| at zero strain / tau_nf", p.stress[0][0] / tau, 1e-9);
    for (unsigned int i = 0; i < steps; ++i)
      step(model, p, pull(p, 0., back));
    check("  |sigma_xx on reloading - sigma_xx on loading| / tau_nf",
          (p.stress[0][0] - stress_left) / tau,
          1e-6);

    deallog << "3. Closing" << std::endl;
    for (unsigned int i = 0; i < steps; ++i)
      step(model, p, pull(p, 0., -back));
    const double sigma0 = p.stress[0][0], eps0 = p.strain[0][0];
    step(model, p, pull(p, 0., -1e-3));
    check("  |compression across the closed crack / (E' d eps) - 1|",
          (p.stress[0][0] - sigma0) /
              (E / (1. - nu * nu) * (p.strain[0][0] - eps0)) -
            1.,
          1e-2);
  }

  deallog << "4. A second crack" << std::endl;
  for (const double second : {90., 30.})
    {
      MaterialPoint p = make_point(model);
      // The first crack, normal to x: pull until it softens a little, then
      // unload to zero strain.
      for (unsigned int i = 0; i < 150; ++i)
        step(model, p, pull(p, 0., (tau / E) / 100.));
      const double back = p.strain[0][0] / 50.;
      for (unsigned int i = 0; i < 50; ++i)
        step(model, p, pull(p, 0., -back));
      // Then pull along the second direction.
      for (unsigned int i = 0; i < 300; ++i)
        step(model, p, pull(p, second, (tau / E) / 100.));
      const unsigned int expected = second > 60. ? 2 : 1;
      check_that("  pull at " + std::to_string(int(second)) +
                   " degrees to the first normal: " + std::to_string(expected) +
                   " crack(s)",
                 count(p) == expected);
      if (expected == 2)
        check("  |second normal . first normal|",
              std::abs(p.state[2] * p.state[4] + p.state[3] * p.state[5]),
              1e-6);
    }

  deallog << "5. Slip, effective separation" << std::endl;
  {
    auto slip_parameters = parameters();
    slip_parameters.mixed_mode =
      SmearedCracks<2>::MixedMode::effective_separation;
    const SmearedCracks<2> model(slip_parameters);
    MaterialPoint          p = make_point(model);
    // Start the crack normal to x, with the smallest opening.
    while (count(p) == 0)
      step(model, p, pull(p, 0., (tau / E) / 1000.));
    const double work_before = p.work;
    // Then shear: eps_xy grows, eps_xx held.
    SymmetricTensor<2, 2> d;
    d[0][1]           = (tau / E) / 50.;
    double shear_work = 0.;
    for (unsigned int i = 0; i < 40000; ++i)
      {
        const double s_old = p.stress[0][1];
        step(model, p, d);
        shear_work += (s_old + p.stress[0][1]) * d[0][1];
        if (i > 100 && std::abs(p.stress[0][1]) < 1e-12)
          break;
      }
    (void)work_before;
    (void)shear_work;
    check_that("  the shear stress has vanished",
               std::abs(p.stress[0][1]) < 1e-12);
    check("  |total work / (G_f / h) - 1|", p.work / (G_f / h) - 1., 2e-3);
  }

  deallog << "5b. Slip, opening as the damage driver" << std::endl;
  {
    MaterialPoint p = make_point(model);
    while (count(p) == 0)
      step(model, p, pull(p, 0., (tau / E) / 1000.));
    const double          history = p.state[2 + 2 * 4];
    SymmetricTensor<2, 2> d;
    d[0][1] = (tau / E) / 50.;
    for (unsigned int i = 0; i < 200; ++i)
      step(model, p, d);
    check("  |growth of the damage history| by slip alone / delta_0",
          (p.state[2 + 2 * 4] - history) / (2. * G_f / tau),
          1e-12);
    check_at_least("  shear stress carried (sigma_xy / tau_nf)",
                   p.stress[0][1] / tau,
                   1.);
  }

  deallog << "7. IMPL-EX, uniaxial strain along 30 degrees" << std::endl;
  {
    auto impl_ex_parameters = parameters();
    impl_ex_parameters.integration =
      SmearedCracks<2>::DamageIntegration::impl_ex;
    const SmearedCracks<2> model(impl_ex_parameters);
    MaterialPoint          p     = make_point(model);
    const double           theta = 30.;
    const double           L =
      h * (std::cos(theta * M_PI / 180.) + std::sin(theta * M_PI / 180.));
    const double e_peak    = 1.5 * tau / (E / (1. - nu * nu));
    const double e_end     = 1.2 * (2. * G_f / tau) / L;
    double       sigma_max = 0.;
    for (unsigned int i = 0; i < 4000; ++i)
      {
        step(model,
             p,
             pull(p,
                  theta,
                  i < 1000 ? e_peak / 1000. : (e_end - e_peak) / 3000.));
        sigma_max = std::max(sigma_max, p.stress * directions(theta).first);
      }
    check("  |peak sigma_nn / tau_nf - 1|", sigma_max / tau - 1., 5e-2);
    check("  |work / (G_f / L) - 1|", p.work / (G_f / L) - 1., 1e-2);
    check("  |dissipation / (G_f / L) - 1|",
          p.dissipated / (G_f / L) - 1.,
          1e-6);
    check("  |sigma| after failure / tau_nf", p.stress.norm(), 1e-9);
  }

  deallog << "8. Failed points" << std::endl;
  for (const auto failed : {SmearedCracks<2>::FailedPoints::no_tension,
                            SmearedCracks<2>::FailedPoints::keep_cracks})
    {
      auto failed_parameters   = parameters();
      failed_parameters.failed = failed;
      const SmearedCracks<2> model(failed_parameters);
      const bool             no_tension =
        failed == SmearedCracks<2>::FailedPoints::no_tension;
      deallog << (no_tension ? "  no tension" : "  keep cracks") << std::endl;
      MaterialPoint p     = make_point(model);
      const double  theta = 30.;
      const auto [nn, tt] = directions(theta);
      const double L =
        h * (std::cos(theta * M_PI / 180.) + std::sin(theta * M_PI / 180.));
      const double e_tt   = 0.5 * tau / E;
      const double e_peak = 1.5 * tau / (E / (1. - nu * nu));
      const double e_end  = 1.2 * (2. * G_f / tau) / L;
      // Pull until the step in which the crack fails completely (the
      // point's flag point_failed turns 1: the switch is due next step).
      const unsigned int failed_flag = model.n_state_components() - 1;
      for (unsigned int i = 0; i < 4000 && p.state[failed_flag] == 0.; ++i)
        step(model,
             p,
             pull(p,
                  theta,
                  i < 1000 ? e_peak / 1000. : (e_end - e_peak) / 3000.) +
               (i < 1000 ? e_tt / 1000. : 0.) * tt);
      if (no_tension)
        check_that("    the point is flagged failed",
                   p.state[failed_flag] == 1.);
      check("    |sigma - E eps_tt t (x) t| / tau_nf at failure",
            (p.stress - E * e_tt * tt).norm() / tau,
            1e-9);
      const double dissipated = p.dissipated;
      step(model, p, e_tt * tt);
      if (no_tension)
        {
          check("    |energy dissipated by the switch / (sigma_tt^2 / 2E) - "
                "1|",
                (p.dissipated - dissipated) / (0.5 * E * e_tt * e_tt) - 1.,
                1e-9);
          SymmetricTensor<2, 2> shear;
          shear[0][1] = 0.5 * tau / E;
          step(model, p, shear);
          check("    |sigma| / tau_nf after stretch along t and shear",
                p.stress.norm() / tau,
                1e-12);
          const SymmetricTensor<2, 2> squeeze =
            -(trace(p.strain) + 1e-3) / 2. * unit_symmetric_tensor<2>();
          step(model, p, squeeze);
          const double bulk = E / (2. * (1. - nu));
          check("    |sigma - K tr(eps) I| / |K tr(eps)| in compression",
                (p.stress - bulk * trace(p.strain) * unit_symmetric_tensor<2>())
                    .norm() /
                  (bulk * std::abs(trace(p.strain))),
                1e-12);
        }
      else
        check("    |sigma_tt / (E 2 eps_tt) - 1| after a stretch along t",
              (p.stress * tt) / (2. * E * e_tt) - 1.,
              1e-9);
    }

  deallog << "6. Bad entries" << std::endl;
  for (const auto &[entry, change] : std::vector<
         std::pair<std::string,
                   std::function<void(SmearedCracks<2>::Parameters &)>>>{
         {"Maximum cracks per point",
          [](SmearedCracks<2>::Parameters &p) { p.max_cracks = 3; }},
         {"Threshold angle",
          [](SmearedCracks<2>::Parameters &p) { p.threshold_angle = 0.; }}})
    {
      auto        p = parameters();
      std::string message;
      change(p);
      try
        {
          SmearedCracks<2> bad(p);
        }
      catch (const std::exception &exc)
        {
          message = Utils::error_message(exc);
        }
      check_that("  " + entry + ": stops naming the entry",
                 message.find(entry) != std::string::npos);
    }

  deallog << "9. Softening = bilinear" << std::endl;
  {
    auto p_bilinear      = parameters();
    p_bilinear.softening = SmearedCracks<2>::Softening::bilinear;
    const SmearedCracks<2> bilinear(p_bilinear);
    const double           w_1 = 0.8 * G_f / tau, w_c = 3.6 * G_f / tau;
    const auto             petersson = [&](const double w) {
      return w < w_1 ? tau * (1. - 2. / 3. * w / w_1) :
                                   std::max(0., tau / 3. * (w_c - w) / (w_c - w_1));
    };
    for (const double theta : {0., 30.})
      {
        MaterialPoint p      = make_point(bilinear);
        const auto [nn, tt]  = directions(theta);
        const double L       = h * (std::abs(std::cos(theta * M_PI / 180.)) +
                              std::abs(std::sin(theta * M_PI / 180.)));
        const double E_plane = E / (1. - nu * nu);
        const double e_peak  = 1.5 * tau / E_plane;
        const double e_end   = 1.2 * w_c / L;
        double       worst = 0., e = 0., sigma_max = 0.;
        for (unsigned int i = 0; i < 4000; ++i)
          {
            const double de =
              i < 1000 ? e_peak / 1000. : (e_end - e_peak) / 3000.;
            step(bilinear, p, pull(p, theta, de));
            e += de;
            const double sigma_nn = p.stress * nn;
            sigma_max             = std::max(sigma_max, sigma_nn);
            if (i >= 1000)
              worst =
                std::max(worst,
                         std::abs(sigma_nn -
                                  petersson(L * (e - sigma_nn / E_plane))));
          }
        const std::string at = "  theta = " + std::to_string(int(theta)) + ": ";
        check(at + "|peak sigma_nn - tau_nf|", sigma_max - tau, 2e-3);
        check(at + "max |sigma_nn - T_Petersson(w)| / tau_nf past the peak",
              worst / tau,
              1e-3);
        check(at + "|work / (G_f / L) - 1|", p.work / (G_f / L) - 1., 1e-3);
        check(at + "|dissipation / (G_f / L) - 1|",
              p.dissipated / (G_f / L) - 1.,
              1e-6);
      }
  }

  deallog << "10. Crack-parallel softening" << std::endl;
  {
    auto p_fade               = parameters();
    p_fade.parallel_softening = true;
    const SmearedCracks<2> fade(p_fade);
    const double           theta = 30.;
    const auto [nn, tt]          = directions(theta);
    const double L =
      h * (std::cos(theta * M_PI / 180.) + std::sin(theta * M_PI / 180.));
    const double E_plane = E / (1. - nu * nu);
    const double delta_0 = 2. * G_f / tau, delta_e = tau / (100. * E_plane / L);
    const double e_tt   = 0.5 * tau / E;
    const double e_peak = 1.5 * tau / E_plane;
    const double e_end  = 1.2 * delta_0 / L;
    // The committed history of the (first) crack in the state.
    const unsigned int history     = 2 + 2 * 2 * 2;
    const unsigned int failed_flag = fade.n_state_components() - 1;
    MaterialPoint      p = make_point(fade), q = make_point(model);
    double             worst_tt = 0., worst_nn = 0.;
    for (unsigned int i = 0; i < 4000 && p.state[failed_flag] == 0.; ++i)
      {
        const double delta_star = p.state[history];
        const bool   cracked    = count(p) > 0;
        const auto   d_eps =
          pull(p, theta, i < 1000 ? e_peak / 1000. : (e_end - e_peak) / 3000.) +
          (i < 1000 ? e_tt / 1000. : 0.) * tt;
        step(fade, p, d_eps);
        step(model, q, d_eps);
        if (!cracked)
          continue;
        const double T =
          delta_star <= delta_e ?
            tau :
            std::max(tau * (delta_0 - delta_star) / (delta_0 - delta_e), 0.);
        const double sigma_nn = p.stress * nn;
        const double unfaded  = E * (p.strain * tt) + nu * sigma_nn;
        worst_tt =
          std::max(worst_tt, std::abs(p.stress * tt - T / tau * unfaded));
        worst_nn = std::max(worst_nn, std::abs(sigma_nn - q.stress * nn));
      }
    check_that("  the point is flagged failed", p.state[failed_flag] == 1.);
    check("  max |sigma_tt - T(delta*) / tau_nf (E eps_tt + nu sigma_nn)| / "
          "tau_nf",
          worst_tt / tau,
          1e-9);
    check("  max |sigma_nn - sigma_nn without the entry| / tau_nf",
          worst_nn / tau,
          1e-9);
    check("  |sigma| / tau_nf at failure", p.stress.norm() / tau, 1e-3);
    const double dissipated = p.dissipated;
    step(fade, p, e_tt * tt);
    check("  energy released by the switch / (sigma_tt^2 / 2E) of 8",
          (p.dissipated - dissipated) / (0.5 * E * e_tt * e_tt),
          1e-6);
  }
}
