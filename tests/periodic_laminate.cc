// Periodic boundary conditions (BackgroundGrid::make_periodic,
// BoundaryDescriptor::set_macroscopic_displacement_gradient, condensed
// Newton-Krylov) against an exact homogenization result.
//
// A laminate of two nickel crystals (C11, C12, C44 = 249, 155, 114 GPa),
// layers normal to x of equal thickness, orientations g_A = (0, 0, 0) and
// g_B = (31, 47, 68) degrees (Bunge). Its effective stiffness is known in
// closed form: the strain is constant in each layer, the layers' strains
// differ by sym(a (x) n) (compatibility) and the traction sigma n is the same
// in both (equilibrium),
//
//   (f_B C_A + f_A C_B) : sym(a (x) n) . n = (C_B - C_A) : E . n,
//   eps_A = E + f_B sym(a (x) n),  eps_B = E - f_A sym(a (x) n),
//   C_eff : E = f_A C_A : eps_A + f_B C_B : eps_B.
//
// The test computes that 6x6 matrix independently of the MPM code (a 3x3
// solve per column) and runs the six virtual tests with periodic boundary
// conditions on a 4x2x2 grid with 2^3 points per cell. The exact
// displacement is piecewise linear in x with kinks on grid planes, which Q1
// represents, and 2 points per direction integrate the gradients of Q1
// exactly, so MPM must reproduce C_eff to the solver tolerance: 1e-6
// relative (Newton 1e-9 of the first residual, GMRES 1e-10). Volumes are not
// updated, because det F differs between the layers and would change the
// weights of the volume average by O(strain).
//
// Checks: C_MPM = C_eff within 1e-6; the mean strain of every test equals
// the prescribed one within 1e-8 (periodic fluctuations have zero mean);
// affine boundary conditions, which force a uniform strain on the faces
// that cut the layers, are stiffer than C_eff (1.1 % on this grid; the check
// asks for 0.1 %, 1000 times the tolerance of the first check). Run on 1
// and 2 ranks.
//
// First, the .prm route in 2D: a homogeneous linear elastic body, periodic
// in x and y (<Periodic directions> = xy) with a macroscopic displacement
// gradient H (non-symmetric) in two load steps. The exact increment of a
// step is (H / 2) x at the grid (the corner node at the origin is held), and
// the points move with it, so after the two steps a point from x_0 is at
// (I + H / 2)^2 x_0, and its (small) strain is the sum of the increments'
// gradients, sym(H); both to the solver tolerance.
#include "tests.h"

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <qsmpm/base/rotation.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/homogenization/virtual_tests.h>
#include <qsmpm/materials/cubic_elastic.h>

using namespace qsmpm;

namespace
{
  constexpr unsigned int voigt_i[6] = {0, 1, 2, 1, 0, 0};
  constexpr unsigned int voigt_j[6] = {0, 1, 2, 2, 2, 1};

  using Matrix6 = VirtualTests::Matrix6;

  // The laminate's effective stiffness in Voigt notation (engineering shear).
  Matrix6
  laminate_stiffness(const SymmetricTensor<4, 3> &C_A,
                     const SymmetricTensor<4, 3> &C_B,
                     const double                 f_A)
  {
    const double       f_B = 1. - f_A;
    const Tensor<1, 3> n({1., 0., 0.});
    FullMatrix<double> K(3, 3);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int l = 0; l < 3; ++l)
            K(i, k) +=
              (f_B * C_A[i][j][k][l] + f_A * C_B[i][j][k][l]) * n[j] * n[l];
    K.gauss_jordan();

    Matrix6 C{};
    for (unsigned int col = 0; col < 6; ++col)
      {
        SymmetricTensor<2, 3> E;
        E[voigt_i[col]][voigt_j[col]] = (col < 3 ? 1. : 0.5);
        const Tensor<1, 3> rhs        = Tensor<2, 3>((C_B - C_A) * E) * n;
        Tensor<1, 3>       a;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int k = 0; k < 3; ++k)
            a[i] += K(i, k) * rhs[k];
        const SymmetricTensor<2, 3> jump = symmetrize(outer_product(a, n));
        const SymmetricTensor<2, 3> sigma =
          f_A * (C_A * (E + f_B * jump)) + f_B * (C_B * (E - f_A * jump));
        for (unsigned int row = 0; row < 6; ++row)
          C[row][col] = sigma[voigt_i[row]][voigt_j[row]];
      }
    return C;
  }

  void
  homogeneous_2d()
  {
    ParameterHandler prm;
    QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Geometry\n"
      "  set Upper corner = 1.5, 1\n"
      "  set Subdivisions = 3, 4\n"
      "  set Periodic directions = xy\n"
      "end\n"
      "subsection Boundary conditions\n"
      "  set Macroscopic displacement gradient = 2e-3, 1e-3, -5e-4, 1.5e-3\n"
      "end\n"
      "subsection Load stepping\n"
      "  set Number of steps = 2\n"
      "end\n"
      "subsection Nonlinear solver\n"
      "  set Tolerance      = 1e-10\n"
      "  set Residual floor = 0\n"
      "  set Linear tolerance = 1e-11\n"
      "end\n"
      "subsection Output\n"
      "  set Directory = results\n"
      "  set Interval  = 0\n"
      "end\n");
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    problem.pcout().set_condition(false);
    problem.initialize(prm);
    problem.run();

    Tensor<2, 2> H;
    H[0][0]              = 2e-3;
    H[0][1]              = 1e-3;
    H[1][0]              = -5e-4;
    H[1][1]              = 1.5e-3;
    const auto  &offsets = problem.points().get_offsets();
    double       u_error = 0, strain_error = 0;
    unsigned int newton_max = 0;
    for (const auto &particle : problem.points().get_particle_handler())
      {
        const double *data = particle.get_properties().data();
        Tensor<1, 2>  u;
        for (unsigned int d = 0; d < 2; ++d)
          u[d] = data[offsets.displacement + d];
        const Point<2>     x0        = particle.get_location() - u;
        const Tensor<2, 2> half_step = unit_symmetric_tensor<2>() + 0.5 * H;
        u_error                      = std::max(u_error,
                           (particle.get_location() -
                            Point<2>(half_step * (half_step * x0)))
                             .norm());
        strain_error =
          std::max(strain_error,
                   (Utils::read_symmetric<2>(data + offsets.strain) -
                    symmetrize(H))
                     .norm());
      }
    for (const auto &step : problem.step_reports())
      newton_max = std::max(newton_max, step.newton.newton_iterations);
    u_error      = Utilities::MPI::max(u_error, MPI_COMM_WORLD) / H.norm();
    strain_error = Utilities::MPI::max(strain_error, MPI_COMM_WORLD) / H.norm();
    deallog << "2D, homogeneous, periodic in x and y, from a .prm" << std::endl;
    check("  max |x_p - (I + H / 2)^2 x_0| / |H|", u_error, 1e-8);
    check("  max |eps_p - sym H| / |H|", strain_error, 1e-8);
    check_that("  2 steps of 1 to 3 Newton iterations",
               problem.step_reports().size() == 2 && newton_max >= 1 &&
                 newton_max <= 3);
  }

  double
  relative_difference(const Matrix6 &A, const Matrix6 &B)
  {
    double diff = 0, norm = 0;
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = 0; j < 6; ++j)
        {
          diff += (A[i][j] - B[i][j]) * (A[i][j] - B[i][j]);
          norm += B[i][j] * B[i][j];
        }
    return std::sqrt(diff / norm);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  homogeneous_2d();

  const double       deg = M_PI / 180.;
  const double       C11 = 249., C12 = 155., C44 = 114.;
  const Tensor<2, 3> g_A = Rotation::from_bunge(0., 0., 0.);
  const Tensor<2, 3> g_B = Rotation::from_bunge(31 * deg, 47 * deg, 68 * deg);
  const auto         C   = Rotation::cubic_stiffness(C11, C12, C44);
  const Matrix6 exact = laminate_stiffness(Rotation::rotate_to_sample(C, g_A),
                                           Rotation::rotate_to_sample(C, g_B),
                                           0.5);

  auto make_model = [&]() {
    auto model = std::make_unique<CubicElastic<3>>(C11, C12, C44);
    model->set_orientation(
      [&](const Point<3> &x) { return x[0] < 0.5 ? g_A : g_B; });
    return std::unique_ptr<ConstitutiveModel<3>>(std::move(model));
  };

  VirtualTests::Parameters p;
  p.subdivisions            = {{4, 2, 2}};
  p.points_per_direction    = 2;
  p.n_load_steps            = 1;
  p.update_volumes          = false;
  p.solver.tolerance        = 1e-9;
  p.solver.residual_floor   = 0.;
  p.solver.linear_tolerance = 1e-10;
  p.solver.preconditioner   = "amg";
  p.output_directory        = "results";

  deallog << "Two-crystal laminate, periodic boundary conditions" << std::endl;
  p.boundary_type = VirtualTests::BoundaryType::periodic;
  VirtualTests periodic(p, MPI_COMM_WORLD);
  periodic.run(make_model);
  check("  |C_MPM - C_laminate| / |C_laminate|",
        relative_difference(periodic.stiffness(), exact),
        1e-6);
  double strain_error = 0;
  for (unsigned int k = 0; k < 6; ++k)
    for (unsigned int a = 0; a < 6; ++a)
      strain_error = std::max(strain_error,
                              std::abs(periodic.reports()[k].mean_strain[a] -
                                       (a == k ? p.strain : 0.)) /
                                p.strain);
  check("  max |mean strain - prescribed strain| / strain", strain_error, 1e-8);
  unsigned int newton_min = 100, newton_max = 0;
  for (const auto &report : periodic.reports())
    {
      newton_min = std::min(newton_min, report.newton_iterations);
      newton_max = std::max(newton_max, report.newton_iterations);
    }
  check_that("  Newton iterations per test within 1 to 3",
             newton_min >= 1 && newton_max <= 3);
  bool any_reaction = false;
  for (const auto &row : periodic.reaction_mask())
    for (const bool measured : row)
      any_reaction = any_reaction || measured;
  check_that("  no reaction stress is reported", !any_reaction);

  deallog << "The same laminate, affine boundary conditions" << std::endl;
  p.boundary_type = VirtualTests::BoundaryType::affine;
  VirtualTests affine(p, MPI_COMM_WORLD);
  affine.run(make_model);
  check_at_least("  |C_affine - C_laminate| / |C_laminate|",
                 relative_difference(affine.stiffness(), exact),
                 1e-3);
}
