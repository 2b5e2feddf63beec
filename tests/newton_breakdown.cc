// What NewtonKrylov reports when GMRES breaks down. deal.II's GMRES divides
// by zero where its Hessenberg matrix is singular and returns a correction
// that is not a finite number; the load step then failed with "the residual
// is not a finite number", which named the symptom, not the cause (the
// Mohr-Coulomb footing of examples/footing with cpGIMP: a node whose points
// had reached the apex of the yield surface, on which the residual does not
// depend at all). The report must name the cause instead.
//
// A two-dof operator R(u) = A u - f whose answers are known:
// - A = diag(2, 1), f = (2, 3): regular; Newton converges to u = (1, 3)
//   (checked to 1e-10 of |u|).
// - A = diag(1, 0), f = (1, 1): singular and f outside its range. The
//   Krylov space of f is all of R^2, A is singular on it, GMRES breaks down
//   in its second iteration: "the Jacobian is singular", from the linear
//   predictor and from the first Newton iteration alike.
// - The same A with the preconditioner diag(1, 1 / A_11) (Jacobi of a
//   singular diagonal: a vector with an infinite entry): "the
//   preconditioner returned a vector that is not a finite number".
// - A = diag(2, 1) with a residual that is not a finite number wherever
//   u_0 != 0 (a constitutive update that fails off the committed state):
//   "the residual of a perturbed iterate".
//
// And where Newton stops, which decides how much of a load a step leaves
// unbalanced. A = diag(1, 1.2), f = (1, 1), no preconditioner and one
// GMRES iteration per Newton iteration: each iteration lowers |R| by the
// same factor, 0.0905 (the residual alternates between the directions
// (1, 1) and (6, -5)), so the residual at which the solve stops is set by
// the stopping test alone. Without a ceiling: at most 1e-6 |R_0| and more
// than 1e-9 |f| (gamma = 1e-6 of the first residual |R_0| = |f|). With
// NewtonParameters::residual_ceiling = 1e-9 |f| (what QuasiStaticProblem
// sets where a rigid body's penalty forces make |R_0| far larger than the
// forces in the body): at most the ceiling.
#include "tests.h"

#include <deal.II/lac/trilinos_vector.h>
#include <limits>
#include <qsmpm/solvers/newton_krylov.h>

using VectorType = TrilinosWrappers::MPI::Vector;

struct TwoDofOperator
{
  double a0, a1;
  double f0, f1;
  bool   jacobi          = false; // the preconditioner diag(1 / A)
  bool   nan_off_u0_zero = false; // R not finite where u_0 != 0

  // What the evaluation found besides R: nothing here.
  int
  residual(const VectorType &u, VectorType &R) const
  {
    R(0) = a0 * u(0) - f0;
    R(1) = a1 * u(1) - f1;
    if (nan_off_u0_zero && u(0) != 0.)
      R(0) = std::numeric_limits<double>::quiet_NaN();
    R.compress(VectorOperation::insert);
    return 0;
  }
  void
  set_constrained_to_zero(VectorType &) const
  {
  }
  void
  make_admissible(VectorType &) const
  {
  }
  // J = A; the preconditioner approximates J^{-1}.
  void
  precondition(VectorType &dst, const VectorType &src) const
  {
    dst = src;
    if (jacobi)
      {
        dst(0) = src(0) / a0;
        dst(1) = src(1) / a1;
        dst.compress(VectorOperation::insert);
      }
  }
  double
  typical_increment_norm() const
  {
    return 1.;
  }
};

void
solve(const std::string &name, const TwoDofOperator &op, const bool predictor)
{
  qsmpm::NewtonParameters parameters;
  parameters.initial_guess =
    predictor ? qsmpm::NewtonParameters::InitialGuess::linear_predictor :
                qsmpm::NewtonParameters::InitialGuess::boundary_values;
  parameters.tolerance        = 1e-12;
  parameters.linear_tolerance = 1e-12;
  const qsmpm::NewtonKrylov<TwoDofOperator, VectorType> newton(parameters);

  VectorType                u(complete_index_set(2), MPI_COMM_WORLD), R;
  const qsmpm::NewtonReport report = newton.solve(op, u, R);
  deallog << name << (predictor ? ", linear predictor: " : ", Newton: ");
  if (report.converged)
    {
      const double error =
        std::hypot(u(0) - op.f0 / op.a0, u(1) - op.f1 / op.a1) /
        std::hypot(op.f0 / op.a0, op.f1 / op.a1);
      deallog << "converged, |u - A^-1 f| / |A^-1 f| < 1e-10: "
              << (error < 1e-10 ? "yes" : "NO") << std::endl;
    }
  else
    deallog << "failed: " << report.failure << std::endl;
}

void
stop(const double ceiling)
{
  const TwoDofOperator    op{1., 1.2, 1., 1.};
  qsmpm::NewtonParameters parameters;
  parameters.initial_guess =
    qsmpm::NewtonParameters::InitialGuess::boundary_values;
  parameters.max_linear_iterations = 1;
  parameters.max_iterations        = 40;
  parameters.residual_ceiling      = ceiling;
  const qsmpm::NewtonKrylov<TwoDofOperator, VectorType> newton(parameters);

  VectorType                u(complete_index_set(2), MPI_COMM_WORLD), R;
  const qsmpm::NewtonReport report = newton.solve(op, u, R);
  const double              f      = std::sqrt(2.);
  deallog << "A = diag(1, 1.2), "
          << (ceiling > 0. ? "ceiling 1e-9 |f|: " : "no ceiling: ")
          << (report.converged ? "converged" : "FAILED");
  if (ceiling > 0.)
    deallog << ", |R| <= ceiling: "
            << (report.final_residual <= ceiling ? "yes" : "NO");
  else
    deallog << ", |R| <= 1e-6 |R_0|: "
            << (report.final_residual <= 1e-6 * report.initial_residual ?
                  "yes" :
                  "NO")
            << ", |R| > 1e-9 |f|: "
            << (report.final_residual > 1e-9 * f ? "yes" : "NO");
  deallog << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::initlog();

  for (const bool predictor : {true, false})
    {
      solve("regular A", {2., 1., 2., 3.}, predictor);
      solve("singular A", {1., 0., 1., 1.}, predictor);
      TwoDofOperator jacobi{1., 0., 1., 1.};
      jacobi.jacobi = true;
      solve("singular A, Jacobi", jacobi, predictor);
      TwoDofOperator nan{2., 1., 2., 3.};
      nan.nan_off_u0_zero = true;
      solve("perturbed residual not finite", nan, predictor);
    }
  stop(0.);
  stop(1e-9 * std::sqrt(2.)); // 1e-9 |f|
}
