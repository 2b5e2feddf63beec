#ifndef qsmpm_loading_constraint_checks_h
#define qsmpm_loading_constraint_checks_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <string>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * Checks of the constraints of a load step that turn silent nonsense into
   * a clear error (issue 12): a body that no displacement condition holds
   * against a rigid-body motion, and a displacement condition that moves
   * nodes the body has left. QuasiStaticProblem calls them every step,
   * where it knows which nodes carry material; both are cheap (a 6x6
   * eigenproblem and two reductions).
   */
  namespace ConstraintChecks
  {
    /**
     * The rigid-body motions (translations and rotations) that the held
     * degrees of freedom do not prevent, each described in words
     * ("translation in x", "rotation about z", or a combination). @p held
     * lists, for this rank's locally owned constrained degrees of freedom
     * whose nodes carry material, the node and the component. A motion is
     * free if it vanishes at every held degree of freedom: the Gram matrix
     * sum r r^T of the rigid-body modes r evaluated there (positions
     * centred and scaled by @p length) is then singular.
     */
    template <int dim>
    std::vector<std::string>
    free_rigid_body_motions(
      const std::vector<std::pair<Point<dim>, unsigned int>> &held,
      const Point<dim>                                       &centre,
      const double                                            length,
      const MPI_Comm                                          communicator);

    /**
     * Throw with a message naming the free motions if there are any. With
     * @p axisymmetric (2D, x = r) the only rigid-body motion is the
     * translation along the axis: the hoop strain u_r / r resists a radial
     * one, and the plane's rotation is none of the body's.
     */
    template <int dim>
    void
    assert_no_rigid_body_motion(
      const std::vector<std::pair<Point<dim>, unsigned int>> &held,
      const Point<dim>                                       &centre,
      const double                                            length,
      const MPI_Comm                                          communicator,
      const bool axisymmetric = false);

    /**
     * Throw if the displacement condition @p name prescribes a non-zero
     * increment (largest magnitude on this rank @p largest_increment) while
     * none of its nodes (this rank's count @p n_active_nodes) carries
     * material: the body has left it and it no longer acts on the body.
     */
    void
    assert_condition_acts(const std::string &name,
                          const unsigned int n_active_nodes,
                          const double       largest_increment,
                          const double       t_old,
                          const double       t_new,
                          const MPI_Comm     communicator);
  } // namespace ConstraintChecks
} // namespace qsmpm

#endif
