#include <cmath>
#include <limits>
#include <qsmpm/base/tensor_functions.h>
#include <qsmpm/materials/hencky.h>
#include <qsmpm/materials/linear_elastic.h>

namespace qsmpm
{
  namespace
  {
    /// b = F F^T.
    template <int dim>
    SymmetricTensor<2, dim>
    left_cauchy_green(const Tensor<2, dim> &F)
    {
      SymmetricTensor<2, dim> b;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            b[i][j] += F[i][k] * F[j][k];
      return b;
    }
  } // namespace



  template <int dim>
  std::pair<double, double>
  Hencky<dim>::lame_parameters(const double young_modulus,
                               const double poisson_ratio)
  {
    AssertThrow(young_modulus > 0,
                ExcMessage("hencky: Young's modulus must be positive."));
    AssertThrow(poisson_ratio > -1 && poisson_ratio < 0.5,
                ExcMessage("hencky: Poisson's ratio must lie in (-1, 0.5)."));
    const double mu     = young_modulus / (2. * (1. + poisson_ratio));
    const double lambda = young_modulus * poisson_ratio /
                          ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
    return {lambda, mu};
  }



  template <int dim>
  Hencky<dim>::Hencky(const double young_modulus, const double poisson_ratio)
  {
    // Check E and nu with a message naming this model.
    lame_parameters(young_modulus, poisson_ratio);
    C = LinearElastic<dim>::isotropic_stiffness(young_modulus,
                                                poisson_ratio,
                                                false);
  }



  template <int dim>
  Hencky<dim>::Hencky(ParameterHandler &prm)
    : Hencky(prm.get_double("Young's modulus"),
             prm.get_double("Poisson's ratio"))
  {
  }



  template <int dim>
  void
  Hencky<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Young's modulus",
                      "1.0",
                      Patterns::Double(0.),
                      "Young's modulus E (Pa, or any consistent unit).");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      Patterns::Double(-1., 0.5),
                      "Poisson's ratio nu, in (-1, 0.5).");
  }



  template <int dim>
  bool
  Hencky<dim>::supports_finite_strain() const
  {
    return true;
  }



  template <int dim>
  void
  Hencky<dim>::update_stress(const PointState<dim>         &old,
                             const SymmetricTensor<2, dim> &strain_increment,
                             SymmetricTensor<2, dim>       &stress,
                             ArrayView<double>) const
  {
    stress = old.stress + C * strain_increment;
  }



  template <int dim>
  SymmetricTensor<4, dim>
  Hencky<dim>::tangent(const PointState<dim> &) const
  {
    return C;
  }



  template <int dim>
  void
  Hencky<dim>::update_kirchhoff_stress(
    const PointState<dim> &,
    const FiniteStrainKinematics<dim> &kinematics,
    SymmetricTensor<2, dim>           &tau,
    ArrayView<double>) const
  {
    const double J = determinant(kinematics.F);
    // Not only a guard against inverted points: the eigen solver should not
    // see NaN entries.
    if (!(J > 0.) || !std::isfinite(J))
      {
        tau = std::numeric_limits<double>::quiet_NaN() *
              unit_symmetric_tensor<dim>();
        return;
      }
    tau = C * (0.5 * TensorFunctions::log(left_cauchy_green(kinematics.F)));
  }



  template <int dim>
  Tensor<4, dim>
  Hencky<dim>::kirchhoff_tangent(
    const PointState<dim> &,
    const FiniteStrainKinematics<dim> &kinematics) const
  {
    const SymmetricTensor<2, dim> b = left_cauchy_green(kinematics.F);
    // M = D : d(ln b)/d b; d tau = 1/2 M : (dl b + b dl^T) and, M being
    // minor-symmetric, d tau_ij / d l_kl = sum_q M_ijkq b_ql.
    const SymmetricTensor<4, dim> M = C * TensorFunctions::log_derivative(b);
    Tensor<4, dim>                c;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            for (unsigned int q = 0; q < dim; ++q)
              c[i][j][k][l] += M[i][j][k][q] * b[q][l];
    return c;
  }



  template <int dim>
  const SymmetricTensor<4, dim> &
  Hencky<dim>::stiffness() const
  {
    return C;
  }



  template class Hencky<2>;
  template class Hencky<3>;

  QSMPM_REGISTER_CONSTITUTIVE_MODEL(Hencky,
                                    "hencky",
                                    "isotropic Hencky hyperelasticity, "
                                    "tau = lambda tr(eps) I + 2 mu eps with "
                                    "the logarithmic strain eps = 1/2 ln b "
                                    "(E, nu; plane strain in 2D; linear "
                                    "elastic for small strain).")
} // namespace qsmpm
