// Large-strain consolidation of a column (issue 31): finite strain, cpGIMP
// shape functions and a mobility that follows the volume ratio J.
//
// A column of height H (Lagrangian coordinate Z, the depth below its
// drained top z = H - Z), Hencky skeleton (uniaxial strain: Kirchhoff
// tau'_yy = M ln J, M = lambda + 2 mu), incompressible constituents (b = 1,
// 1/M = 0), no self-weight. Its top is held and drained; its base, free and
// impermeable, is pushed up by a dead load q at time 0+, which compresses
// the column by 20 % once it has consolidated.
//
// Reference: the one-dimensional large-strain consolidation equation of
// Gibson, England and Hussey (Geotechnique 17 (1967) 261-273), written for
// J = (1 + e) / (1 + e0) in the Lagrangian coordinate:
//
//   dJ/dt = d/dZ ( D(J) dJ/dZ ),   D(J) = kappa(J) (-d sigma'/dJ) / J,
//
// with sigma' = -M ln J / J the effective Cauchy stress (compression
// positive) and kappa the mobility (k / gamma_w). With the mobility
// kappa(J) = kappa_0 J^3 / (1 - ln J) (entry Mobility factor) the
// coefficient is constant, D = kappa_0 M, and the equation is linear:
// J = J_inf + (1 - J_inf) W(z, T_v), W Terzaghi's series sum_m 2 / M_m
// sin(M_m z / H) exp(-M_m^2 T_v), T_v = D t / H^2, J_inf from
// sigma'(J_inf) = q. Then p = q - sigma'(J) and the base has risen by the
// integral of 1 - J. The exact pressure differs from Terzaghi's
// small-strain q W by up to 8 % of q at T_v = 0.5.
//
// Checks: the pressure and displacement errors over the points at T_v =
// 0.1, 0.5, 1 on 32 cells; how they fall with the step and the cell size;
// that Terzaghi's small-strain pressure, and the same column with a
// constant mobility, are far from the large-strain solution (the test
// sees the difference); 3D against plane strain; at small strain cpGIMP
// gives Terzaghi's column; the column drained at its rising base (Pore
// fluid/Drained surface region) instead of its top; the same on 1 and 2
// ranks.

#include "tests.h"

#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/porous/poroelastic_model.h>

using namespace qsmpm;

namespace
{
  constexpr double H = 10., E = 1.5e6, nu = 0.25, kappa0 = 1e-6, q = 5e5;
  const double     M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const double     D = kappa0 * M;

  /// J_inf: M ln J / J = -q, by bisection.
  double
  final_volume_ratio(const double load)
  {
    double lo = 0.3, hi = 1.;
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double mid                            = 0.5 * (lo + hi);
        (M * std::log(mid) / mid < -load ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }

  /// Terzaghi's W at depth z below the drained top.
  double
  terzaghi(const double z, const double Tv)
  {
    double W = 0;
    for (unsigned int m = 0; m < 400; ++m)
      {
        const double Mm = M_PI * (2 * m + 1) / 2;
        W += 2. / Mm * std::sin(Mm * z / H) * std::exp(-Mm * Mm * Tv);
      }
    return W;
  }

  double
  exact_pressure(const double z, const double Tv, const double load)
  {
    const double J_inf = final_volume_ratio(load);
    const double J     = J_inf + (1 - J_inf) * terzaghi(z, Tv);
    return load + M * std::log(J) / J;
  }

  /// The upward displacement of the material at height Y (initial): the
  /// integral of 1 - J from the held top down to Y, with the column
  /// drained at its top or at its base (W of the distance from it).
  double
  exact_displacement(const double Y,
                     const double Tv,
                     const double load,
                     const bool   drained_base)
  {
    const double J_inf = final_volume_ratio(load);
    double       sum   = 0;
    for (unsigned int m = 0; m < 400; ++m)
      {
        const double Mm = M_PI * (2 * m + 1) / 2;
        // The integral of W from Y to H.
        sum += 2. * H / (Mm * Mm) *
               (drained_base ? std::cos(Mm * Y / H) :
                               1 - std::cos(Mm * (H - Y) / H)) *
               std::exp(-Mm * Mm * Tv);
      }
    return (1 - J_inf) * (H - Y - sum);
  }

  struct Variant
  {
    std::string  kinematics      = "finite strain";
    std::string  model           = "hencky";
    std::string  shape_functions = "cpGIMP";
    std::string  mobility_factor = "J^3 / (1 - log(J))";
    double       load            = q;
    unsigned int cells           = 32;
    /// The load on the grid's face (Traction boundaries) instead of the
    /// body's surface (Surface traction region).
    bool on_grid_face = false;
    /// Drained at the base, the body's surface that moves (Pore fluid/
    /// Drained surface region), instead of at the top, a grid face.
    bool drained_base = false;
    /// Steps per unit T_v: the first step, and the largest, are 1/12800
    /// and 1/128 of T_v = 1 times 1 / refinement.
    double time_refinement = 1.;
    /// Pore fluid/Coupling tolerance (empty: the default, 1e-5).
    std::string coupling_tolerance;
  };

  /// The column along y; in 3D one cell thick in z as in x.
  template <int dim>
  std::string
  column_prm(const Variant &v, const double Tv)
  {
    // The first step 1/12800 of T_v = 1, then steps growing by 10 % up to
    // T_v = 1/128; the load is there from the first step on.
    const double       t_end = Tv * H * H / D;
    const double       dt0   = H * H / D / 12800 / v.time_refinement;
    std::ostringstream prm;
    const bool         three = dim == 3;
    prm << std::setprecision(12) << "set Dimension = " << dim << "\n"
        << "subsection Geometry\n  set Lower corner = 0, 0"
        << (three ? ", 0" : "") << "\n"
        << "  set Upper corner = " << H / v.cells << ", " << H;
    if (three)
      prm << ", " << H / v.cells;
    prm << "\n  set Subdivisions = 1, " << v.cells << (three ? ", 1" : "")
        << "\nend\n"
        << "subsection Material points\n"
        << "  set Points per cell per direction = 2\n"
        << "  set Shape functions = " << v.shape_functions << "\n"
        << "  set Kinematics = " << v.kinematics << "\nend\n"
        << "subsection Material\n  set Model = " << v.model << "\n"
        << "  subsection " << v.model << "\n"
        << "    set Young's modulus = " << E << "\n"
        << "    set Poisson's ratio = " << nu << "\n  end\nend\n"
        << "subsection Boundary conditions\n"
        << "  set Dirichlet boundaries = 0:x, 1:x, "
        << (three ? "3:xyz, 4:z, 5:z" : "3:xy") << "\n"
        << (v.on_grid_face ? "  set Traction boundaries = 2\n" :
                             "  set Surface traction region = y < 0.001\n")
        << "  subsection Displacement\n"
        << "    set Function expression = 0; 0" << (three ? "; 0" : "")
        << "\n  end\n"
        << "  subsection " << (v.on_grid_face ? "Traction" : "Surface traction")
        << "\n    set Function expression = 0; " << v.load
        << (three ? "; 0" : "") << "\n  end\nend\n"
        << "subsection Pore fluid\n  set Enabled = true\n"
        << "  set Mobility = " << kappa0 << "\n"
        << "  set Mobility factor = " << v.mobility_factor << "\n"
        << (v.drained_base ? "  set Drained surface region = y < 0.001\n" :
                             "  set Drained boundaries = 3\n")
        << (v.coupling_tolerance.empty() ?
              std::string() :
              "  set Coupling tolerance = " + v.coupling_tolerance + "\n")
        << "end\n"
        << "subsection Load stepping\n"
        << "  set Final load factor = " << t_end << "\n"
        << "  set Number of steps = "
        << static_cast<unsigned int>(std::ceil(t_end / dt0)) << "\n"
        << "  set Increment growth factor = 1.1\n"
        << "  set Maximum increment = " << H * H / D / 128 / v.time_refinement
        << "\nend\n"
        << "subsection Output\n  set Interval = 0\n  set Directory = "
           "large-strain-out\nend\n";
    return prm.str();
  }

  struct Result
  {
    bool completed = false;
    /// L2 over the points of p - p_exact over the load, and of u_y -
    /// u_exact over the final settlement (1 - J_inf) H.
    double pressure = 1, displacement = 1;
    /// The same for Terzaghi's small-strain pressure (the load times W).
    double pressure_vs_terzaghi = 1;
    /// The base's rise over H.
    double base_rise = 0;
  };

  template <int dim = 2>
  Result
  run(const Variant &v, const double Tv)
  {
    ParameterHandler prm;
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
    QuasiStaticProblem<dim>::Parameters::declare_parameters(prm);
    prm.parse_input_from_string(column_prm<dim>(v, Tv));
    QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
    problem.pcout().set_condition(false);
    problem.initialize(prm);
    Result result;
    try
      {
        problem.run();
        result.completed = true;
      }
    catch (const std::exception &exc)
      {
        deallog << "  run stopped: " << qsmpm::Utils::error_message(exc)
                << std::endl;
        return result;
      }

    const auto &points  = problem.points();
    const auto &offsets = points.get_offsets();
    const auto &model =
      dynamic_cast<const PoroelasticModel<dim> &>(points.get_model());
    const unsigned int p_offset = offsets.state + model.pressure_offset();
    const double       J_inf    = final_volume_ratio(v.load);
    double             sum_p = 0, sum_t = 0, sum_u = 0, volume = 0, base = 0;
    for (const auto &particle : points.get_particle_handler())
      {
        const auto   data = particle.get_properties();
        const double u    = data[offsets.displacement + 1];
        const double Y    = particle.get_location()[1] - u;
        const double V    = data[offsets.initial_volume];
        const double p    = data[p_offset];
        // The distance from the drained end.
        const double z = v.drained_base ? Y : H - Y;
        sum_p += V * std::pow(p - exact_pressure(z, Tv, v.load), 2);
        sum_t += V * std::pow(p - v.load * terzaghi(z, Tv), 2);
        sum_u +=
          V *
          std::pow(u - exact_displacement(Y, Tv, v.load, v.drained_base), 2);
        volume += V;
        base = std::max(base, u);
      }
    const MPI_Comm comm = MPI_COMM_WORLD;
    volume              = Utilities::MPI::sum(volume, comm);
    result.pressure =
      std::sqrt(Utilities::MPI::sum(sum_p, comm) / volume) / v.load;
    result.pressure_vs_terzaghi =
      std::sqrt(Utilities::MPI::sum(sum_t, comm) / volume) / v.load;
    result.displacement =
      std::sqrt(Utilities::MPI::sum(sum_u, comm) / volume) / ((1 - J_inf) * H);
    result.base_rise = Utilities::MPI::max(base, comm) / H;
    return result;
  }

  void
  check(const std::string &what, const bool passed)
  {
    deallog << what << ": " << (passed ? "PASS" : "FAIL") << std::endl;
  }

  bool
  verbose()
  {
    return std::getenv("QSMPM_VERBOSE") != nullptr &&
           Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::MPILogInitAll       log;

  deallog << "1. Large strain, cpGIMP, kappa(J): errors against the exact "
             "solution, 32 cells (J_inf = "
          << std::setprecision(4) << final_volume_ratio(q) << ")" << std::endl;
  for (const double Tv : {0.1, 0.5, 1.0})
    {
      const Result r = run(Variant(), Tv);
      if (verbose())
        std::cout << "T_v " << Tv << ": p error " << r.pressure << ", u error "
                  << r.displacement << ", p vs Terzaghi "
                  << r.pressure_vs_terzaghi << ", base rise " << r.base_rise
                  << std::endl;
      std::ostringstream label;
      label << "  T_v = " << Tv;
      // Tolerance 1 %: the for Terzaghi; implicit Euler with the
      // step's geometry and mobility taken at its start is of first order
      // in the step, measured 0.2-0.4 %.
      check(label.str() + ": completed, pressure L2 error < 1 % of q",
            r.completed && r.pressure < 0.01);
      check(label.str() + ": displacement L2 error < 1 % of the final "
                          "settlement",
            r.displacement < 0.01);
      // What a small-strain code would be measured against: the check
      // above can tell the two apart.
      check(label.str() + ": Terzaghi's small-strain pressure is more than "
                          "2 % of q away",
            r.pressure_vs_terzaghi > 0.02);
    }

  deallog << "2. Refinement, T_v = 0.5: the steps halved; the cells halved"
          << std::endl;
  {
    Variant half_steps;
    half_steps.time_refinement = 2;
    Variant coarse             = half_steps;
    coarse.cells               = 16;
    const Result r0            = run(Variant(), 0.5);
    const Result r1            = run(half_steps, 0.5);
    const Result r2            = run(coarse, 0.5);
    if (verbose())
      std::cout << "32 cells: p error " << r0.pressure << " -> " << r1.pressure
                << " with half the steps; u error 16 / 32 "
                << "cells " << r2.displacement << " / " << r1.displacement
                << " (p " << r2.pressure << " / " << r1.pressure << ")"
                << std::endl;
    // Implicit Euler, with the step's geometry and mobility taken at its
    // start: first order in the step (measured ratio 0.46). In space the
    // pressure error is then at a floor of 0.04-0.08 % of q on 16 to 64
    // cells (doc/example_consolidation.md); the displacement error falls.
    check("  half the steps: pressure error falls by more than 40 %",
          r1.completed && r1.pressure < 0.6 * r0.pressure);
    check("  half the steps: displacement error falls from 16 to 32 cells",
          r2.completed && r1.displacement < r2.displacement);
  }

  deallog << "3. 3D: 1 x 16 x 1 cells, 2^3 points per cell, T_v = 0.5, "
             "half the steps, Coupling tolerance 1e-6"
          << std::endl;
  {
    Variant coarse;
    coarse.cells              = 16;
    coarse.time_refinement    = 2;
    coarse.coupling_tolerance = "1e-6";
    const Result plane        = run(coarse, 0.5);
    const Result solid        = run<3>(coarse, 0.5);
    if (verbose())
      std::cout << "3D: p error " << solid.pressure << " (2D " << plane.pressure
                << "), u error " << solid.displacement << " (2D "
                << plane.displacement << ")" << std::endl;
    check("  completed, pressure error < 1 % of q",
          solid.completed && solid.pressure < 0.01);
    // A one-dimensional problem: plane strain and 3D differ only by where
    // the fixed-stress iterations stop, which contract differently with
    // the drained bulk modulus (lambda + mu, lambda + 2 mu / 3). Measured
    // with the default Coupling tolerance 1e-5: 3.6e-4 of q; with 1e-6
    // (here): 7e-6; with 1e-7: 2e-7.
    check("  Coupling tolerance 1e-6: pressure and displacement errors equal "
          "to 2D's within 5e-5",
          std::abs(solid.pressure - plane.pressure) < 5e-5 &&
            std::abs(solid.displacement - plane.displacement) < 5e-5);
  }

  deallog << "4. A constant mobility instead of kappa(J), T_v = 0.5"
          << std::endl;
  {
    Variant constant;
    constant.mobility_factor = "1";
    const Result c           = run(constant, 0.5);
    if (verbose())
      std::cout << "constant mobility: p error " << c.pressure << std::endl;
    // The test sees the permeability's change with J (-58 % at J_inf).
    check("  completed, pressure error > 3 % of q",
          c.completed && c.pressure > 0.03);
  }

  deallog << "5. Small strain, cpGIMP, load q / 100 on the grid's face: "
             "Terzaghi's column, T_v = 0.5"
          << std::endl;
  {
    Variant gimp;
    gimp.kinematics      = "small strain";
    gimp.model           = "linear elastic";
    gimp.mobility_factor = "1";
    gimp.load            = q / 100;
    gimp.on_grid_face    = true;
    const Result g       = run(gimp, 0.5);
    if (verbose())
      std::cout << "small strain, cpGIMP: error against Terzaghi "
                << g.pressure_vs_terzaghi << std::endl;
    check("  pressure L2 error < 1 % of the load",
          g.completed && g.pressure_vs_terzaghi < 0.01);
  }
  deallog << "6. Drained at the base, the surface that rises (Drained "
             "surface region), T_v = 0.5"
          << std::endl;
  {
    // The same closed forms with z the distance from the base: in the
    // large-strain column the drained surface moves up by 1.5 m (4.8
    // cells) while the pressure drops across it.
    Variant large;
    large.drained_base = true;
    Variant small;
    small.kinematics      = "small strain";
    small.model           = "linear elastic";
    small.shape_functions = "linear";
    small.mobility_factor = "1";
    small.load            = q / 100;
    small.drained_base    = true;
    const Result l        = run(large, 0.5);
    const Result s        = run(small, 0.5);
    if (verbose())
      std::cout << "drained base: large strain p error " << l.pressure
                << ", u error " << l.displacement
                << "; small strain, linear: p error against Terzaghi "
                << s.pressure_vs_terzaghi << std::endl;
    // Measured 0.18 % and 0.10 % (0.13 % and 0.07 % with the drained top).
    check("  large strain, cpGIMP: pressure L2 error < 1 % of q, "
          "displacement < 1 % of the settlement",
          l.completed && l.pressure < 0.01 && l.displacement < 0.01);
    check("  small strain, linear: pressure L2 error < 1 % of the load",
          s.completed && s.pressure_vs_terzaghi < 0.01);
  }
  return 0;
}
