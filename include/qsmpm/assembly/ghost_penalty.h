#ifndef qsmpm_assembly_ghost_penalty_h
#define qsmpm_assembly_ghost_penalty_h

#include <qsmpm/assembly/local_stiffness.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/particles/material_point_set.h>
#include <qsmpm/particles/shape_cache.h>
#include <vector>

namespace qsmpm
{
  /**
   * The ghost penalty of cut cells (Burman 2010; for the material-point
   * method Coombs 2023, "Ghost stabilisation of the material point method
   * for stable quasi-static and dynamic analysis of large deformation
   * problems", IJNME 124): a grid node that the material only just reaches
   * has almost no stiffness, and with it the step's Jacobian is nearly
   * singular -- Newton then stalls, most of all at finite strain, where the
   * stress stiffness of a compressed point can make such a node's
   * stiffness vanish. The penalty
   *
   *   g(du, v) = sum_F gamma E_s h_F int_F [[grad du . n]] . [[grad v . n]]
   *
   * over the faces F shared by two cells all of whose nodes carry
   * material, of which at least one is cut (it has a node with less than a
   * quarter of a cell's volume of material in its support), ties the
   * increments of such nodes to the gradient of the increment in the
   * neighbouring cells. It vanishes for every linear field -- the
   * increments of rigid-body motions and of homogeneous strains -- so it
   * carries no load to any support: its nodal forces sum to zero
   * (EquilibriumAudit sees nothing), and on refinement it vanishes with
   * the gradient jumps of the discrete solution. E_s is the mean stiffness
   * of the grid's degrees of freedom (the diagonal of the tangent), so
   * that gamma has no units. Bilinear and trilinear cells have no jumps of
   * higher normal derivatives, so the first one is all there is.
   *
   * With several bodies (contact between bodies, each body with its own
   * field on the grid) the faces are chosen for each field by that body's
   * material alone, and the penalty acts on that field only.
   *
   * The residual of a step becomes R(du) - G du; the preconditioner's
   * matrix K + G (TangentAssembler::assemble() adds it, LocalStiffness
   * applies it).
   */
  template <int dim>
  class GhostPenalty : public LocalStiffness
  {
  public:
    /**
     * The matrix G of the step: the cut cells and faces of the points of
     * @p cache (whose volumes are at @p volume_offset), with the penalty
     * factor @p gamma and the stiffness scale @p stiffness_scale.
     *
     * @p axisymmetric: the volumes are per radian (r dA), and so is the
     * stiffness, r times a plane one's. A node is cut by the area of
     * material in its support, and the face integrals are taken over
     * r dGamma / r_m, r_m the grid's mid-radius, at which @p stiffness_scale
     * (a mean over the grid) is taken to be.
     */
    void
    reinit(const BackgroundGrid<dim> &grid,
           const ShapeCache<dim>     &cache,
           const unsigned int         volume_offset,
           const double               gamma,
           const double               stiffness_scale,
           const bool                 axisymmetric = false);

    /// The number of faces penalized in the last reinit() (all ranks).
    unsigned int
    n_faces() const
    {
      return n_terms();
    }
  };
} // namespace qsmpm

#endif
