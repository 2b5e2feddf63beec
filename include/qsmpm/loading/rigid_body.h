#ifndef qsmpm_loading_rigid_body_h
#define qsmpm_loading_rigid_body_h

#include <array>
#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <memory>
#include <string>
#include <vector>

namespace qsmpm
{
  using namespace dealii;

  /**
   * A rigid body that the material points cannot enter: its shape in the
   * initial configuration, the translation it makes as a function of the
   * load factor, and the friction of its surface. RigidContact turns it
   * into forces on the points; this class only describes it.
   *
   * Shapes (the body is the set where signed_distance() < 0):
   *  - half-space: every x with (x - point) . normal < 0; @p normal is
   *    the outward normal of the body, towards the material;
   *  - box: lower corner @p point, upper corner @p upper_corner;
   *  - sphere (a circle in 2D, a cylinder along z in plane strain):
   *    centre @p point, radius @p radius;
   *  - polygon: the convex polygon with the @p vertices (in the x-y
   *    plane, in either order; a wedge, a punch with chamfers, a cone's
   *    section in plane strain); in 3D the prism it spans along z;
   *  - cone: a cone penetrometer: the tip @p point, the axis @p normal
   *    (from the tip into the body), the half-angle @p half_angle at the
   *    tip, and above the cone a shaft of @p radius. In 3D the solid of
   *    revolution; in an axisymmetric problem (tip on the axis x = 0,
   *    axis along y) the same cone; in plane strain a wedge with a shaft.
   *
   * Friction of the surface:
   *  - frictionless: the body pushes along its normal only;
   *  - coulomb: a tangential traction up to mu times the contact pressure
   *    (stick below, slip at it);
   *  - rough: no slip at all (mu infinite);
   *  - tied: the points that touch the body (or lie in it) at the start
   *    of a step are glued to it, in tension as in compression, along the
   *    surface as across it: a displacement condition on a surface that
   *    need not coincide with the grid's faces (the body is then a
   *    support or a grip, which moves with its motion).
   */
  template <int dim>
  struct RigidBody
  {
    enum class Shape
    {
      half_space,
      box,
      sphere,
      polygon,
      cone
    };

    enum class Friction
    {
      frictionless,
      coulomb,
      rough,
      tied
    };

    /// Names the body in reactions.csv, in the points' output (the field
    /// contact_<name>) and in messages.
    std::string name = "body";

    Shape shape = Shape::half_space;
    /// half-space: a point of its plane; box: the lower corner; sphere:
    /// the centre (initial configuration).
    Point<dim> point;
    /// half-space: the outward unit normal; cone: the unit axis, from the
    /// tip into the body.
    Tensor<1, dim> normal;
    /// box: the upper corner.
    Point<dim> upper_corner;
    /// sphere: the radius; cone: the radius of its shaft.
    double radius = 0.;
    /// cone: the angle between the axis and the cone's face (radians).
    double half_angle = 0.;
    /// polygon: its vertices, x and y (the z coordinate is ignored),
    /// relative to @p point, counterclockwise (set_polygon() orders them).
    std::vector<Tensor<1, dim>> vertices;

    /// Make the body the convex polygon with the corners @p corners
    /// (positions at t = 0, in either order): @p point becomes their
    /// centroid. Throws with a message naming the body unless there are at
    /// least 3 corners forming a convex polygon.
    void
    set_polygon(const std::vector<Point<dim>> &corners);

    /// The body's displacement (dim components) as a function of the load
    /// factor t (set_time(t), evaluated at the origin); nullptr: at rest.
    std::shared_ptr<Function<dim>> motion;

    /**
     * A body driven by a force: the direction along which its motion is
     * not prescribed (zero, the default: the body follows @p motion
     * alone). Along it the body moves, in each step, until the contact
     * force of the material balances @p load; @p motion's component along
     * it is ignored, the others are prescribed. Set both or neither.
     */
    Tensor<1, dim> load_direction;

    /// The force the body exerts on the material along
    /// @p load_direction (per unit thickness in 2D) as a function of the
    /// load factor t (set_time(t), evaluated at the origin).
    std::shared_ptr<Function<dim>> load;

    /// Whether a force drives the body along load_direction.
    bool
    load_driven() const
    {
      return load_direction.norm() > 0.;
    }

    /// The unit vector of load_direction (zero if not load_driven()).
    Tensor<1, dim>
    load_unit() const;

    /// The force along load_direction at load factor @p t.
    double
    force(const double t) const;

    /// The prescribed part of the body's translation at load factor @p t:
    /// displacement(t) without its component along load_direction.
    Tensor<1, dim>
    prescribed_displacement(const double t) const;

    Friction friction = Friction::frictionless;
    /// mu of Coulomb friction.
    double friction_coefficient = 0.;

    /**
     * The penalty factor gamma: the contact stiffness per unit area is
     * gamma k / h^(dim-1), k the mean stiffness of the grid's degrees of
     * freedom (the diagonal of the step's tangent), h the smallest cell
     * size, so that gamma has no units. A point penetrates the body by
     * about p h / (gamma E): the larger gamma, the closer to
     * impenetrability and the stiffer Newton's problem.
     */
    double penalty_factor = 100.;

    /// The body's translation at load factor @p t.
    Tensor<1, dim>
    displacement(const double t) const;

    /**
     * The signed distance of @p x from the body's surface when the body
     * has moved by @p motion (positive outside, negative inside), and in
     * @p normal the body's outward unit normal at the nearest point of its
     * surface. The caller evaluates displacement() once per load factor.
     */
    double
    signed_distance(const Point<dim>     &x,
                    const Tensor<1, dim> &motion,
                    Tensor<1, dim>       &normal) const;

    /**
     * The same for @p y = x - point - motion, the position relative to
     * the body's reference point in its initial configuration. Near the
     * surface of a half-space (and the lower faces of a box) @p y is small,
     * so that the gap has the round-off of y, not of x: a penalty of
     * stiffness epsilon turns a round-off of 1e-16 |x| into forces of
     * epsilon 1e-16 |x|, which kept Newton from its tolerance in steady
     * sliding, where the residual of a step is itself tiny.
     */
    double
    signed_distance_from_point(const Tensor<1, dim> &y,
                               Tensor<1, dim>       &normal) const;

    /**
     * A flat face of a box or a polygon: the points y (relative to the
     * body's reference point, initial configuration) with
     * normal . y = offset whose coordinates y . tangents[k] lie in
     * [lower[k], upper[k]] (infinite along z for a polygon in 3D).
     * normal . y - offset is the signed distance of y from the face's
     * plane, positive on the side the outward normal points to.
     */
    struct Face
    {
      Tensor<1, dim>                      normal;
      double                              offset = 0.;
      std::array<Tensor<1, dim>, dim - 1> tangents;
      std::array<double, dim - 1>         lower;
      std::array<double, dim - 1>         upper;
    };

    /// The flat faces of a box (2 dim of them), a polygon (one per edge)
    /// and a cone in 2D (its faces and the sides of its shaft); none for a
    /// half-space and a sphere, whose surfaces have no edges, and for a
    /// cone in 3D, whose surface is curved.
    std::vector<Face>
    faces() const;

    /// Throws with a message naming the body if its description is
    /// incomplete (a zero normal, an empty box, a radius <= 0, mu < 0, a
    /// load direction without a load or the other way round, a cone's
    /// half-angle outside (0, 90) degrees).
    void
    check() const;

    /// Friction from its name: frictionless, coulomb, rough or tied.
    static Friction
    parse_friction(const std::string &name);

    /// Shape from its name: half-space, box, sphere, polygon or cone.
    static Shape
    parse_shape(const std::string &name);
  };
} // namespace qsmpm

#endif
