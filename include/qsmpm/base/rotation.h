#ifndef qsmpm_base_rotation_h
#define qsmpm_base_rotation_h

#include <array>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * Crystal orientations in Bunge's convention and what is needed to use
   * them for the polycrystal of paper Section 4: Euler angles <-> rotation
   * matrices, the 24 proper rotations of cubic crystal symmetry, the 4 of
   * orthorhombic sample symmetry, disorientation angles, mean orientations
   * and the rotation of a fourth-order stiffness tensor.
   *
   * Convention (Bunge, passive). An orientation g = (phi1, Phi, phi2) is the
   * matrix
   *
   *   g = R_z(phi2) R_x(Phi) R_z(phi1),   R_z(a) = [[c, s, 0], [-s, c, 0],
   *                                                 [0, 0, 1]], ...
   *
   * which maps components in the sample frame to components in the crystal
   * frame: v_crystal = g v_sample. Its rows are the crystal axes [100],
   * [010], [001] written in sample coordinates, its third column
   * (sin phi2 sin Phi, cos phi2 sin Phi, cos Phi) is the sample normal z in
   * crystal coordinates. Strain goes to the crystal frame as
   * eps_c = g eps_s g^T, stress comes back as sigma_s = g^T sigma_c g, so the
   * stiffness in the sample frame is C_s,ijkl = g_mi g_nj g_ok g_pl C_c,mnop.
   * Angles are in radians unless a name says otherwise.
   */
  class Rotation
  {
  public:
    /// The matrix g of the Bunge angles (phi1, Phi, phi2), radians.
    static Tensor<2, 3>
    from_bunge(const double phi1, const double Phi, const double phi2);

    /// Bunge angles (phi1, Phi, phi2) of a rotation matrix, phi1 and phi2 in
    /// [0, 2 pi), Phi in [0, pi].
    static std::array<double, 3>
    to_bunge(const Tensor<2, 3> &g);

    /// The 24 proper rotations of the cubic point group (m-3m), identity
    /// first.
    static const std::vector<Tensor<2, 3>> &
    cubic_symmetry();

    /// The 4 proper rotations of orthorhombic sample symmetry (mmm):
    /// identity and the 180 degree rotations about x, y and z.
    static const std::vector<Tensor<2, 3>> &
    orthorhombic_symmetry();

    /// Rotation angle of a rotation matrix, in [0, pi].
    static double
    angle(const Tensor<2, 3> &g);

    /**
     * Disorientation angle between two orientations of cubic crystals: the
     * smallest rotation angle of S g_b g_a^T over the 24 cubic symmetry
     * rotations S (at most 62.8 degrees).
     */
    static double
    disorientation(const Tensor<2, 3> &g_a, const Tensor<2, 3> &g_b);

    /**
     * The same where it is less than @p bound (radians); elsewhere some
     * value of at least @p bound, found without the angle itself: the
     * largest trace over the symmetries, 1 + 2 cos(angle), decides (with a
     * margin of round-off, inside which the angle is computed), which
     * saves the arc tangent for most pairs of a search within a small
     * bound.
     */
    static double
    disorientation(const Tensor<2, 3> &g_a,
                   const Tensor<2, 3> &g_b,
                   const double        bound);

    /**
     * The symmetry-equivalent S g of @p g (S cubic) closest to @p reference,
     * i.e. with the smallest rotation angle of S g reference^T.
     */
    static Tensor<2, 3>
    closest_equivalent(const Tensor<2, 3> &g, const Tensor<2, 3> &reference);

    /**
     * Mean orientation of a set of orientations (weights optional): every
     * orientation is first replaced by its cubic equivalent closest to the
     * first one, then the unit quaternions are averaged (signs aligned) and
     * normalized. For orientations within a few degrees of each other this
     * is the usual mean rotation to second order in the spread.
     */
    static Tensor<2, 3>
    mean(const std::vector<Tensor<2, 3>> &orientations,
         const std::vector<double>       &weights = {});

    /// Unit quaternion (w, x, y, z), w >= 0, of a rotation matrix.
    static std::array<double, 4>
    to_quaternion(const Tensor<2, 3> &g);

    /// Rotation matrix of a unit quaternion.
    static Tensor<2, 3>
    from_quaternion(const std::array<double, 4> &q);

    /**
     * The stiffness in the sample frame of a crystal with stiffness @p C in
     * its own frame and orientation @p g:
     * C_s,ijkl = g_mi g_nj g_ok g_pl C_mnop.
     */
    static SymmetricTensor<4, 3>
    rotate_to_sample(const SymmetricTensor<4, 3> &C, const Tensor<2, 3> &g);

    /// The cubic stiffness tensor of C11, C12, C44 in the crystal frame.
    static SymmetricTensor<4, 3>
    cubic_stiffness(const double C11, const double C12, const double C44);

    /// A 6x6 matrix in Voigt notation (order 11, 22, 33, 23, 13, 12,
    /// engineering shear strains) of a stiffness tensor.
    static std::array<std::array<double, 6>, 6>
    to_voigt(const SymmetricTensor<4, 3> &C);
  };
} // namespace qsmpm

#endif
