// The finite-difference Jacobian-vector product of paper eqs. (A.3)-(A.4)
// against the exact product -K s, with K the stiffness assembled from the
// model's tangent (exact for linear elasticity without volume updates), in
// 2D and 3D, at du = 0 and at du != 0 (both branches of Kelley's h).
// Directions s are arbitrary (deterministic pseudo-random) with zero
// constrained components. The finite-difference error is O(h) relative,
// h ~ 1e-7: tolerance 1e-5.
//
// The same with cpGIMP shape functions (linear elasticity, small strain),
// and at finite strain (Hencky, cpGIMP) after a committed deformation of
// about 5 % strain, where the assembled consistent tangent (c - tau_al
// delta_kb on the initial volume) is the exact Jacobian: at du = 0 from the
// committed state (a missing geometric term would be an error of order
// tau / E = 5e-2), at du != 0 (strains of a few 1e-3 within the step) from
// the iterate's Delta F (QuasiStaticResidual::iterate_kinematics(): the
// tangent and stress there, the gradients Delta F^{-T} grad_n N; measured
// 3.6e-7 to 5.9e-7, while the committed state's stiffness is off by 3.1e-3
// to 1.2e-2 there).
//
// The same three with F-bar (the cell's mean volume change): K then holds
// the terms of the mean (TangentAssembler::assemble() with fbar_terms, as
// at a Newton iterate), without which the product
// differs from the Jacobian's by 0.14-0.16 relative (measured with the terms
// left out: every F-bar case fails); at a finite-strain iterate the mean is
// weighted with each point's det Delta F (unweighted: 1.5e-4 to 2.1e-4).
//
// Von Mises plasticity at small strain (yield stress 0.05, E = 50: the
// iterate du != 0 yields), plane and axisymmetric, with and without F-bar:
// the matrix of the consistent tangents at the iterate (measured 9e-9 to
// 1.5e-8; the committed, elastic tangents: 0.38-0.42). Axisymmetric
// (r, z): the hoop strain's stiffness with the 3D tangent's hoop entries
// (ConstitutiveModel::consistent_tangent_axisymmetric(); those of an
// isotropic tangent taken from the in-plane one: 1.4e-2 to 1.5e-2 at the
// yielding iterate), and F-bar's terms of the mean of the three normal
// strains (without them: 0.12-0.17).
//
// Von Mises at finite strain (cpGIMP, after the committed deformation
// above, which stays elastic under the yield stress 6; an iterate du != 0
// 60 times larger, which yields), plane and axisymmetric, with and without
// F-bar: 3.2e-8 to 3.5e-8 (the committed state's matrix: 0.66-0.74).
// Axisymmetric, the stiffness of the hoop terms at the iterate: the 3D
// tangent kirchhoff_tangent_axisymmetric() (with the hoop entries of an
// isotropic tangent instead: 1.4e-2 to 1.5e-2), the hoop stretch in the
// hoop gradient N / (r Delta F_tt) (without it: 1.1e-2 to 1.7e-2) and the
// hoop stress's geometric term -tau_tt (without it: 8.4e-3 to 1.1e-2).
#include "tests.h"

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_tools.h>
#include <qsmpm/assembly/quasi_static_residual.h>
#include <qsmpm/assembly/tangent_assembler.h>
#include <qsmpm/loading/boundary_descriptor.h>
#include <qsmpm/loading/displacement_constraints.h>
#include <qsmpm/materials/hencky.h>
#include <qsmpm/materials/linear_elastic.h>
#include <qsmpm/materials/von_mises.h>
#include <qsmpm/solvers/jacobian_free_operator.h>

template <int dim>
struct Operator
{
  const qsmpm::QuasiStaticResidual<dim> &residual_evaluator;
  const AffineConstraints<double>       &constraints;
  void
  residual(const TrilinosWrappers::MPI::Vector &du,
           TrilinosWrappers::MPI::Vector       &R) const
  {
    residual_evaluator.evaluate(du, R);
  }
  void
  set_constrained_to_zero(TrilinosWrappers::MPI::Vector &v) const
  {
    constraints.set_zero(v);
  }
  double
  typical_increment_norm() const
  {
    return residual_evaluator.typical_increment_norm();
  }
};

// yield_stress > 0: von Mises plasticity instead of linear elasticity (at
// finite strain instead of Hencky), and at finite strain an iterate
// @p iterate_size times larger (1e-3); the iterate du != 0 then yields at
// most points.
template <int dim>
void
test(const qsmpm::Formulation &formulation,
     const double              yield_stress = 0.,
     const double              iterate_size = 1e-3)
{
  const bool                    finite_strain = formulation.finite_strain();
  qsmpm::BackgroundGrid<dim>    grid(MPI_COMM_WORLD);
  Point<dim>                    upper;
  std::array<unsigned int, dim> n;
  for (unsigned int d = 0; d < dim; ++d)
    {
      upper[d] = 1. + d;
      n[d]     = 4 + d;
    }
  grid.make_box(Point<dim>(), upper, n);
  std::unique_ptr<qsmpm::ConstitutiveModel<dim>> model;
  if (yield_stress > 0.)
    model = std::make_unique<qsmpm::VonMises<dim>>(50., 0.3, yield_stress);
  else if (finite_strain)
    model = std::make_unique<qsmpm::Hencky<dim>>(50., 0.3);
  else
    model = std::make_unique<qsmpm::LinearElastic<dim>>(50., 0.3);
  qsmpm::MaterialPointSet<dim> points(grid, *model, formulation);
  // The body does not fill the grid: inactive nodes are constrained.
  points.fill([](const Point<dim> &x) { return x[0] < 0.8; },
              2,
              qsmpm::MaterialPointSet<dim>::Placement::regular);

  qsmpm::ShapeCache<dim>          cache;
  qsmpm::QuasiStaticResidual<dim> residual(grid,
                                           points,
                                           cache,
                                           /*update_volumes=*/finite_strain);
  cache.reinit(grid, points, residual.ghosted_layout());

  qsmpm::BoundaryDescriptor<dim> bcs;
  std::array<bool, dim>          all;
  all.fill(true);
  bcs.add_dirichlet_boundary(
    0, all, std::make_shared<Functions::ZeroFunction<dim>>(dim));
  AffineConstraints<double> constraints;
  qsmpm::DisplacementConstraints<dim>(bcs).make(grid, 0., 1., constraints);
  for (const auto dof : cache.dofs_without_points(grid))
    if (!constraints.is_constrained(dof))
      constraints.add_line(dof);
  constraints.close();

  TrilinosWrappers::MPI::Vector f_ext(grid.locally_owned_dofs(),
                                      MPI_COMM_WORLD);
  residual.set_external_force(f_ext);
  TrilinosWrappers::MPI::Vector s(f_ext), du(f_ext), du_iterate(f_ext),
    R(f_ext), Js(f_ext), Ks(f_ext);
  if (finite_strain)
    {
      // A committed deformation, u_i = 0.05 x_0 (1 + 0.3 sin(1 + 2 i)) at
      // every dof i (zero on the clamped face x_0 = 0), strains of about
      // 5 %; the step then starts from it.
      TrilinosWrappers::MPI::Vector                 u0(f_ext);
      std::map<types::global_dof_index, Point<dim>> support;
      DoFTools::map_dofs_to_support_points(grid.get_mapping(),
                                           grid.get_dof_handler(),
                                           support);
      for (const auto i : grid.locally_owned_dofs())
        {
          const Point<dim> &x = support.at(i);
          u0(i) = 0.05 * x[0] * (1. + 0.3 * std::sin(1. + 2. * i));
        }
      u0.compress(VectorOperation::insert);
      constraints.set_zero(u0);
      TrilinosWrappers::MPI::Vector u0_ghosted(grid.locally_owned_dofs(),
                                               grid.locally_relevant_dofs(),
                                               MPI_COMM_WORLD);
      u0_ghosted = u0;
      residual.commit(u0_ghosted);
    }
  qsmpm::TangentAssembler<dim> tangent;
  tangent.reinit(grid, formulation.gimp());

  for (const auto i : grid.locally_owned_dofs())
    {
      s(i)          = std::sin(1. + 3.7 * i);
      du_iterate(i) = iterate_size * std::cos(0.3 + 1.3 * i);
    }
  s.compress(VectorOperation::insert);
  du_iterate.compress(VectorOperation::insert);
  constraints.set_zero(s);
  constraints.set_zero(du_iterate);

  const Operator<dim>           op{residual, constraints};
  qsmpm::IterateKinematics<dim> iterate;
  for (const bool zero_du : {true, false})
    {
      if (zero_du)
        du = 0.;
      else
        {
          du = du_iterate;
          residual.iterate_kinematics(du, iterate);
        }
      // At du = 0 the stiffness of the committed state; at du != 0 that
      // of the iterate (at finite strain its Delta F moves the gradients,
      // the stress and the tangent by about 1e-2).
      tangent.assemble(grid,
                       points,
                       cache,
                       constraints,
                       nullptr,
                       {},
                       qsmpm::TangentAssembler<dim>::Tangent::secant,
                       zero_du ? nullptr : &iterate,
                       /*fbar_terms=*/true);
      residual.evaluate(du, R);
      const qsmpm::JacobianFreeOperator<Operator<dim>,
                                        TrilinosWrappers::MPI::Vector>
        J(op, du, R, 1e-7);
      J.vmult(Js, s);
      tangent.matrix().vmult(Ks, s);
      constraints.set_zero(Ks);
      Js += Ks; // J s = -K s
      deallog << dim << "D, "
              << (formulation.axisymmetric ? "axisymmetric, " : "")
              << (yield_stress > 0. ? "von Mises, " : "")
              << (finite_strain && yield_stress > 0. ? "finite strain, " :
                  finite_strain      ? "finite strain (hencky), " :
                  formulation.gimp() ? "small strain, " :
                                       "")
              << (formulation.gimp() ? "cpGIMP, " : "")
              << (formulation.fbar() ? "F-bar, " : "") << "du "
              << (zero_du ? "= 0" : "!= 0") << std::endl;
      check("  ||J_fd s - (-K s)|| / ||K s||",
            Js.l2_norm() / Ks.l2_norm(),
            1e-5);
    }
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;
  qsmpm::Formulation               linear, gimp, finite;
  gimp.shape_functions   = qsmpm::ShapeFunctions::cpgimp;
  finite.shape_functions = qsmpm::ShapeFunctions::cpgimp;
  finite.kinematics      = qsmpm::Kinematics::finite_strain;
  for (const auto &formulation : {linear, gimp, finite})
    {
      test<2>(formulation);
      test<3>(formulation);
    }
  // F-bar: the stiffness of the cell's mean volume change (B-bar forces
  // at small strain, plain virtual gradients at finite strain).
  for (auto formulation : {linear, gimp, finite})
    {
      formulation.volumetric = qsmpm::VolumetricTreatment::fbar;
      test<2>(formulation);
      test<3>(formulation);
    }
  // Plasticity at small strain: the consistent tangents at the iterate.
  // Axisymmetric (r, z): the hoop strain's stiffness with the 3D tangent's
  // hoop entries (ConstitutiveModel::consistent_tangent_axisymmetric()),
  // and with F-bar the mean of three normal strains.
  qsmpm::Formulation axisymmetric;
  axisymmetric.axisymmetric = true;
  for (auto formulation : {linear, axisymmetric})
    for (const bool fbar : {false, true})
      {
        if (fbar)
          formulation.volumetric = qsmpm::VolumetricTreatment::fbar;
        if (formulation.axisymmetric)
          test<2>(formulation);
        test<2>(formulation, /*yield_stress=*/0.05);
      }
  // Von Mises at finite strain (Hencky inside the surface, cpGIMP), plane
  // and axisymmetric, with and without F-bar: the committed deformation
  // stays elastic (yield stress 6), the iterate du != 0, 60 times larger
  // than above, yields. Axisymmetric: the 3D tangent at the iterate
  // (kirchhoff_tangent_axisymmetric()), the hoop stretch in the hoop
  // gradient and the hoop stress's geometric term.
  for (const bool axisymmetric_problem : {false, true})
    for (const bool fbar : {false, true})
      {
        qsmpm::Formulation formulation = finite;
        formulation.axisymmetric       = axisymmetric_problem;
        if (fbar)
          formulation.volumetric = qsmpm::VolumetricTreatment::fbar;
        test<2>(formulation, /*yield_stress=*/6., /*iterate_size=*/6e-2);
      }
}
