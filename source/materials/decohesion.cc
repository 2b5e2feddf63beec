#include <algorithm>
#include <cmath>
#include <deal.II/base/function_parser.h>
#include <memory>
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

    /// The cracking region from a parsed expression (true where > 0.5).
    template <int dim>
    std::function<bool(const Point<dim> &)>
    parse_region(const std::string &expression)
    {
      auto parser = std::make_shared<FunctionParser<dim>>(1);
      parser->initialize(dim == 2 ? "x,y" : "x,y,z",
                         expression,
                         std::map<std::string, double>());
      return [parser](const Point<dim> &x) { return parser->value(x) > 0.5; };
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

    // Offsets of the state fields, by name: the order is defined once, in
    // state_fields().
    unsigned int offset = 0;
    for (const auto &field : state_fields())
      {
        if (field.name == crack_allowed_name)
          allowed_offset = offset;
        else if (field.name == crack_normal_name)
          normal_offset = offset;
        else if (field.name == crack_opening_name)
          opening_offset = offset;
        else if (field.name == opening_ratio_name)
          opening_ratio_offset = offset;
        else if (field.name == sigma_xx_ratio_name)
          sigma_xx_offset = offset;
        else if (field.name == sigma_yy_ratio_name)
          sigma_yy_offset = offset;
        offset += field.n_components;
      }
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
    crack_region = parse_region<dim>(parameters.cracking_region);
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
    return {{crack_allowed_name, 1},
            {crack_normal_name, dim},
            {crack_opening_name, 1},
            {opening_ratio_name, 1},
            {sigma_xx_ratio_name, 1},
            {sigma_yy_ratio_name, 1}};
  }



  template <int dim>
  void
  Decohesion<dim>::initialize_state(const Point<dim> &x,
                                    ArrayView<double> state) const
  {
    std::fill(state.begin(), state.end(), 0.);
    state[allowed_offset] = crack_region(x) ? 1. : 0.;
  }



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
            // A completely failed crack that opens is traction free: also
            // the shear traction t_s = sigma.n - tau_n n is released, by a
            // tangential jump du_s = L_c t_s / mu (for isotropic C,
            // C:sym(du_s (x) n).n = mu du_s when du_s is normal to n, which
            // leaves tau_n = 0 unchanged).
            if (w >= u0)
              {
                const Tensor<1, dim> t    = stress * n;
                const Tensor<1, dim> slip = t - (t * n) * n;
                stress -= (C * symmetrize(outer_product(slip, n))) / mu;
              }
          }
      }

    new_state[opening_offset]       = w;
    new_state[opening_ratio_offset] = w / u0;
    new_state[sigma_xx_offset]      = stress[0][0] / tau_nf;
    new_state[sigma_yy_offset]      = stress[1][1] / tau_nf;
  }



  template <int dim>
  SymmetricTensor<4, dim>
  Decohesion<dim>::tangent(const PointState<dim> &old) const
  {
    const double w = old.state[opening_offset];
    if (w <= 0.)
      return C;
    Tensor<1, dim> n;
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = old.state[normal_offset + d];
    const SymmetricTensor<2, dim> Cnn = C * symmetrize(outer_product(n, n));
    if (w >= u0)
      return C - outer_product(Cnn, Cnn) / M;
    // A softening crack: the secant normal stiffness k of the crack band,
    // the traction of the softening line tau_n = tau_nf (1 - w/u0) over the
    // normal strain tau_n / M + w / L_c that carries it (elastic part and
    // smeared opening), k / M = tau_n / (tau_n + M w / L_c). It falls from
    // M at initiation to 0 at complete failure, where it meets the tangent
    // above, and unlike the consistent tangent (negative across a loading
    // crack) it keeps the matrix positive definite for AMG.
    const double tau_n    = tau_nf * (1. - w / u0);
    const double k_over_M = tau_n / (tau_n + M * w / smearing_length(n));
    return C - (1. - k_over_M) * outer_product(Cnn, Cnn) / M;
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
    return (work(w_new) - work(w_old)) / smearing_length(n);
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
