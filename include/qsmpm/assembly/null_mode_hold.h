#ifndef qsmpm_assembly_null_mode_hold_h
#define qsmpm_assembly_null_mode_hold_h

#include <deal.II/lac/affine_constraints.h>
#include <qsmpm/assembly/ghost_penalty.h>
#include <qsmpm/assembly/local_stiffness.h>
#include <qsmpm/assembly/tangent_assembler.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>

namespace qsmpm
{
  /**
   * The hold of the motions of two degrees of freedom that no point
   * stiffens although each of them alone has stiffness: the rank-revealing
   * part of the hold of <Material points/Minimum nodal stiffness>.
   *
   * A point on a face of its cell (xi_d = 0 or 1) has N_i = 0 and grad N_i
   * normal to that face at the nodes of the opposite face: it stiffens
   * their common motion but not their motion against each other. If the
   * points of the other cells of those nodes carry no stiffness (a crack
   * band that failed completely, with one point per cell), the step's
   * Jacobian is singular although every diagonal entry is positive, and a
   * direct factorization returns infinities.
   *
   * Such a mode is found exactly where it lives: K is symmetric positive
   * semi-definite, so a null vector v of a principal 2 x 2 submatrix of K
   * is a null vector of K (v^T K v = 0). The pairs of coupled dofs whose
   * submatrix has its smaller eigenvalue at most the threshold of the hold
   * get a spring on that mode, k v v^T with k the mean stiffness of the
   * dofs: the residual of the step becomes R(du) - S du and the
   * preconditioner's matrix K + S. Since no point stiffens v, no point's
   * force has a part along it (v^T R = 0), the spring's force vanishes at
   * the solution, v^T du = 0 there, and no load goes to it: the mode is
   * held like a dof without stiffness, without a constraint that would
   * couple dofs beyond K's pattern.
   *
   * The search needs K with its off-diagonal entries, one assembly. It is
   * made only in a step where the points of some cell all lie within
   * sqrt(threshold fraction) of one face of their cell (with the default
   * 1e-8, 1e-4 of the cell): a point at a distance delta of the face
   * stiffens the opposite nodes' relative motion by delta^2 of its own
   * stiffness, so farther points give the mode more than the threshold.
   * Linear shape functions only (a GIMP domain has no such degenerate
   * position).
   */
  template <int dim>
  class NullModeHold : public LocalStiffness
  {
  public:
    /**
     * The springs of the step whose shape functions @p cache holds, for the
     * step's closed @p constraints (with the single dofs without stiffness
     * already held), the stiffness of @p ghost_penalty and
     * @p additional_term (contact) included, the threshold
     * @p fraction times @p mean_stiffness (the mean diagonal of K).
     * Collective.
     */
    void
    reinit(
      const BackgroundGrid<dim>                            &grid,
      const MaterialPointSet<dim>                          &points,
      const ShapeCache<dim>                                &cache,
      const AffineConstraints<double>                      &constraints,
      const GhostPenalty<dim>                              *ghost_penalty,
      const typename TangentAssembler<dim>::AdditionalTerm &additional_term,
      const double                                          fraction,
      const double                                          mean_stiffness);

    /// The number of modes held in the last reinit() (all ranks).
    unsigned int
    n_modes() const
    {
      return n_terms();
    }

  private:
    /// Whether the points of some cell of this rank all lie within
    /// @p delta (in reference coordinates) of one face of their cell.
    static bool
    points_on_a_face(const ShapeCache<dim> &cache, const double delta);
  };
} // namespace qsmpm

#endif
