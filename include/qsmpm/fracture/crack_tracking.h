#ifndef qsmpm_fracture_crack_tracking_h
#define qsmpm_fracture_crack_tracking_h

#include <deal.II/base/mpi.h>
#include <qsmpm/materials/smeared_cracks.h>
#include <qsmpm/particles/material_point_set.h>

namespace qsmpm
{
  /**
   * Crack tracking for the smeared-crack model (`Crack tracking = true` in
   * "Material/smeared cracks"): which points may start a crack in the next
   * step.
   *
   * <h3>Why</h3>
   * Where a crack band crosses the grid at an angle, the cells beside the
   * band's staircase of cells are strained by the band's kinks, reach
   * tau_nf and crack as well: the band widens and bends towards the grid's
   * lines, and the work of fracture grows (measured in the notched plate at
   * 30 degrees to the grid: 1.27 G_f times the ligament without tracking).
   * Crack tracking (Cervera and Chiumenti 2006; Slobbe, Hendriks and Rots
   * 2012) lets only the band that the crack's own path crosses crack.
   *
   * <h3>The rule</h3>
   * Every cracked point k carries a path point a_k (its `crack_anchor`) and
   * its first crack's normal n_k and smearing length L_k: its path is the
   * line through a_k normal to n_k. The band of that line is the set of
   * cells it crosses: a cell with centre c belongs to it if |(c - a_k) .
   * n_k| <= L_k / 2 (with L = h sum_i |n_i|, the projection of a cell onto
   * n, which is what SmearedCracks' default smearing length is, this is
   * exactly the set of cells the line crosses, touching cells included).
   * A point without a crack may start one in the next step if no path point
   * lies within the radius r (`Crack tracking radius` times h) of its
   * cell's centre, or if its cell belongs to the band of one that does.
   * Cells, not points, decide: all points of a cell see the same normal
   * strain across a band (SmearedCracks, "The smearing length").
   *
   * With `Crack tracking localization` f > 0, once one crack has
   * dissipated f G_f (per unit crack area) the body counts as localized:
   * from then on a point away from all paths is held back as well, so that
   * new cracks grow only in the bands of the existing paths.
   *
   * A point that has started a crack in the step just committed gets its
   * path point from the nearest path within r (the one whose line passes
   * closest to its cell's centre): the projection of its cell's centre
   * onto that line. The path thus continues from cell to cell, and turns
   * with the normals of the new cracks. Without a path within r, the point
   * starts a new path through its cell's centre. New cracks are anchored
   * one after another, the most opened first (then by position), the same
   * on every rank: points that cracked together near each other share one
   * path. It also gets its smearing length (`crack_band_length`) from the
   * band's direction: L of the mean of the normals of the paths whose bands
   * contain its cell, its own included (SmearedCracks, "The smearing
   * length").
   *
   * After each step's commit (QuasiStaticProblem calls update()), the
   * cracked points are gathered on every rank (a few doubles per cracked
   * point; the band holds few of all points), so that the decision does not
   * depend on the partition.
   */
  template <int dim>
  class CrackTracking
  {
  public:
    explicit CrackTracking(const SmearedCracks<dim> &model);

    /**
     * Anchor the cracks that started in the step just committed and set
     * every point's permission (`crack_allowed`) for the next step. Returns
     * the number of points (on all ranks) held back: in the cracking region,
     * without a crack, near a crack path (anywhere, once localized) but
     * outside its band.
     */
    unsigned long long
    update(MaterialPointSet<dim> &points, const MPI_Comm communicator) const;

  private:
    const SmearedCracks<dim> &model;
  };
} // namespace qsmpm

#endif
