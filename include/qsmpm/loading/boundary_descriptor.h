#ifndef qsmpm_loading_boundary_descriptor_h
#define qsmpm_loading_boundary_descriptor_h

#include <array>
#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <functional>
#include <memory>
#include <qsmpm/loading/rigid_body.h>
#include <string>
#include <utility>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * What a quasi-static problem prescribes on its boundary and as loads, as
   * data: which grid boundary or node set has which displacement, which
   * boundary carries which traction, the body force, the point loads and
   * the macroscopic displacement gradient of a periodic grid. All of them
   * are functions of the load factor t (passed to every Function as its
   * time):
   *
   * - displacement control (paper eq. 2.16): on grid boundary ids or on node
   *   sets selected by position, per component, or only the normal component
   *   ("sliding");
   * - load control (paper eqs. 2.10-2.12): a body force per unit volume at
   *   the points, tractions on grid boundary faces, tractions on the body's
   *   own surface (carried by its surface points, so that they move with
   *   it: SurfaceTractions), and nodal point loads.
   *
   * The descriptor only describes; nothing in it knows the grid or the
   * points. The classes that turn it into the data of a load step read it:
   * DisplacementConstraints (the constraints of the step and the degrees of
   * freedom of each support), ExternalForceAssembler (f_ext) and
   * ReactionForces (the force of each support). ParsedBoundaryConditions
   * fills it from the subsection "Boundary conditions" of a .prm file; in
   * C++ the add_ and set_ functions below fill it directly. This is the
   * BoundaryDescriptor of ExaDG (structure/user_interface/
   * boundary_descriptor.h) with the conditions of qsmpm.
   */
  template <int dim>
  class BoundaryDescriptor
  {
  public:
    /// One displacement condition.
    struct DirichletCondition
    {
      /// "boundary_<id>" or the name given to add_dirichlet_nodes(); the
      /// reaction files use it.
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

    /// How a traction on the body's surface acts as the body deforms.
    enum class SurfaceLoadType
    {
      /// A force per unit initial area, of fixed direction: the traction
      /// function (dim components) at the point's initial position.
      dead,
      /// A pressure p (the first component of the function; the others
      /// must be zero) on the current surface, along its current inward
      /// normal: force -p n da with n da = J F^{-T} N dA (Nanson). At
      /// small strain the same as a dead traction -p N.
      pressure
    };

    /// A traction on the body's own surface (SurfaceTractions).
    struct SurfaceTraction
    {
      /// Names the condition in messages and reactions.csv.
      std::string name;
      /// Which faces of the body's initial surface are loaded: true at the
      /// face's centre (initial configuration).
      std::function<bool(const Point<dim> &)> selector;
      std::shared_ptr<Function<dim>>          traction;
      SurfaceLoadType                         type;
    };

    /**
     * A traction on the faces of the body's initial surface where
     * @p selector is true, carried by the material points next to those
     * faces with their share of the area, so that it follows the body
     * (SurfaceTractions). Unlike add_traction(), the loaded surface need
     * not lie on a grid face and may leave it. Add every surface traction
     * before the material points are made: each point carries the area of
     * each condition.
     */
    void
    add_surface_traction(
      const std::string                             &name,
      const std::function<bool(const Point<dim> &)> &selector,
      const std::shared_ptr<Function<dim>>          &traction,
      const SurfaceLoadType type = SurfaceLoadType::dead);

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
     * A rigid body that the points cannot enter (RigidContact): its force
     * on the material is a load of the step, and the material's force on
     * it a column of reactions.csv. Add every rigid body before the
     * material points are made: each point carries its contact traction
     * with each body. Throws if the description is incomplete.
     */
    void
    add_rigid_body(const RigidBody<dim> &body);

    /**
     * Make boundary @p id of the box (BackgroundGrid::make_box(): 2d and
     * 2d + 1 are normal to direction d) a rigid, frictionless plate: its
     * nodes move as one along its normal, by what the traction on it
     * (add_traction()) makes them (RigidPlates), while their other
     * components stay free. A displacement condition may not hold the same
     * boundary along its normal.
     */
    void
    add_rigid_plate(const types::boundary_id id);

    /// The displacement conditions, in the order they were added.
    const std::vector<DirichletCondition> &
    dirichlet_conditions() const;

    /// The boundary ids of the rigid plates.
    const std::vector<types::boundary_id> &
    rigid_plates() const;

    /// The traction of each loaded boundary id.
    const std::vector<
      std::pair<types::boundary_id, std::shared_ptr<Function<dim>>>> &
    tractions() const;

    /// The tractions on the body's surface, in the order they were added.
    const std::vector<SurfaceTraction> &
    surface_tractions() const;

    /// The body force, or nullptr.
    const std::shared_ptr<Function<dim>> &
    body_force() const;

    /// The point loads: location and force at t = 1.
    const std::vector<std::pair<Point<dim>, Tensor<1, dim>>> &
    point_loads() const;

    /// Whether a macroscopic displacement gradient is prescribed.
    bool
    has_macroscopic_gradient() const;

    /// H(t); only if has_macroscopic_gradient().
    Tensor<2, dim>
    macroscopic_gradient(const double t) const;

    /// The point held at u = H(t) (x - reference) on a fully periodic grid.
    const Point<dim> &
    macroscopic_reference() const;

    /// The rigid bodies, in the order they were added.
    const std::vector<RigidBody<dim>> &
    rigid_bodies() const;

    /// Whether any load (body force, traction, point load, rigid body) is
    /// given.
    bool
    has_loads() const;

  private:
    std::vector<DirichletCondition> dirichlet;
    std::vector<std::pair<types::boundary_id, std::shared_ptr<Function<dim>>>>
                                                       traction_functions;
    std::vector<SurfaceTraction>                       surface_traction_list;
    std::vector<RigidBody<dim>>                        rigid_body_list;
    std::vector<types::boundary_id>                    plate_ids;
    std::shared_ptr<Function<dim>>                     body_force_function;
    std::vector<std::pair<Point<dim>, Tensor<1, dim>>> nodal_loads;
    std::function<Tensor<2, dim>(const double)>        gradient;
    Point<dim>                                         reference;
  };
} // namespace qsmpm

#endif
