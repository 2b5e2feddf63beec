#ifndef qsmpm_loading_rigid_plates_h
#define qsmpm_loading_rigid_plates_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/loading/boundary_descriptor.h>
#include <qsmpm/loading/preconditioner_correction.h>
#include <vector>

namespace qsmpm
{
  /**
   * Boundaries of the grid that move as rigid, frictionless plates along
   * their normal, by an amount that is not prescribed but follows from the
   * load on them (BoundaryDescriptor::add_rigid_plate()): a plate pressed
   * onto a sample by a given force (an oedometer, Mandel's problem, a
   * footing of uniform settlement). The force is the traction on the
   * boundary (BoundaryDescriptor::add_traction(), <Traction boundaries>);
   * its resultant is what the plate carries, however it spreads over the
   * nodes.
   *
   * <h3>How</h3>
   * The plate's unknowns are the normal components u_i, i in T, of its
   * grid nodes that carry material (T excludes the held and the
   * constrained ones). The residual of the step is evaluated at P du, the
   * increment with all u_i of a plate replaced by their mean ubar, and its
   * rows in T are replaced by
   *
   *   Rtilde_i = Rbar - kbar (du_i - ubar),   Rbar = (1/|T|) sum_T R_j(P du),
   *
   * kbar the mean stiffness of the step's degrees of freedom. At a
   * solution, summing over T gives Rbar = 0 (the plate is in equilibrium:
   * the material's force on it balances the traction), and then
   * du_i = ubar (it moves as one). The tie is exact, not a penalty: kbar
   * only scales the rows, like those of the material, so that Newton's
   * norms and GMRES see them alike. The rest of the body sees P du, so
   * the internal forces are those of the rigid motion. One sum over the
   * ranks per residual; no constraint couples dofs of different ranks.
   *
   * <h3>The preconditioner</h3>
   * The preconditioner's matrix K_A gets the tie's diagonal, kbar, in the
   * rows of T (add_to()), not its coupling through the mean, so AMG sees
   * the plate's nodes as held by springs instead of moving as one.
   * precondition() completes it with what the tie changes. Written with
   * Q, the map from the unknowns of the tied problem (the free dofs and
   * one ubar per plate) to the increment P du, the Jacobian's equations
   * are, exactly: Q^T K Q y = Q^T r (the rows of each plate summed: its
   * equilibrium) and, in each plate row, du_i - ubar = (r_i - mean_T r) /
   * kbar (up to the sign convention of Preconditioner::vmult()). So
   *
   *   1. z = K_A^{-1} r (the preconditioner) with its plate entries
   *      replaced by their mean (z in the range of Q);
   *   2. a coarse correction in the span of the plates' modes phi_k:
   *      z += sum_k c_k phi_k, (Phi^T K Phi) c = Phi^T (r - K z), with
   *      phi_k the plate k moved by one and the body following it
   *      (K phi_k = 0 in the rows of the free dofs, from a few sweeps of
   *      the preconditioner, setup_preconditioner()), so that the plate's
   *      motion, which the springs of K_A hold back, is the one that
   *      balances the residual's force on the plate;
   *   3. the plate entries' deviations from the mean, exactly.
   *
   * K is the material's part of K_A: K_A minus the diagonal add_to()
   * added when K_A was assembled (kept, since a preconditioner may serve
   * several steps). The cost per application: one product with K_A and
   * a few sums over the ranks; per new preconditioner (or new plate
   * nodes): four sweeps per plate. On Mandel's specimen (32 x 32 cells,
   * 400 steps, examples/consolidation) GMRES per Newton iteration falls
   * from 6.97 to 4.06 with the fixed-stress split and from 12.99 to 7.19
   * with the monolithic coupling (two sweeps: 4.37 and 9.48, eight: 4.04
   * and 7.62).
   */
  template <int dim>
  class RigidPlates
    : public PreconditionerCorrection<TrilinosWrappers::MPI::Vector>
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    /// The plates of @p boundary, which must outlive this object.
    explicit RigidPlates(const BoundaryDescriptor<dim> &boundary);

    /// Whether there are plates at all.
    bool
    empty() const;

    /**
     * The plates' degrees of freedom of a step: the normal component at
     * every node of their faces that this rank owns and @p constraints
     * leave free; @p stiffness_scale is kbar. Throws with a message naming
     * the plate if none of its nodes carries material. Collective.
     */
    void
    reinit_step(const BackgroundGrid<dim>       &grid,
                const AffineConstraints<double> &constraints,
                const double                     stiffness_scale);

    /// P du: @p du with each plate's entries replaced by their mean, which
    /// it returns (one per plate). Collective.
    std::vector<double>
    project(const VectorType &du, VectorType &projected) const;

    /// Replace the plates' rows of @p R (the residual at P @p du) by
    /// Rtilde; @p mean is what project() returned for @p du. Collective.
    void
    tie(const VectorType          &du,
        const std::vector<double> &mean,
        VectorType                &R) const;

    /// K += kbar on the diagonal of the plates' dofs (owned rows; K not
    /// yet compressed): the preconditioner's share of the tie. If
    /// @p preconditioner_matrix, K is the matrix of the step's
    /// preconditioner, the one setup_preconditioner() will be given.
    void
    add_to(TrilinosWrappers::SparseMatrix &K,
           const bool                      preconditioner_matrix = true) const;


    /**
     * The plates' modes phi_k and their coarse matrix Phi^T K Phi for this
     * step (after reinit_step()), from @p K_A, the matrix add_to() added
     * to, and its preconditioner @p M; @p zero_constrained zeros the
     * constrained entries of a vector. @p sweeps preconditioned sweeps
     * make phi_k follow the plate into the body. Unless
     * @p new_preconditioner (K_A and M built for this step), the modes of
     * an earlier step serve again if the plates have the same nodes.
     * Collective.
     */
    void
    setup_preconditioner(
      const TrilinosWrappers::SparseMatrix    &K_A,
      const Preconditioning                   &M,
      const std::function<void(VectorType &)> &zero_constrained,
      const bool                               new_preconditioner,
      const unsigned int                       sweeps = 4);

    /// Whether setup_preconditioner() was called for the current step.
    bool
    has_preconditioner() const override;

    /**
     * dst = the tied problem's preconditioner applied to @p src (see the
     * class description), with M the preconditioner of K_A, the sign of
     * Preconditioner::vmult(). Collective.
     */
    void
    precondition(const Preconditioning &M,
                 VectorType            &dst,
                 const VectorType      &src) const override;

    /// The mean of @p v over each plate's dofs (all ranks): of a converged
    /// increment, each plate's motion in the step. Collective.
    std::vector<double>
    means(const VectorType &v) const;

  private:
    const BoundaryDescriptor<dim> &boundary;
    MPI_Comm                       communicator = MPI_COMM_NULL;
    /// Per plate: its dofs owned here, and their number on all ranks.
    std::vector<std::vector<types::global_dof_index>> dofs;
    std::vector<double>                               n_dofs;
    double                                            stiffness = 0.;

    /// The diagonal add_to() added to the preconditioner's matrix: its
    /// dofs (owned here) and kbar, as they were when it was assembled.
    mutable std::vector<types::global_dof_index> matrix_dofs;
    mutable double                               matrix_stiffness = 0.;

    /// The plates' modes phi_k and (Phi^T K Phi)^{-1}
    /// (setup_preconditioner()), the plates' dofs they were computed for,
    /// and K_A, the matrix they were computed with.
    std::vector<VectorType>                           modes;
    std::vector<std::vector<types::global_dof_index>> mode_dofs;
    FullMatrix<double>                                coarse_inverse;
    const TrilinosWrappers::SparseMatrix *preconditioner_matrix = nullptr;
    mutable VectorType                    scratch;
    mutable Vector<double>                coarse_rhs, coarse_solution;

    /// Each plate's entries of @p v replaced by their mean (P v), which
    /// it returns (one per plate). Collective.
    std::vector<double>
    average_plates(VectorType &v) const;

    /// y = K x, K the material's part of K_A (the plates' diagonal removed).
    void
    material_vmult(const TrilinosWrappers::SparseMatrix &K_A,
                   VectorType                           &y,
                   const VectorType                     &x) const;
  };
} // namespace qsmpm

#endif
