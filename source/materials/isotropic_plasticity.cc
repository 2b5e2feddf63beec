#include <cmath>
#include <limits>
#include <qsmpm/base/tensor_functions.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/materials/isotropic_plasticity.h>
#include <qsmpm/materials/linear_elastic.h>
#include <sstream>

namespace qsmpm
{
  std::string
  to_text(const double x)
  {
    std::ostringstream s;
    s << x;
    return s.str();
  }



  void
  add_cohesion_friction_parameters(ParameterHandler &prm,
                                   double           &cohesion,
                                   double           &friction_angle,
                                   double           &dilatancy_angle,
                                   double           &hardening_modulus)
  {
    prm.add_parameter("Cohesion",
                      cohesion,
                      "c0 >= 0: the Mohr-Coulomb cohesion (same unit as "
                      "Young's modulus).",
                      Patterns::Double(0.));
    prm.add_parameter("Friction angle",
                      friction_angle,
                      "phi in [0, 90): the friction angle in degrees.",
                      Patterns::Double(0., 90.));
    prm.add_parameter("Dilatancy angle",
                      dilatancy_angle,
                      "psi in [0, phi]: the dilatancy angle in degrees "
                      "(psi = phi: associative flow).",
                      Patterns::Double(0., 90.));
    prm.add_parameter("Hardening modulus",
                      hardening_modulus,
                      "H >= 0: linear hardening of the cohesion, c = c0 + H "
                      "alpha (0: perfect plasticity).",
                      Patterns::Double(0.));
  }



  void
  check_cohesion_friction(const std::string &model,
                          const double       c0,
                          const double       friction_angle_deg,
                          const double       dilatancy_angle_deg,
                          const double       H)
  {
    AssertThrow(c0 >= 0 && std::isfinite(c0),
                ExcMessage(model +
                           ": the 'Cohesion' must be non-negative (is " +
                           to_text(c0) + ")."));
    AssertThrow(friction_angle_deg >= 0 && friction_angle_deg < 90,
                ExcMessage(model +
                           ": the 'Friction angle' must lie in [0, 90) "
                           "degrees (is " +
                           to_text(friction_angle_deg) + ")."));
    AssertThrow(dilatancy_angle_deg >= 0 &&
                  dilatancy_angle_deg <= friction_angle_deg,
                ExcMessage(model +
                           ": the 'Dilatancy angle' must lie in [0, "
                           "'Friction angle'] (is " +
                           to_text(dilatancy_angle_deg) +
                           " degrees, the friction angle " +
                           to_text(friction_angle_deg) + ")."));
    AssertThrow(H >= 0 && std::isfinite(H),
                ExcMessage(model +
                           ": the 'Hardening modulus' must be non-negative "
                           "(softening is not supported; is " +
                           to_text(H) + ")."));
    AssertThrow(friction_angle_deg > 0 || c0 > 0,
                ExcMessage(model +
                           ": with a zero 'Friction angle' the 'Cohesion' "
                           "must be positive."));
  }



  namespace
  {
    // Offsets in the state: elastic strain (6), alpha, increment.
    constexpr unsigned int eps_offset       = 0;
    constexpr unsigned int alpha_offset     = 6;
    constexpr unsigned int increment_offset = 7;
    constexpr unsigned int n_state          = 8;

    /// exp(a) of a symmetric tensor, in its eigenbasis.
    SymmetricTensor<2, 3>
    tensor_exp(const SymmetricTensor<2, 3> &a)
    {
      const auto            eig = TensorFunctions::eigen_decomposition(a);
      SymmetricTensor<2, 3> result;
      for (const auto &e : eig)
        result +=
          std::exp(e.first) * symmetrize(outer_product(e.second, e.second));
      return result;
    }

    /// f b f^T for a symmetric b.
    SymmetricTensor<2, 3>
    push_forward(const Tensor<2, 3> &f, const SymmetricTensor<2, 3> &b)
    {
      return symmetrize(
        Tensor<2, 3>(f * static_cast<Tensor<2, 3>>(b) * transpose(f)));
    }

    template <int dim>
    bool
    is_identity(const Tensor<2, dim> &t)
    {
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          if (t[i][j] != (i == j ? 1. : 0.))
            return false;
      return true;
    }

    template <int dim>
    SymmetricTensor<2, dim>
    nan_tensor()
    {
      return std::numeric_limits<double>::quiet_NaN() *
             unit_symmetric_tensor<dim>();
    }
  } // namespace



  template <int dim>
  IsotropicPlasticity<dim>::IsotropicPlasticity(const double young_modulus,
                                                const double poisson_ratio)
    : lambda(
        LinearElastic<dim>::lame_parameters(young_modulus, poisson_ratio).first)
    , mu(LinearElastic<dim>::lame_parameters(young_modulus, poisson_ratio)
           .second)
    , K(lambda + 2. / 3. * mu)
    , D(lambda * outer_product(unit_symmetric_tensor<3>(),
                               unit_symmetric_tensor<3>()) +
        2. * mu * identity_tensor<3>())
  {
  }



  template <int dim>
  std::vector<StateField>
  IsotropicPlasticity<dim>::state_fields() const
  {
    return {{elastic_strain_name, 6}, {alpha_name, 1}, {increment_name, 1}};
  }



  template <int dim>
  void
  IsotropicPlasticity<dim>::initialize_state(const Point<dim> &,
                                             ArrayView<double> state) const
  {
    for (double &s : state)
      s = 0.;
  }



  template <int dim>
  SymmetricTensor<2, 3>
  IsotropicPlasticity<dim>::elastic_strain(const ArrayView<const double> &state)
  {
    AssertThrow(state.size() == n_state,
                ExcMessage("plasticity: the point state has " +
                           std::to_string(state.size()) +
                           " components, expected 8."));
    return Utils::read_symmetric<3>(state.data() + eps_offset);
  }



  template <int dim>
  double
  IsotropicPlasticity<dim>::equivalent_plastic_strain(
    const ArrayView<const double> &state)
  {
    return state[alpha_offset];
  }



  template <int dim>
  void
  IsotropicPlasticity<dim>::set_equivalent_plastic_strain(
    ArrayView<double> state,
    const double      alpha)
  {
    AssertDimension(state.size(), n_state);
    state[alpha_offset] = alpha;
  }



  template <int dim>
  double
  IsotropicPlasticity<dim>::plastic_increment(
    const ArrayView<const double> &state)
  {
    return state[increment_offset];
  }



  template <int dim>
  SymmetricTensor<2, 3>
  IsotropicPlasticity<dim>::stress_3d(
    const ArrayView<const double> &state) const
  {
    return elastic_stress(elastic_strain(state));
  }



  template <int dim>
  SymmetricTensor<2, 3>
  IsotropicPlasticity<dim>::elastic_stress(
    const SymmetricTensor<2, 3> &eps_e) const
  {
    return D * eps_e;
  }



  template <int dim>
  SymmetricTensor<2, 3>
  IsotropicPlasticity<dim>::elastic_strain_of(
    const SymmetricTensor<2, 3> &stress) const
  {
    return deviator(stress) / (2. * mu) +
           trace(stress) / (9. * K) * unit_symmetric_tensor<3>();
  }



  template <int dim>
  SymmetricTensor<2, dim>
  IsotropicPlasticity<dim>::initial_stress(const Point<dim> &x,
                                           const unsigned int,
                                           const SymmetricTensor<2, 3> *sigma0,
                                           ArrayView<double> state) const
  {
    if (sigma0 != nullptr)
      {
        const SymmetricTensor<2, 3> eps   = elastic_strain_of(*sigma0);
        const SymmetricTensor<2, 3> sigma = elastic_stress(eps);
        // The yield function's own scale: its value at the stress and at
        // zero stress, and what the point's hardening changes, bracket what
        // round-off can reach (a stress on the surface: a Cam Clay point
        // with an overconsolidation ratio of 1).
        const double alpha = equivalent_plastic_strain(state);
        const double f     = yield_function(sigma, alpha);
        const double scale = std::abs(yield_function(sigma, 0.)) +
                             std::abs(yield_function({}, 0.)) +
                             std::abs(f - yield_function(sigma, 0.)) + 1e-300;
        if (!(f <= 1e-10 * scale))
          {
            std::ostringstream message;
            message << "Material points: <Initial stress> at (" << x
                    << ") lies outside the yield surface of the model '"
                    << this->name() << "' (" << *sigma0 << ").";
            AssertThrow(false, ExcMessage(message.str()));
          }
        Utils::write_symmetric<3>(eps, state.data() + eps_offset);
      }
    return extract(stress_3d(state));
  }



  template <int dim>
  SymmetricTensor<4, 3>
  IsotropicPlasticity<dim>::elastic_tangent(const SymmetricTensor<2, 3> &) const
  {
    // The preconditioner's matrix at a committed state: the elastic
    // stiffness. The continuum elastoplastic tangent, assembled without the
    // F-bar linearization, is nearly singular in the deviatoric directions
    // and locks in the volumetric ones: on the footing (examples/footing,
    // F-bar) GMRES then stalls and Newton fails in steps that converge with
    // the elastic matrix.
    return D;
  }



  template <int dim>
  const SymmetricTensor<4, 3> &
  IsotropicPlasticity<dim>::elastic_stiffness() const
  {
    return D;
  }



  template <int dim>
  double
  IsotropicPlasticity<dim>::bulk_modulus() const
  {
    return K;
  }



  template <int dim>
  double
  IsotropicPlasticity<dim>::shear_modulus() const
  {
    return mu;
  }



  template <int dim>
  SymmetricTensor<2, 3>
  IsotropicPlasticity<dim>::embed(const SymmetricTensor<2, dim> &t)
  {
    SymmetricTensor<2, 3> result;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        result[i][j] = t[i][j];
    return result;
  }



  template <int dim>
  Tensor<2, 3>
  IsotropicPlasticity<dim>::embed(const Tensor<2, dim> &t, const double zz)
  {
    Tensor<2, 3> result;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        result[i][j] = t[i][j];
    for (unsigned int i = dim; i < 3; ++i)
      result[i][i] = zz;
    return result;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  IsotropicPlasticity<dim>::extract(const SymmetricTensor<2, 3> &t)
  {
    SymmetricTensor<2, dim> result;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        result[i][j] = t[i][j];
    return result;
  }



  template <int dim>
  SymmetricTensor<4, dim>
  IsotropicPlasticity<dim>::extract(const SymmetricTensor<4, 3> &t)
  {
    SymmetricTensor<4, dim> result;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = k; l < dim; ++l)
            result[i][j][k][l] = t[i][j][k][l];
    return result;
  }



  template <int dim>
  Tensor<4, dim>
  IsotropicPlasticity<dim>::extract(const Tensor<4, 3> &t)
  {
    Tensor<4, dim> result;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            result[i][j][k][l] = t[i][j][k][l];
    return result;
  }



  template <int dim>
  void
  IsotropicPlasticity<dim>::update_stress(
    const PointState<dim>         &old,
    const SymmetricTensor<2, dim> &strain_increment,
    SymmetricTensor<2, dim>       &stress,
    ArrayView<double>              new_state) const
  {
    Return r;
    return_map(elastic_strain(old.state) + embed(strain_increment),
               equivalent_plastic_strain(old.state),
               false,
               r);
    stress = extract(r.stress);
    Utils::write_symmetric<3>(r.elastic_strain, new_state.data() + eps_offset);
    new_state[alpha_offset]     = r.alpha;
    new_state[increment_offset] = r.increment;
  }



  template <int dim>
  std::optional<std::array<double, 2>>
  IsotropicPlasticity<dim>::elastic_volume_strains(
    const PointState<dim>  &old,
    ArrayView<const double> new_state) const
  {
    AssertThrow(old.state.size() == n_state && new_state.size() == n_state,
                ExcMessage("plasticity: the point state has " +
                           std::to_string(old.state.size()) +
                           " components, expected 8."));
    // The trace: the first three entries of deal.II's unrolled order.
    const double *e0 = old.state.data() + eps_offset;
    const double *e1 = new_state.data() + eps_offset;
    return std::array<double, 2>{
      {e0[0] + e0[1] + e0[2], e1[0] + e1[1] + e1[2]}};
  }



  template <int dim>
  bool
  IsotropicPlasticity<dim>::plastic_flow_changes_volume() const
  {
    return true;
  }



  template <int dim>
  bool
  IsotropicPlasticity<dim>::supports_axisymmetry() const
  {
    return dim == 2;
  }



  template <int dim>
  void
  IsotropicPlasticity<dim>::update_stress_axisymmetric(
    const PointState<dim> &old,
    const double,
    const SymmetricTensor<2, dim> &strain_increment,
    const double                   hoop_strain_increment,
    SymmetricTensor<2, dim>       &stress,
    double                        &hoop_stress,
    ArrayView<double>              new_state) const
  {
    AssertThrow(dim == 2,
                ExcMessage("Material points/Axisymmetric needs dim = 2."));
    SymmetricTensor<2, 3> increment = embed(strain_increment);
    increment[2][2]                 = hoop_strain_increment;
    Return r;
    return_map(elastic_strain(old.state) + increment,
               equivalent_plastic_strain(old.state),
               false,
               r);
    stress      = extract(r.stress);
    hoop_stress = r.stress[2][2];
    Utils::write_symmetric<3>(r.elastic_strain, new_state.data() + eps_offset);
    new_state[alpha_offset]     = r.alpha;
    new_state[increment_offset] = r.increment;
  }



  template <int dim>
  SymmetricTensor<4, 3>
  IsotropicPlasticity<dim>::consistent_tangent_axisymmetric(
    const PointState<dim> &old,
    const double,
    const SymmetricTensor<2, dim> &strain_increment,
    const double                   hoop_strain_increment) const
  {
    AssertThrow(dim == 2,
                ExcMessage("Material points/Axisymmetric needs dim = 2."));
    SymmetricTensor<2, 3> increment = embed(strain_increment);
    increment[2][2]                 = hoop_strain_increment;
    if (increment.norm() == 0.)
      return elastic_tangent(elastic_strain(old.state));
    Return r;
    return_map(elastic_strain(old.state) + increment,
               equivalent_plastic_strain(old.state),
               true,
               r);
    return r.tangent;
  }



  template <int dim>
  SymmetricTensor<4, dim>
  IsotropicPlasticity<dim>::tangent(const PointState<dim> &old) const
  {
    return extract(elastic_tangent(elastic_strain(old.state)));
  }



  template <int dim>
  SymmetricTensor<4, dim>
  IsotropicPlasticity<dim>::consistent_tangent(
    const PointState<dim>         &old,
    const SymmetricTensor<2, dim> &strain_increment) const
  {
    if (strain_increment.norm() == 0.)
      return tangent(old);
    Return r;
    return_map(elastic_strain(old.state) + embed(strain_increment),
               equivalent_plastic_strain(old.state),
               true,
               r);
    return extract(r.tangent);
  }



  template <int dim>
  bool
  IsotropicPlasticity<dim>::supports_finite_strain() const
  {
    return true;
  }



  template <int dim>
  void
  IsotropicPlasticity<dim>::update_kirchhoff_stress(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics,
    SymmetricTensor<2, dim>           &tau,
    ArrayView<double>                  new_state) const
  {
    double unused;
    update_kirchhoff_stress_axisymmetric(
      old, kinematics, tau, unused, new_state);
  }



  template <int dim>
  bool
  IsotropicPlasticity<dim>::supports_axisymmetric_finite_strain() const
  {
    return dim == 2;
  }



  template <int dim>
  void
  IsotropicPlasticity<dim>::update_kirchhoff_stress_axisymmetric(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics,
    SymmetricTensor<2, dim>           &tau,
    double                            &tau_hoop,
    ArrayView<double>                  new_state) const
  {
    // Plane strain: the hoop stretch is one, and tau_zz is the
    // out-of-plane stress.
    const double J = determinant(kinematics.F);
    const double Jd =
      determinant(kinematics.delta_F) * kinematics.delta_hoop_stretch;
    if (!(J > 0.) || !std::isfinite(J) || !(Jd > 0.) || !std::isfinite(Jd))
      {
        tau      = nan_tensor<dim>();
        tau_hoop = std::numeric_limits<double>::quiet_NaN();
        // Keep the state well defined (a failed trial is not committed).
        for (unsigned int i = 0; i < n_state; ++i)
          new_state[i] = old.state[i];
        return;
      }
    const Tensor<2, 3> f =
      embed(kinematics.delta_F, kinematics.delta_hoop_stretch);
    const SymmetricTensor<2, 3> b_trial =
      push_forward(f, tensor_exp(2. * elastic_strain(old.state)));
    Return r;
    return_map(0.5 * TensorFunctions::log(b_trial),
               equivalent_plastic_strain(old.state),
               false,
               r);
    tau      = extract(r.stress);
    tau_hoop = r.stress[2][2];
    Utils::write_symmetric<3>(r.elastic_strain, new_state.data() + eps_offset);
    new_state[alpha_offset]     = r.alpha;
    new_state[increment_offset] = r.increment;
  }



  template <int dim>
  Tensor<4, dim>
  IsotropicPlasticity<dim>::kirchhoff_tangent(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics) const
  {
    return extract(kirchhoff_tangent_axisymmetric(old, kinematics));
  }



  template <int dim>
  Tensor<4, 3>
  IsotropicPlasticity<dim>::kirchhoff_tangent_axisymmetric(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics) const
  {
    const Tensor<2, 3> f =
      embed(kinematics.delta_F, kinematics.delta_hoop_stretch);
    const SymmetricTensor<2, 3> b_trial =
      push_forward(f, tensor_exp(2. * elastic_strain(old.state)));
    SymmetricTensor<4, 3> D_alg;
    if (is_identity(kinematics.delta_F) && kinematics.delta_hoop_stretch == 1.)
      D_alg = elastic_tangent(elastic_strain(old.state));
    else
      {
        Return r;
        return_map(0.5 * TensorFunctions::log(b_trial),
                   equivalent_plastic_strain(old.state),
                   true,
                   r);
        D_alg = r.tangent;
      }
    // M = D_alg : d(ln b)/d b (with the factor 1/2 of eps = 1/2 ln b);
    // d tau = 1/2 M : (dl b + b dl^T) and, M being minor-symmetric,
    // d tau_ij / d l_kl = sum_q M_ijkq b_ql.
    const SymmetricTensor<4, 3> M =
      D_alg * TensorFunctions::log_derivative(b_trial);
    Tensor<4, 3> c;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = 0; l < 3; ++l)
            for (unsigned int q = 0; q < 3; ++q)
              c[i][j][k][l] += M[i][j][k][q] * b_trial[q][l];
    return c;
  }



  template class IsotropicPlasticity<2>;
  template class IsotropicPlasticity<3>;
} // namespace qsmpm
