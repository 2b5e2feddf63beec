#include <algorithm>
#include <deal.II/base/exceptions.h>
#include <fstream>
#include <iomanip>
#include <qsmpm/fracture/load_displacement_curve.h>

namespace qsmpm
{
  void
  LoadDisplacementCurve::add(const unsigned int step,
                             const double       displacement,
                             const double       force)
  {
    curve.push_back({step, displacement, force});
  }



  const std::vector<LoadDisplacementCurve::Point> &
  LoadDisplacementCurve::points() const
  {
    return curve;
  }



  double
  LoadDisplacementCurve::peak_force() const
  {
    double peak = 0.;
    for (const auto &p : curve)
      peak = std::max(peak, p.force);
    return peak;
  }



  double
  LoadDisplacementCurve::peak_displacement() const
  {
    const auto peak = std::max_element(curve.begin(),
                                       curve.end(),
                                       [](const Point &a, const Point &b) {
                                         return a.force < b.force;
                                       });
    return peak == curve.end() ? 0. : peak->displacement;
  }



  double
  LoadDisplacementCurve::work() const
  {
    double W = 0., delta = 0., P = 0.;
    for (const auto &p : curve)
      {
        W += 0.5 * (P + p.force) * (p.displacement - delta);
        delta = p.displacement;
        P     = p.force;
      }
    return W;
  }



  bool
  LoadDisplacementCurve::fallen_below(const double fraction) const
  {
    if (curve.empty())
      return false;
    const double peak = peak_force();
    return peak > 0. && curve.back().force < peak &&
           curve.back().force < fraction * peak;
  }



  void
  LoadDisplacementCurve::write_csv(const std::string &filename) const
  {
    std::ofstream file(filename);
    AssertThrow(file, dealii::ExcMessage("Cannot write <" + filename + ">."));
    file << "step,displacement_m,force_N\n" << std::setprecision(10);
    for (const auto &p : curve)
      file << p.step << ',' << p.displacement << ',' << p.force << '\n';
  }
} // namespace qsmpm
