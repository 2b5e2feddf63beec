#include <algorithm>
#include <deal.II/base/exceptions.h>
#include <qsmpm/loading/boundary_descriptor.h>

namespace qsmpm
{
  // The add_ and set_ functions check what a later step could not: that a
  // function has one component per coordinate direction. Everything that
  // needs the grid (does a condition select any node, is the grid periodic)
  // is checked when a step is made of the description.
  template <int dim>
  void
  BoundaryDescriptor<dim>::add_dirichlet_boundary(
    const types::boundary_id              id,
    const std::array<bool, dim>          &components,
    const std::shared_ptr<Function<dim>> &displacement,
    const bool                            normal_only)
  {
    AssertThrow(displacement && displacement->n_components == dim,
                ExcMessage("A displacement function needs dim components."));
    dirichlet.push_back({"boundary_" + std::to_string(id),
                         id,
                         {},
                         components,
                         normal_only,
                         displacement});
  }



  template <int dim>
  void
  BoundaryDescriptor<dim>::add_dirichlet_nodes(
    const std::string                             &name,
    const std::function<bool(const Point<dim> &)> &selector,
    const std::array<bool, dim>                   &components,
    const std::shared_ptr<Function<dim>>          &displacement)
  {
    AssertThrow(displacement && displacement->n_components == dim,
                ExcMessage("A displacement function needs dim components."));
    dirichlet.push_back({name,
                         numbers::invalid_boundary_id,
                         selector,
                         components,
                         false,
                         displacement});
  }



  template <int dim>
  void
  BoundaryDescriptor<dim>::add_traction(
    const types::boundary_id              id,
    const std::shared_ptr<Function<dim>> &traction)
  {
    AssertThrow(traction && traction->n_components == dim,
                ExcMessage("A traction function needs dim components."));
    traction_functions.emplace_back(id, traction);
  }



  template <int dim>
  void
  BoundaryDescriptor<dim>::add_surface_traction(
    const std::string                             &name,
    const std::function<bool(const Point<dim> &)> &selector,
    const std::shared_ptr<Function<dim>>          &traction,
    const SurfaceLoadType                          type)
  {
    AssertThrow(traction && traction->n_components == dim,
                ExcMessage("A surface traction function needs dim "
                           "components (a pressure: the first one)."));
    AssertThrow(selector,
                ExcMessage("A surface traction needs a selector of the "
                           "loaded faces."));
    surface_traction_list.push_back({name, selector, traction, type});
  }



  template <int dim>
  const std::vector<typename BoundaryDescriptor<dim>::SurfaceTraction> &
  BoundaryDescriptor<dim>::surface_tractions() const
  {
    return surface_traction_list;
  }



  template <int dim>
  void
  BoundaryDescriptor<dim>::set_body_force(
    const std::shared_ptr<Function<dim>> &force)
  {
    AssertThrow(force && force->n_components == dim,
                ExcMessage("A body force function needs dim components."));
    body_force_function = force;
  }



  template <int dim>
  void
  BoundaryDescriptor<dim>::set_macroscopic_displacement_gradient(
    const std::function<Tensor<2, dim>(const double)> &H,
    const Point<dim>                                  &reference_point)
  {
    gradient  = H;
    reference = reference_point;
  }



  template <int dim>
  void
  BoundaryDescriptor<dim>::add_point_load(const Point<dim>     &location,
                                          const Tensor<1, dim> &force)
  {
    nodal_loads.emplace_back(location, force);
  }



  template <int dim>
  const std::vector<typename BoundaryDescriptor<dim>::DirichletCondition> &
  BoundaryDescriptor<dim>::dirichlet_conditions() const
  {
    return dirichlet;
  }



  template <int dim>
  const std::vector<
    std::pair<types::boundary_id, std::shared_ptr<Function<dim>>>> &
  BoundaryDescriptor<dim>::tractions() const
  {
    return traction_functions;
  }



  template <int dim>
  const std::shared_ptr<Function<dim>> &
  BoundaryDescriptor<dim>::body_force() const
  {
    return body_force_function;
  }



  template <int dim>
  const std::vector<std::pair<Point<dim>, Tensor<1, dim>>> &
  BoundaryDescriptor<dim>::point_loads() const
  {
    return nodal_loads;
  }



  template <int dim>
  bool
  BoundaryDescriptor<dim>::has_macroscopic_gradient() const
  {
    return static_cast<bool>(gradient);
  }



  template <int dim>
  Tensor<2, dim>
  BoundaryDescriptor<dim>::macroscopic_gradient(const double t) const
  {
    Assert(has_macroscopic_gradient(), ExcInternalError());
    return gradient(t);
  }



  template <int dim>
  const Point<dim> &
  BoundaryDescriptor<dim>::macroscopic_reference() const
  {
    return reference;
  }



  template <int dim>
  bool
  BoundaryDescriptor<dim>::has_loads() const
  {
    return body_force_function || !traction_functions.empty() ||
           !surface_traction_list.empty() || !nodal_loads.empty() ||
           !rigid_body_list.empty();
  }



  template <int dim>
  void
  BoundaryDescriptor<dim>::add_rigid_body(const RigidBody<dim> &body)
  {
    body.check();
    for (const auto &other : rigid_body_list)
      AssertThrow(other.name != body.name,
                  ExcMessage("Two rigid bodies are called <" + body.name +
                             ">: give each its own name."));
    rigid_body_list.push_back(body);
  }



  template <int dim>
  const std::vector<RigidBody<dim>> &
  BoundaryDescriptor<dim>::rigid_bodies() const
  {
    return rigid_body_list;
  }



  template <int dim>
  void
  BoundaryDescriptor<dim>::add_rigid_plate(const types::boundary_id id)
  {
    AssertThrow(id < 2 * dim,
                ExcMessage("Boundary conditions: a rigid plate on boundary " +
                           std::to_string(id) +
                           ", which a box does not "
                           "have; its ids are 0 to " +
                           std::to_string(2 * dim - 1) + "."));
    AssertThrow(std::find(plate_ids.begin(), plate_ids.end(), id) ==
                  plate_ids.end(),
                ExcMessage("Boundary conditions: boundary " +
                           std::to_string(id) +
                           " is given twice as a rigid plate."));
    plate_ids.push_back(id);
  }



  template <int dim>
  const std::vector<types::boundary_id> &
  BoundaryDescriptor<dim>::rigid_plates() const
  {
    return plate_ids;
  }



  template class BoundaryDescriptor<2>;
  template class BoundaryDescriptor<3>;
} // namespace qsmpm
