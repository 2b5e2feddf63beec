#ifndef qsmpm_solvers_preconditioner_h
#define qsmpm_solvers_preconditioner_h

#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>
#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <memory>
#include <qsmpm/grid/background_grid.h>
#include <string>
#include <vector>

namespace qsmpm
{
  /**
   * The rigid-body modes of the grid's displacement space (dim translations
   * and dim(dim-1)/2 infinitesimal rotations about the box centre) at the
   * locally owned degrees of freedom: the near-null space of elasticity that
   * smoothed-aggregation AMG needs to coarsen vector problems well. deal.II
   * 9.4 only offers constant modes, so they are built here.
   */
  template <int dim>
  std::unique_ptr<Epetra_MultiVector>
  make_rigid_body_modes(const BackgroundGrid<dim> &grid,
                        const Epetra_Map          &owned_map);

  /**
   * The preconditioner of the Jacobian-free GMRES: an approximate inverse of
   * the stiffness K at the points (TangentAssembler), rebuilt once per load
   * step. Since the Jacobian is J ~ -K, vmult() applies -K^{-1}.
   *
   * Types: "none" (the paper's unpreconditioned GMRES), "jacobi" (diagonal
   * of K), "amg" (Trilinos ML smoothed aggregation with the rigid-body
   * near-null space, or its translations only, one W-cycle per
   * application) and "direct" (a sparse LU
   * factorization of K by Amesos KLU, once per step, then two triangular
   * solves per application). KLU gathers the matrix on one rank and its
   * cost grows faster than linearly with the size, so "direct" is for small
   * problems (a few 10^4 dofs), where it is much cheaper than AMG's setup
   * and leaves GMRES only the difference between K and the Jacobian.
   */
  template <int dim>
  class Preconditioner
  {
  public:
    enum class Type
    {
      none,
      jacobi,
      amg,
      direct
    };

    static Type
    parse_type(const std::string &name);

    /**
     * With @p rotations (the default) AMG's near-null space holds the
     * rigid-body rotations besides the translations (see
     * make_rigid_body_modes()); without, only the translations. With an
     * @p anisotropy_threshold > 0, AMG aggregates the nodes by ML's
     * auxiliary matrix of their distances (weights 1/|x_i - x_j|^2, the
     * grid's vertices), dropping connections whose scaled weight is below
     * the threshold: on stretched cells the aggregates follow the short
     * directions, along which the stiffness is strong. On cells of equal
     * sides, on a periodic grid and with 0, the aggregation is by the
     * stiffness.
     */
    explicit Preconditioner(const Type   type                 = Type::amg,
                            const bool   rotations            = true,
                            const double anisotropy_threshold = 0.);

    Type
    type() const;

    /// Whether a matrix is needed (false for none).
    bool
    needs_matrix() const;

    /**
     * Build from the stiffness @p K of the current step. @p pattern names
     * K's sparsity pattern (TangentAssembler::pattern_generation()): if it
     * is that of the last setup(), K is the same matrix object with new
     * values, and "direct" keeps KLU's symbolic factorization (its
     * fill-reducing ordering) and only refactors the values. The default,
     * an invalid number, always starts afresh.
     */
    void
    setup(const TrilinosWrappers::SparseMatrix &K,
          const BackgroundGrid<dim>            &grid,
          const unsigned int pattern = numbers::invalid_unsigned_int);

    /// dst = -P^{-1} src (identity copy for none).
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

  private:
    Type   preconditioner_type;
    bool   with_rotations;
    double anisotropy_threshold;
    /// The x, y (and z) coordinates of the locally owned nodes, in the
    /// order of their first dofs, for ML's auxiliary aggregation.
    std::array<std::vector<double>, dim> node_coordinates;
    TrilinosWrappers::PreconditionJacobi jacobi;
    TrilinosWrappers::PreconditionAMG    amg;
    std::unique_ptr<Epetra_MultiVector>  rigid_body_modes;
    /// The problem KLU works on: K, and the vectors of each vmult().
    mutable std::unique_ptr<Epetra_LinearProblem> direct_problem;
    /// Amesos KLU with its symbolic and numeric factorizations of K.
    std::unique_ptr<Amesos_BaseSolver> direct;
    /// The @p pattern of the matrix KLU analysed.
    unsigned int analysed_pattern = numbers::invalid_unsigned_int;
  };
} // namespace qsmpm

#endif
