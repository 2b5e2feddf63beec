#ifndef qsmpm_assembly_tangent_assembler_h
#define qsmpm_assembly_tangent_assembler_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <functional>
#include <qsmpm/assembly/ghost_penalty.h>
#include <qsmpm/assembly/iterate_kinematics.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>

namespace qsmpm
{
  /**
   * The stiffness matrix at the material points,
   *
   *   K_ij = sum_p Omega_p B_i(x_p)^T C_p B_j(x_p),
   *
   * with C_p the tangent the constitutive model supplies at the committed
   * state of point p (or at a Newton iterate, assemble()), and with F-bar
   * possibly the terms of the cell's mean volume change (B-bar at small
   * strain).
   * Since R(du) = f_ext - f_int(du), the Jacobian of the
   * residual is J = -K when C_p is the exact tangent (linear models, without
   * volume updates); otherwise K is an approximation that is good enough to
   * precondition the Jacobian-free GMRES.
   *
   * Rows and columns of constrained degrees of freedom carry only a diagonal
   * entry, so the matrix is regular and AMG can be built on it.
   */
  template <int dim>
  class TangentAssembler
  {
  public:
    /**
     * Build the sparsity pattern of the grid (once, or after the grid
     * changed). With @p gimp, the pattern is instead built in every
     * assemble() from the nodes that the points of each cell reach (the
     * nodes of the 3^dim cells around it at most), across periodic faces
     * and MPI ranks too.
     */
    void
    reinit(const BackgroundGrid<dim> &grid, const bool gimp = false);

    /// A term that adds its stiffness to K with the step's constraints,
    /// within the couplings K's pattern already has (e.g. the contact of
    /// the points with rigid bodies).
    using AdditionalTerm =
      std::function<void(const AffineConstraints<double> &,
                         TrilinosWrappers::SparseMatrix &)>;

    /// Which tangent of the constitutive model K is built from.
    enum class Tangent
    {
      /// ConstitutiveModel::tangent(): positive definite where the model
      /// softens (a secant), for AMG and Jacobi.
      secant,
      /// ConstitutiveModel::loading_tangent(): the slope of the branch each
      /// point is on, possibly indefinite, for a direct factorization.
      loading
    };

    /**
     * Assemble K at the points of @p cache from the model's @p kind of
     * tangent, plus the matrix of @p ghost_penalty if given (its couplings
     * across faces then join the pattern, made anew for the step), plus
     * @p additional_term if given.
     *
     * With @p iterate (QuasiStaticResidual::iterate_kinematics() of a
     * Newton iterate), K is instead the stiffness at that iterate: at small
     * strain the model's ConstitutiveModel::consistent_tangent() at each
     * point's strain increment (axisymmetric:
     * consistent_tangent_axisymmetric(), whose hoop entries the hoop
     * strain's stiffness takes); at finite strain its kirchhoff_tangent()
     * and Kirchhoff stress at the point's Delta F, with the gradients
     * Delta F^{-T} grad_n N of the residual's tau Delta F^{-T} grad_n N,
     * and F-bar's mean weighted with each point's det Delta F
     * (axisymmetric: kirchhoff_tangent_axisymmetric(), the hoop stretch
     * Delta F_tt in the hoop gradient N / (r Delta F_tt) and in det Delta
     * F, and the hoop stress's geometric term). So K is the Jacobian of the
     * residual there (elastoplastic where the iterate yields; with the geometry
     * and stress of the iterate at finite strain), which the tangents of the
     * committed state are not. A point whose tangent the model cannot give
     * there (an exception, a value that is not finite, an inverted point) gets
     * that of its committed state.
     *
     * With @p fbar_terms and F-bar, K holds the terms of the cell's mean
     * volume change (in axisymmetric problems the mean of the three
     * normal strains, the hoop strain among them), without which
     * it is not the Jacobian of the F-bar residual (0.12-0.17 off on an
     * elastic or plastic block: test jacobian_product). The matrix at a
     * Newton iterate has them (QuasiStaticProblem); the one built once per
     * step from the committed state, whose yielding points are elastic in
     * it anyway, does not: there they saved 2-7 % of the GMRES iterations
     * of the footings of examples/footing, and they would move every curve
     * of perfect plasticity with F-bar within the Newton tolerance
     * (doc/benchmarks.md).
     */
    void
    assemble(const BackgroundGrid<dim>       &grid,
             const MaterialPointSet<dim>     &points,
             const ShapeCache<dim>           &cache,
             const AffineConstraints<double> &constraints,
             const GhostPenalty<dim>         *ghost_penalty   = nullptr,
             const AdditionalTerm            &additional_term = {},
             const Tangent                    kind            = Tangent::secant,
             const IterateKinematics<dim>    *iterate         = nullptr,
             const bool                       fbar_terms      = false);

    const TrilinosWrappers::SparseMatrix &
    matrix() const;



    /// Whether the pattern is built in every assemble() (GIMP, reinit()).
    bool
    has_step_patterns() const
    {
      return pattern_per_step;
    }

    /**
     * A number that changes whenever matrix() gets a new sparsity pattern
     * (in reinit(), and with GIMP in every assemble()): while it stays the
     * same, a factorization may keep its symbolic part.
     */
    unsigned int
    pattern_generation() const
    {
      return n_patterns;
    }

    /**
     * The diagonal of K without any constraint, K_(i,a),(i,a) = sum_p
     * Omega_p grad N_i . C_p[a, ., a, .] . grad N_i: the stiffness of each
     * degree of freedom against its own motion. @p diagonal is a vector of
     * the grid's locally owned dofs; its entries are summed over the ranks.
     * A node whose points have all lost their stiffness in a direction (a
     * completely failed crack band that opens) has a zero here: the step's
     * linear systems are singular unless that dof is held.
     */
    static void
    assemble_diagonal(const MaterialPointSet<dim>   &points,
                      const ShapeCache<dim>         &cache,
                      TrilinosWrappers::MPI::Vector &diagonal);

  private:
    /// GIMP: the pattern of the couplings that the points reach this step.
    void
    make_step_pattern(const BackgroundGrid<dim> &grid,
                      const ShapeCache<dim>     &cache,
                      const GhostPenalty<dim>   *ghost_penalty);

    TrilinosWrappers::SparseMatrix K;
    AffineConstraints<double>      periodicity;
    IndexSet                       writable_rows;
    bool                           pattern_per_step = false;
    unsigned int                   n_patterns       = 0;
  };
} // namespace qsmpm

#endif
