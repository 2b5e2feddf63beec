// What the tests of Prandtl's smooth strip footing on a weightless c-phi
// soil share (footing_drucker_prager, footing_dilatancy): half
// of the soil (x >= 0), 6 a wide and 4 a deep, a/h = 4 (24 x 16 cells),
// 2 x 2 points per cell, the footing the top nodes with x <= a pushed down
// by 0.02 a, rollers on the sides, the base fixed. Wider than
// tests/footing_plasticity since the mechanism of a c-phi soil is (its
// passive wedge reaches the surface at x = 6.1 a for phi = 20 degrees,
// against 3 a for phi = 0).
#ifndef qsmpm_tests_c_phi_footing_h
#define qsmpm_tests_c_phi_footing_h

#include "nodal_footing.h"

namespace c_phi_footing
{
  using namespace qsmpm;

  /// The footing's half-width, the soil's cohesion and its elasticity.
  const double a = 1., c = 100., E = 1e6, nu = 0.3;

  /// Prandtl-Reissner: q_u = c N_c, N_c = (N_q - 1) cot phi,
  /// N_q = exp(pi tan phi) tan^2(pi/4 + phi/2).
  inline double
  bearing_factor(const double phi_degrees)
  {
    const double phi = phi_degrees * numbers::PI / 180.;
    const double Nq  = std::exp(numbers::PI * std::tan(phi)) *
                      std::pow(std::tan(numbers::PI / 4. + phi / 2.), 2);
    return (Nq - 1.) / std::tan(phi);
  }

  /**
   * The .prm text of the tests: 2D, 2 x 2 points per cell with @p locking
   * (and the entries @p points_extra), the model @p model with E, nu, c,
   * phi = psi = @p phi_degrees, no hardening (and the entries
   * @p model_extra), 20 steps, Newton tolerance 1e-9 with 8 line-search
   * steps, no output but into @p directory.
   */
  inline std::string
  prm_text(const std::string &model,
           const std::string &locking,
           const double       phi_degrees,
           const std::string &directory,
           const std::string &points_extra = "",
           const std::string &model_extra  = "")
  {
    std::ostringstream text;
    text << "set Dimension = 2\n"
         << "subsection Material points\n"
         << "  set Points per cell per direction = 2\n"
         << points_extra << "  set Volumetric locking = " << locking
         << "\nend\n"
         << "subsection Material\n  set Model = " << model << "\n"
         << "  subsection " << model << "\n"
         << "    set Young's modulus = " << E << "\n"
         << "    set Poisson's ratio = " << nu << "\n"
         << "    set Cohesion = " << c << "\n"
         << "    set Friction angle = " << phi_degrees << "\n"
         << "    set Dilatancy angle = " << phi_degrees << "\n"
         << "    set Hardening modulus = 0\n"
         << model_extra << "  end\nend\n"
         << "subsection Load stepping\n  set Number of steps = 20\nend\n"
         << "subsection Nonlinear solver\n"
         << "  set Tolerance = 1e-9\n  set Line search steps = 8\nend\n"
         << "subsection Output\n  set Interval = 0\n"
         << "  set Directory = " << directory << "\nend\n";
    return text.str();
  }

  /**
   * prm_text() for Drucker-Prager with the plane-strain Mohr-Coulomb
   * matching, whose associated flow reproduces c N_c.
   */
  inline std::string
  drucker_prager_text(const std::string &locking,
                      const double       phi_degrees,
                      const std::string &directory,
                      const std::string &points_extra = "")
  {
    return prm_text("Drucker-Prager",
                    locking,
                    phi_degrees,
                    directory,
                    points_extra,
                    "    set Mohr-Coulomb matching = plane strain\n");
  }

  using nodal_footing::Result;

  /**
   * The footing (nodal_footing::run()) on the soil 6 a wide with the
   * problem's entries @p prm_text; @p inspect, if given, sees the problem
   * after a completed run; @p radius > 0: the ring of an axisymmetric
   * problem (nodal_footing::run()).
   */
  inline Result
  run(const MPI_Comm                                      comm,
      const std::string                                  &prm_text,
      const std::function<void(QuasiStaticProblem<2> &)> &inspect = {},
      const double                                        radius  = 0.)
  {
    return nodal_footing::run(comm, prm_text, 6., c, inspect, radius);
  }

  /// The pressure over c after the last step, NaN without steps.
  inline double
  last(const Result &r)
  {
    return r.pressure_over_c.empty() ?
             std::numeric_limits<double>::quiet_NaN() :
             r.pressure_over_c.back();
  }

  /// The largest relative difference of the pressure curves @p r and
  /// @p reference, NaN if they have different lengths.
  inline double
  curve_difference(const Result &r, const Result &reference)
  {
    if (r.pressure_over_c.size() != reference.pressure_over_c.size())
      return std::numeric_limits<double>::quiet_NaN();
    double difference = 0.;
    for (unsigned int i = 0; i < r.pressure_over_c.size(); ++i)
      difference =
        std::max(difference,
                 std::abs(r.pressure_over_c[i] / reference.pressure_over_c[i] -
                          1.));
    return difference;
  }
} // namespace c_phi_footing

#endif
