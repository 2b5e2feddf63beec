#include <algorithm>
#include <cmath>
#include <cstring>
#include <deal.II/base/utilities.h>
#include <iostream>
#include <limits>
#include <qsmpm/base/tensor_functions.h>
#include <qsmpm/materials/umat.h>
#include <sstream>

namespace qsmpm
{
  namespace
  {
    /// Abaqus's order of the tensor components: xx, yy, zz, xy, xz, yz.
    constexpr unsigned int voigt_i[6] = {0, 1, 2, 0, 0, 1};
    constexpr unsigned int voigt_j[6] = {0, 1, 2, 1, 2, 2};

    /// Column-major 3x3 array of a tensor.
    void
    write_matrix(const Tensor<2, 3> &A, double *a)
    {
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          a[i + 3 * j] = A[i][j];
    }

    template <int dim>
    Tensor<2, 3>
    embed(const Tensor<2, dim> &A)
    {
      Tensor<2, 3> B = unit_symmetric_tensor<3>();
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          B[i][j] = A[i][j];
      return B;
    }

    /// The components @p v (NTENS of them, engineering shears if
    /// @p engineering) as a symmetric 3D tensor.
    SymmetricTensor<2, 3>
    from_voigt(const double      *v,
               const unsigned int n_tensor,
               const bool         engineering)
    {
      SymmetricTensor<2, 3> t;
      for (unsigned int k = 0; k < n_tensor; ++k)
        t[voigt_i[k]][voigt_j[k]] = (k >= 3 && engineering) ? 0.5 * v[k] : v[k];
      return t;
    }

    void
    to_voigt(const SymmetricTensor<2, 3> &t,
             const unsigned int           n_tensor,
             const bool                   engineering,
             double                      *v)
    {
      for (unsigned int k = 0; k < n_tensor; ++k)
        v[k] = (k >= 3 && engineering ? 2. : 1.) * t[voigt_i[k]][voigt_j[k]];
    }
  } // namespace



  template <int dim>
  void
  Umat<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter(
      "UMAT library",
      library,
      "The shared library with the UMAT: a path (a name without a slash is "
      "looked for in the working directory first, then on the linker's "
      "path). Build one with, e.g., gfortran -shared -fPIC -O2 -o "
      "libmymodel.so mymodel.f.",
      Patterns::Anything());
    prm.add_parameter("Symbol",
                      symbol,
                      "The UMAT's name in the library: umat_ for a Fortran "
                      "SUBROUTINE UMAT compiled by gfortran, or an "
                      "extern \"C\" function of that name.",
                      Patterns::Anything());
    prm.add_parameter("Material name",
                      material_name,
                      "CMNAME, the material name the UMAT receives (at most "
                      "80 characters).",
                      Patterns::Anything());
    prm.add_parameter("Properties",
                      properties,
                      "PROPS, the material constants, comma-separated; "
                      "NPROPS is their number.",
                      Patterns::List(Patterns::Double(), 0, 10000));
    prm.add_parameter("Number of state variables",
                      n_state_variables,
                      "NSTATV, the number of solution-dependent state "
                      "variables the UMAT keeps per point.",
                      Patterns::Integer(0, 10000));
    prm.add_parameter("Initial state variables",
                      initial_state_variables,
                      "The initial STATEV: empty (all zero) or NSTATV "
                      "comma-separated values.",
                      Patterns::List(Patterns::Double(), 0, 10000));
    prm.add_parameter(
      "Elastic strain state variable",
      elastic_strain_state_variable,
      "k > 0: STATEV(k), STATEV(k+1), STATEV(k+2) hold the direct components "
      "(xx, yy, zz) of the elastic strain, as Abaqus's example UMATs keep "
      "EELAS in STATEV(1:NTENS). With Volumetric locking = F-bar at small "
      "strain the cell's common volume change is then only the elastic one "
      "and each point keeps its own plastic volume change, so that a "
      "dilatant flow (Drucker-Prager, Mohr-Coulomb) does not lock: Prandtl's "
      "footing on a c-phi soil at a/h = 4 carried 7.5 % more without it (test "
      "umat_drucker_prager). 0 (default): the UMAT's whole volume change "
      "counts as elastic (plain F-bar), right for a UMAT whose plastic flow "
      "keeps the volume (von Mises) and for one without an elastic strain "
      "(hypoplasticity).",
      Patterns::Integer(0, 10000));
  }



  template <int dim>
  void
  Umat<dim>::declare_parameters(ParameterHandler &prm)
  {
    Parameters::declare_parameters(prm);
  }



  template <int dim>
  Umat<dim>::Umat(ParameterHandler &prm)
    : Umat(Parameters::from(prm))
  {
  }



  template <int dim>
  Umat<dim>::Umat(const Parameters &parameters)
    : parameters(parameters)
  {
    AssertThrow(parameters.material_name.size() <= 80,
                ExcMessage("Material/umat/Material name: at most 80 "
                           "characters (Abaqus's CHARACTER*80 CMNAME)."));
    AssertThrow(parameters.initial_state_variables.empty() ||
                  parameters.initial_state_variables.size() ==
                    parameters.n_state_variables,
                ExcMessage(
                  "Material/umat/Initial state variables: " +
                  std::to_string(parameters.initial_state_variables.size()) +
                  " values for Number of state variables = " +
                  std::to_string(parameters.n_state_variables) +
                  " (give none, or one per state variable)."));
    AssertThrow(parameters.elastic_strain_state_variable == 0 ||
                  parameters.elastic_strain_state_variable + 2 <=
                    parameters.n_state_variables,
                ExcMessage(
                  "Material/umat/Elastic strain state variable = " +
                  std::to_string(parameters.elastic_strain_state_variable) +
                  ": STATEV(k) to STATEV(k+2) must lie within Number of "
                  "state variables = " +
                  std::to_string(parameters.n_state_variables) + "."));
    std::fill(std::begin(cmname), std::end(cmname), ' ');
    std::copy(parameters.material_name.begin(),
              parameters.material_name.end(),
              cmname);

    strain_offset    = parameters.n_state_variables;
    stress_zz_offset = strain_offset + n_tensor;
    energy_offset    = stress_zz_offset + (dim == 2 ? 1 : 0);
    noel_offset      = energy_offset + 3;

    umat = load_umat(parameters.library, parameters.symbol);
    probe();
  }



  template <int dim>
  std::string
  Umat<dim>::name() const
  {
    return "umat (" + parameters.material_name + ")";
  }



  template <int dim>
  std::vector<StateField>
  Umat<dim>::state_fields() const
  {
    std::vector<StateField> fields;
    if (parameters.n_state_variables > 0)
      fields.push_back({"umat_statev", parameters.n_state_variables});
    fields.push_back({"umat_strain", n_tensor});
    if (dim == 2)
      fields.push_back({"umat_stress_zz", 1});
    fields.push_back({"umat_energy", 3});
    fields.push_back({"umat_noel", 1});
    return fields;
  }



  template <int dim>
  void
  Umat<dim>::initialize_state(const Point<dim> &, ArrayView<double> state) const
  {
    std::fill(state.begin(), state.end(), 0.);
    std::copy(parameters.initial_state_variables.begin(),
              parameters.initial_state_variables.end(),
              state.begin());
  }



  template <int dim>
  void
  Umat<dim>::initialize_point_state(const Point<dim>           &x,
                                    const unsigned int          material_id,
                                    const types::particle_index id,
                                    ArrayView<double>           state) const
  {
    this->initialize_material_state(x, material_id, state);
    state[noel_offset] = static_cast<double>(id + 1);
  }



  namespace
  {
    /// Delta R and ln(Delta V) of Delta F = Delta V Delta R (3x3), or
    /// false if det(Delta F) is not positive.
    bool
    polar_log(const Tensor<2, 3>    &f,
              Tensor<2, 3>          &R,
              SymmetricTensor<2, 3> &log_V)
    {
      const double j = determinant(f);
      if (!(j > 0.) || !std::isfinite(j))
        return false;
      const auto eig =
        TensorFunctions::eigen_decomposition(symmetrize(f * transpose(f)));
      SymmetricTensor<2, 3> V_inv;
      log_V = SymmetricTensor<2, 3>();
      for (const auto &[lambda, n] : eig)
        {
          const SymmetricTensor<2, 3> nn = symmetrize(outer_product(n, n));
          log_V += 0.5 * std::log(lambda) * nn;
          V_inv += (1. / std::sqrt(lambda)) * nn;
        }
      R = V_inv * f;
      return true;
    }
  } // namespace



  template <int dim>
  void
  Umat<dim>::prepare(const PointState<dim> &old,
                     const Tensor<2, 3>    &rotation,
                     Call                  &call,
                     double                *statev) const
  {
    const double *state = old.state.data();
    std::copy(state, state + parameters.n_state_variables, statev);

    SymmetricTensor<2, 3> sigma,
      stran = from_voigt(state + strain_offset, n_tensor, true);
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        sigma[i][j] = old.stress[i][j];
    if (dim == 2)
      sigma[2][2] = state[stress_zz_offset];
    if (rotation != Tensor<2, 3>(unit_symmetric_tensor<3>()))
      {
        sigma = symmetrize(rotation * sigma * transpose(rotation));
        stran = symmetrize(rotation * stran * transpose(rotation));
      }
    to_voigt(sigma, n_tensor, false, call.stress);
    to_voigt(stran, n_tensor, true, call.stran);
    std::copy(state + energy_offset, state + energy_offset + 3, call.energy);

    for (unsigned int d = 0; d < 3; ++d)
      call.coords[d] = d < dim ? old.position[d] : 0.;
    call.celent = std::pow(old.volume, 1. / dim);
    call.noel   = static_cast<int>(state[noel_offset]);
    call.pnewdt = 1e36;
    std::fill(std::begin(call.ddsdde), std::end(call.ddsdde), 0.);
  }



  template <int dim>
  void
  Umat<dim>::prepare_small_strain(
    const PointState<dim>         &old,
    const SymmetricTensor<2, dim> &strain_increment,
    Call                          &call,
    double                        *statev) const
  {
    const Tensor<2, 3> I = unit_symmetric_tensor<3>();
    prepare(old, I, call, statev);
    SymmetricTensor<2, 3> de;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        de[i][j] = strain_increment[i][j];
    to_voigt(de, n_tensor, true, call.dstran);
    write_matrix(I, call.drot);
    write_matrix(I, call.dfgrd0);
    write_matrix(I, call.dfgrd1);
  }



  template <int dim>
  bool
  Umat<dim>::prepare_finite_strain(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics,
    Call                              &call,
    double                            *statev) const
  {
    Tensor<2, 3>          R;
    SymmetricTensor<2, 3> log_V;
    if (!(determinant(kinematics.F) > 0.) ||
        !polar_log(embed(kinematics.delta_F), R, log_V))
      return false;
    prepare(old, R, call, statev);
    to_voigt(log_V, n_tensor, true, call.dstran);
    write_matrix(R, call.drot);
    write_matrix(embed(kinematics.F_old), call.dfgrd0);
    write_matrix(embed(kinematics.F), call.dfgrd1);
    return true;
  }



  template <int dim>
  void
  Umat<dim>::raw_call(Call &call, double *statev, double *props) const
  {
    double rpl = 0., drpldt = 0., ddsddt[6] = {}, drplde[6] = {};
    double time[2] = {0., 0.}, dtime = 1., temp = 0., dtemp = 0.;
    double predef[1] = {0.}, dpred[1] = {0.};
    int    ndi = 3, nshr = n_tensor - 3, ntens = n_tensor;
    int    nstatv = parameters.n_state_variables;
    int    nprops = parameters.properties.size();
    int    npt = 1, layer = 1, kspt = 1, kstep = 1, kinc = 1;
    umat(call.stress,
         statev,
         call.ddsdde,
         &call.energy[0],
         &call.energy[1],
         &call.energy[2],
         &rpl,
         ddsddt,
         drplde,
         &drpldt,
         call.stran,
         call.dstran,
         time,
         &dtime,
         &temp,
         &dtemp,
         predef,
         dpred,
         cmname,
         &ndi,
         &nshr,
         &ntens,
         &nstatv,
         props,
         &nprops,
         call.coords,
         call.drot,
         &call.pnewdt,
         &call.celent,
         call.dfgrd0,
         call.dfgrd1,
         &call.noel,
         &npt,
         &layer,
         &kspt,
         &kstep,
         &kinc,
         sizeof(cmname));
  }



  template <int dim>
  bool
  Umat<dim>::invoke(Call                  &call,
                    double                *statev,
                    const PointState<dim> &old) const
  {
    raw_call(call, statev, const_cast<double *>(parameters.properties.data()));
    bool finite = true;
    for (unsigned int k = 0; k < n_tensor; ++k)
      finite = finite && std::isfinite(call.stress[k]);
    if (!finite && !reported)
      {
        reported = true;
        std::ostringstream message;
        message << "UMAT '" << parameters.material_name
                << "' returned a stress that is not a finite number at "
                << "point NOEL = " << call.noel << " (material id "
                << old.material_id << ", x = " << old.position
                << "); the load step is cut back." << std::endl;
        std::cerr << message.str();
      }
    return finite && call.pnewdt >= 1.;
  }



  template <int dim>
  void
  Umat<dim>::store(const Call &call, ArrayView<double> new_state) const
  {
    for (unsigned int k = 0; k < n_tensor; ++k)
      new_state[strain_offset + k] = call.stran[k] + call.dstran[k];
    if (dim == 2)
      new_state[stress_zz_offset] = call.stress[2];
    std::copy(call.energy, call.energy + 3, &new_state[energy_offset]);
    new_state[noel_offset] = call.noel;
  }



  template <int dim>
  SymmetricTensor<4, 3>
  Umat<dim>::ddsdde_tensor(const Call &call) const
  {
    // sigma_ij = C_ijkl eps_kl sums eps_xy and eps_yx: C_ijxy multiplies
    // gamma_xy = 2 eps_xy, which is what DDSDDE's column xy does.
    SymmetricTensor<4, 3> C;
    for (unsigned int a = 0; a < n_tensor; ++a)
      for (unsigned int b = 0; b < n_tensor; ++b)
        C[voigt_i[a]][voigt_j[a]][voigt_i[b]][voigt_j[b]] =
          call.ddsdde[a + n_tensor * b];
    return C;
  }



  template <int dim>
  void
  Umat<dim>::update_stress(const PointState<dim>         &old,
                           const SymmetricTensor<2, dim> &strain_increment,
                           SymmetricTensor<2, dim>       &stress,
                           ArrayView<double>              new_state) const
  {
    Call call;
    prepare_small_strain(old, strain_increment, call, new_state.data());

    if (!invoke(call, new_state.data(), old))
      {
        stress = std::numeric_limits<double>::quiet_NaN() *
                 unit_symmetric_tensor<dim>();
        return;
      }
    const SymmetricTensor<2, 3> sigma =
      from_voigt(call.stress, n_tensor, false);
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        stress[i][j] = sigma[i][j];
    store(call, new_state);
  }



  template <int dim>
  SymmetricTensor<4, dim>
  Umat<dim>::consistent_tangent(
    const PointState<dim>         &old,
    const SymmetricTensor<2, dim> &strain_increment) const
  {
    // The trial state variables are thrown away; a scratch copy per thread
    // that grows once, not an allocation per point.
    thread_local std::vector<double> statev;
    statev.resize(parameters.n_state_variables);
    Call call;
    prepare_small_strain(old, strain_increment, call, statev.data());
    invoke(call, statev.data(), old);

    const SymmetricTensor<4, 3> C3 = ddsdde_tensor(call);
    SymmetricTensor<4, dim>     C;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = k; l < dim; ++l)
            C[i][j][k][l] = C3[i][j][k][l];
    return C;
  }



  template <int dim>
  SymmetricTensor<4, dim>
  Umat<dim>::tangent(const PointState<dim> &old) const
  {
    return consistent_tangent(old, SymmetricTensor<2, dim>());
  }



  template <int dim>
  std::optional<std::array<double, 2>>
  Umat<dim>::elastic_volume_strains(const PointState<dim>  &old,
                                    ArrayView<const double> new_state) const
  {
    if (parameters.elastic_strain_state_variable == 0)
      return std::nullopt;
    // STATEV are the first fields of the state (state_fields()).
    const double *e0 =
      old.state.data() + parameters.elastic_strain_state_variable - 1;
    const double *e1 =
      new_state.data() + parameters.elastic_strain_state_variable - 1;
    return std::array<double, 2>{
      {e0[0] + e0[1] + e0[2], e1[0] + e1[1] + e1[2]}};
  }



  template <int dim>
  bool
  Umat<dim>::plastic_flow_changes_volume() const
  {
    return parameters.elastic_strain_state_variable > 0;
  }



  template <int dim>
  bool
  Umat<dim>::supports_finite_strain() const
  {
    return true;
  }



  template <int dim>
  void
  Umat<dim>::update_kirchhoff_stress(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics,
    SymmetricTensor<2, dim>           &tau,
    ArrayView<double>                  new_state) const
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double J   = determinant(kinematics.F);
    Call         call;
    if (!prepare_finite_strain(old, kinematics, call, new_state.data()))
      {
        tau = nan * unit_symmetric_tensor<dim>();
        return;
      }
    if (!invoke(call, new_state.data(), old))
      {
        tau = nan * unit_symmetric_tensor<dim>();
        return;
      }
    const SymmetricTensor<2, 3> sigma =
      from_voigt(call.stress, n_tensor, false);
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        tau[i][j] = J * sigma[i][j];
    store(call, new_state);
  }



  template <int dim>
  Tensor<4, dim>
  Umat<dim>::kirchhoff_tangent(
    const PointState<dim>             &old,
    const FiniteStrainKinematics<dim> &kinematics) const
  {
    Tensor<4, dim>                   c;
    const double                     J = determinant(kinematics.F);
    thread_local std::vector<double> statev;
    statev.resize(parameters.n_state_variables);
    Call call;
    if (!prepare_finite_strain(old, kinematics, call, statev.data()))
      return c;
    invoke(call, statev.data(), old);

    const SymmetricTensor<4, 3> D = ddsdde_tensor(call);
    const SymmetricTensor<2, 3> sigma =
      from_voigt(call.stress, n_tensor, false);
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            c[i][j][k][l] = J * D[i][j][k][l] + J * sigma[i][j] * (k == l) +
                            0.5 * J *
                              ((i == k) * sigma[l][j] - (i == l) * sigma[k][j] -
                               sigma[i][k] * (j == l) + sigma[i][l] * (j == k));
    return c;
  }



  template <int dim>
  void
  Umat<dim>::probe() const
  {
    // Guards behind PROPS and STATEV. NaN behind PROPS: a UMAT that reads
    // beyond NPROPS carries it into its stress or DDSDDE. Zeros behind
    // STATEV (the initial value a UMAT expects of its state, so that it
    // takes its usual path): a UMAT that writes beyond NSTATV changes them
    // (a plastic model once it yields, which the second, large increment
    // makes it do).
    constexpr unsigned int guard = 64;
    const double           nan   = std::numeric_limits<double>::quiet_NaN();
    std::vector<double>    props(parameters.properties);
    props.resize(props.size() + guard, nan);

    std::vector<double> state(this->n_state_components(), 0.);
    initialize_state(Point<dim>(), ArrayView<double>(state));
    PointState<dim> initial{SymmetricTensor<2, dim>(),
                            SymmetricTensor<2, dim>(),
                            ArrayView<const double>(state),
                            1.,
                            0,
                            Point<dim>()};

    // A shear strain of 5 %: beyond the elastic range of soils, concrete and
    // metals alike.
    const double shear = 0.05;
    for (const double increment : {0., shear})
      {
        std::vector<double> statev(parameters.n_state_variables + guard, 0.);
        Call                call;
        // The shear as engineering strain gamma_xy = 2 eps_xy.
        SymmetricTensor<2, dim> shear_strain;
        shear_strain[0][1] = 0.5 * increment;
        prepare_small_strain(initial, shear_strain, call, statev.data());
        raw_call(call, statev.data(), props.data());

        for (unsigned int k = parameters.n_state_variables; k < statev.size();
             ++k)
          AssertThrow(statev[k] == 0.,
                      ExcMessage(
                        "Material/umat/Number of state variables: the UMAT '" +
                        parameters.material_name + "' writes STATEV(" +
                        std::to_string(k + 1) + ") but NSTATV is " +
                        std::to_string(parameters.n_state_variables) + "."));
        if (increment == 0.)
          {
            bool finite = true;
            for (unsigned int k = 0; k < n_tensor; ++k)
              finite = finite && std::isfinite(call.stress[k]);
            for (unsigned int k = 0; k < n_tensor * n_tensor; ++k)
              finite = finite && std::isfinite(call.ddsdde[k]);
            AssertThrow(
              finite,
              ExcMessage(
                "Material/umat/Properties: the UMAT '" +
                parameters.material_name +
                "' returns a stress or DDSDDE that is not a finite number "
                "for a zero strain increment at the initial state, with "
                "NPROPS = " +
                std::to_string(parameters.properties.size()) +
                " and NSTATV = " +
                std::to_string(parameters.n_state_variables) +
                ": does it need more properties (or initial state "
                "variables)?"));
          }
      }
  }



  template class Umat<2>;
  template class Umat<3>;

  QSMPM_REGISTER_CONSTITUTIVE_MODEL(
    Umat,
    "umat",
    "An Abaqus/Standard UMAT subroutine (Fortran or C) from a shared "
    "library, with Abaqus's calling convention: plane strain (NDI = 3, "
    "NSHR = 1) or 3D, small strain or finite strain (co-rotational, "
    "logarithmic strain increments, DROT); see doc/user_models.md.")
} // namespace qsmpm
