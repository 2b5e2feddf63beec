#ifndef qsmpm_fracture_load_displacement_curve_h
#define qsmpm_fracture_load_displacement_curve_h

#include <string>
#include <vector>

namespace qsmpm
{
  /**
   * A load-deflection curve P(delta) of a displacement-controlled fracture
   * test (paper Fig. 1b and Fig. 3): the accepted steps, the peak load, the
   * work of the load W = integral of P d(delta) (trapezoidal rule), which
   * at complete failure equals the fracture energy times the ligament area
   * (work-of-fracture test), and the CSV file load_displacement.csv.
   */
  class LoadDisplacementCurve
  {
  public:
    /// One accepted step.
    struct Point
    {
      unsigned int step;
      double       displacement;
      double       force;
    };

    /// Append a point (displacements must not decrease).
    void
    add(const unsigned int step, const double displacement, const double force);

    const std::vector<Point> &
    points() const;

    /// The largest force so far (0 for an empty curve).
    double
    peak_force() const;

    /// The displacement at the peak force.
    double
    peak_displacement() const;

    /// integral of P d(delta) from the first point (and from (0, 0)).
    double
    work() const;

    /// Whether the peak has passed and the last force is below
    /// @p fraction times the peak.
    bool
    fallen_below(const double fraction) const;

    /**
     * Write "step,displacement_m,force_N" and one line per point to
     * @p filename (call on one MPI rank only).
     */
    void
    write_csv(const std::string &filename) const;

  private:
    std::vector<Point> curve;
  };
} // namespace qsmpm

#endif
