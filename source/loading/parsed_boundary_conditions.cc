#include <cmath>
#include <cstdlib>
#include <deal.II/base/function_parser.h>
#include <deal.II/lac/vector.h>
#include <iostream>
#include <qsmpm/base/parsed_region.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/loading/parsed_boundary_conditions.h>
#include <qsmpm/loading/parsed_rigid_body.h>
#include <sstream>

namespace qsmpm
{
  namespace
  {
    // The subsections of the four functions of "Boundary conditions", in
    // the order of ParsedBoundaryConditions::functions.
    const std::array<std::string, 4> function_subsections = {
      {"Displacement", "Traction", "Surface traction", "Body force"}};

    // The default of each function: zero in every component.
    template <int dim>
    std::string
    zero_expression()
    {
      return dim == 2 ? "0; 0" : "0; 0; 0";
    }

    // The small language of <Dirichlet boundaries>. An item is
    // "<boundary id>:<components>", e.g. "0:xy" or "2:n"; the ids are those
    // of the box (BackgroundGrid), so anything else is a mistake in the
    // input and not a condition that would select no node.
    template <int dim>
    struct DirichletItem
    {
      types::boundary_id    boundary_id;
      std::array<bool, dim> components;
      bool                  normal_only;
    };

    template <int dim>
    DirichletItem<dim>
    parse_dirichlet_item(const std::string &entry)
    {
      const auto parts = Utils::split(entry, ':');
      AssertThrow(parts.size() == 2,
                  ExcMessage("Boundary conditions: the entry <Dirichlet "
                             "boundaries> expects <id>:<components> items, "
                             "got <" +
                             entry + ">."));
      // string_to_int() would stop with "Can't convert <two> to an
      // integer.", which does not name the entry.
      int id = -1;
      try
        {
          id = dealii::Utilities::string_to_int(parts[0]);
        }
      catch (const std::exception &)
        {
          AssertThrow(false,
                      ExcMessage("Boundary conditions: <" + parts[0] +
                                 "> in <Dirichlet boundaries> = <" + entry +
                                 "> is not a boundary id (a box has ids 0 "
                                 "to " +
                                 std::to_string(2 * dim - 1) + ")."));
        }
      AssertThrow(id >= 0 && id < 2 * dim,
                  ExcMessage("Boundary conditions: boundary id <" + parts[0] +
                             "> in <Dirichlet boundaries> does "
                             "not exist; a box has ids 0 to " +
                             std::to_string(2 * dim - 1) + "."));
      DirichletItem<dim> item;
      item.boundary_id = id;
      item.components  = Utils::parse_components<dim>(parts[1],
                                                     "Dirichlet boundaries",
                                                     item.normal_only);
      return item;
    }



    // <Macroscopic displacement gradient>: dim x dim numbers, row by row.
    template <int dim>
    Tensor<2, dim>
    parse_macroscopic_gradient(const std::string &text)
    {
      const auto entries = Utils::split(text, ',');
      AssertThrow(entries.size() == dim * dim,
                  ExcMessage("Boundary conditions: <Macroscopic displacement "
                             "gradient> needs " +
                             std::to_string(dim * dim) + " numbers, got " +
                             std::to_string(entries.size()) + "."));
      Tensor<2, dim> H;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          {
            const std::string &entry = entries[i * dim + j];
            // string_to_double() would not name the entry.
            try
              {
                H[i][j] = dealii::Utilities::string_to_double(entry);
              }
            catch (const std::exception &)
              {
                AssertThrow(false,
                            ExcMessage("Boundary conditions: <" + entry +
                                       "> in <Macroscopic displacement "
                                       "gradient> is not a number."));
              }
            AssertThrow(std::isfinite(H[i][j]),
                        ExcMessage("Boundary conditions: <" + entry +
                                   "> in <Macroscopic displacement "
                                   "gradient> is not a finite number."));
          }
      return H;
    }



    // An item of <Traction boundaries>. The pattern of the entry admits only
    // non-negative integers, but not only the ids a box has: a traction on
    // id 9 would load nothing.
    template <int dim>
    types::boundary_id
    parse_traction_id(const std::string &entry)
    {
      const int id = dealii::Utilities::string_to_int(entry);
      AssertThrow(id >= 0 && id < 2 * dim,
                  ExcMessage("Boundary conditions: boundary id <" + entry +
                             "> in <Traction boundaries> does not exist; a "
                             "box has ids 0 to " +
                             std::to_string(2 * dim - 1) + "."));
      return id;
    }
  } // namespace



  template <int dim>
  void
  ParsedBoundaryConditions<dim>::Parameters::declare_parameters(
    ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    {
      prm.declare_entry(
        "Dirichlet boundaries",
        "",
        Patterns::Anything(),
        "Comma-separated list of <boundary id>:<components>, e.g. "
        "\"0:xy, 1:x, 2:n\". Components are letters from x, y, z, or n for "
        "the normal component only (a face free to slide). The prescribed "
        "values come from the function of subsection <Displacement> at the "
        "node positions, with t = load factor. Box boundary ids: 0/1 = x "
        "min/max, 2/3 = y min/max, 4/5 = z min/max.");
      prm.declare_entry("Traction boundaries",
                        "",
                        Patterns::List(Patterns::Integer(0)),
                        "Boundary ids loaded by the function of subsection "
                        "<Traction> (force per area, t = load factor). The "
                        "load acts on the grid's faces: for a body that "
                        "stays on them. A body that moves away from the "
                        "face would lose the load (the equilibrium check "
                        "stops the run); use <Surface traction region>.");
      prm.declare_entry(
        "Rigid plate boundaries",
        "",
        Patterns::List(Patterns::Integer(0)),
        "Boundary ids whose nodes move as one rigid, frictionless plate "
        "along the boundary's normal, by what the load on them makes them "
        "(the traction of <Traction boundaries> on the same id is the "
        "plate's load; its other components stay free): a plate pressed "
        "onto the body by a given force. A displacement condition may not "
        "hold the same boundary along its normal.");
      prm.declare_entry(
        "Surface traction region",
        "",
        Patterns::Anything(),
        "Where the body's own surface carries the function of subsection "
        "<Surface traction>: an expression in x, y (and z), non-zero on the "
        "loaded part of the initial surface, e.g. \"x > 9.99\" or \"1\" "
        "for all of it. The faces of the body's surface are found from the "
        "material points; the points next to a loaded face carry its area "
        "and the load moves with them, at small and finite strain, with "
        "linear and GIMP shape functions. Empty: none.");
      prm.declare_entry(
        "Surface traction type",
        "dead",
        Patterns::Selection("dead|pressure"),
        "dead: the function is a force per unit initial area of fixed "
        "direction (dim components), at the point's initial position. "
        "pressure: its first component is a pressure p (the others must be "
        "0) on the current surface, along the current inward normal "
        "(force -p n da, a follower load).");
      prm.declare_entry(
        "Macroscopic displacement gradient",
        "",
        Patterns::Anything(),
        "For a grid with <Periodic directions>: the displacement gradient H "
        "(dim x dim numbers, row by row, multiplied by the load factor t), "
        "so that u = t H x + a periodic fluctuation; across a periodic "
        "direction d the displacement jumps by t H L_d e_d. Empty: H = 0.");
      for (const std::string &name : function_subsections)
        {
          prm.enter_subsection(name);
          Functions::ParsedFunction<dim>::declare_parameters(prm, dim);
          prm.set("Function expression", zero_expression<dim>());
          prm.set("Variable names", dim == 2 ? "x,y,t" : "x,y,z,t");
          prm.leave_subsection();
        }
      ParsedRigidBody<dim>::declare_parameters(prm);
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  ParsedBoundaryConditions<dim>::Parameters::parse_parameters(
    ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    dirichlet            = prm.get("Dirichlet boundaries");
    traction             = prm.get("Traction boundaries");
    rigid_plates         = prm.get("Rigid plate boundaries");
    macroscopic_gradient = prm.get("Macroscopic displacement gradient");
    surface_region       = prm.get("Surface traction region");
    surface_type         = prm.get("Surface traction type");
    prm.leave_subsection();
  }



  template <int dim>
  void
  ParsedBoundaryConditions<dim>::parse_parameters(
    ParameterHandler        &prm,
    BoundaryDescriptor<dim> &boundary)
  {
    Parameters parameters;
    parameters.parse_parameters(prm);
    parse_functions(prm);
    const auto &[displacement, traction, surface_traction, body_force] =
      functions;

    for (const auto &entry : Utils::split(parameters.dirichlet, ','))
      {
        const auto item = parse_dirichlet_item<dim>(entry);
        boundary.add_dirichlet_boundary(item.boundary_id,
                                        item.components,
                                        displacement,
                                        item.normal_only);
      }
    if (!parameters.macroscopic_gradient.empty())
      {
        const Tensor<2, dim> H =
          parse_macroscopic_gradient<dim>(parameters.macroscopic_gradient);
        boundary.set_macroscopic_displacement_gradient(
          [H](const double t) { return t * H; });
      }
    for (const auto &entry : Utils::split(parameters.traction, ','))
      boundary.add_traction(parse_traction_id<dim>(entry), traction);
    for (const auto &entry : Utils::split(parameters.rigid_plates, ','))
      boundary.add_rigid_plate(dealii::Utilities::string_to_int(entry));
    if (!parameters.surface_region.empty())
      add_surface_traction(parameters, surface_traction, boundary);
    if (expressions[3] != zero_expression<dim>())
      boundary.set_body_force(body_force);
    prm.enter_subsection("Boundary conditions");
    ParsedRigidBody<dim>::parse_parameters(prm, boundary);
    prm.leave_subsection();
  }



  template <int dim>
  void
  ParsedBoundaryConditions<dim>::add_surface_traction(
    const Parameters                                      &parameters,
    const std::shared_ptr<Functions::ParsedFunction<dim>> &traction,
    BoundaryDescriptor<dim>                               &boundary)
  {
    using Type = typename BoundaryDescriptor<dim>::SurfaceLoadType;
    const Type type =
      parameters.surface_type == "pressure" ? Type::pressure : Type::dead;
    // A pressure is one number: components that are not zero would be
    // ignored.
    if (type == Type::pressure)
      {
        const auto components = Utils::split(expressions[2], ';');
        const auto is_zero    = [](const std::string &text) {
          char  *end   = nullptr;
          double value = std::strtod(text.c_str(), &end);
          return end != text.c_str() && *end == '\0' && value == 0.;
        };
        for (unsigned int c = 1; c < components.size(); ++c)
          AssertThrow(is_zero(components[c]),
                      ExcMessage("Boundary conditions: with <Surface "
                                 "traction type = pressure> the pressure is "
                                 "the first expression of Surface traction/"
                                 "<Function expression> = <" +
                                 expressions[2] +
                                 ">, and the others must be 0."));
      }

    boundary.add_surface_traction(
      "Boundary conditions/Surface traction region = " +
        parameters.surface_region,
      parse_region<dim>(parameters.surface_region,
                        "Boundary conditions: <Surface traction region>",
                        "on the loaded surface"),
      traction,
      type);
  }



  template <int dim>
  void
  ParsedBoundaryConditions<dim>::parse_functions(ParameterHandler &prm)
  {
    // deal.II's own messages for a wrong number of expressions ("The number
    // of components (2) is not equal to the number of expressions (3).") or
    // a malformed constant ("Invalid format") do not say which of the four
    // functions is meant, so we add the subsection and the entries. A first
    // evaluation (at the origin, t = 0) finds syntax errors and unknown
    // variables now rather than in the middle of the first load step.
    prm.enter_subsection("Boundary conditions");
    for (unsigned int i = 0; i < functions.size(); ++i)
      {
        functions[i] = std::make_shared<Functions::ParsedFunction<dim>>(dim);
        prm.enter_subsection(function_subsections[i]);
        expressions[i] = prm.get("Function expression");
        const std::string entries =
          "Boundary conditions/" + function_subsections[i] +
          ": <Function expression> = <" + expressions[i] +
          "> with <Variable names> = <" + prm.get("Variable names") +
          "> and <Function constants> = <" + prm.get("Function constants") +
          ">";
        try
          {
            functions[i]->parse_parameters(prm);
            Vector<double> values(dim);
            evaluate_quietly<dim>(*functions[i], Point<dim>(), values);
          }
        catch (const std::exception &exc)
          {
            AssertThrow(false,
                        ExcMessage(entries + ": " + Utils::error_message(exc) +
                                   " (a function needs " + std::to_string(dim) +
                                   " expressions separated by ';' in the "
                                   "variables of <Variable names>, and "
                                   "constants as name=value, ...)."));
          }
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }



  template <int dim>
  void
  ParsedBoundaryConditions<dim>::check_functions(
    const std::vector<Point<dim>> &points,
    const std::vector<double>     &load_factors) const
  {
    Vector<double> values(dim);
    for (unsigned int i = 0; i < functions.size(); ++i)
      if (functions[i] != nullptr)
        {
          Functions::ParsedFunction<dim> &function = *functions[i];
          const double                    time     = function.get_time();
          for (const double t : load_factors)
            {
              function.set_time(t);
              for (const auto &point : points)
                {
                  evaluate_quietly<dim>(function, point, values);
                  for (unsigned int c = 0; c < dim; ++c)
                    if (!std::isfinite(values[c]))
                      {
                        function.set_time(time);
                        std::ostringstream where;
                        where
                          << "Boundary conditions/" << function_subsections[i]
                          << ": <Function expression> = <" << expressions[i]
                          << "> gives " << values[c] << " in component " << c
                          << " at x = (" << point << "), t = " << t
                          << "; every value must be a finite number.";
                        AssertThrow(false, ExcMessage(where.str()));
                      }
                }
            }
          function.set_time(time);
        }
  }



  template class ParsedBoundaryConditions<2>;
  template class ParsedBoundaryConditions<3>;
} // namespace qsmpm
