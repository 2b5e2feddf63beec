#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
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
      }
    return 0.;
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
      }
    AssertThrow(friction != Friction::coulomb || friction_coefficient >= 0.,
                ExcMessage(body + "the friction coefficient must not be "
                                  "negative."));
    AssertThrow(penalty_factor > 0.,
                ExcMessage(body + "the penalty factor must be positive."));
    AssertThrow(motion == nullptr || motion->n_components == dim,
                ExcMessage(body + "the motion must have dim components."));
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
    AssertThrow(false,
                ExcMessage("Unknown friction <" + name +
                           ">: frictionless, coulomb or rough."));
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
    AssertThrow(false,
                ExcMessage("Unknown rigid body shape <" + name +
                           ">: half-space, box or sphere."));
    return Shape::half_space;
  }



  template struct RigidBody<2>;
  template struct RigidBody<3>;
} // namespace qsmpm
