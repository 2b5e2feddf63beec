// The polygon shape of RigidBody (set_polygon(), signed_distance()), and a
// polygon from a .prm file pressing on a column:
//
// 1. A rectangle given as a polygon against the same rectangle as a box
//    (an independent implementation of the signed distance): distance and
//    normal at 11 x 13 points inside and around it, to 1e-12.
// 2. A wedge (0,0), (2,0), (1,1), given clockwise: the signed distances
//    and normals at four points, by hand: inside (1, 0.5): -1 / (2 sqrt 2)
//    to the slanted faces; below (1, -1): 1, normal -y; beside a corner
//    (3, 0): 1, normal +x; above the apex (1, 2): 1, normal +y.
// 3. Bad vertices stop with a message: a reflex corner, three on a line,
//    two vertices only.
// 4. The column of contact_rigid_bodies (1 x 1, rollers, E = 1000,
//    nu = 0.3, plane strain, cpGIMP) compacted by 1 % by a polygon whose
//    bottom face y = 1 is wider than the column (the .prm route): every
//    point's stress within 1 % of the exact uniaxial strain state.
#include "prm_text.h"
#include "tests.h"

#include <cmath>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/loading/rigid_body.h>

using namespace qsmpm;

namespace
{
  double
  distance_and_normal(const RigidBody<2> &body,
                      const Point<2>     &x,
                      Tensor<1, 2>       &n)
  {
    return body.signed_distance(x, Tensor<1, 2>(), n);
  }

  std::string
  message_of(const std::vector<Point<2>> &corners)
  {
    try
      {
        RigidBody<2> body;
        body.name = "punch";
        body.set_polygon(corners);
      }
    catch (const std::exception &exc)
      {
        return qsmpm::Utils::error_message(exc);
      }
    return "no error";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  deallog << "1. A rectangle as a polygon against the box" << std::endl;
  RigidBody<2> box, polygon;
  box.shape        = RigidBody<2>::Shape::box;
  box.point        = Point<2>(0.5, -1.);
  box.upper_corner = Point<2>(2., 1.);
  polygon.set_polygon({Point<2>(0.5, -1.),
                       Point<2>(2., -1.),
                       Point<2>(2., 1.),
                       Point<2>(0.5, 1.)});
  double largest = 0.;
  for (unsigned int i = 0; i < 11; ++i)
    for (unsigned int j = 0; j < 13; ++j)
      {
        const Point<2> x(-0.4 + 0.3137 * i, -2.1 + 0.3411 * j);
        Tensor<1, 2>   n_box, n_polygon;
        const double   d_box     = distance_and_normal(box, x, n_box);
        const double   d_polygon = distance_and_normal(polygon, x, n_polygon);
        largest                  = std::max(
          {largest, std::abs(d_box - d_polygon), (n_box - n_polygon).norm()});
      }
  check("largest difference of distance or normal", largest, 1e-12);

  deallog << "2. A wedge, clockwise" << std::endl;
  RigidBody<2> wedge;
  wedge.set_polygon({Point<2>(0., 0.), Point<2>(1., 1.), Point<2>(2., 0.)});
  const std::vector<std::tuple<Point<2>, double, Tensor<1, 2>>> cases = {
    {Point<2>(1., 0.5),
     -0.5 / std::sqrt(2.),
     Tensor<1, 2>({-1. / std::sqrt(2.), 1. / std::sqrt(2.)})},
    {Point<2>(1., -1.), 1., Tensor<1, 2>({0., -1.})},
    {Point<2>(3., 0.), 1., Tensor<1, 2>({1., 0.})},
    {Point<2>(1., 2.), 1., Tensor<1, 2>({0., 1.})}};
  for (const auto &[x, distance, normal] : cases)
    {
      Tensor<1, 2> n;
      const double d = distance_and_normal(wedge, x, n);
      // At (1, 0.5) both slanted faces are nearest: either normal.
      const Tensor<1, 2> mirrored({-normal[0], normal[1]});
      std::ostringstream label;
      label << "at (" << x[0] << ", " << x[1]
            << "): |distance - exact| + |normal - exact|";
      check(label.str(),
            std::abs(d - distance) +
              std::min((n - normal).norm(), (n - mirrored).norm()),
            1e-14);
    }

  deallog << "3. Bad vertices" << std::endl;
  const std::string reflex = message_of(
    {Point<2>(0., 0.), Point<2>(2., 0.), Point<2>(1., 0.3), Point<2>(1., 1.)});
  check_that("a reflex corner: the message names the body and convexity",
             reflex.find("punch") != std::string::npos &&
               reflex.find("convex") != std::string::npos);
  const std::string line = message_of(
    {Point<2>(0., 0.), Point<2>(1., 0.), Point<2>(2., 0.), Point<2>(1., 1.)});
  check_that("three on a line: stops",
             line.find("convex") != std::string::npos);
  const std::string two = message_of({Point<2>(0., 0.), Point<2>(1., 0.)});
  check_that("two vertices: stops",
             two.find("at least 3 vertices") != std::string::npos);

  deallog << "4. A polygon compacting a column by 1 %" << std::endl;
  const double       E = 1000., nu = 0.3;
  const double       lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
  const double       M      = E * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
  std::ostringstream text;
  text << "set Dimension = 2\n"
       << "subsection Geometry\n  set Lower corner = 0,0\n"
       << "  set Upper corner = 1,1.25\n  set Subdivisions = 8,10\nend\n"
       << "subsection Material points\n"
       << "  set Points per cell per direction = 2\n"
       << "  set Region lower corner = 0,0\n"
       << "  set Region upper corner = 1,1\n"
       << "  set Shape functions = cpGIMP\nend\n"
       << "subsection Material\n  set Model = linear elastic\n"
       << "  subsection linear elastic\n"
       << "    set Young's modulus = " << E << "\n"
       << "    set Poisson's ratio = " << nu << "\n  end\nend\n"
       << "subsection Boundary conditions\n"
       << "  set Dirichlet boundaries = 0:x, 1:x, 2:y\n"
       << "  subsection Rigid body\n"
       << "    set Shape = polygon\n    set Name = punch\n"
       << "    set Vertices = -0.5, 1; 1.5, 1; 1.2, 1.6; -0.2, 1.6\n"
       << "    subsection Motion\n"
       << "      set Function expression = 0; -0.01*t\n"
       << "    end\n  end\nend\n"
       << "subsection Load stepping\n  set Number of steps = 2\nend\n"
       << "subsection Nonlinear solver\n  set Tolerance = 1e-10\nend\n"
       << "subsection Output\n  set Interval = 0\n"
       << "  set Directory = shapes-out\nend\n";
  QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
  initialize_from_text(problem, text.str());
  problem.run();
  const double sigma_yy = -M * 0.01, sigma_xx = -lambda * 0.01;
  const auto  &offsets = problem.points().get_offsets();
  double       error   = 0.;
  for (const auto &particle : problem.points().get_particle_handler())
    {
      const SymmetricTensor<2, 2> s = qsmpm::Utils::read_symmetric<2>(
        &particle.get_properties()[offsets.stress]);
      error = std::max({error,
                        std::abs(s[1][1] - sigma_yy),
                        std::abs(s[0][0] - sigma_xx),
                        std::abs(s[0][1])});
    }
  check("every point's stress: max error / (M d)",
        Utilities::MPI::max(error, MPI_COMM_WORLD) / (M * 0.01),
        0.01);
  check("the punch's force / (M d) - 1",
        problem.rigid_body_loads()[0].force[1] / (M * 0.01) - 1.,
        0.01);
}
