#ifndef qsmpm_loading_parsed_rigid_body_h
#define qsmpm_loading_parsed_rigid_body_h

#include <deal.II/base/parameter_handler.h>
#include <qsmpm/loading/boundary_descriptor.h>

namespace qsmpm
{
  /**
   * The subsection "Boundary conditions/Rigid body" of a .prm file: one
   * rigid body (RigidBody) that the points cannot enter, e.g.
   *
   *   subsection Rigid body
   *     set Shape  = half-space
   *     set Name   = plate
   *     set Point  = 0, 1
   *     set Normal = 0, -1
   *     set Friction = coulomb
   *     set Friction coefficient = 0.3
   *     subsection Motion
   *       set Function expression = 0; -0.01*t
   *     end
   *   end
   *
   * More bodies can be added from C++ (BoundaryDescriptor::
   * add_rigid_body()).
   */
  template <int dim>
  struct ParsedRigidBody
  {
    /// Declare the subsection (inside "Boundary conditions").
    static void
    declare_parameters(ParameterHandler &prm);

    /// Read the subsection (inside "Boundary conditions") and add the body
    /// to @p boundary unless its Shape is none. Throws with a message that
    /// names the entry for every mistake.
    static void
    parse_parameters(ParameterHandler &prm, BoundaryDescriptor<dim> &boundary);
  };
} // namespace qsmpm

#endif
