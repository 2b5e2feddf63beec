#ifndef qsmpm_loading_external_force_assembler_h
#define qsmpm_loading_external_force_assembler_h

#include <deal.II/lac/trilinos_vector.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/loading/boundary_descriptor.h>
#include <qsmpm/particles/shape_cache.h>

namespace qsmpm
{
  /**
   * The external force f_ext(t) of paper eq. (2.10) from the loads of a
   * BoundaryDescriptor:
   *
   *   f_ext_i = sum_p Omega_p b(x_p) N_i(x_p)              (body force, 2.11)
   *           + int_{Gamma_t} t_bar N_i dA                 (tractions, 2.12)
   *           + t F_i                                      (point loads).
   *
   * The body force is integrated with the points (and the ShapeCache of the
   * step), the tractions with Gauss quadrature over the faces of the
   * background grid. Tractions therefore assume that the loaded surface of
   * the body coincides with a grid boundary. With several bodies (a
   * multi-field grid) the force of a grid node is divided among the fields
   * of the bodies in proportion to their material at the node.
   */
  template <int dim>
  class ExternalForceAssembler
  {
  public:
    /// The loads of @p boundary, which must outlive this object.
    explicit ExternalForceAssembler(const BoundaryDescriptor<dim> &boundary);

    /**
     * Axisymmetric (r, z) kinematics: the tractions are integrated over
     * r dGamma, the force per radian (the body force is per radian through
     * the points' volumes, point loads are taken as given: per radian).
     */
    void
    set_axisymmetric(const bool axisymmetric);

    /**
     * f_ext at load factor @p t. The volume of a point is read at offset
     * @p volume_offset of its properties: the current volume at small
     * strain, the initial one at finite strain, where a body force is per
     * unit initial volume (rho_0 b).
     */
    void
    assemble(const BackgroundGrid<dim>     &grid,
             const ShapeCache<dim>         &cache,
             const unsigned int             volume_offset,
             const double                   t,
             TrilinosWrappers::MPI::Vector &f_ext) const;

  private:
    /// The three kinds of load, each added to f_ext (not compressed).
    void
    add_body_force(const ShapeCache<dim>         &cache,
                   const unsigned int             volume_offset,
                   const double                   t,
                   TrilinosWrappers::MPI::Vector &f_ext) const;
    /// The loads on grid nodes; @p volumes: with several bodies, the
    /// material of each body at each node (ghosted; field_share()).
    void
    add_tractions(const BackgroundGrid<dim>           &grid,
                  const TrilinosWrappers::MPI::Vector &volumes,
                  const double                         t,
                  TrilinosWrappers::MPI::Vector       &f_ext) const;
    void
    add_point_loads(const BackgroundGrid<dim>           &grid,
                    const TrilinosWrappers::MPI::Vector &volumes,
                    const double                         t,
                    TrilinosWrappers::MPI::Vector       &f_ext) const;

    /**
     * The part of a grid node's force that goes to the field of the
     * component @p component of the node, whose dofs (all components) are
     * @p node_dofs: 1 on one field; with several bodies that body's share
     * of the material at the node (see the implementation).
     */
    static double
    field_share(const BackgroundGrid<dim>                  &grid,
                const TrilinosWrappers::MPI::Vector        &volumes,
                const std::vector<types::global_dof_index> &node_dofs,
                const unsigned int                          component);

    const BoundaryDescriptor<dim> &boundary;
    bool                           axisymmetric = false;
  };
} // namespace qsmpm

#endif
