#ifndef qsmpm_loading_parsed_boundary_conditions_h
#define qsmpm_loading_parsed_boundary_conditions_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <memory>
#include <qsmpm/loading/boundary_descriptor.h>
#include <string>
#include <vector>

namespace qsmpm
{
  /**
   * The subsection "Boundary conditions" of a .prm file and its translation
   * into a BoundaryDescriptor: the entries
   *
   *   Dirichlet boundaries = 0:xy, 1:x, 2:n
   *   Traction boundaries  = 3
   *   Surface traction region = x > 9.99
   *   Surface traction type   = dead
   *   Macroscopic displacement gradient = 1e-3, 0, 0, 0
   *
   * (the small language "id:components" of the first one: boundary ids of
   * the box, components from x, y, z, or n for the normal component only)
   * and the four functions of the subsections Displacement, Traction,
   * Surface traction and Body force, which every displacement condition,
   * every traction boundary, the surface traction (SurfaceTractions) and
   * the body force share.
   *
   * Every mistake in the subsection stops the run with a message that names
   * the entry; deal.II's own messages (of ParsedFunction, of
   * Utilities::string_to_int()) do not. The functions are kept (shared with
   * the descriptor) so that check_functions() can later evaluate them where
   * the grid is known.
   */
  template <int dim>
  class ParsedBoundaryConditions
  {
  public:
    /**
     * The entries of the subsection, as text.
     */
    struct Parameters
    {
      /// "id:components, id:components"; components from x, y, z or n.
      std::string dirichlet;
      /// Boundary ids that carry the traction function.
      std::string traction;
      /// <Rigid plate boundaries>.
      std::string rigid_plates;
      /// H (dim x dim numbers, row by row) of a periodic grid, or empty.
      std::string macroscopic_gradient;
      /// Where the body's surface carries the function of "Surface
      /// traction": an expression in x, y (z), non-zero there; or empty.
      std::string surface_region;
      /// "dead" or "pressure" (BoundaryDescriptor::SurfaceLoadType).
      std::string surface_type;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /**
     * Read the subsection and add its conditions to @p boundary: Dirichlet
     * boundaries with the function of subsection "Displacement", traction
     * boundaries with "Traction", the body force of "Body force" (unless it
     * is zero) and the macroscopic displacement gradient.
     */
    void
    parse_parameters(ParameterHandler &prm, BoundaryDescriptor<dim> &boundary);

    /**
     * Evaluate the four functions (subsections Displacement, Traction,
     * Surface traction and Body force) at each of @p points for each load
     * factor in
     * @p load_factors, and throw an exception that names the subsection, the
     * expression, the point and t if one of them gives a value that is not
     * a finite number (e.g. sqrt(-1), 1/0). Without this check a NaN in a
     * load only shows up as a residual that is not a number, after every
     * cut-back of the first load step. Each rank may check points of its
     * own; the caller then makes all ranks stop together
     * (Utils::throw_if_any_rank()). Does nothing before parse_parameters().
     */
    void
    check_functions(const std::vector<Point<dim>> &points,
                    const std::vector<double>     &load_factors) const;

  private:
    /// Add the surface traction of <Surface traction region> to
    /// @p boundary.
    void
    add_surface_traction(
      const Parameters                                      &parameters,
      const std::shared_ptr<Functions::ParsedFunction<dim>> &traction,
      BoundaryDescriptor<dim>                               &boundary);

    /// Read and try out the four functions.
    void
    parse_functions(ParameterHandler &prm);

    /// Displacement, Traction, Surface traction and Body force.
    std::array<std::shared_ptr<Functions::ParsedFunction<dim>>, 4> functions;
    /// Their expressions, for messages.
    std::array<std::string, 4> expressions;
  };
} // namespace qsmpm

#endif
