#ifndef qsmpm_loading_boundary_conditions_h
#define qsmpm_loading_boundary_conditions_h

#include <array>
#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <functional>
#include <memory>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/particles/shape_cache.h>
#include <string>
#include <vector>

namespace qsmpm
{
  /**
   * Loads and supports of a quasi-static problem, all functions of the load
   * factor t (passed to every Function as its time):
   *
   * - displacement control (paper eq. 2.16): on grid boundary ids or on node
   *   sets selected by position, per component, or only the normal component
   *   ("sliding"); the increment of a step is g(x, t_new) - g(x, t_old);
   * - load control (paper eqs. 2.10-2.12): a body force per unit volume at
   *   the points, tractions on grid boundary faces, and nodal point loads.
   *
   * It also turns the displacement conditions into the AffineConstraints of
   * one load step and sums the reaction forces on each of them.
   *
   * Tractions are integrated over the faces of the background grid, so they
   * assume that the loaded surface of the body coincides with a grid
   * boundary.
   */
  template <int dim>
  class BoundaryConditions
  {
  public:
    /**
     * The subsection "Boundary conditions" of a .prm file.
     */
    struct Parameters
    {
      /// "id:components, id:components"; components from x, y, z or n.
      std::string dirichlet;
      /// Boundary ids that carry the traction function.
      std::string traction;
      /// H (dim x dim numbers, row by row) of a periodic grid, or empty.
      std::string macroscopic_gradient;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /// One displacement condition.
    struct DirichletCondition
    {
      std::string name;
      /// numbers::invalid_boundary_id for a node set.
      types::boundary_id                      boundary_id;
      std::function<bool(const Point<dim> &)> selector;
      std::array<bool, dim>                   components;
      bool                                    normal_only;
      std::shared_ptr<Function<dim>>          displacement;
    };

    /**
     * Prescribe the displacement @p displacement (dim components, evaluated
     * at load factor t) on the nodes of boundary @p id, for the components
     * in @p components, or only for the normal component of each face if
     * @p normal_only.
     */
    void
    add_dirichlet_boundary(const types::boundary_id              id,
                           const std::array<bool, dim>          &components,
                           const std::shared_ptr<Function<dim>> &displacement,
                           const bool normal_only = false);

    /// Prescribe the displacement on all grid nodes where @p selector is true.
    void
    add_dirichlet_nodes(const std::string                             &name,
                        const std::function<bool(const Point<dim> &)> &selector,
                        const std::array<bool, dim>          &components,
                        const std::shared_ptr<Function<dim>> &displacement);

    /// A traction (force per area, dim components) on boundary @p id.
    void
    add_traction(const types::boundary_id              id,
                 const std::shared_ptr<Function<dim>> &traction);

    /// A body force per unit volume (dim components) at the points.
    void
    set_body_force(const std::shared_ptr<Function<dim>> &body_force);

    /**
     * The macroscopic displacement gradient H(t) of a grid with periodic
     * directions (BackgroundGrid::make_periodic()): the displacement is
     * u(x) = H(t) x + w(x) with w periodic, i.e. across each periodic
     * direction d it jumps by H(t) L_d e_d, L_d the box length. Without
     * this call H = 0. If every direction is periodic, the one node that all
     * box corners are tied to is held at u = H(t) (x - @p reference), which
     * removes the rigid translation; otherwise displacement conditions on
     * the other faces must do so.
     */
    void
    set_macroscopic_displacement_gradient(
      const std::function<Tensor<2, dim>(const double)> &H,
      const Point<dim> &reference = Point<dim>());

    /// A force at the grid node at @p location, scaled by the load factor.
    void
    add_point_load(const Point<dim> &location, const Tensor<1, dim> &force);

    /**
     * Read the .prm subsection: Dirichlet boundaries with the function of
     * subsection "Displacement", traction boundaries with "Traction", and the
     * body force of "Body force".
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * The constraints of the step t_old -> t_new: the periodicity
     * constraints with the increment of the macroscopic jump (if the grid
     * is periodic), the displacement increments on constrained nodes and
     * zero increments on the degrees of freedom in @p inactive_dofs (nodes
     * without points).
     */
    void
    make_constraints(const BackgroundGrid<dim> &grid,
                     const IndexSet            &inactive_dofs,
                     const double               t_old,
                     const double               t_new,
                     AffineConstraints<double> &constraints);

    /**
     * The external force f_ext(t) (paper eq. 2.10): body force at the points
     * of @p cache, tractions and point loads.
     */
    void
    assemble_external_force(const BackgroundGrid<dim>     &grid,
                            const ShapeCache<dim>         &cache,
                            const unsigned int             volume_offset,
                            const double                   t,
                            TrilinosWrappers::MPI::Vector &f_ext) const;

    /**
     * Reaction force on each displacement condition: minus the sum of the
     * residual over its constrained degrees of freedom (the force the
     * support exerts on the body), summed over all ranks.
     */
    std::vector<Tensor<1, dim>>
    reactions(const TrilinosWrappers::MPI::Vector &residual,
              const MPI_Comm                       communicator) const;

    const std::vector<DirichletCondition> &
    dirichlet_conditions() const;

    /// Whether a macroscopic displacement gradient is prescribed.
    bool
    has_macroscopic_gradient() const
    {
      return static_cast<bool>(macroscopic_gradient);
    }

    /// Whether any load (body force, traction, point load) is given.
    bool
    has_loads() const;

    /**
     * Evaluate the three functions read by parse_parameters() (subsections
     * Displacement, Traction and Body force) at each of @p points for each
     * load factor in @p load_factors, and throw an exception that names the
     * subsection, the expression, the point and t if one of them gives a
     * value that is not a finite number (e.g. sqrt(-1), 1/0). Without this
     * check a NaN in a load only shows up as a residual that is not a number,
     * after every cut-back of the first load step. The caller passes the
     * same points on every MPI rank (e.g. the vertices of the coarse grid,
     * which every rank holds), so that all ranks stop together. Does nothing
     * for functions that did not come from parse_parameters().
     */
    void
    check_parsed_functions(const std::vector<Point<dim>> &points,
                           const std::vector<double>     &load_factors) const;

  private:
    /// The periodicity lines of make_constraints(), not closed.
    void
    add_periodicity_constraints(const BackgroundGrid<dim> &grid,
                                const double               t_old,
                                const double               t_new,
                                AffineConstraints<double> &constraints) const;

    std::vector<DirichletCondition>             dirichlet;
    std::function<Tensor<2, dim>(const double)> macroscopic_gradient;
    Point<dim>                                  macroscopic_reference;
    /// Per condition: its locally owned (dof, component) pairs.
    std::vector<std::vector<std::pair<types::global_dof_index, unsigned int>>>
      constrained_dofs;

    std::vector<std::pair<types::boundary_id, std::shared_ptr<Function<dim>>>>
                                                       tractions;
    std::shared_ptr<Function<dim>>                     body_force;
    std::vector<std::pair<Point<dim>, Tensor<1, dim>>> point_loads;

    /// Functions read from the .prm file.
    std::shared_ptr<Functions::ParsedFunction<dim>> parsed_displacement;
    std::shared_ptr<Functions::ParsedFunction<dim>> parsed_traction;
    std::shared_ptr<Functions::ParsedFunction<dim>> parsed_body_force;
    /// Their subsections and expressions, for messages.
    std::array<std::string, 3> parsed_expressions;
  };
} // namespace qsmpm

#endif
