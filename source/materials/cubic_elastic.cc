#include <cmath>
#include <qsmpm/base/rotation.h>
#include <qsmpm/materials/cubic_elastic.h>

namespace qsmpm
{
  namespace
  {
    // The tensor index pair of an unrolled symmetric-tensor component.
    template <int dim>
    TableIndices<2>
    unrolled_pair(const unsigned int a)
    {
      return SymmetricTensor<2, dim>::unrolled_to_component_indices(a);
    }

    // Position of M_ab (a <= b) in the packed upper triangle.
    template <int dim>
    constexpr unsigned int
    packed(const unsigned int a, const unsigned int b)
    {
      constexpr unsigned int n =
        SymmetricTensor<2, dim>::n_independent_components;
      return a * n - a * (a - 1) / 2 + (b - a);
    }

    // sigma_a += sum_b M_ab d_eps_b with the packed rotated stiffness M, the
    // off-diagonal strain components counted twice (eps_xy and eps_yx).
    template <int dim>
    inline void
    add_stress_increment(const double                  *M,
                         const SymmetricTensor<2, dim> &d_eps,
                         SymmetricTensor<2, dim>       &stress)
    {
      constexpr unsigned int n =
        SymmetricTensor<2, dim>::n_independent_components;
      double e[n];
      for (unsigned int b = 0; b < n; ++b)
        e[b] = d_eps.access_raw_entry(b) * (b < dim ? 1. : 2.);
      for (unsigned int a = 0; a < n; ++a)
        {
          double s = 0;
          for (unsigned int b = 0; b < n; ++b)
            s += M[a <= b ? packed<dim>(a, b) : packed<dim>(b, a)] * e[b];
          stress.access_raw_entry(a) += s;
        }
    }
  } // namespace



  template <int dim>
  CubicElastic<dim>::CubicElastic(const double                 C11,
                                  const double                 C12,
                                  const double                 C44,
                                  const std::array<double, 3> &euler_angles)
    : C_crystal(Rotation::cubic_stiffness(C11, C12, C44))
    , default_orientation(
        Rotation::from_bunge(euler_angles[0], euler_angles[1], euler_angles[2]))
  {
    // Positive definiteness of a cubic stiffness.
    AssertThrow(C11 - C12 > 0 && C11 + 2. * C12 > 0 && C44 > 0,
                ExcMessage("cubic elastic: the stiffness must be positive "
                           "definite: C11 - C12 > 0, C11 + 2 C12 > 0 and "
                           "C44 > 0."));
  }



  template <int dim>
  CubicElastic<dim>::CubicElastic(const Parameters &parameters)
    : CubicElastic(parameters.C11,
                   parameters.C12,
                   parameters.C44,
                   {{parameters.euler_angles[0] * M_PI / 180.,
                     parameters.euler_angles[1] * M_PI / 180.,
                     parameters.euler_angles[2] * M_PI / 180.}})
  {
  }



  template <int dim>
  CubicElastic<dim>::CubicElastic(ParameterHandler &prm)
    : CubicElastic(Parameters::from(prm))
  {
  }



  template <int dim>
  void
  CubicElastic<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("C11",
                      C11,
                      "Cubic constant C11 in the crystal frame (default: "
                      "nickel, GPa; paper Section 4).",
                      Patterns::Double(0.));
    prm.add_parameter("C12", C12, "Cubic constant C12.", Patterns::Double());
    prm.add_parameter("C44", C44, "Cubic constant C44.", Patterns::Double(0.));
    prm.add_parameter("Euler angles",
                      euler_angles,
                      "Bunge angles phi1, Phi, phi2 in degrees of the "
                      "orientation of all points (programs such as the "
                      "polycrystal example set one per grain instead).",
                      Patterns::List(Patterns::Double(), 3, 3));
  }



  template <int dim>
  void
  CubicElastic<dim>::declare_parameters(ParameterHandler &prm)
  {
    Parameters::declare_parameters(prm);
  }



  template <int dim>
  void
  CubicElastic<dim>::set_orientation(const OrientationFunction &function)
  {
    orientation = function;
  }



  template <int dim>
  std::vector<StateField>
  CubicElastic<dim>::state_fields() const
  {
    return {{"rotated_stiffness", n_entries}};
  }



  template <int dim>
  SymmetricTensor<4, dim>
  CubicElastic<dim>::sample_stiffness(const Tensor<2, 3> &g) const
  {
    const SymmetricTensor<4, 3> C = Rotation::rotate_to_sample(C_crystal, g);
    SymmetricTensor<4, dim>     result;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = k; l < dim; ++l)
            result[i][j][k][l] = C[i][j][k][l];
    return result;
  }



  template <int dim>
  void
  CubicElastic<dim>::initialize_state(const Point<dim> &x,
                                      ArrayView<double> state) const
  {
    const SymmetricTensor<4, dim> C =
      sample_stiffness(orientation ? orientation(x) : default_orientation);
    constexpr unsigned int n =
      SymmetricTensor<2, dim>::n_independent_components;
    for (unsigned int a = 0; a < n; ++a)
      for (unsigned int b = a; b < n; ++b)
        {
          const auto ij            = unrolled_pair<dim>(a);
          const auto kl            = unrolled_pair<dim>(b);
          state[packed<dim>(a, b)] = C[ij[0]][ij[1]][kl[0]][kl[1]];
        }
  }



  template <int dim>
  void
  CubicElastic<dim>::update_stress(const PointState<dim>         &old,
                                   const SymmetricTensor<2, dim> &d_eps,
                                   SymmetricTensor<2, dim>       &stress,
                                   ArrayView<double> new_state) const
  {
    stress = old.stress;
    add_stress_increment(old.state.data(), d_eps, stress);
    std::copy(old.state.begin(), old.state.end(), new_state.begin());
  }



  template <int dim>
  void
  CubicElastic<dim>::update_stresses(
    const PointStateBatch<dim>              &old,
    ArrayView<const SymmetricTensor<2, dim>> strain_increments,
    ArrayView<SymmetricTensor<2, dim>>       stresses,
    ArrayView<double>) const
  {
    for (unsigned int i = 0; i < old.size(); ++i)
      {
        stresses[i] = old.stress(i);
        add_stress_increment(old.state(i).data(),
                             strain_increments[i],
                             stresses[i]);
      }
  }



  template <int dim>
  typename PointStateBatch<dim>::Fields
  CubicElastic<dim>::batch_fields() const
  {
    typename PointStateBatch<dim>::Fields fields;
    fields.strain      = false;
    fields.volume      = false;
    fields.material_id = false;
    return fields;
  }



  template <int dim>
  bool
  CubicElastic<dim>::state_is_constant() const
  {
    return true;
  }



  template <int dim>
  SymmetricTensor<4, dim>
  CubicElastic<dim>::tangent(const PointState<dim> &old) const
  {
    constexpr unsigned int n =
      SymmetricTensor<2, dim>::n_independent_components;
    SymmetricTensor<4, dim> C;
    for (unsigned int a = 0; a < n; ++a)
      for (unsigned int b = 0; b < n; ++b)
        {
          const auto ij = unrolled_pair<dim>(a);
          const auto kl = unrolled_pair<dim>(b);
          C[ij[0]][ij[1]][kl[0]][kl[1]] =
            old.state[a <= b ? packed<dim>(a, b) : packed<dim>(b, a)];
        }
    return C;
  }



  template <int dim>
  const SymmetricTensor<4, 3> &
  CubicElastic<dim>::crystal_stiffness() const
  {
    return C_crystal;
  }



  template class CubicElastic<2>;
  template class CubicElastic<3>;

  QSMPM_REGISTER_CONSTITUTIVE_MODEL(CubicElastic,
                                    "cubic elastic",
                                    "linear elasticity of a cubic crystal "
                                    "(C11, C12, C44) in a per-point Bunge "
                                    "orientation; plane strain in 2D.")
} // namespace qsmpm
