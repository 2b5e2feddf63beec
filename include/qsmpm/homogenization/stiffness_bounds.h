#ifndef qsmpm_homogenization_stiffness_bounds_h
#define qsmpm_homogenization_stiffness_bounds_h

#include <array>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * The Voigt, Reuss and Hill estimates of the effective stiffness of an
   * aggregate of crystals with given orientations and volume weights, and
   * the in-plane Young's moduli of a 6x6 stiffness (the quantities compared
   * in paper Section 4 and its Table I):
   *
   * - Voigt: the volume average of the rotated stiffnesses, C_V = <C(g)>;
   * - Reuss: the inverse of the average compliance, C_R = <C(g)^-1>^-1;
   * - Hill: C_H = (C_V + C_R) / 2;
   *
   * and for any 6x6 stiffness C (Voigt order 11, 22, 33, 23, 13, 12,
   * engineering shear strains, no symmetry assumed) S = C^-1,
   * E_x = 1 / S_11, E_y = 1 / S_22, E_in-plane = (E_x + E_y) / 2.
   * For a uniform texture this Hill E is the usual one from the Hill bulk
   * and shear moduli.
   */
  class StiffnessBounds
  {
  public:
    using Matrix6 = std::array<std::array<double, 6>, 6>;

    /// In-plane Young's moduli of a stiffness.
    struct InPlane
    {
      double E_x;
      double E_y;
      double E_in_plane;
    };

    /**
     * Crystals of stiffness @p C_crystal (crystal frame) with orientations
     * @p g (Bunge, sample -> crystal) and weights @p w (any positive
     * scale, e.g. grain volumes).
     */
    StiffnessBounds(const SymmetricTensor<4, 3>     &C_crystal,
                    const std::vector<Tensor<2, 3>> &g,
                    const std::vector<double>       &w);

    const Matrix6 &
    voigt() const;
    const Matrix6 &
    reuss() const;
    const Matrix6 &
    hill() const;

    /// Inverse of a 6x6 matrix; throws if it is singular.
    static Matrix6
    inverse(const Matrix6 &C);

    /// In-plane moduli of the stiffness @p C.
    static InPlane
    in_plane(const Matrix6 &C);

  private:
    Matrix6 C_voigt;
    Matrix6 C_reuss;
    Matrix6 C_hill;
  };
} // namespace qsmpm

#endif
