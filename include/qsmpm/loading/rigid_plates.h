#ifndef qsmpm_loading_rigid_plates_h
#define qsmpm_loading_rigid_plates_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/loading/boundary_descriptor.h>
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
   * The preconditioner's matrix gets the tie's diagonal, kbar, in the
   * rows of T (add_to()), not its coupling through the mean: on Mandel's
   * specimen GMRES needs 5.0, 5.2, 6.5 iterations per Newton step on 8^2,
   * 16^2, 32^2 cells (6.0, 7.2, 10.1 without the diagonal).
   */
  template <int dim>
  class RigidPlates
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
    /// yet compressed): the preconditioner's share of the tie.
    void
    add_to(TrilinosWrappers::SparseMatrix &K) const;

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
  };
} // namespace qsmpm

#endif
