// A user-defined constitutive model, compiled outside qsmpm: small-strain
// isotropic linear elasticity parameterized by the bulk modulus K and the
// shear modulus G,
//
//   sigma^{k+1} = sigma^k + (K - 2G/3) tr(d_eps) I + 2 G d_eps,
//
// selected with `set Model = K-G elastic` and configured in the subsection
// "Material/K-G elastic". In 2D it is plane strain (eps_zz = 0) with the
// three-dimensional K. It is the model of the tutorial doc/user_models.md;
// the test install_package compiles it into a user program and into a
// plugin for the driver (`qsmpm --plugin`), and checks that it gives the
// reactions of the built-in `linear elastic` with
// E = 9KG/(3K+G), nu = (3K-2G)/(2(3K+G)).
#include <qsmpm/materials/constitutive_model.h>

namespace user_models
{
  using namespace dealii;

  template <int dim>
  class KGElastic : public qsmpm::ConstitutiveModel<dim>
  {
  public:
    // The entries of the model's own subsection "Material/K-G elastic".
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Bulk modulus",
                        "1.0",
                        Patterns::Double(0.),
                        "K, the bulk modulus (> 0).");
      prm.declare_entry("Shear modulus",
                        "1.0",
                        Patterns::Double(0.),
                        "G, the shear modulus (> 0).");
    }

    // The factory passes the ParameterHandler positioned in that
    // subsection.
    explicit KGElastic(ParameterHandler &prm)
    {
      const double K = prm.get_double("Bulk modulus");
      const double G = prm.get_double("Shear modulus");
      AssertThrow(K > 0 && G > 0,
                  ExcMessage("K-G elastic: K and G must be positive."));
      C = (K - 2. / 3. * G) * outer_product(unit_symmetric_tensor<dim>(),
                                            unit_symmetric_tensor<dim>()) +
          2. * G * identity_tensor<dim>();
    }

    std::string
    name() const override
    {
      return "K-G elastic";
    }

    // The stress update: pure, it only writes its output arguments. The
    // model keeps no history, so new_state is empty.
    void
    update_stress(const qsmpm::PointState<dim>  &old,
                  const SymmetricTensor<2, dim> &strain_increment,
                  SymmetricTensor<2, dim>       &stress,
                  ArrayView<double> /*new_state*/) const override
    {
      stress = old.stress + C * strain_increment;
    }

    // The tangent (exact for a linear model), used by the preconditioner.
    SymmetricTensor<4, dim>
    tangent(const qsmpm::PointState<dim> &) const override
    {
      return C;
    }

  private:
    SymmetricTensor<4, dim> C;
  };

  // Registration for dim = 2 and 3, at namespace scope of the class.
  QSMPM_REGISTER_CONSTITUTIVE_MODEL(KGElastic,
                                    "K-G elastic",
                                    "isotropic linear elasticity in terms of "
                                    "the bulk and shear moduli (a user model).")
} // namespace user_models
