#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <limits>
#include <qsmpm/loading/rigid_body.h>

namespace qsmpm
{
  template <int dim>
  Tensor<1, dim>
  RigidBody<dim>::displacement(const double t) const
  {
    Tensor<1, dim> u;
    if (motion == nullptr)
      return u;
    motion->set_time(t);
    for (unsigned int d = 0; d < dim; ++d)
      u[d] = motion->value(Point<dim>(), d);
    return u;
  }



  template <int dim>
  double
  RigidBody<dim>::signed_distance(const Point<dim>     &x,
                                  const Tensor<1, dim> &motion_so_far,
                                  Tensor<1, dim>       &n) const
  {
    // The body moves as a whole: measure in its initial configuration.
    return signed_distance_from_point((x - point) - motion_so_far, n);
  }



  template <int dim>
  double
  RigidBody<dim>::signed_distance_from_point(const Tensor<1, dim> &y,
                                             Tensor<1, dim>       &n) const
  {
    switch (shape)
      {
        case Shape::half_space:
          n = normal;
          return y * normal;
        case Shape::sphere:
          {
            const double length = y.norm();
            n                   = length > 0. ? y / length : Tensor<1, dim>();
            if (length == 0.)
              n[dim - 1] = 1.;
            return length - radius;
          }
        case Shape::box:
          {
            // q_d > 0: outside the slab 0 <= y_d <= size_d, by q_d.
            Tensor<1, dim> q, outside;
            unsigned int   nearest = 0;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double size  = upper_corner[d] - point[d];
                const bool   below = -y[d] > y[d] - size;
                q[d]               = below ? -y[d] : y[d] - size;
                outside[d]         = std::max(q[d], 0.) * (below ? -1. : 1.);
                if (q[d] > q[nearest])
                  nearest = d;
              }
            const double distance = outside.norm();
            if (distance > 0.)
              {
                n = outside / distance;
                return distance;
              }
            // Inside: the nearest face.
            n          = Tensor<1, dim>();
            n[nearest] = -y[nearest] > y[nearest] - (upper_corner[nearest] -
                                                     point[nearest]) ?
                           -1. :
                           1.;
            return q[nearest];
          }
        case Shape::polygon:
          {
            // Inside: the largest distance to the edges' lines, all
            // negative. Outside: the distance to the nearest edge segment.
            Tensor<1, dim> p;
            p[0]                   = y[0];
            p[1]                   = y[1];
            const unsigned int m   = vertices.size();
            double             in  = -std::numeric_limits<double>::max();
            double             out = std::numeric_limits<double>::max();
            Tensor<1, dim>     in_normal, out_normal;
            for (unsigned int i = 0; i < m; ++i)
              {
                const Tensor<1, dim> &a    = vertices[i];
                const Tensor<1, dim>  edge = vertices[(i + 1) % m] - a;
                Tensor<1, dim>        outward;
                outward[0] = edge[1];
                outward[1] = -edge[0];
                outward /= outward.norm();
                const double along_line = outward * (p - a);
                if (along_line > in)
                  {
                    in        = along_line;
                    in_normal = outward;
                  }
                const double s =
                  std::clamp(((p - a) * edge) / (edge * edge), 0., 1.);
                const Tensor<1, dim> offset   = p - (a + s * edge);
                const double         distance = offset.norm();
                if (distance < out)
                  {
                    out        = distance;
                    out_normal = distance > 0. ? offset / distance : outward;
                  }
              }
            if (in <= 0.)
              {
                n = in_normal;
                return in;
              }
            n = out_normal;
            return out;
          }
        case Shape::cone:
          {
            // In the meridian half-plane of y: zeta along the axis from the
            // tip, rho >= 0 from the axis (in plane strain the side of the
            // wedge y lies on). The section there is convex: the face from
            // the tip (0, 0) to the rim c = (R, R / tan(alpha)), then the
            // shaft rho = R upwards; the mirrored half is never nearer.
            const double   zeta   = y * normal;
            Tensor<1, dim> radial = y - zeta * normal;
            const double   rho    = radial.norm();
            if (rho > 0.)
              radial /= rho;
            else
              {
                // On the axis: any direction across it.
                radial                                    = Tensor<1, dim>();
                radial[std::abs(normal[0]) < 0.9 ? 0 : 1] = 1.;
                radial -= (radial * normal) * normal;
                radial /= radial.norm();
              }
            const double sin_a = std::sin(half_angle),
                         cos_a = std::cos(half_angle);
            const double rim   = radius * cos_a / sin_a;
            const double face  = rho * cos_a - zeta * sin_a; // < 0 inside
            if (zeta >= 0. && face <= 0. && rho <= radius)
              {
                // Inside: the nearer of the face's line and the shaft.
                if (face >= rho - radius)
                  {
                    n = cos_a * radial - sin_a * normal;
                    return face;
                  }
                n = radial;
                return rho - radius;
              }
            if (zeta >= rim && rho > radius)
              {
                n = radial;
                return rho - radius;
              }
            // Outside, nearest to the face's segment (its ends included).
            const double s     = std::clamp((rho * radius + zeta * rim) /
                                          (radius * radius + rim * rim),
                                        0.,
                                        1.);
            const double d_rho = rho - s * radius, d_zeta = zeta - s * rim;
            const double distance = std::hypot(d_rho, d_zeta);
            n = distance > 0. ? (d_rho * radial + d_zeta * normal) / distance :
                                cos_a * radial - sin_a * normal;
            return distance;
          }
      }
    return 0.;
  }



  template <int dim>
  std::vector<typename RigidBody<dim>::Face>
  RigidBody<dim>::faces() const
  {
    constexpr double  unbounded = std::numeric_limits<double>::infinity();
    std::vector<Face> list;
    if (shape == Shape::box)
      for (unsigned int d = 0; d < dim; ++d)
        for (const bool lower : {true, false})
          {
            Face face;
            face.normal[d] = lower ? -1. : 1.;
            face.offset    = lower ? 0. : upper_corner[d] - point[d];
            for (unsigned int k = 0, e = 0; e < dim; ++e)
              if (e != d)
                {
                  face.tangents[k][e] = 1.;
                  face.lower[k]       = 0.;
                  face.upper[k]       = upper_corner[e] - point[e];
                  ++k;
                }
            list.push_back(face);
          }
    else if (shape == Shape::polygon)
      for (unsigned int i = 0; i < vertices.size(); ++i)
        {
          const Tensor<1, dim> &a    = vertices[i];
          const Tensor<1, dim> &b    = vertices[(i + 1) % vertices.size()];
          const Tensor<1, dim>  edge = b - a;
          Face                  face;
          face.normal[0] = edge[1];
          face.normal[1] = -edge[0];
          face.normal /= face.normal.norm();
          face.offset      = face.normal * a;
          face.tangents[0] = edge / edge.norm();
          face.lower[0]    = face.tangents[0] * a;
          face.upper[0]    = face.tangents[0] * b;
          if constexpr (dim == 3)
            {
              face.tangents[1][2] = 1.;
              face.lower[1]       = -unbounded;
              face.upper[1]       = unbounded;
            }
          list.push_back(face);
        }
    else if (shape == Shape::cone && dim == 2)
      {
        // In a plane the section is flat-faced: the two faces from the tip
        // to the rims and the two sides of the shaft above them.
        Tensor<1, dim> across;
        across[0]          = normal[1];
        across[1]          = -normal[0];
        const double rim   = radius / std::tan(half_angle);
        const double sin_a = std::sin(half_angle), cos_a = std::cos(half_angle);
        for (const double side : {1., -1.})
          {
            const Tensor<1, dim> e = side * across;
            Face                 face;
            face.normal      = cos_a * e - sin_a * normal;
            face.tangents[0] = sin_a * e + cos_a * normal;
            face.lower[0]    = 0.;
            face.upper[0]    = radius / sin_a;
            list.push_back(face);
            Face shaft;
            shaft.normal      = e;
            shaft.offset      = radius;
            shaft.tangents[0] = normal;
            shaft.lower[0]    = rim;
            shaft.upper[0]    = unbounded;
            list.push_back(shaft);
          }
      }
    return list;
  }



  template <int dim>
  void
  RigidBody<dim>::set_polygon(const std::vector<Point<dim>> &corners)
  {
    const std::string body = "Rigid body <" + name + ">: ";
    AssertThrow(corners.size() >= 3,
                ExcMessage(body + "a polygon needs at least 3 vertices."));
    shape = Shape::polygon;
    point = Point<dim>();
    for (const auto &corner : corners)
      for (unsigned int d = 0; d < 2; ++d)
        point[d] += corner[d] / corners.size();
    vertices.clear();
    for (const auto &corner : corners)
      {
        Tensor<1, dim> v;
        v[0] = corner[0] - point[0];
        v[1] = corner[1] - point[1];
        vertices.push_back(v);
      }
    const auto cross = [](const Tensor<1, dim> &a, const Tensor<1, dim> &b) {
      return a[0] * b[1] - a[1] * b[0];
    };
    double area = 0.;
    for (unsigned int i = 0; i < vertices.size(); ++i)
      area += cross(vertices[i], vertices[(i + 1) % vertices.size()]);
    if (area < 0.)
      std::reverse(vertices.begin(), vertices.end());
    const unsigned int m = vertices.size();
    for (unsigned int i = 0; i < m; ++i)
      AssertThrow(cross(vertices[(i + 1) % m] - vertices[i],
                        vertices[(i + 2) % m] - vertices[(i + 1) % m]) > 0.,
                  ExcMessage(body + "the vertices must form a convex polygon "
                                    "(no three on a line, no reflex "
                                    "corner)."));
  }



  template <int dim>
  Tensor<1, dim>
  RigidBody<dim>::load_unit() const
  {
    const double size = load_direction.norm();
    return size > 0. ? load_direction / size : Tensor<1, dim>();
  }



  template <int dim>
  double
  RigidBody<dim>::force(const double t) const
  {
    if (load == nullptr)
      return 0.;
    load->set_time(t);
    return load->value(Point<dim>());
  }



  template <int dim>
  Tensor<1, dim>
  RigidBody<dim>::prescribed_displacement(const double t) const
  {
    const Tensor<1, dim> u = displacement(t);
    const Tensor<1, dim> d = load_unit();
    return u - (u * d) * d;
  }



  template <int dim>
  void
  RigidBody<dim>::check() const
  {
    const std::string body = "Rigid body <" + name + ">: ";
    switch (shape)
      {
        case Shape::half_space:
          AssertThrow(std::abs(normal.norm() - 1.) < 1e-12,
                      ExcMessage(body + "the normal of a half-space must "
                                        "be a unit vector."));
          break;
        case Shape::box:
          for (unsigned int d = 0; d < dim; ++d)
            AssertThrow(upper_corner[d] > point[d],
                        ExcMessage(body + "the upper corner of a box must "
                                          "lie above its lower corner in "
                                          "every direction."));
          break;
        case Shape::sphere:
          AssertThrow(radius > 0.,
                      ExcMessage(body + "the radius must be positive."));
          break;
        case Shape::polygon:
          AssertThrow(vertices.size() >= 3,
                      ExcMessage(body + "a polygon needs at least 3 "
                                        "vertices (set_polygon())."));
          break;
        case Shape::cone:
          AssertThrow(std::abs(normal.norm() - 1.) < 1e-12,
                      ExcMessage(body + "the axis of a cone must be a unit "
                                        "vector."));
          AssertThrow(radius > 0.,
                      ExcMessage(body + "the radius must be positive."));
          AssertThrow(half_angle > 0. && half_angle < M_PI / 2.,
                      ExcMessage(body + "the half-angle of a cone must lie "
                                        "between 0 and 90 degrees."));
          break;
      }
    AssertThrow(friction != Friction::coulomb || friction_coefficient >= 0.,
                ExcMessage(body + "the friction coefficient must not be "
                                  "negative."));
    AssertThrow(penalty_factor > 0.,
                ExcMessage(body + "the penalty factor must be positive."));
    AssertThrow(motion == nullptr || motion->n_components == dim,
                ExcMessage(body + "the motion must have dim components."));
    AssertThrow(load_driven() == (load != nullptr),
                ExcMessage(body + "a body driven by a force needs both a "
                                  "load direction and a load."));
    AssertThrow(load == nullptr || load->n_components == 1,
                ExcMessage(body + "the load must have one component."));
  }



  template <int dim>
  typename RigidBody<dim>::Friction
  RigidBody<dim>::parse_friction(const std::string &name)
  {
    if (name == "frictionless")
      return Friction::frictionless;
    if (name == "coulomb")
      return Friction::coulomb;
    if (name == "rough")
      return Friction::rough;
    if (name == "tied")
      return Friction::tied;
    AssertThrow(false,
                ExcMessage("Unknown friction <" + name +
                           ">: frictionless, coulomb, rough or tied."));
    return Friction::frictionless;
  }



  template <int dim>
  typename RigidBody<dim>::Shape
  RigidBody<dim>::parse_shape(const std::string &name)
  {
    if (name == "half-space")
      return Shape::half_space;
    if (name == "box")
      return Shape::box;
    if (name == "sphere")
      return Shape::sphere;
    if (name == "polygon")
      return Shape::polygon;
    if (name == "cone")
      return Shape::cone;
    AssertThrow(false,
                ExcMessage("Unknown rigid body shape <" + name +
                           ">: half-space, box, sphere, polygon or cone."));
    return Shape::half_space;
  }



  template struct RigidBody<2>;
  template struct RigidBody<3>;
} // namespace qsmpm
