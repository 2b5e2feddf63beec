#include <array>
#include <cmath>
#include <limits>
#include <qsmpm/materials/modified_cam_clay.h>
#include <sstream>

namespace qsmpm
{
  namespace
  {
    /// The parameters, after their check (for the base's constructor).
    template <typename Parameters>
    const Parameters &
    checked(const Parameters &p)
    {
      p.check();
      return p;
    }

    /// Young's modulus and Poisson's ratio of the unstrained point (K =
    /// p0 / kappa, G): the base class's linear elasticity, which this model
    /// replaces by its own elastic law.
    template <typename Parameters>
    std::pair<double, double>
    initial_young_poisson(const Parameters &p)
    {
      const double K = p.initial_pressure / p.swelling_index;
      const double G = p.shear_modulus;
      return {9. * K * G / (3. * K + G),
              (3. * K - 2. * G) / (2. * (3. * K + G))};
    }

    /// Solve the 2 x 2 system a x = b.
    std::array<double, 2>
    solve_2x2(const double a11,
              const double a12,
              const double a21,
              const double a22,
              const double b1,
              const double b2)
    {
      const double det = a11 * a22 - a12 * a21;
      return {{(b1 * a22 - a12 * b2) / det, (a11 * b2 - a21 * b1) / det}};
    }
  } // namespace



  template <int dim>
  void
  ModifiedCamClay<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Shear modulus",
                      shear_modulus,
                      "G > 0: the constant elastic shear modulus (Pa, or any "
                      "consistent unit).",
                      Patterns::Double(0.));
    prm.add_parameter(
      "Swelling index",
      swelling_index,
      "kappa > 0: the slope of the swelling (unloading-reloading) line, "
      "-d(volumetric strain) / d ln p with the logarithmic volumetric "
      "strain (kappa / (1 + e0) of the (ln p, e) plot). The elastic bulk "
      "modulus is p / kappa.",
      Patterns::Double(0.));
    prm.add_parameter(
      "Compression index",
      compression_index,
      "lambda > kappa: the slope of the normal compression line in the "
      "same plot (lambda / (1 + e0) of the (ln p, e) plot).",
      Patterns::Double(0.));
    prm.add_parameter("Critical state slope",
                      critical_state_slope,
                      "M > 0: the slope q / p of the critical-state line (M "
                      "= 6 sin(phi) / (3 - sin(phi)) for the friction angle "
                      "phi in triaxial compression).",
                      Patterns::Double(0.));
    prm.add_parameter("Initial pressure",
                      initial_pressure,
                      "p0 > 0: the mean effective pressure of an unstrained "
                      "point; every point starts at the stress -p0 I, which "
                      "the boundary tractions must balance.",
                      Patterns::Double(0.));
    prm.add_parameter("Preconsolidation pressure",
                      preconsolidation_pressure,
                      "p_c0 >= p0: the initial size of the yield surface (p_c0 "
                      "= p0: normally consolidated; the overconsolidation "
                      "ratio is p_c0 / p0). With an 'Overconsolidation "
                      "ratio' only the reference of the hardening variable "
                      "(any p_c0 > 0).",
                      Patterns::Double(0.));
    prm.add_parameter(
      "Overconsolidation ratio",
      overconsolidation_ratio,
      "0 (the default): every point's yield surface starts at the "
      "'Preconsolidation pressure'. OCR >= 1: each point's starts through "
      "the stress the point starts from (Material points/Initial stress, "
      "or -p0 I without it), scaled by OCR: p_c = OCR (p + q^2 / (M^2 p)) "
      "(1: normally consolidated, the stress on the surface), e.g. for a "
      "layer whose stress grows with depth. The point's "
      "equivalent_plastic_strain then starts at (lambda - kappa) ln(p_c / "
      "Preconsolidation pressure), which may be negative.",
      Patterns::Double(0.));
  }



  template <int dim>
  void
  ModifiedCamClay<dim>::Parameters::check() const
  {
    const auto positive = [](const double x, const std::string &entry) {
      AssertThrow(x > 0 && std::isfinite(x),
                  ExcMessage("Modified Cam Clay: the '" + entry +
                             "' must be positive (is " + to_text(x) + ")."));
    };
    positive(shear_modulus, "Shear modulus");
    positive(swelling_index, "Swelling index");
    positive(critical_state_slope, "Critical state slope");
    positive(initial_pressure, "Initial pressure");
    AssertThrow(compression_index > swelling_index &&
                  std::isfinite(compression_index),
                ExcMessage("Modified Cam Clay: the 'Compression index' must "
                           "be larger than the 'Swelling index' (is " +
                           to_text(compression_index) +
                           ", the swelling index " + to_text(swelling_index) +
                           ")."));
    // With an overconsolidation ratio, p_c0 is only the reference of
    // alpha; the points' surfaces come from their own stresses.
    positive(preconsolidation_pressure, "Preconsolidation pressure");
    AssertThrow(overconsolidation_ratio > 0. ||
                  (preconsolidation_pressure >= initial_pressure &&
                   std::isfinite(preconsolidation_pressure)),
                ExcMessage("Modified Cam Clay: the 'Preconsolidation "
                           "pressure' must be at least the 'Initial pressure' "
                           "(is " +
                           to_text(preconsolidation_pressure) +
                           ", the initial pressure " +
                           to_text(initial_pressure) +
                           "): the unstrained point must lie inside the "
                           "yield surface."));
    AssertThrow(overconsolidation_ratio == 0. ||
                  (overconsolidation_ratio >= 1. &&
                   std::isfinite(overconsolidation_ratio)),
                ExcMessage("Modified Cam Clay: the 'Overconsolidation ratio' "
                           "must be 0 (off) or at least 1 (is " +
                           to_text(overconsolidation_ratio) + ")."));
  }



  template <int dim>
  ModifiedCamClay<dim>::ModifiedCamClay(const Parameters &parameters)
    : IsotropicPlasticity<dim>(initial_young_poisson(checked(parameters)).first,
                               initial_young_poisson(parameters).second)
    , param(parameters)
  {
  }



  template <int dim>
  ModifiedCamClay<dim>::ModifiedCamClay(ParameterHandler &prm)
    : ModifiedCamClay(Parameters::from(prm))
  {
  }



  template <int dim>
  void
  ModifiedCamClay<dim>::declare_parameters(ParameterHandler &prm)
  {
    Parameters::declare_parameters(prm);
  }



  template <int dim>
  const typename ModifiedCamClay<dim>::Parameters &
  ModifiedCamClay<dim>::parameters() const
  {
    return param;
  }



  template <int dim>
  double
  ModifiedCamClay<dim>::preconsolidation_pressure(const double alpha) const
  {
    return param.preconsolidation_pressure *
           std::exp(alpha / (param.compression_index - param.swelling_index));
  }



  template <int dim>
  SymmetricTensor<2, dim>
  ModifiedCamClay<dim>::initial_stress(const Point<dim>            &x,
                                       const unsigned int           material_id,
                                       const SymmetricTensor<2, 3> *sigma0,
                                       ArrayView<double>            state) const
  {
    const double ocr = param.overconsolidation_ratio;
    if (ocr > 0.)
      {
        const SymmetricTensor<2, 3> start =
          sigma0 != nullptr ?
            *sigma0 :
            -param.initial_pressure * unit_symmetric_tensor<3>();
        const double p = -trace(start) / 3.;
        if (!(p > 0.))
          {
            std::ostringstream message;
            message << "Material points: <Initial stress> at (" << x
                    << ") has the mean pressure " << p
                    << ": the model 'Modified Cam Clay' needs p > 0 "
                       "(compression) to start from it.";
            AssertThrow(false, ExcMessage(message.str()));
          }
        const double q_squared = 1.5 * deviator(start) * deviator(start);
        const double M         = param.critical_state_slope;
        const double pc        = ocr * (p + q_squared / (M * M * p));
        this->set_equivalent_plastic_strain(
          state,
          (param.compression_index - param.swelling_index) *
            std::log(pc / param.preconsolidation_pressure));
      }
    return IsotropicPlasticity<dim>::initial_stress(x,
                                                    material_id,
                                                    sigma0,
                                                    state);
  }



  template <int dim>
  SymmetricTensor<2, 3>
  ModifiedCamClay<dim>::elastic_stress(const SymmetricTensor<2, 3> &eps_e) const
  {
    const double p =
      param.initial_pressure * std::exp(-trace(eps_e) / param.swelling_index);
    return -p * unit_symmetric_tensor<3>() +
           2. * param.shear_modulus * deviator(eps_e);
  }



  template <int dim>
  SymmetricTensor<4, 3>
  ModifiedCamClay<dim>::elastic_tangent(
    const SymmetricTensor<2, 3> &eps_e) const
  {
    const double p =
      param.initial_pressure * std::exp(-trace(eps_e) / param.swelling_index);
    const SymmetricTensor<4, 3> one_one =
      outer_product(unit_symmetric_tensor<3>(), unit_symmetric_tensor<3>());
    return p / param.swelling_index * one_one +
           2. * param.shear_modulus * (identity_tensor<3>() - one_one / 3.);
  }



  template <int dim>
  SymmetricTensor<2, 3>
  ModifiedCamClay<dim>::elastic_strain_of(
    const SymmetricTensor<2, 3> &stress) const
  {
    const double p = -trace(stress) / 3.;
    if (!(p > 0))
      {
        std::ostringstream message;
        message << "Modified Cam Clay: the stress (" << stress
                << ") has no positive mean pressure, and no elastic strain "
                   "gives it (an <Initial stress> of Material points must "
                   "be compressive).";
        AssertThrow(false, ExcMessage(message.str()));
      }
    const double v_e =
      param.swelling_index * std::log(p / param.initial_pressure);
    return -v_e / 3. * unit_symmetric_tensor<3>() +
           deviator(stress) / (2. * param.shear_modulus);
  }



  template <int dim>
  void
  ModifiedCamClay<dim>::return_map(
    const SymmetricTensor<2, 3> &trial_elastic_strain,
    const double                 alpha_old,
    const bool                   want_tangent,
    Return                      &r) const
  {
    const double kappa = param.swelling_index;
    const double theta = param.compression_index - kappa;
    const double G     = param.shear_modulus;
    const double M2 = param.critical_state_slope * param.critical_state_slope;
    const double p0 = param.initial_pressure;
    const SymmetricTensor<2, 3> I = unit_symmetric_tensor<3>();

    const double                v_tr   = -trace(trial_elastic_strain);
    const SymmetricTensor<2, 3> e_tr   = deviator(trial_elastic_strain);
    const double                e_norm = e_tr.norm();
    const double                q_tr   = std::sqrt(6.) * G * e_norm;
    const double                p_tr   = p0 * std::exp(v_tr / kappa);
    const double                pc_old = preconsolidation_pressure(alpha_old);
    const double f_tr = q_tr * q_tr / M2 + p_tr * (p_tr - pc_old);

    const auto failed = [&]() {
      // Not a state the model can return (an overflowing pressure, or no
      // convergence): NaN, which Newton's line search treats as a failed
      // trial; the state stays the committed one.
      r.stress         = std::numeric_limits<double>::quiet_NaN() * I;
      r.elastic_strain = trial_elastic_strain;
      r.alpha          = alpha_old;
      r.increment      = 0.;
      if (want_tangent)
        r.tangent =
          std::numeric_limits<double>::quiet_NaN() * identity_tensor<3>();
    };
    if (!std::isfinite(f_tr) || !std::isfinite(e_norm))
      return failed();

    if (f_tr <= 1e-13 * pc_old * pc_old)
      {
        r.stress         = -p_tr * I + 2. * G * e_tr;
        r.elastic_strain = trial_elastic_strain;
        r.alpha          = alpha_old;
        r.increment      = 0.;
        if (want_tangent)
          r.tangent = elastic_tangent(trial_elastic_strain);
        return;
      }

    // Newton's method in x = ln(p / p0) and d gamma, from the trial state.
    struct Residual
    {
      double p, pc, rho, q, da, r1, r2;
    };
    const auto residual = [&](const double x, const double g) {
      Residual s;
      s.p   = p0 * std::exp(x);
      s.da  = v_tr - kappa * x;
      s.pc  = pc_old * std::exp(s.da / theta);
      s.rho = 1. / (1. + 6. * G * g / M2);
      s.q   = q_tr * s.rho;
      s.r1  = s.da - g * (2. * s.p - s.pc);
      s.r2  = s.q * s.q / M2 + s.p * (s.p - s.pc);
      return s;
    };
    const auto size = [&](const Residual &s) {
      return std::abs(s.r1) / kappa + std::abs(s.r2) / (pc_old * pc_old);
    };

    double   x = v_tr / kappa, g = 0.;
    Residual s = residual(x, g);
    // The 2 x 2 Jacobian of (r1, r2) in (x, g) at the state s.
    double     a11, a12, a21, a22;
    const auto jacobian = [&](const Residual &s, const double g) {
      a11 = -kappa - g * (2. * s.p + s.pc * kappa / theta);
      a12 = -(2. * s.p - s.pc);
      a21 = 2. * s.p * s.p - s.p * s.pc * (1. - kappa / theta);
      a22 = -2. * s.q / M2 * (6. * G / M2) * q_tr * s.rho * s.rho;
    };
    bool converged = false;
    for (unsigned int it = 0; it < 60 && !converged; ++it)
      {
        jacobian(s, g);
        const auto d = solve_2x2(a11, a12, a21, a22, -s.r1, -s.r2);
        if (!std::isfinite(d[0]) || !std::isfinite(d[1]))
          break;
        // Backtracking: halve the step until the scaled residual falls
        // (at most 30 times; a step at round-off that does not reduce it
        // ends the iteration).
        const double old_size = size(s);
        double       step     = 1.;
        Residual     trial;
        bool         reduced = false;
        for (unsigned int b = 0; b < 30; ++b, step *= 0.5)
          {
            trial = residual(x + step * d[0], g + step * d[1]);
            if (std::isfinite(trial.r1) && std::isfinite(trial.r2) &&
                size(trial) < old_size)
              {
                reduced = true;
                break;
              }
          }
        if (!reduced)
          {
            converged = old_size < 1e-11;
            break;
          }
        x += step * d[0];
        g += step * d[1];
        s = trial;
        converged =
          size(s) < 1e-14 ||
          (std::abs(d[0]) < 1e-15 * (1. + std::abs(x)) && size(s) < 1e-11);
      }
    if (!converged || !(g >= 0.))
      return failed();

    r.stress         = -s.p * I + s.rho * 2. * G * e_tr;
    r.elastic_strain = -kappa * x / 3. * I + s.rho * e_tr;
    r.alpha          = alpha_old + s.da;
    r.increment      = s.da;
    if (!want_tangent)
      return;

    // The algorithmic tangent: the implicit derivative of (x, g) in the
    // trial invariants v_tr and q_tr, with d v_tr = -1 : d eps and d q_tr =
    // sqrt(6) G n : d eps, n = e_tr / |e_tr|.
    jacobian(s, g);
    const auto dv = solve_2x2(
      a11, a12, a21, a22, -(1. + g * s.pc / theta), s.p * s.pc / theta);
    const auto dq = solve_2x2(a11, a12, a21, a22, 0., -2. * s.q / M2 * s.rho);
    const SymmetricTensor<2, 3> dq_tr =
      e_norm > 0 ? SymmetricTensor<2, 3>(std::sqrt(6.) * G / e_norm * e_tr) :
                   SymmetricTensor<2, 3>();
    const SymmetricTensor<2, 3> dx_deps = -dv[0] * I + dq[0] * dq_tr;
    const SymmetricTensor<2, 3> dg_deps = -dv[1] * I + dq[1] * dq_tr;
    const SymmetricTensor<2, 3> drho_deps =
      -s.rho * s.rho * 6. * G / M2 * dg_deps;
    r.tangent =
      -s.p * outer_product(I, dx_deps) +
      2. * G * s.rho * (identity_tensor<3>() - outer_product(I, I) / 3.) +
      2. * G * outer_product(e_tr, drho_deps);
  }



  template <int dim>
  SymmetricTensor<4, 3>
  ModifiedCamClay<dim>::continuum_tangent(const SymmetricTensor<2, 3> &stress,
                                          const double alpha) const
  {
    const double p  = -trace(stress) / 3.;
    const double pc = preconsolidation_pressure(alpha);
    const double M2 = param.critical_state_slope * param.critical_state_slope;
    const SymmetricTensor<2, 3> n =
      -(2. * p - pc) / 3. * unit_symmetric_tensor<3>() +
      3. / M2 * deviator(stress);
    const SymmetricTensor<2, 3> eps = elastic_strain_of(stress);
    Return                      r;
    return_map(eps + 1e-7 * (eps.norm() + param.swelling_index) * n / n.norm(),
               alpha,
               true,
               r);
    return r.tangent;
  }



  template <int dim>
  double
  ModifiedCamClay<dim>::yield_function(const SymmetricTensor<2, 3> &stress,
                                       const double                 alpha) const
  {
    const double p  = -trace(stress) / 3.;
    const double q  = std::sqrt(1.5) * deviator(stress).norm();
    const double M2 = param.critical_state_slope * param.critical_state_slope;
    return q * q / M2 + p * (p - preconsolidation_pressure(alpha));
  }



  template class ModifiedCamClay<2>;
  template class ModifiedCamClay<3>;

  QSMPM_REGISTER_CONSTITUTIVE_MODEL(
    ModifiedCamClay,
    "Modified Cam Clay",
    "Modified Cam Clay: the critical-state clay model (elliptic yield "
    "surface, associative flow, hardening with the plastic compaction) "
    "with a pressure-dependent hyperelastic bulk modulus p / kappa and a "
    "constant shear modulus, starting from an isotropic pressure; plane "
    "strain in 2D; finite strain by the exponential map of "
    "IsotropicPlasticity.")
} // namespace qsmpm
