// Disorientation of cubic crystals (paper Section 4.3: the 7 degree
// threshold of the texture assignment). Symmetry-equivalent orientations
// S g have zero disorientation; rotations about <100> by a give min(a,
// 90 - a); 60 degrees about <111> (the Sigma3 twin) gives 60 degrees;
// 45 degrees about <100> gives 45; the largest possible disorientation,
// 62.8 degrees, belongs to 62.8 degrees about <1, 1, sqrt2 - 1>... here the
// rotation of 60 degrees about <110> (60.0). The mean of orientations spread
// symmetrically about g is g, also when some are given as symmetry
// equivalents.
#include "tests.h"

#include <qsmpm/base/rotation.h>

using namespace qsmpm;

// Active rotation by angle a about the unit axis n (Rodrigues).
Tensor<2, 3>
axis_angle(Tensor<1, 3> n, const double a)
{
  n /= n.norm();
  Tensor<2, 3> R;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      R[i][j] = std::cos(a) * (i == j) + (1 - std::cos(a)) * n[i] * n[j];
  R[0][1] -= std::sin(a) * n[2];
  R[1][0] += std::sin(a) * n[2];
  R[0][2] += std::sin(a) * n[1];
  R[2][0] -= std::sin(a) * n[1];
  R[1][2] -= std::sin(a) * n[0];
  R[2][1] += std::sin(a) * n[0];
  return R;
}

int
main()
{
  initlog();
  const double       deg = M_PI / 180.;
  const Tensor<2, 3> g   = Rotation::from_bunge(23 * deg, 61 * deg, 17 * deg);

  double max_equivalent = 0;
  for (const auto &S : Rotation::cubic_symmetry())
    max_equivalent =
      std::max(max_equivalent, Rotation::disorientation(g, S * g));
  check("max disorientation of g and S g over 24 S (deg)",
        max_equivalent / deg,
        1e-6);

  struct Case
  {
    std::string  name;
    Tensor<1, 3> axis;
    double       angle, expected;
  };
  const std::vector<Case> cases = {
    {"10 deg about [001]", Tensor<1, 3>({0, 0, 1}), 10, 10},
    {"45 deg about [001]", Tensor<1, 3>({0, 0, 1}), 45, 45},
    {"50 deg about [100]", Tensor<1, 3>({1, 0, 0}), 50, 40},
    {"80 deg about [010]", Tensor<1, 3>({0, 1, 0}), 80, 10},
    {"60 deg about [111] (Sigma3)", Tensor<1, 3>({1, 1, 1}), 60, 60},
    {"120 deg about [111] (a symmetry)", Tensor<1, 3>({1, 1, 1}), 120, 0},
    {"180 deg about [110] (a symmetry)", Tensor<1, 3>({1, 1, 0}), 180, 0},
    {"38.94 deg about [110] (Sigma9)", Tensor<1, 3>({1, 1, 0}), 38.94, 38.94},
    {"5 deg about [123]", Tensor<1, 3>({1, 2, 3}), 5, 5}};
  for (const auto &c : cases)
    {
      // Misorientation in the crystal frame: g_b = R g_a.
      const Tensor<2, 3> gb = axis_angle(c.axis, c.angle * deg) * g;
      check(c.name + ": disorientation - " + format(c.expected) + " deg",
            Rotation::disorientation(g, gb) / deg - c.expected,
            1e-6);
      check("  symmetric in its arguments",
            (Rotation::disorientation(gb, g) -
             Rotation::disorientation(g, gb)) /
              deg,
            1e-8);
    }

  // The disorientation within a bound (the texture assignment's search
  // within 7 degrees): the same angle where it is below the bound, a value
  // of at least the bound elsewhere, also for angles within 1e-9 degrees
  // of the bound.
  {
    const double        bound = 7. * deg;
    bool                agree = true;
    std::vector<double> angles;
    for (const auto &c : cases)
      angles.push_back(c.angle);
    for (int k = -100; k <= 100; ++k)
      angles.push_back(7. + 1e-3 * k);
    for (const double offset : {-1e-9, 0., 1e-9})
      angles.push_back(7. + offset);
    for (const auto &axis : {Tensor<1, 3>({1, 2, 3}), Tensor<1, 3>({0, 0, 1})})
      for (const double angle : angles)
        {
          const Tensor<2, 3> gb      = axis_angle(axis, angle * deg) * g;
          const double       exact   = Rotation::disorientation(g, gb);
          const double       bounded = Rotation::disorientation(g, gb, bound);
          agree =
            agree && (exact < bound ? bounded == exact : bounded >= bound);
        }
    check_that("disorientation within 7 deg: the angle below, at least 7 deg "
               "above (" +
                 std::to_string(2 * angles.size()) + " pairs)",
               agree);
  }

  // Mean orientation: +-3 degrees about two axes around g, some replaced by
  // symmetry equivalents.
  std::vector<Tensor<2, 3>> set;
  for (const double s : {-3., 3.})
    for (const auto &axis : {Tensor<1, 3>({1, 0, 0}), Tensor<1, 3>({0, 1, 1})})
      set.push_back(axis_angle(axis, s * deg) * g);
  set[1] = Rotation::cubic_symmetry()[5] * set[1];
  set[3] = Rotation::cubic_symmetry()[17] * set[3];
  check("mean of a symmetric spread about g: disorientation to g (deg)",
        Rotation::disorientation(Rotation::mean(set), g) / deg,
        1e-6);
  check("quaternion round trip",
        (Rotation::from_quaternion(Rotation::to_quaternion(g)) - g).norm(),
        1e-14);
}
