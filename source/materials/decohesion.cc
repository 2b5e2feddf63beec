#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <qsmpm/base/parsed_region.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/materials/decohesion.h>
#include <qsmpm/materials/linear_elastic.h>
#include <sstream>

namespace qsmpm
{
  namespace
  {
    /// "principal" -> zero tensor; "1,0" -> the unit vector along it.
    template <int dim>
    Tensor<1, dim>
    parse_normal(const std::string &text)
    {
      if (text == "principal")
        return Tensor<1, dim>();
      const Point<dim> p =
        Utils::parse_point<dim>(text, "decohesion/Crack normal");
      AssertThrow(p.norm() > 0,
                  ExcMessage("decohesion: 'Crack normal' must be "
                             "'principal' or a non-zero direction."));
      return Tensor<1, dim>(p / p.norm());
    }

  } // namespace



  template <int dim>
  Decohesion<dim>::Decohesion(const double          young_modulus,
                              const double          poisson_ratio,
                              const bool            plane_stress,
                              const double          tensile_strength,
                              const double          fracture_energy,
                              const Tensor<1, dim> &fixed_normal,
                              const double          band_width)
    : C(LinearElastic<dim>::isotropic_stiffness(young_modulus,
                                                poisson_ratio,
                                                plane_stress))
    , tau_nf(tensile_strength)
    , G_f(fracture_energy)
    , u0(2. * fracture_energy / tensile_strength)
    , fixed_normal(fixed_normal.norm() > 0 ?
                     fixed_normal / fixed_normal.norm() :
                     fixed_normal)
    , band_width(band_width)
    , M(C[0][0][0][0])
    , mu(C[0][1][0][1])
    , crack_region([](const Point<dim> &) { return true; })
  {
    AssertThrow(tensile_strength > 0,
                ExcMessage("decohesion: the tensile strength tau_nf must be "
                           "positive."));
    AssertThrow(fracture_energy > 0,
                ExcMessage("decohesion: the fracture energy G_f must be "
                           "positive."));
    AssertThrow(band_width > 0,
                ExcMessage("decohesion: set 'Crack band width' to the cell "
                           "size h of the background grid (the width of the "
                           "band of cells that cracks); it must be positive."));
    if (!(band_width < stability_limit()))
      {
        std::ostringstream message;
        message << "decohesion: the softening branch is locally unstable: "
                << "the smearing length L_c = " << band_width
                << " must be smaller than M u0 / tau_nf = " << stability_limit()
                << " (M = n.C:(n(x)n).n = " << M
                << ", u0 = 2 G_f / tau_nf = " << u0
                << "). Refine the grid (smaller h) or check E, tau_nf, G_f.";
        AssertThrow(false, ExcMessage(message.str()));
      }

    compute_offsets();
  }



  template <int dim>
  void
  Decohesion<dim>::compute_offsets()
  {
    // Offsets of the state fields, by name: the order is defined once, in
    // state_fields().
    unsigned int offset = 0;
    slip_offset         = numbers::invalid_unsigned_int;
    for (const auto &field : state_fields())
      {
        if (field.name == crack_allowed_name)
          allowed_offset = offset;
        else if (field.name == crack_normal_name)
          normal_offset = offset;
        else if (field.name == crack_opening_name)
          opening_offset = offset;
        else if (field.name == crack_slip_name)
          slip_offset = offset;
        offset += field.n_components;
      }
  }



  template <int dim>
  void
  Decohesion<dim>::set_shear_retention(const ShearRetention retention)
  {
    shear_retention = retention;
    compute_offsets();
  }



  template <int dim>
  Decohesion<dim>::Decohesion(const Parameters &parameters)
    : Decohesion(parameters.elastic.elasticity.young_modulus,
                 parameters.elastic.elasticity.poisson_ratio,
                 parameters.elastic.plane_stress,
                 parameters.tensile_strength,
                 parameters.fracture_energy,
                 parse_normal<dim>(parameters.crack_normal),
                 parameters.crack_band_width)
  {
    crack_region = parse_region<dim>(parameters.cracking_region,
                                     "decohesion: <Cracking region>",
                                     "where cracks may start",
                                     RegionTest::above_one_half);
    set_shear_retention(parameters.shear_retention);
  }



  template <int dim>
  Decohesion<dim>::Decohesion(ParameterHandler &prm)
    : Decohesion(Parameters::from(prm))
  {
  }



  template <int dim>
  void
  Decohesion<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    elastic.add_parameters(prm);
    prm.add_parameter("Tensile strength",
                      tensile_strength,
                      "tau_nf: the normal traction at which a crack starts "
                      "(Rankine criterion, paper eq. 3.1).",
                      Patterns::Double(0.));
    prm.add_parameter("Fracture energy",
                      fracture_energy,
                      "G_f: energy dissipated per unit crack area (J/m^2); "
                      "the area under the linear softening law, so that the "
                      "opening at complete failure is u0 = 2 G_f / tau_nf.",
                      Patterns::Double(0.));
    prm.add_parameter("Crack normal",
                      crack_normal,
                      "'principal': the direction of the largest principal "
                      "stress when the crack starts; or a fixed direction, "
                      "'1,0' (2D) or '1,0,0' (3D) for a crack normal to x as "
                      "in the paper.",
                      Patterns::Anything());
    prm.add_parameter("Crack band width",
                      crack_band_width,
                      "h_band: the cell size of the background grid, i.e. the "
                      "width of the band of cells that cracks. The smearing "
                      "length is L_c = h_band max_i |n_i| (h for a crack "
                      "parallel to a cell edge), for any number of points per "
                      "cell. Must be positive and below M u0 / tau_nf (local "
                      "stability).",
                      Patterns::Double(0.));
    Utils::add_selection<ShearRetention>(
      prm,
      "Shear retention",
      shear_retention,
      {{"abrupt", ShearRetention::abrupt}, {"linear", ShearRetention::linear}},
      "abrupt: the crack carries shear tractions elastically until complete "
      "failure and releases them at once (the paper's runs). linear: the "
      "band's secant shear stiffness falls with the opening, t_s = (1 - "
      "[[u_n]]/u0) mu gamma_s (a shear retention factor), so that the "
      "traction vanishes continuously at complete failure; the stress "
      "update has no jump there, which path following through complete "
      "failure needs. A completely failed crack then also closes without "
      "traction down to the opening u0 (contact); with abrupt retention a "
      "crack that unloads keeps its opening.");
    prm.add_parameter("Cracking region",
                      cracking_region,
                      "An expression in x, y (and z): points created where it "
                      "is > 0.5 may crack, the others stay elastic. E.g. "
                      "'abs(x) < 0.005' for a band of width 1 cm around x = 0.",
                      Patterns::Anything());
  }



  template <int dim>
  void
  Decohesion<dim>::declare_parameters(ParameterHandler &prm)
  {
    Parameters::declare_parameters(prm);
  }



  template <int dim>
  void
  Decohesion<dim>::set_crack_region(
    const std::function<bool(const Point<dim> &)> &region)
  {
    crack_region = region;
  }



  template <int dim>
  std::vector<StateField>
  Decohesion<dim>::state_fields() const
  {
    std::vector<StateField> fields = {{crack_allowed_name, 1},
                                      {crack_normal_name, dim},
                                      {crack_opening_name, 1}};
    if (shear_retention == ShearRetention::linear)
      fields.push_back({crack_slip_name, dim});
    return fields;
  }



  template <int dim>
  std::vector<StateField>
  Decohesion<dim>::output_fields() const
  {
    return {{opening_ratio_name, 1},
            {sigma_xx_ratio_name, 1},
            {sigma_yy_ratio_name, 1}};
  }



  template <int dim>
  void
  Decohesion<dim>::compute_output_fields(const PointState<dim> &point,
                                         ArrayView<double>      values) const
  {
    values[0] = point.state[opening_offset] / u0;
    values[1] = point.stress[0][0] / tau_nf;
    values[2] = point.stress[1][1] / tau_nf;
  }



  template <int dim>
  void
  Decohesion<dim>::initialize_state(const Point<dim> &x,
                                    ArrayView<double> state) const
  {
    std::fill(state.begin(), state.end(), 0.);
    state[allowed_offset] = crack_region(x) ? 1. : 0.;
  }



  namespace
  {
    /// dim - 1 unit vectors orthogonal to the unit vector @p n and to each
    /// other.
    template <int dim>
    std::array<Tensor<1, dim>, dim - 1>
    tangents(const Tensor<1, dim> &n)
    {
      if constexpr (dim == 2)
        return {{Tensor<1, 2>({-n[1], n[0]})}};
      else
        {
          // Start from the axis least aligned with n.
          unsigned int axis = 0;
          for (unsigned int d = 1; d < dim; ++d)
            if (std::abs(n[d]) < std::abs(n[axis]))
              axis = d;
          Tensor<1, dim> e;
          e[axis]          = 1.;
          Tensor<1, dim> t = e - (e * n) * n;
          t /= t.norm();
          return {{t, cross_product_3d(n, t)}};
        }
    }
  } // namespace



  template <int dim>
  Tensor<1, dim>
  Decohesion<dim>::initiation_normal(
    const SymmetricTensor<2, dim> &sigma_trial) const
  {
    if (fixed_normal.norm() > 0)
      return (fixed_normal * sigma_trial * fixed_normal >= tau_nf) ?
               fixed_normal :
               Tensor<1, dim>();
    // Rankine: F_n(sigma.n, 0) is largest on the plane of the largest
    // principal stress. Eigenvalues are cheap; eigenvectors only when needed.
    if (eigenvalues(sigma_trial)[0] < tau_nf)
      return Tensor<1, dim>();
    return eigenvectors(sigma_trial)[0].second;
  }



  template <int dim>
  void
  Decohesion<dim>::update_stress(
    const PointState<dim>         &old,
    const SymmetricTensor<2, dim> &strain_increment,
    SymmetricTensor<2, dim>       &stress,
    ArrayView<double>              new_state) const
  {
    std::copy(old.state.begin(), old.state.end(), new_state.begin());
    // Elastic trial stress at the committed opening.
    stress = old.stress + C * strain_increment;

    Tensor<1, dim> n;
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = old.state[normal_offset + d];
    if (n.norm_square() == 0. && old.state[allowed_offset] > 0.)
      {
        n = initiation_normal(stress);
        for (unsigned int d = 0; d < dim; ++d)
          new_state[normal_offset + d] = n[d];
      }

    double w = old.state[opening_offset];
    if (n.norm_square() > 0.)
      {
        const double L_c       = smearing_length(n);
        const double tau_trial = n * stress * n;
        // Residual of the consistency condition at opening increment 0.
        const double excess = tau_trial - tau_nf * std::max(0., 1. - w / u0);
        if (excess > 0.)
          {
            // Softening branch: tau_tr - (M/L_c) dw = tau_nf (1 - (w+dw)/u0).
            double dw = excess / (M / L_c - tau_nf / u0);
            // Beyond complete failure the limit is tau_n = 0.
            if (w + dw > u0)
              dw = std::max(tau_trial * L_c / M, u0 - w);
            w += dw;
            const SymmetricTensor<2, dim> nn = symmetrize(outer_product(n, n));
            stress -= (dw / L_c) * (C * nn);
          }
        // With linear retention, a completely failed crack that closes does
        // so without traction: its opening falls back, down to u0 (below
        // that, the crack is in contact and closes elastically at constant
        // opening, as any crack that unloads). Otherwise the slightest
        // closing of a broken band meets the full normal stiffness M at
        // once, at whatever opening it had reached: a strut across an open
        // crack, which in the far tail of a fracture test carries load that
        // no crack could. The paper's model (abrupt) keeps the opening of
        // a crack that unloads; with its sudden shear release, a free
        // closing makes Newton alternate between the two states.
        else if (shear_retention == ShearRetention::linear && w > u0 &&
                 tau_trial < 0.)
          {
            // (w = u0 exactly in contact.)
            const double w_new = std::max(w + tau_trial * L_c / M, u0);
            stress -=
              ((w_new - w) / L_c) * (C * symmetrize(outer_product(n, n)));
            w = w_new;
          }
        // A completely failed crack that opens is traction free: with
        // abrupt retention also the shear traction t_s = sigma.n - tau_n n
        // is released, by a tangential jump du_s = L_c t_s / mu (for
        // isotropic C, C:sym(du_s (x) n).n = mu du_s when du_s is normal to
        // n, which leaves tau_n = 0 unchanged).
        if (shear_retention == ShearRetention::abrupt && excess > 0. && w >= u0)
          {
            const Tensor<1, dim> t    = stress * n;
            const Tensor<1, dim> slip = t - (t * n) * n;
            stress -= (C * symmetrize(outer_product(slip, n))) / mu;
          }
        // Linear shear retention: with the band's shear strain gamma_s since
        // initiation, mu gamma_s = t_tr + (mu / L_c) s_old (the trial shear
        // traction plus what the committed slip s_old released), the
        // traction is beta mu gamma_s, i.e. the slip is
        // s = L_c (1 - beta) gamma_s. The normal correction above leaves the
        // shear traction alone (isotropic C), and a slip normal to n leaves
        // tau_n alone, so the two updates are independent.
        if (shear_retention == ShearRetention::linear)
          {
            const double         L_c  = smearing_length(n);
            const double         beta = std::max(0., 1. - w / u0);
            const Tensor<1, dim> t    = stress * n;
            Tensor<1, dim>       s_old;
            for (unsigned int d = 0; d < dim; ++d)
              s_old[d] = old.state[slip_offset + d];
            const Tensor<1, dim> mu_gamma =
              t - (t * n) * n + (mu / L_c) * s_old;
            const Tensor<1, dim> s_new = (L_c / mu) * (1. - beta) * mu_gamma;
            stress -= (C * symmetrize(outer_product(s_new - s_old, n))) / L_c;
            for (unsigned int d = 0; d < dim; ++d)
              new_state[slip_offset + d] = s_new[d];
          }
      }

    new_state[opening_offset] = w;
  }



  template <int dim>
  SymmetricTensor<4, dim>
  Decohesion<dim>::tangent(const PointState<dim> &old) const
  {
    return crack_tangent(old, false);
  }



  template <int dim>
  SymmetricTensor<4, dim>
  Decohesion<dim>::loading_tangent(const PointState<dim> &old) const
  {
    return crack_tangent(old, true);
  }



  template <int dim>
  SymmetricTensor<4, dim>
  Decohesion<dim>::crack_tangent(const PointState<dim> &old,
                                 const bool             loading) const
  {
    const double w = old.state[opening_offset];
    if (w <= 0.)
      return C;
    Tensor<1, dim> n;
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = old.state[normal_offset + d];
    const SymmetricTensor<2, dim> Cnn = C * symmetrize(outer_product(n, n));
    // Linear shear retention: the secant shear stiffness beta mu on the
    // crack plane, C : S = 2 beta mu S for S = sym(t (x) n), t a unit
    // tangent (S : S = 1/2).
    SymmetricTensor<4, dim> shear_loss;
    if (shear_retention == ShearRetention::linear)
      {
        const double beta = std::max(0., 1. - w / u0);
        for (const Tensor<1, dim> &t : tangents(n))
          {
            const SymmetricTensor<2, dim> S = symmetrize(outer_product(t, n));
            shear_loss += (1. - beta) * 4. * mu * outer_product(S, S);
          }
      }
    if (w >= u0)
      return C - outer_product(Cnn, Cnn) / M - shear_loss;
    // A softening crack: the secant normal stiffness k of the crack band,
    // the traction of the softening line tau_n = tau_nf (1 - w/u0) over the
    // normal strain tau_n / M + w / L_c that carries it (elastic part and
    // smeared opening), k / M = tau_n / (tau_n + M w / L_c). It falls from
    // M at initiation to 0 at complete failure, where it meets the tangent
    // above, and unlike the slope of the softening line it keeps the matrix
    // positive definite for AMG.
    //
    // With @p loading, a crack whose committed normal stress is on the
    // softening line (it opened in the last step) keeps opening: d tau_n =
    // -(tau_nf / u0) d w and d tau_n = M (d eps_n - d w / L_c) give the
    // normal stiffness k / M = -a / (M - a), a = L_c tau_nf / u0, negative,
    // and finite since L_c < M u0 / tau_nf (local stability). A crack below
    // the line has unloaded and keeps the secant.
    const double L_c   = smearing_length(n);
    const double a     = L_c * tau_nf / u0;
    const double tau_n = tau_nf * (1. - w / u0);
    const bool   opening =
      loading && a < M && n * (old.stress * n) >= tau_n - 1e-6 * tau_nf;
    const double k_over_M =
      opening ? -a / (M - a) : tau_n / (tau_n + M * w / L_c);
    return C - (1. - k_over_M) * outer_product(Cnn, Cnn) / M - shear_loss;
  }



  template <int dim>
  double
  Decohesion<dim>::critical_opening() const
  {
    return u0;
  }



  template <int dim>
  double
  Decohesion<dim>::tensile_strength() const
  {
    return tau_nf;
  }



  template <int dim>
  double
  Decohesion<dim>::smearing_length(const Tensor<1, dim> &n) const
  {
    double largest = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      largest = std::max(largest, std::abs(n[d]));
    return band_width * largest;
  }



  template <int dim>
  double
  Decohesion<dim>::stability_limit() const
  {
    return M * u0 / tau_nf;
  }



  template <int dim>
  const SymmetricTensor<4, dim> &
  Decohesion<dim>::stiffness() const
  {
    return C;
  }



  template <int dim>
  double
  Decohesion<dim>::dissipation(const PointState<dim>  &old,
                               ArrayView<const double> new_state) const
  {
    const double w_old = old.state[opening_offset],
                 w_new = new_state[opening_offset];
    if (!(w_new > w_old))
      return 0.;
    Tensor<1, dim> n;
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = new_state[normal_offset + d];
    // The area under the softening law up to w (beyond u0 nothing more).
    const auto work = [this](const double w) {
      const double v = std::min(w, u0);
      return tau_nf * (v - 0.5 * v * v / u0);
    };
    const double L_c    = smearing_length(n);
    double       result = (work(w_new) - work(w_old)) / L_c;
    // Linear shear retention: the secant shear stiffness falls from
    // beta_old mu to beta_new mu at the shear strain gamma_s, which releases
    // (beta_old - beta_new) mu |gamma_s|^2 / 2; gamma_s from the new slip,
    // s = L_c (1 - beta) gamma_s.
    if (shear_retention == ShearRetention::linear)
      {
        const double beta_old = std::max(0., 1. - w_old / u0),
                     beta_new = std::max(0., 1. - w_new / u0);
        if (beta_new < 1.)
          {
            double slip_squared = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              slip_squared +=
                new_state[slip_offset + d] * new_state[slip_offset + d];
            const double L = L_c * (1. - beta_new);
            result += 0.5 * (beta_old - beta_new) * mu * slip_squared / (L * L);
          }
      }
    return result;
  }



  template class Decohesion<2>;
  template class Decohesion<3>;

  QSMPM_REGISTER_CONSTITUTIVE_MODEL(
    Decohesion,
    "decohesion",
    "Schreyer's elastic-decohesive smeared-crack model, mode I, linear "
    "softening (paper eqs. 3.1-3.2): E, nu, tau_nf, G_f, crack normal, crack "
    "band width, cracking region.")
} // namespace qsmpm
