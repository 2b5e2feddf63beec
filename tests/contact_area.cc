// RigidContact::contact_area(): the area with which a point's box touches a
// rigid body. Omega_p / (2 r) (r = -n . a, the box's extent along the
// body's normal by the rule of RigidContact), bounded by twice the area of
// the box's projection on the plane normal to n. The references are
// computed here independently: the projection from the box's corners (the
// extent of their projections on the tangent line, or the area of the
// convex hull of the projected corners in 3D, by the shoelace formula).
//
// - An undeformed box facing the body with a face: the face (2D: 2 l; 3D:
//   4 l^2), from Omega_p / (2 r) with r = l, the bound not reached.
// - The same box under 30 % shear with n along the sheared edge's normal
//   and at 45 degrees: the bound not reached (Omega_p / (2 r) below the
//   projection).
// - The point of the cone penetration of examples/contact at 3.7 R (its
//   deformation gradient, h / 4 = 0.0625, radius 0.747, the cone's face
//   normal, r = 1.049e-7 as the contact found it): Omega_p / (2 r) = 4671,
//   the bound 2 x 2.42 = 4.84. Without the bound the test fails.
// - A 3D needle along a plane: bounded likewise.
#include "tests.h"

#include <algorithm>
#include <qsmpm/loading/rigid_contact.h>
#include <vector>

// The length (2D) or area (3D) of the projection of the box with half-edges
// F e_d half_d on the plane normal to n, from its corners.
double
projection(const Tensor<2, 2> &F,
           const Tensor<1, 2> &half,
           const Tensor<1, 2> &n)
{
  const Tensor<1, 2> t({-n[1], n[0]});
  double             lo = 1e300, hi = -1e300;
  for (const double s0 : {-1., 1.})
    for (const double s1 : {-1., 1.})
      {
        Tensor<1, 2> corner;
        for (unsigned int i = 0; i < 2; ++i)
          corner[i] = s0 * F[i][0] * half[0] + s1 * F[i][1] * half[1];
        lo = std::min(lo, t * corner);
        hi = std::max(hi, t * corner);
      }
  return hi - lo;
}

double
projection(const Tensor<2, 3> &F,
           const Tensor<1, 3> &half,
           const Tensor<1, 3> &n)
{
  // Two tangents, the 8 corners in their coordinates, the convex hull
  // (gift wrapping) and its area.
  Tensor<1, 3> t1 = cross_product_3d(n, Tensor<1, 3>({1., 0., 0.}));
  if (t1.norm() < 0.5)
    t1 = cross_product_3d(n, Tensor<1, 3>({0., 1., 0.}));
  t1 /= t1.norm();
  const Tensor<1, 3>                     t2 = cross_product_3d(n, t1);
  std::vector<std::pair<double, double>> p;
  for (const double s0 : {-1., 1.})
    for (const double s1 : {-1., 1.})
      for (const double s2 : {-1., 1.})
        {
          Tensor<1, 3> c;
          for (unsigned int i = 0; i < 3; ++i)
            c[i] = s0 * F[i][0] * half[0] + s1 * F[i][1] * half[1] +
                   s2 * F[i][2] * half[2];
          p.emplace_back(t1 * c, t2 * c);
        }
  const auto cross = [](const auto &o, const auto &a, const auto &b) {
    return (a.first - o.first) * (b.second - o.second) -
           (a.second - o.second) * (b.first - o.first);
  };
  std::sort(p.begin(), p.end());
  std::vector<std::pair<double, double>> hull;
  for (int pass = 0; pass < 2; ++pass)
    {
      const std::size_t start = hull.size();
      for (const auto &q : p)
        {
          while (hull.size() >= start + 2 &&
                 cross(hull[hull.size() - 2], hull.back(), q) <= 0.)
            hull.pop_back();
          hull.push_back(q);
        }
      hull.pop_back();
      std::reverse(p.begin(), p.end());
    }
  double area = 0.;
  for (std::size_t i = 0; i < hull.size(); ++i)
    {
      const auto &a = hull[i], &b = hull[(i + 1) % hull.size()];
      area += a.first * b.second - b.first * a.second;
    }
  return std::abs(area) / 2.;
}

// r = -n . a of RigidContact: sum_d |e_d| (n . e_d / |e_d|)^2.
template <int dim>
double
extent(const Tensor<2, dim> &F,
       const Tensor<1, dim> &half,
       const Tensor<1, dim> &n)
{
  double r = 0.;
  for (unsigned int d = 0; d < dim; ++d)
    {
      Tensor<1, dim> e;
      for (unsigned int i = 0; i < dim; ++i)
        e[i] = F[i][d] * half[d];
      r += (n * e) * (n * e) / e.norm();
    }
  return r;
}

template <int dim>
void
check(const std::string    &name,
      const Tensor<2, dim> &F,
      const Tensor<1, dim> &half,
      const Tensor<1, dim> &n,
      const double          r,
      const double          volume,
      const double          radius,
      const double          expected)
{
  const double area =
    qsmpm::RigidContact<dim>::contact_area(F, half, n, r, volume, radius);
  const double projected = radius * projection(F, half, n);
  deallog << name << ": Omega_p / (2 r) = " << volume / (2. * r)
          << ", projection = " << projected << ", area = " << area
          << "; area = " << (expected > 0. ? "expected" : "2 x projection")
          << " to 1e-12: "
          << (std::abs(area - (expected > 0. ? expected : 2. * projected)) <=
                  1e-12 * area ?
                "yes" :
                "NO")
          << std::endl;
}

int
main()
{
  qsmpm_tests::initlog();
  deallog << std::setprecision(6);

  // 2D, an undeformed box, half-length 0.5, facing the body with a face.
  {
    const Tensor<2, 2> I = unit_symmetric_tensor<2>();
    const Tensor<1, 2> half({0.5, 0.5}), n({0., 1.});
    check<2>("2D box, face on", I, half, n, extent(I, half, n), 1., 1., 1.);
    Tensor<2, 2> shear = I;
    shear[0][1]        = 0.3;
    const Tensor<1, 2> diagonal({std::sqrt(0.5), std::sqrt(0.5)});
    for (const auto &[name, normal] :
         {std::make_pair("face on", n), std::make_pair("45 degrees", diagonal)})
      check<2>(std::string("2D box, 30 % shear, ") + name,
               shear,
               half,
               normal,
               extent(shear, half, normal),
               1.,
               1.,
               1. / (2. * extent(shear, half, normal)));
  }
  // The cone's point at 3.7 R (axisymmetric: volume per radian, radius
  // 0.747128).
  {
    Tensor<2, 2> F;
    F[0][0] = 11.7157;
    F[0][1] = 1.27347;
    F[1][0] = 20.2929;
    F[1][1] = 2.20985;
    const Tensor<1, 2> half({0.0625, 0.0625});
    const Tensor<1, 2> n({0.866025, -0.5});
    check<2>(
      "the cone's needle", F, half, n, 1.04904e-7, 0.000980067, 0.747128, 0.);
  }
  // 3D: a unit cube facing the body, then drawn out 20 times along x and
  // sheared onto the plane normal to z.
  {
    const Tensor<2, 3> I = unit_symmetric_tensor<3>();
    const Tensor<1, 3> half({0.5, 0.5, 0.5}), n({0., 0., 1.});
    check<3>("3D cube, face on", I, half, n, extent(I, half, n), 1., 1., 1.);
    Tensor<2, 3> F = I;
    F[0][0]        = 20.;
    F[2][2]        = 0.05;
    F[0][2]        = 19.;
    check<3>("3D needle along the plane",
             F,
             half,
             n,
             extent(F, half, n),
             determinant(F),
             1.,
             0.);
  }
}
