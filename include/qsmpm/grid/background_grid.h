#ifndef qsmpm_grid_background_grid_h
#define qsmpm_grid_background_grid_h

#include <array>
#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <memory>
#include <qsmpm/base/parameter_struct.h>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * The background grid of the material-point method: a uniform Cartesian
   * box of Q1 cells on a parallel::distributed::Triangulation with the
   * vector-valued FE_Q(1)^dim space of grid displacement increments (paper
   * eq. 2.6 and 2.17).
   *
   * The grid never deforms in qsmpm: the nodes "move with the body" only
   * within a load step, which is why shape functions are evaluated once per
   * step at the points' positions from the start of the step (paper Section
   * 2.3). After the step the grid is, in effect, reset.
   *
   * Boundary ids are those of GridGenerator::subdivided_hyper_rectangle with
   * colorize = true: 2d for the face x_d = lower corner, 2d+1 for x_d = upper
   * corner (0 = left, 1 = right, 2 = bottom, 3 = top, 4 = back, 5 = front).
   *
   * The box can be made periodic in some directions (make_periodic()): the
   * faces 2d and 2d+1 are then identified in the p4est forest, so that
   * ghost layers and locally relevant degrees of freedom reach across them,
   * and make_periodicity_constraints() ties the nodes of face 2d to those
   * of face 2d+1. DisplacementConstraints adds the macroscopic jump of the
   * displacement across the period.
   */
  template <int dim>
  class BackgroundGrid
  {
  public:
    /**
     * The subsection "Geometry" of a .prm file.
     */
    struct Parameters : ParameterStruct<Parameters>
    {
      Point<dim>                    lower_corner;
      Point<dim>                    upper_corner;
      std::array<unsigned int, dim> subdivisions;
      /// Letters of the directions in which the box is periodic ("xy";
      /// empty: none).
      std::string periodic;

      /// The defaults: the unit box, 8 cells in each direction.
      Parameters();

      /// Declare the entries, bound to the members.
      void
      add_parameters(ParameterHandler &prm);

      /// The directions of the letters in <tt>periodic</tt>; throws on a
      /// letter that is not one of them.
      std::vector<unsigned int>
      periodic_directions() const;

      /// The letters and a box of positive extent.
      void
      check() const;
    };

    explicit BackgroundGrid(const MPI_Comm communicator);

    /**
     * Give every node one displacement per body (the multi-field grid of
     * Bardenhagen et al. 2001): the finite element becomes
     * FE_Q(1)^(dim @p n), and component b * dim + c is the displacement
     * component c of body b. Points of body b see only body b's field, so
     * that two bodies at the same node can move apart; BodyContact ties
     * the fields where the bodies touch. Call it before make_box(); the
     * default is one body, whose field is the grid's only one.
     */
    void
    set_n_bodies(const unsigned int n);

    /// The number of bodies, each with its own displacement field.
    unsigned int
    n_bodies() const
    {
      return bodies;
    }

    /// Degrees of freedom per node: dim times n_bodies(). Those of a node
    /// are consecutive, body by body.
    unsigned int
    n_node_dofs() const
    {
      return dim * bodies;
    }

    /**
     * Create the box and distribute the degrees of freedom.
     */
    void
    make_box(const Point<dim>                    &lower_corner,
             const Point<dim>                    &upper_corner,
             const std::array<unsigned int, dim> &subdivisions);

    /// Create the box of the parameters, periodic where they say so.
    void
    make_box(const Parameters &parameters);

    /**
     * Identify the faces 2d and 2d+1 for every direction d in
     * @p directions (after make_box(), before adding points), and
     * redistribute the degrees of freedom.
     */
    void
    make_periodic(const std::vector<unsigned int> &directions);

    /// The directions given to make_periodic() (sorted).
    const std::vector<unsigned int> &
    periodic_directions() const;

    /**
     * Add the homogeneous periodicity constraints u(face 2d) = u(face 2d+1)
     * of all periodic directions to @p constraints (not closed; lines for
     * locally relevant degrees of freedom).
     */
    void
    make_periodicity_constraints(AffineConstraints<double> &constraints) const;

    /// Number of nodes in the block of node_block_dofs(): 4^dim.
    static constexpr unsigned int n_block_nodes = dim == 2 ? 16 : 64;

    /**
     * The degrees of freedom of the 4^dim nodes of the 3^dim cells around
     * @p cell (the cell and every cell sharing a vertex with it): node
     * (a_0, a_1[, a_2]), a_d = 0..3, at cell->vertex(0) + (a_d - 1) h_d e_d,
     * has index a_0 + 4 a_1 + 16 a_2, and its component c is entry
     * index * dim + c of @p dofs. Neighbours are found across ordinary and
     * periodic faces; all of them are locally owned or ghost cells when
     * @p cell is locally owned. Nodes outside the grid get
     * numbers::invalid_dof_index. Each node takes its dofs from the
     * nearest cell of the block that has it (the cell itself first), so
     * that nodes of the cell are never replaced by their periodic images.
     * These are the nodes that a GIMP point in @p cell can reach. On a grid
     * of several bodies (set_n_bodies()), the dofs of body @p body.
     */
    void
    node_block_dofs(const typename DoFHandler<dim>::active_cell_iterator &cell,
                    std::vector<types::global_dof_index>                 &dofs,
                    const unsigned int body = 0) const;

    /**
     * Renumber and redistribute degrees of freedom, e.g. after the
     * triangulation was repartitioned.
     */
    void
    distribute_dofs();

    const parallel::distributed::Triangulation<dim> &
    get_triangulation() const;
    parallel::distributed::Triangulation<dim> &
    get_triangulation();
    const DoFHandler<dim> &
    get_dof_handler() const;
    const FESystem<dim> &
    get_fe() const;
    const MappingQ1<dim> &
    get_mapping() const;
    const IndexSet &
    locally_owned_dofs() const;
    const IndexSet &
    locally_relevant_dofs() const;
    MPI_Comm
    get_communicator() const;

    /**
     * The locally relevant dofs whose entry of @p sums (a vector of the
     * locally owned dofs, its entries summed over the ranks and compressed)
     * is at most @p threshold: the nodes without enough material or
     * stiffness, the same on every rank that sees them.
     */
    IndexSet
    dofs_at_most(const TrilinosWrappers::MPI::Vector &sums,
                 const double                         threshold) const;

    /**
     * The active cell around @p x and the reference location of x in it,
     * searched from @p hint outwards (deal.II's
     * GridTools::find_active_cell_around_point() with a GridTools::Cache
     * that the grid keeps); an invalid iterator if x lies beyond the grid
     * or in an artificial cell.
     */
    std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>
    find_cell_around(
      const Point<dim>                                        &x,
      const typename Triangulation<dim>::active_cell_iterator &hint) const;

    /// The DoFHandler's iterator to the triangulation's @p cell.
    typename DoFHandler<dim>::active_cell_iterator
    dof_cell(
      const typename Triangulation<dim>::active_cell_iterator &cell) const;

    /// Lower and upper corners of the box.
    const Point<dim> &
    lower_corner() const;
    const Point<dim> &
    upper_corner() const;

    /// Edge lengths of one cell.
    Tensor<1, dim>
    cell_size() const;

    /// The smallest of the cell's extents.
    double
    min_cell_size() const;

    /**
     * The vertices of this rank's cells, each once: all of them, or, if
     * there are more than @p max_count, every k-th of them, at most
     * @p max_count.
     */
    std::vector<Point<dim>>
    local_vertices(const std::size_t max_count) const;

    /**
     * Whether the (bi/tri)linear map of @p cell is affine,
     * x = vertex(0) + J xi (a parallelogram or parallelepiped: every cell
     * of a Cartesian grid), to 1e-12 of |J|; @p jacobian is J, columns
     * vertex(2^d) - vertex(0). On an affine cell, the Jacobian of the map
     * is that J at every point, and the reference location of x is
     * J^{-1} (x - vertex(0)).
     */
    static bool
    affine_map(const typename Triangulation<dim>::cell_iterator &cell,
               Tensor<2, dim>                                   &jacobian);

  private:
    /**
     * Make the box of box_lower, box_upper, box_subdivisions, periodic in
     * the directions of periodic: a coarse mesh of as few cells as the
     * subdivisions allow, refined globally (see the .cc file for why), and
     * distribute the degrees of freedom.
     */
    void
    build();

    MPI_Comm                                  communicator;
    parallel::distributed::Triangulation<dim> triangulation;
    unsigned int                              bodies = 1;
    std::unique_ptr<FESystem<dim>>            fe;
    MappingQ1<dim>                            mapping;
    DoFHandler<dim>                           dof_handler;
    /// For find_cell_around(), made at its first use.
    mutable std::unique_ptr<GridTools::Cache<dim>> locator;
    IndexSet                                       owned_dofs;
    IndexSet                                       relevant_dofs;
    Point<dim>                                     box_lower;
    Point<dim>                                     box_upper;
    std::array<unsigned int, dim>                  box_subdivisions;
    std::vector<unsigned int>                      periodic;
  };
} // namespace qsmpm

#endif
