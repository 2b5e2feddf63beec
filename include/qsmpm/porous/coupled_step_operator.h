#ifndef qsmpm_porous_coupled_step_operator_h
#define qsmpm_porous_coupled_step_operator_h

#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_vector.h>
#include <qsmpm/assembly/quasi_static_residual.h>
#include <qsmpm/core/step_operator.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>
#include <qsmpm/porous/pore_pressure_solver.h>

namespace qsmpm
{
  /**
   * The load step of a saturated body as one nonlinear problem in the
   * displacement increment and the pore pressure, for NewtonKrylov
   * (`Pore fluid/Coupling = monolithic`): the unknowns x = [du, p / s] and
   * the residual [R_u(du, p), s R_p(du, p)], R_u the displacement residual
   * of StepOperator with the pressure p at the points, R_p the flow
   * equation of PorePressureSolver, s = PorePressureSolver::pressure_scale()
   * (p / s is a displacement, s R_p a force: GMRES and Newton's stopping
   * test weigh both blocks alike).
   *
   * <h3>Preconditioner</h3>
   * Block lower-triangular, with the fixed-stress approximation of the
   * Schur complement (White, Castelletto and Tchelepi 2016, who show
   * that the fixed-stress split is a block Gauss-Seidel iteration with
   * it; GMRES with the block-triangular preconditioner then needs a
   * number of iterations bounded independently of the grid):
   *
   *   du = P_u^{-1} r_u,
   *   p  = S^{-1} (r_p - B du),   S = A + L_p N_i N_j,
   *
   * P_u the displacement's preconditioner (AMG or the direct solver, as
   * without a fluid), B the flow residual's derivative with respect to the
   * displacement (linearized at du = 0), S the flow matrix with the
   * fixed-stress term L_p = b^2 / K_p, applied by one AMG cycle.
   *
   * The residual writes the pressure of each iterate into the points'
   * pressure iterate (PorePressureSolver::set_pressure()); on return of
   * NewtonKrylov::solve() the points hold that of the returned solution.
   */
  template <int dim>
  class CoupledStepOperator
  {
  public:
    using VectorType = TrilinosWrappers::MPI::BlockVector;
    using Evaluation = typename StepOperator<dim>::Evaluation;

    /**
     * @p step: the displacement's operator of the step, @p flow the pore
     * pressure solver after its begin_step(), @p residual the residual
     * that @p step evaluates (whose packed copy of the points' fields is
     * renewed when the pressure changes).
     */
    CoupledStepOperator(const StepOperator<dim>             &step,
                        PorePressureSolver<dim>             &flow,
                        QuasiStaticResidual<dim>            &residual,
                        const ShapeCache<dim>               &cache,
                        MaterialPointSet<dim>               &points,
                        const TrilinosWrappers::MPI::Vector &du)
      : step(step)
      , flow(flow)
      , residual_evaluator(residual)
      , cache(cache)
      , points(points)
      , scale(flow.pressure_scale())
      , du_ghosted(residual.ghosted_layout())
    {
      Assert(scale > 0., ExcInternalError());
      layout.reinit(std::vector<IndexSet>{du.locally_owned_elements(),
                                          flow.locally_owned_dofs()},
                    du.get_mpi_communicator());
      // The scratch vector shares the pressure block's layout: vectors of
      // one layout copy into each other without an MPI exchange.
      p.reinit(layout.block(1));
    }

    /// The unknowns with the displacement @p du and the nodal pressure
    /// @p pressure (both in the owned layout).
    VectorType
    make_vector(const TrilinosWrappers::MPI::Vector &du,
                const TrilinosWrappers::MPI::Vector &pressure) const
    {
      VectorType x(layout);
      x.block(0) = du;
      x.block(1) = pressure;
      x.block(1) *= 1. / scale;
      return x;
    }

    /// The pressure of the unknowns @p x (owned layout) into @p p.
    void
    pressure(const VectorType &x, TrilinosWrappers::MPI::Vector &p) const
    {
      p.equ(scale, x.block(1));
    }

    Evaluation
    residual(const VectorType &x, VectorType &R) const
    {
      pressure(x, p);
      flow.set_pressure(cache, points, p);
      residual_evaluator.point_state_changed();
      const Evaluation evaluation = step.residual(x.block(0), R.block(0));
      residual_evaluator.import_ghosts(x.block(0), du_ghosted);
      flow.flow_residual(cache, du_ghosted, p, R.block(1));
      R.block(1) *= scale;
      return evaluation;
    }

    void
    set_constrained_to_zero(VectorType &v) const
    {
      step.set_constrained_to_zero(v.block(0));
      flow.set_constrained_to_zero(v.block(1));
    }

    void
    make_admissible(VectorType &v) const
    {
      step.make_admissible(v.block(0));
      flow.set_constrained_to_zero(v.block(1));
    }

    void
    precondition(VectorType &dst, const VectorType &src) const
    {
      step.precondition(dst.block(0), src.block(0));
      step.make_admissible(dst.block(0));
      residual_evaluator.import_ghosts(dst.block(0), du_ghosted);
      flow.coupling_product(cache, du_ghosted, p);
      // In the scaled unknowns: r_p / s - B du, and p / s.
      p.sadd(-1., 1. / scale, src.block(1));
      flow.set_constrained_to_zero(p);
      flow.precondition_schur(dst.block(1), p);
      dst.block(1) *= 1. / scale;
    }

    double
    typical_increment_norm() const
    {
      return step.typical_increment_norm();
    }

    double
    increment_scale_floor() const
    {
      return step.increment_scale_floor();
    }

    double
    dissipation(const Evaluation &evaluation) const
    {
      return step.dissipation(evaluation);
    }

    void
    reject_inverted_points(const Evaluation &evaluation,
                           NewtonReport     &report) const
    {
      step.reject_inverted_points(evaluation, report);
    }

  private:
    const StepOperator<dim>  &step;
    PorePressureSolver<dim>  &flow;
    QuasiStaticResidual<dim> &residual_evaluator;
    const ShapeCache<dim>    &cache;
    MaterialPointSet<dim>    &points;
    /// PorePressureSolver::pressure_scale() of the step.
    const double scale;
    /// The layout of the unknowns.
    VectorType layout;
    /// Scratch: the displacement with ghosts, a pressure-sized vector.
    mutable TrilinosWrappers::MPI::Vector du_ghosted, p;
  };
} // namespace qsmpm

#endif
