#include <deal.II/base/parsed_function.h>
#include <deal.II/lac/vector.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/loading/parsed_rigid_body.h>

namespace qsmpm
{
  template <int dim>
  void
  ParsedRigidBody<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Rigid body");
    prm.declare_entry("Shape",
                      "none",
                      Patterns::Selection(
                        "none|half-space|box|sphere|polygon|cone"),
                      "A rigid body the material points cannot enter "
                      "(contact by a penalty on the points' surfaces). none: "
                      "no body. half-space: the side of the plane through "
                      "<Point> away from <Normal>. box: from <Point> (lower "
                      "corner) to <Upper corner>. sphere: centre <Point>, "
                      "<Radius> (a circle in 2D). polygon: the convex "
                      "polygon with the corners <Vertices> in the x-y plane "
                      "(in 3D the prism along z). cone: a cone "
                      "penetrometer, tip <Point>, axis <Normal> (from the "
                      "tip into the body), <Half-angle>, and above the cone "
                      "a shaft of <Radius> (in 3D the solid of revolution; "
                      "in an axisymmetric problem the cone, with the tip on "
                      "the axis and <Normal> = 0, 1; in plane strain a "
                      "wedge with a shaft). Positions are those at "
                      "t = 0; the body then moves by <Motion>.");
    prm.declare_entry("Name",
                      "body",
                      Patterns::Anything(),
                      "Names the body in reactions.csv (the material's "
                      "force on it, columns <Name>_Fx, ...) and the points' "
                      "contact traction in the output (contact_<Name>).");
    prm.declare_entry("Point",
                      dim == 2 ? "0, 0" : "0, 0, 0",
                      Patterns::Anything(),
                      "half-space: a point of its plane; box: its lower "
                      "corner; sphere: its centre; cone: its tip (not used "
                      "by a polygon).");
    prm.declare_entry("Normal",
                      dim == 2 ? "0, 1" : "0, 0, 1",
                      Patterns::Anything(),
                      "half-space: its outward unit normal (towards the "
                      "material); cone: its axis, from the tip into the "
                      "body.");
    prm.declare_entry("Upper corner",
                      dim == 2 ? "1, 1" : "1, 1, 1",
                      Patterns::Anything(),
                      "box: its upper corner.");
    prm.declare_entry("Radius",
                      "1",
                      Patterns::Double(0.),
                      "sphere: its radius; cone: the radius of its shaft.");
    prm.declare_entry("Half-angle",
                      "30",
                      Patterns::Double(0., 90.),
                      "cone: the angle between its axis and its face, in "
                      "degrees (30: the standard 60 degree penetrometer).");
    prm.declare_entry("Vertices",
                      "",
                      Patterns::Anything(),
                      "polygon: its corners, x and y of each, separated by "
                      "';' (e.g. \"0, 1; 1, 1; 0.5, 0.5\" for a wedge "
                      "pointing down), in either order.");
    prm.declare_entry("Friction",
                      "frictionless",
                      Patterns::Selection("frictionless|coulomb|rough|tied"),
                      "frictionless: normal contact only. coulomb: "
                      "tangential traction up to <Friction coefficient> "
                      "times the contact pressure (stick, then slip; "
                      "Newton then takes at least 8 steps of line search, "
                      "Nonlinear solver/Line search steps). rough: no "
                      "slip. tied: the points that touch the body (their "
                      "surface within half their size of it) or lie in it "
                      "are glued to it, in tension and compression, along "
                      "and across the surface: a displacement condition on "
                      "a surface off the grid's faces (a support or a grip "
                      "that moves with <Motion>).");
    prm.declare_entry("Friction coefficient",
                      "0",
                      Patterns::Double(0.),
                      "mu of Coulomb friction.");
    prm.declare_entry("Penalty factor",
                      "100",
                      Patterns::Double(0.),
                      "gamma: the contact stiffness per area is gamma k / "
                      "h^(dim-1), k the mean stiffness of the grid's "
                      "degrees of freedom, h the smallest cell size. A "
                      "point penetrates the body by about p h / (gamma E).");
    prm.declare_entry(
      "Load direction",
      "",
      Patterns::Anything(),
      "Empty (the default): the body follows <Motion>. Otherwise the "
      "direction \"x,y\" (\"x,y,z\") in which a force, <Load>, pushes the "
      "body into the material: along it the body moves until the material "
      "balances that force (its motion there is an unknown of each step, "
      "in reactions.csv as <Name>_u), across it it follows <Motion>.");
    prm.enter_subsection("Motion");
    Functions::ParsedFunction<dim>::declare_parameters(prm, dim);
    prm.set("Function expression", dim == 2 ? "0; 0" : "0; 0; 0");
    prm.set("Variable names", dim == 2 ? "x,y,t" : "x,y,z,t");
    prm.leave_subsection();
    prm.enter_subsection("Load");
    Functions::ParsedFunction<dim>::declare_parameters(prm, 1);
    prm.set("Variable names", dim == 2 ? "x,y,t" : "x,y,z,t");
    prm.leave_subsection();
    prm.leave_subsection();
  }



  template <int dim>
  void
  ParsedRigidBody<dim>::parse_parameters(ParameterHandler        &prm,
                                         BoundaryDescriptor<dim> &boundary)
  {
    prm.enter_subsection("Rigid body");
    const std::string shape = prm.get("Shape");
    if (shape == "none")
      {
        prm.leave_subsection();
        return;
      }
    const std::string where = "Boundary conditions/Rigid body: ";
    RigidBody<dim>    body;
    body.name  = prm.get("Name");
    body.shape = RigidBody<dim>::parse_shape(shape);
    body.point = Utils::parse_point<dim>(prm.get("Point"), where + "<Point>");
    const Point<dim> normal =
      Utils::parse_point<dim>(prm.get("Normal"), where + "<Normal>");
    AssertThrow((body.shape != RigidBody<dim>::Shape::half_space &&
                 body.shape != RigidBody<dim>::Shape::cone) ||
                  normal.norm() > 0.,
                ExcMessage(where + "<Normal> must not be zero."));
    if (normal.norm() > 0.)
      body.normal = normal / normal.norm();
    body.upper_corner = Utils::parse_point<dim>(prm.get("Upper corner"),
                                                where + "<Upper corner>");
    body.radius       = prm.get_double("Radius");
    body.half_angle   = prm.get_double("Half-angle") * M_PI / 180.;
    if (body.shape == RigidBody<dim>::Shape::polygon)
      {
        std::vector<Point<dim>> corners;
        for (const auto &text :
             Utilities::split_string_list(prm.get("Vertices"), ';'))
          {
            const Point<2> xy =
              Utils::parse_point<2>(text, where + "<Vertices>");
            Point<dim> corner;
            corner[0] = xy[0];
            corner[1] = xy[1];
            corners.push_back(corner);
          }
        body.set_polygon(corners);
      }
    body.friction = RigidBody<dim>::parse_friction(prm.get("Friction"));
    body.friction_coefficient = prm.get_double("Friction coefficient");
    body.penalty_factor       = prm.get_double("Penalty factor");
    AssertThrow(body.penalty_factor > 0.,
                ExcMessage(where + "<Penalty factor> must be positive."));
    auto motion = std::make_shared<Functions::ParsedFunction<dim>>(dim);
    prm.enter_subsection("Motion");
    try
      {
        motion->parse_parameters(prm);
        motion->set_time(0.);
        Vector<double> values(dim);
        motion->vector_value(Point<dim>(), values);
      }
    catch (const std::exception &exc)
      {
        AssertThrow(false,
                    ExcMessage(
                      where + "Motion: <Function expression> = <" +
                      prm.get("Function expression") +
                      ">: " + Utils::error_message(exc) +
                      " (the body's displacement: " + std::to_string(dim) +
                      " expressions in t separated by ';')."));
      }
    prm.leave_subsection();
    const std::string direction = prm.get("Load direction");
    if (!direction.empty())
      {
        const Point<dim> d =
          Utils::parse_point<dim>(direction, where + "<Load direction>");
        AssertThrow(d.norm() > 0.,
                    ExcMessage(where + "<Load direction> must not be zero."));
        body.load_direction = d / d.norm();
        auto load = std::make_shared<Functions::ParsedFunction<dim>>(1);
        prm.enter_subsection("Load");
        try
          {
            load->parse_parameters(prm);
            load->set_time(0.);
            load->value(Point<dim>());
          }
        catch (const std::exception &exc)
          {
            AssertThrow(false,
                        ExcMessage(where + "Load: <Function expression> = <" +
                                   prm.get("Function expression") +
                                   ">: " + Utils::error_message(exc) +
                                   " (the force on the body along <Load "
                                   "direction>: one expression in t)."));
          }
        prm.leave_subsection();
        body.load = load;
      }
    prm.leave_subsection();
    body.motion = motion;
    boundary.add_rigid_body(body);
  }



  template struct ParsedRigidBody<2>;
  template struct ParsedRigidBody<3>;
} // namespace qsmpm
