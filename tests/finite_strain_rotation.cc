// Objectivity of the finite-strain kinematics: a pre-stressed block that is
// rotated rigidly keeps its stress state, rotated with it.
//
// A square block (a cube in 3D) in the middle of a larger grid of empty
// cells, Hencky model, Kinematics = finite strain. Every grid node is
// prescribed (nodes without points too; Dirichlet conditions take
// precedence over the zero increments of inactive nodes), with one
// displacement function of the load factor t over 11 unit steps:
//
//   step 1 (t = 0 -> 1):  increment (F0 - I)(x - c),  F0 = diag(1.1, 0.95
//                          (, 1.05)), a homogeneous stretch about c;
//   steps 2-11:           increment (R - I)(x - c), R the rotation by 9
//                          degrees about c (about z in 3D), applied to
//                          wherever the material is at the start of the step.
//
// The grid is linear (or the GIMP weights reproduce linear fields, since the
// points' domains stay inside the grid), so Delta F = F0 in the first step
// and Delta F = R in each later one, and after the 10 rotation steps
// F = Q F0 with Q the rotation by 90 degrees. Checks at every point:
//
// after step 1:  F = F0; J = det F0; the Cauchy stress equals the closed form
//                of the Hencky model, sigma = (lambda tr(ln F0) I
//                + 2 mu ln F0) / J; the point sits at c + F0 (X - c);
// after step 11: the principal stresses equal those after step 1;
//                sigma = Q sigma_1 Q^T (sigma_1 the point's stress after
//                step 1); F = Q F0; J = det F0; the point sits at
//                c + Q F0 (X - c).
//
// With linear and with cpGIMP shape functions, in 2D (plane strain) and 3D
// (rotation about z). All tolerances are far above round-off (the errors are
// below 1e-13) and far below what a wrong kinematic update gives: the
// small-strain update (Kinematics = small strain) of the same motion misses
// the closed-form stress by 13% after the stretch and changes the principal
// stresses by O(1) during the rotation.
#include "rotated_block.h"

#include <qsmpm/materials/hencky.h>

namespace
{
  const double E = 1e3, nu = 0.3;

  /// The closed-form Hencky (Cauchy) stress of F0, the Kirchhoff stress
  /// over det F0.
  template <int dim>
  SymmetricTensor<2, dim>
  hencky_stress(const Tensor<2, dim> &F0)
  {
    return rotated_block_test::log_strain_stress(F0, E, nu) / determinant(F0);
  }

  template <int dim>
  void
  test(const ShapeFunctions shape_functions, const std::string &name)
  {
    rotated_block_test::rotated_block<dim>(shape_functions,
                                           name,
                                           std::make_unique<Hencky<dim>>(E, nu),
                                           hencky_stress<dim>);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  test<2>(ShapeFunctions::linear, "linear");
  test<2>(ShapeFunctions::cpgimp, "cpGIMP");
  test<3>(ShapeFunctions::linear, "linear");
  test<3>(ShapeFunctions::cpgimp, "cpGIMP");
}
