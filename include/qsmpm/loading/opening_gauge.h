#ifndef qsmpm_loading_opening_gauge_h
#define qsmpm_loading_opening_gauge_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>
#include <qsmpm/particles/shape_cache.h>
#include <string>

namespace qsmpm
{
  using namespace dealii;

  /**
   * A clip gauge between two material points: the quantity that opening
   * control (Load stepping/Control = opening) prescribes per step, the way
   * fracture tests on quasi-brittle materials are run in the laboratory
   * (crack-mouth opening displacement, CMOD, control). It is the
   * "indirect displacement control" of de Borst (1987): the load factor of
   * a step is an unknown, and a linear function of the displacement
   * increment, the gauge's opening, is prescribed instead. Where the
   * load-point displacement of a softening specimen snaps back, the opening
   * of a crack keeps growing, so that the whole path is traced.
   *
   * The gauge is defined by two positions x_a and x_b; its points are the
   * material points nearest to them in the initial configuration
   * (X_p = x_p - u_p), its direction e = (x_b - x_a)/|x_b - x_a| is fixed,
   * and its opening in a step is
   *
   *   w . du = (sum_i N_i(x_b) du_i - sum_i N_i(x_a) du_i) . e,
   *
   * with the step's shape functions at the two points (those that move
   * the points, MaterialPointSet::advect()). The points are found anew in
   * each step from their initial positions, so that the gauge needs no
   * state of its own in checkpoints and is the same on any number of MPI
   * ranks; ties between points equally far from x_a (or x_b) go to the
   * point with the lexicographically smallest X. Give positions near a
   * point, not exactly between two.
   */
  template <int dim>
  class OpeningGauge
  {
  public:
    /**
     * The gauge of the entry "Opening gauge", "x_a; x_b" with dim
     * coordinates each. Throws with a message naming the entry if the text
     * is malformed or the two positions coincide.
     */
    explicit OpeningGauge(const std::string &text);

    /**
     * The vector w with w . du = the opening of the gauge for the grid
     * increment du of the step whose shape functions @p cache holds. @p w
     * must have the layout of du; it is overwritten. @p displacement: the
     * offset of the points' displacement u_p in their properties. Throws if
     * a position of the gauge has no point within @p max_distance (a
     * gauge outside the body). Collective.
     */
    void
    make_vector(const ShapeCache<dim>         &cache,
                const unsigned int             displacement,
                const double                   max_distance,
                const MPI_Comm                 communicator,
                TrilinosWrappers::MPI::Vector &w) const;

  private:
    /// The cache index of the point nearest to @p x in the initial
    /// configuration if this rank owns it, else invalid. Collective.
    unsigned int
    find_point(const ShapeCache<dim> &cache,
               const unsigned int     displacement,
               const Point<dim>      &x,
               const double           max_distance,
               const MPI_Comm         communicator) const;

    Point<dim>     x_a;
    Point<dim>     x_b;
    Tensor<1, dim> e;
  };
} // namespace qsmpm

#endif
