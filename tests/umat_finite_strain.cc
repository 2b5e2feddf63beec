// The UMAT adapter at finite strain (Kinematics = finite strain):
// Abaqus's co-rotational convention (DROT, rotated STRESS and STRAN,
// logarithmic strain increments) must make a hypoelastic UMAT objective.
//
// The rotated pre-stressed block of finite_strain_rotation.cc
// (rotated_block.h), with the Fortran UMAT of linear elasticity
// (tests/umat/umat_elastic.f, E = 1e3, nu = 0.3) instead of Hencky:
// stretched by F0 = diag(1.1, 0.95 (, 1.05)) in one step, then rotated by
// 90 degrees in 10 rigid steps. The closed form after the stretch: the
// UMAT gets DSTRAN = ln(Delta V) = ln F0 and returns the Cauchy stress
//
//   sigma = lambda tr(ln F0) I + 2 mu ln F0
//
// (Hencky's Kirchhoff stress; in 2D the in-plane part, ln F0_zz = 0).
// After the rotation the principal stresses are unchanged and sigma =
// Q sigma_1 Q^T to 1e-8 (objectivity), with linear and cpGIMP shape
// functions, 2D and 3D. Without the rotation of STRESS by DROT the
// stress would stay sigma_1 while the body turns: an error of O(1).
#include "rotated_block.h"

#include <qsmpm/materials/umat.h>

namespace
{
  const double E = 1e3, nu = 0.3;

  template <int dim>
  SymmetricTensor<2, dim>
  log_strain_stress(const Tensor<2, dim> &F0)
  {
    return rotated_block_test::log_strain_stress(F0, E, nu);
  }

  template <int dim>
  void
  test(const ShapeFunctions shape_functions, const std::string &name)
  {
    typename Umat<dim>::Parameters umat;
    umat.library       = std::string(QSMPM_UMAT_DIR) + "/libumat_elastic.so";
    umat.material_name = "ELASTIC";
    umat.properties    = {E, nu};
    rotated_block_test::rotated_block<dim>(shape_functions,
                                           name,
                                           std::make_unique<Umat<dim>>(umat),
                                           log_strain_stress<dim>);
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
