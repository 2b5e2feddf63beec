/* ---------------------------------------------------------------------
 *
 * qsmpm example: contact
 *
 * Rigid bodies in contact with the material points, against the known
 * answers of the contact benchmarks: a plate compacting an elastic column,
 * Prandtl's strip footing as a rigid body (smooth and rough), a block
 * sliding on a floor with Coulomb friction, and Hertz's cylinder; and two
 * elastic blocks in contact with each other, pressed and pulled apart. Each
 * problem is a parameter file of the general driver, which the program
 * writes next to its results (run any of them with build/qsmpm <file>).
 * summary.txt gets one "name = value" line per measured figure.
 *
 * Usage:
 *   ./contact [contact.prm]
 *   mpirun -np 2 ./contact contact.prm
 *
 * ---------------------------------------------------------------------
 */

// @sect3{Include files}
#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <sstream>
#include <string>
#include <vector>

namespace Contact
{
  using namespace dealii;
  using namespace qsmpm;

  // @sect3{Parameters}
  //
  // The grids of the benchmarks; everything else of each problem is in the
  // parameter file the program writes for it.
  struct Parameters
  {
    unsigned int footing_cells    = 16;
    unsigned int footing_steps    = 40;
    unsigned int hertz_cells      = 96;
    std::string  output_directory = "output-contact";

    void
    add_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact benchmarks");
      prm.add_parameter("Footing cells per half-width",
                        footing_cells,
                        "a/h of the rigid footings.");
      prm.add_parameter("Footing load steps", footing_steps, "");
      prm.add_parameter("Hertz cells",
                        hertz_cells,
                        "Cells along each side of the half block under "
                        "Hertz's cylinder (0.6 x 0.6).");
      prm.add_parameter("Output directory", output_directory, "");
      prm.leave_subsection();
    }
  };



  // @sect3{Running one parameter file}
  //
  // Writes @p text to <directory>/<name>.prm (rank 0), reads it back as a
  // user's file, and runs it with @p observe called after every accepted
  // step.
  template <int dim>
  class Benchmark
  {
  public:
    Benchmark(const std::string &directory,
              const std::string &name,
              const std::string &text)
      : problem(MPI_COMM_WORLD)
    {
      const std::string file = directory + "/" + name + ".prm";
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          std::ofstream out(file);
          AssertThrow(out, ExcMessage("Cannot write <" + file + ">."));
          out << text;
        }
      MPI_Barrier(MPI_COMM_WORLD);
      ParameterHandler prm;
      prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
      QuasiStaticProblem<dim>::Parameters::declare_parameters(prm);
      prm.parse_input(file);
      problem.pcout().set_condition(false);
      problem.initialize(prm);
    }

    QuasiStaticProblem<dim> problem;
  };



  // The material and output subsections all problems share: E = 1000
  // (footings: 1e6), plane strain.
  std::string
  elastic(const double E, const double nu)
  {
    std::ostringstream text;
    text << "subsection Material\n  set Model = linear elastic\n"
         << "  subsection linear elastic\n"
         << "    set Young's modulus = " << E << "\n"
         << "    set Poisson's ratio = " << nu << "\n  end\nend\n";
    return text.str();
  }

  std::string
  no_fields(const std::string &directory)
  {
    return "subsection Output\n  set Interval = 0\n  set Directory = " +
           directory + "\nend\n";
  }



  // @sect3{The benchmarks}
  class ContactBenchmarks
  {
  public:
    explicit ContactBenchmarks(const std::string &parameter_file)
      : pcout(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      ParameterHandler prm;
      settings.add_parameters(prm);
      prm.parse_input(parameter_file);
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::filesystem::create_directories(settings.output_directory);
    }

    void
    run()
    {
      Timer timer;
      plate();
      footing("smooth");
      footing("rough");
      friction();
      hertz();
      two_blocks();
      sliding_blocks();
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          write_footing_plot();
          std::ofstream out(settings.output_directory + "/summary.txt");
          out << std::setprecision(6);
          for (const auto &[name, value] : summary)
            out << name << " = " << value << '\n';
        }
      pcout << "wrote " << settings.output_directory << "/summary.txt ("
            << std::fixed << std::setprecision(0) << timer.wall_time() << " s)"
            << std::defaultfloat << std::setprecision(6) << std::endl;
    }

  private:
    // @sect4{Two elastic blocks}
    //
    // Contact between deformable bodies on a multi-field grid: block A
    // [0, 1] x [0, 0.5] (material id 0) and block B [1 + g, 2] (id 1),
    // g = h / 2, h = 1/8, E = 1000, nu = 0.3, 2 x 2 points per cell; the
    // left face holds u_x = 0, top and bottom u_y = 0 (uniaxial strain),
    // the right face moves B by u(t): to A over t in [0, 0.4] (the gap
    // closes, no force), 0.006 further (compression, to t = 0.7), then back
    // to 0.01 beyond where B started touching (t = 1: the blocks come apart
    // at t = 0.82). The same run with one block [0, 2 - g] (every point on
    // one field), loaded from t = 0.4 by u(t) + g, is what the two blocks
    // must give in compression; after separation the force must vanish.
    // The force is the reaction of the right face (its x component).
    std::vector<double>
    blocks(const bool two)
    {
      const double       g = 0.0625;
      std::ostringstream u;
      // u(t) of the right face, and its displacement condition.
      u << "if(t <= 0.4, " << -g << " * t / 0.4, if(t <= 0.7, " << -g
        << " - 0.006 * (t - 0.4) / 0.3, " << -g
        << " - 0.006 + 0.016 * (t - 0.7) / 0.3))";
      const std::string right =
        two ? u.str() :
              "if(t <= 0.4, 0, " + u.str() + " + " + std::to_string(g) + ")";
      std::ostringstream text;
      text << std::setprecision(17) << "set Dimension = 2\n"
           << "subsection Geometry\n  set Upper corner = 2, 0.5\n"
           << "  set Subdivisions = 16, 4\nend\n"
           << "subsection Material points\n"
           << "  set Region expression = "
           << (two ? "if(x < 1 || x > 1.0625, 1, 0)" : "if(x < 1.9375, 1, 0)")
           << "\n  set Material id = " << (two ? "if(x < 1, 0, 1)" : "0")
           << "\nend\n"
           << (two ? "subsection Contact between bodies\n"
                     "  set Bodies = 0; 1\nend\n" :
                     "")
           << elastic(1000., 0.3) << "subsection Boundary conditions\n"
           << "  set Dirichlet boundaries = 0:x, 1:x, 2:y, 3:y\n"
           << "  subsection Displacement\n"
           << "    set Function expression = if(x > 1.99, " << right
           << ", 0); 0\n"
           << "  end\nend\n"
           << "subsection Load stepping\n  set Number of steps = 10\nend\n"
           << "subsection Nonlinear solver\n  set Tolerance = 1e-10\nend\n"
           << no_fields(settings.output_directory +
                        (two ? "/two-blocks" : "/one-block"));
      Benchmark<2>        b(settings.output_directory,
                     two ? "two-blocks" : "one-block",
                     text.str());
      std::vector<double> force;
      b.problem.set_step_callback([&](const StepReport &) {
        force.push_back(b.problem.reactions().at(1)[0]);
        return true;
      });
      b.problem.run();
      return force;
    }

    void
    two_blocks()
    {
      const std::vector<double> two = blocks(true), one = blocks(false);
      AssertThrow(two.size() == 10 && one.size() == 10,
                  ExcMessage("two blocks: a run did not take 10 steps"));
      double peak = 0., difference = 0., apart = 0.;
      for (const double f : two)
        peak = std::max(peak, std::abs(f));
      for (unsigned int k = 4; k < 8; ++k)
        difference = std::max(difference, std::abs(two[k] - one[k]) / peak);
      for (unsigned int k = 8; k < 10; ++k)
        apart = std::max(apart, std::abs(two[k]));
      pcout << "two blocks: in compression |F_two - F_one| / peak <= "
            << difference << ", after separation |F| / peak = " << apart / peak
            << std::endl;
      summary.emplace_back("two_blocks_compression_difference", difference);
      summary.emplace_back("two_blocks_tension_force_over_peak", apart / peak);
    }

    // @sect4{A block sliding on a block}
    //
    // Coulomb friction between deformable bodies: block B [0.5, 1.5] x
    // [0.5 + g, 1] (material id 1) above block A [0, 2] x [0, 0.5] (id 0,
    // held at its base), g = h / 2, h = 1/8, the material and points of the
    // two blocks above, mu = 0.3. B's top face moves B onto A (2 steps),
    // presses it by 0.005 (2 steps) and pushes it along A by 0.008 (8
    // steps). The force on the top face is the force between the blocks:
    // once B slides (the last 3 steps), H / V = mu.
    void
    sliding_blocks()
    {
      const double       mu = 0.3;
      std::ostringstream text;
      // The step k = 12 t: u_y to -g in steps 1-2, by -0.005 more in steps
      // 3-4, then u_x by 0.001 per step.
      text << "set Dimension = 2\n"
           << "subsection Geometry\n  set Upper corner = 2, 1\n"
           << "  set Subdivisions = 16, 8\nend\n"
           << "subsection Material points\n"
           << "  set Region expression = "
           << "if(y < 0.5 || (y > 0.5625 && x > 0.5 && x < 1.5), 1, 0)\n"
           << "  set Material id = if(y < 0.5, 0, 1)\nend\n"
           << "subsection Contact between bodies\n"
           << "  set Bodies = 0; 1\n  set Friction = coulomb\n"
           << "  set Friction coefficient = " << mu << "\nend\n"
           << elastic(1000., 0.3) << "subsection Boundary conditions\n"
           << "  set Dirichlet boundaries = 2:xy, 3:xy\n"
           << "  subsection Displacement\n"
           << "    set Function constants = g = 0.0625\n"
           << "    set Function expression = "
           << "if(y > 0.99, if(12 * t <= 4, 0, 0.001 * (12 * t - 4)), 0); "
           << "if(y > 0.99, if(12 * t <= 2, -g * 6 * t, "
           << "if(12 * t <= 4, -g - 0.0025 * (12 * t - 2), -g - 0.005)), 0)\n"
           << "  end\nend\n"
           << "subsection Load stepping\n  set Number of steps = 12\nend\n"
           << "subsection Nonlinear solver\n  set Tolerance = 1e-10\nend\n"
           << no_fields(settings.output_directory + "/sliding-blocks");
      Benchmark<2> b(settings.output_directory, "sliding-blocks", text.str());
      std::vector<double> ratio;
      b.problem.set_step_callback([&](const StepReport &) {
        // The reaction of the top face (the second condition).
        const auto &force = b.problem.reactions().at(1);
        ratio.push_back(std::abs(force[0] / force[1]));
        return true;
      });
      b.problem.run();
      AssertThrow(ratio.size() == 12,
                  ExcMessage("sliding blocks: the run did not take 12 steps"));
      double low = ratio[9], high = ratio[9];
      for (unsigned int k = 10; k < 12; ++k)
        {
          low  = std::min(low, ratio[k]);
          high = std::max(high, ratio[k]);
        }
      pcout << "sliding blocks: |H| / |V| / mu while sliding " << low / mu
            << " to " << high / mu << std::endl;
      summary.emplace_back("sliding_blocks_friction_over_mu_low", low / mu);
      summary.emplace_back("sliding_blocks_friction_over_mu_high", high / mu);
    }

    // @sect4{The rigid plate}
    //
    // An elastic column 1 x 1 (E = 1000, nu = 0.3) on rollers, compacted by
    // 1 % by a frictionless half-space; cpGIMP, h = 1/8. Uniaxial strain:
    // sigma_yy = -M d / H and sigma_xx = -lambda d / H everywhere.
    void
    plate()
    {
      const double       E = 1000., nu = 0.3, d = 0.01;
      std::ostringstream text;
      text << "set Dimension = 2\n"
           << "subsection Geometry\n  set Upper corner = 1,1.25\n"
           << "  set Subdivisions = 8,10\nend\n"
           << "subsection Material points\n"
           << "  set Region lower corner = 0,0\n"
           << "  set Region upper corner = 1,1\n"
           << "  set Shape functions = cpGIMP\nend\n"
           << elastic(E, nu) << "subsection Boundary conditions\n"
           << "  set Dirichlet boundaries = 0:x, 1:x, 2:y\n"
           << "  subsection Rigid body\n"
           << "    set Shape = half-space\n    set Name = plate\n"
           << "    set Point = 0, 1\n    set Normal = 0, -1\n"
           << "    subsection Motion\n"
           << "      set Function expression = 0; " << -d << "*t\n"
           << "    end\n  end\nend\n"
           << "subsection Load stepping\n  set Number of steps = 5\nend\n"
           << "subsection Nonlinear solver\n  set Tolerance = 1e-10\nend\n"
           << no_fields(settings.output_directory + "/plate");
      Benchmark<2> b(settings.output_directory, "plate", text.str());
      b.problem.run();
      const double lambda = E * nu / ((1. + nu) * (1. - 2. * nu)),
                   M = lambda + E / (1. + nu), sigma_yy = -M * d,
                   sigma_xx = -lambda * d;
      const auto &offsets   = b.problem.points().get_offsets();
      double      error     = 0.;
      for (const auto &particle : b.problem.points().get_particle_handler())
        {
          const SymmetricTensor<2, 2> s = Utils::read_symmetric<2>(
            &particle.get_properties()[offsets.stress]);
          error = std::max({error,
                            std::abs(s[1][1] - sigma_yy),
                            std::abs(s[0][0] - sigma_xx),
                            std::abs(s[0][1])});
        }
      error = Utilities::MPI::max(error, MPI_COMM_WORLD) / std::abs(sigma_yy);
      pcout << "plate: largest stress error of a point " << error
            << " (relative to sigma_yy)" << std::endl;
      summary.emplace_back("plate_stress_error", error);
    }

    // @sect4{Prandtl's footing as a rigid body}
    //
    // A rigid box of half-width a = 1 pushed 0.02 a into a von Mises
    // (Tresca) soil, c = 100, E = 1e6, nu = 0.3, 5 a wide and deep, on
    // rollers at its sides and fixed at its base; F-bar, h = a / cells,
    // smooth or rough. q_u / c (the pressure at the end) against 2 + pi;
    // the curve's largest jump is the largest change of the pressure in one
    // step from where it first reaches 99 % of its largest value on,
    // relative to q_u (the prescribed-node footing of examples/footing
    // jumps as new rows of nodes join it). The points do not move (`Move
    // points = false`, `Update volumes = false`): Prandtl's limit load is
    // that of the small-displacement theory, which the points then
    // integrate on a fixed quadrature, while the footing meets them where
    // their displacement puts them. Moving points cross the grid's lines as
    // the soil under the footing sinks, and the pressure falls by about 1 c
    // per cell width of settlement between jumps at the crossings
    // (doc/example_footing.md); fixed, the curve has a plateau whose height
    // converges at first order in h, up to about a third of a cell of
    // settlement (the run ends at 0.32 h; beyond, the smooth footing's
    // pressure turns, an open question of doc/example_footing.md). The
    // preconditioner is the sparse factorization of the Jacobian at each
    // Newton iterate (`Preconditioner = direct`, `Preconditioner update =
    // Newton iteration`; 13,000 dofs at a/h = 16): AMG built once per step
    // from the committed, elastic tangents leaves GMRES to make up the
    // yielding of the step, and the inexact corrections cost Newton
    // iterations on the plateau as well (doc/example_contact.md).
    void
    footing(const std::string &surface)
    {
      const double       c = 100., a = 1.;
      const unsigned int n = settings.footing_cells;
      std::ostringstream text;
      text << std::setprecision(17) << "set Dimension = 2\n"
           << "subsection Geometry\n  set Upper corner = 5, 5\n"
           << "  set Subdivisions = " << 5 * n << ", " << 5 * n << "\nend\n"
           << "subsection Material points\n"
           << "  set Region lower corner = 0,0\n"
           << "  set Region upper corner = 5,5\n"
           << "  set Volumetric locking = F-bar\n"
           << "  set Move points = false\n  set Update volumes = false\nend\n"
           << "subsection Material\n  set Model = von Mises\n"
           << "  subsection von Mises\n    set Young's modulus = 1e6\n"
           << "    set Poisson's ratio = 0.3\n"
           << "    set Yield stress = " << std::sqrt(3.) * c << "\n"
           << "    set Hardening modulus = 0\n  end\nend\n"
           << "subsection Boundary conditions\n"
           << "  set Dirichlet boundaries = 0:x, 1:x, 2:xy\n"
           << "  subsection Rigid body\n"
           << "    set Shape = box\n    set Name = footing\n"
           << "    set Point = " << -a << ", 5\n"
           << "    set Upper corner = " << a << ", " << 5. + a << "\n"
           << "    set Friction = "
           << (surface == "rough" ? "rough" : "frictionless") << "\n"
           << "    set Penalty factor = 10\n"
           << "    subsection Motion\n"
           << "      set Function expression = 0; " << -0.02 * a << "*t\n"
           << "    end\n  end\nend\n"
           << "subsection Load stepping\n  set Number of steps = "
           << settings.footing_steps << "\nend\n"
           << "subsection Nonlinear solver\n  set Line search steps = 8\n"
           << "  set Preconditioner = direct\n"
           << "  set Preconditioner update = Newton iteration\nend\n"
           << no_fields(settings.output_directory + "/footing-" + surface);
      Benchmark<2>        b(settings.output_directory,
                     "footing-" + surface,
                     text.str());
      std::vector<double> q, t;
      b.problem.set_step_callback([&](const StepReport &report) {
        q.push_back(b.problem.rigid_body_loads().front().force[1] / a);
        t.push_back(report.load_factor);
        return true;
      });
      Timer timer;
      b.problem.run();
      const double q_u = q.back(), exact = 2. + numbers::PI;
      // Jumps: the largest change in one step from where the pressure first
      // reaches 99 % of its largest value on (before, the curve rises
      // steeply and smoothly through the knee of yield).
      const double largest = *std::max_element(q.begin(), q.end());
      double       jump    = 0.;
      bool         plateau = false;
      for (unsigned int k = 0; k + 1 < q.size(); ++k)
        {
          plateau = plateau || q[k] >= 0.99 * largest;
          if (plateau)
            jump = std::max(jump, std::abs(q[k + 1] - q[k]) / q_u);
        }
      pcout << "footing (" << surface << "), a/h = " << n
            << ": q_u / c = " << q_u / c << " (2 + pi = " << exact << ", error "
            << q_u / c / exact - 1. << "), largest jump " << jump << " q_u, "
            << std::fixed << std::setprecision(0) << timer.wall_time() << " s"
            << std::defaultfloat << std::setprecision(6) << std::endl;
      summary.emplace_back("rigid_footing_" + surface + "_over_c", q_u / c);
      for (unsigned int k = 0; k < q.size(); ++k)
        footing_curves.push_back(
          {{surface == "rough" ? 1. : 0., t[k], q[k] / c}});
      if (surface == "smooth")
        summary.emplace_back("largest_jump_over_qu", jump);
    }

    // @sect4{A block sliding on a floor}
    //
    // A block 1 x 0.5 (E = 1000, nu = 0.3) pressed onto a floor by q = 10,
    // the floor then sliding 0.2 under it in 100 steps, Coulomb mu = 0.3.
    // Once every point slips, the floor's tangential force over its normal
    // force is mu: the mean over the second half of the sliding steps.
    void
    friction()
    {
      const double       mu = 0.3;
      std::ostringstream text;
      text << "set Dimension = 2\n"
           << "subsection Geometry\n  set Upper corner = 1.5,1\n"
           << "  set Subdivisions = 12,8\nend\n"
           << "subsection Material points\n"
           << "  set Region lower corner = 0,0.25\n"
           << "  set Region upper corner = 1,0.75\nend\n"
           << elastic(1000., 0.3) << "subsection Boundary conditions\n"
           << "  set Dirichlet boundaries = 0:x\n"
           << "  set Surface traction region = y > 0.74\n"
           << "  subsection Surface traction\n"
           << "    set Function expression = 0; -10*min(t, 1)\n  end\n"
           << "  subsection Rigid body\n"
           << "    set Shape = half-space\n    set Name = floor\n"
           << "    set Point = 0, 0.25\n    set Normal = 0, 1\n"
           << "    set Friction = coulomb\n"
           << "    set Friction coefficient = " << mu << "\n"
           << "    subsection Motion\n"
           << "      set Function expression = 0.2*max(t - 1, 0); 0\n"
           << "    end\n  end\nend\n"
           << "subsection Load stepping\n  set Final load factor = 2\n"
           << "  set Number of steps = 200\nend\n"
           << no_fields(settings.output_directory + "/friction");
      Benchmark<2>        b(settings.output_directory, "friction", text.str());
      std::vector<double> ratio;
      b.problem.set_step_callback([&](const StepReport &report) {
        const auto &floor = b.problem.rigid_body_loads().front();
        if (report.load_factor > 1.5 + 1e-12)
          ratio.push_back(std::abs(floor.force[0] / floor.force[1]));
        return true;
      });
      b.problem.run();
      double mean = 0.;
      for (const double r : ratio)
        mean += r / ratio.size();
      pcout << "friction: F_x / F_y over mu, mean of the last " << ratio.size()
            << " sliding steps: " << mean / mu << std::endl;
      summary.emplace_back("friction_ratio_over_mu", mean / mu);
    }

    // @sect4{Hertz}
    //
    // A rigid cylinder R = 1 pressed 0.01 into an elastic half block
    // 0.6 x 0.6 (E = 1000, nu = 0.3, plane strain, cpGIMP, symmetry at
    // x = 0), Penalty factor = 1 (doc/contact.md). The half-width from the
    // second moment of the points' contact pressure (a^2 / 4 for Hertz's
    // ellipse) and the largest point pressure against Hertz's a and p0 for
    // the measured force (Johnson 1985, eqs. 4.43-4.45).
    void
    hertz()
    {
      const double       E = 1000., nu = 0.3, R = 1., W = 0.6;
      const unsigned int n = settings.hertz_cells;
      std::ostringstream text;
      text << "set Dimension = 2\n"
           << "subsection Geometry\n  set Upper corner = " << W << "," << W
           << "\n  set Subdivisions = " << n << "," << n << "\nend\n"
           << "subsection Material points\n"
           << "  set Shape functions = cpGIMP\nend\n"
           << elastic(E, nu) << "subsection Boundary conditions\n"
           << "  set Dirichlet boundaries = 0:x, 1:x, 2:xy\n"
           << "  subsection Rigid body\n"
           << "    set Shape = sphere\n    set Name = cylinder\n"
           << "    set Point = 0, " << W + R << "\n"
           << "    set Radius = " << R << "\n"
           << "    set Penalty factor = 1\n"
           << "    subsection Motion\n"
           << "      set Function expression = 0; -0.01*t\n"
           << "    end\n  end\nend\n"
           << "subsection Load stepping\n  set Number of steps = 5\nend\n"
           << "subsection Nonlinear solver\n  set Tolerance = 1e-8\nend\n"
           << no_fields(settings.output_directory + "/hertz");
      Benchmark<2> b(settings.output_directory, "hertz", text.str());
      b.problem.run();
      const double h = W / n;
      const double P = 2. * std::abs(b.problem.rigid_body_loads()[0].force[1]);
      const double E_star  = E / (1. - nu * nu);
      const double a       = std::sqrt(4. * P * R / (numbers::PI * E_star));
      const double p0      = 2. * P / (numbers::PI * a);
      const auto  &offsets = b.problem.points().get_offsets();
      double       force = 0., second_moment = 0., peak = 0.;
      for (const auto &particle : b.problem.points().get_particle_handler())
        {
          const double p = -particle.get_properties()[offsets.contact + 1];
          if (p <= 0.)
            continue;
          const double x = particle.get_location()[0];
          force += p * h / 2.;
          second_moment += p * h / 2. * x * x;
          peak = std::max(peak, p);
        }
      force                = Utilities::MPI::sum(force, MPI_COMM_WORLD);
      second_moment        = Utilities::MPI::sum(second_moment, MPI_COMM_WORLD);
      peak                 = Utilities::MPI::max(peak, MPI_COMM_WORLD);
      const double a_error = 2. * std::sqrt(second_moment / force) / a - 1.;
      const double p_error = peak / p0 - 1.;
      pcout << "hertz, a/h = " << a / h << ": half-width error " << a_error
            << ", peak pressure error " << p_error << std::endl;
      summary.emplace_back("hertz_half_width_error", a_error);
      summary.emplace_back("hertz_peak_pressure_error", p_error);
    }

    // The footings' pressure against the settlement (rank 0):
    // footing_curves.csv, and footing_pressure_settlement.png if gnuplot is
    // installed.
    void
    write_footing_plot() const
    {
      const std::string &dir = settings.output_directory;
      std::ofstream      csv(dir + "/footing_curves.csv");
      csv << "rough,settlement_over_s,q_over_c\n";
      for (const auto &[rough, s, q] : footing_curves)
        csv << rough << ',' << s << ',' << q << '\n';
      csv.close();
      std::ofstream gp(dir + "/footing.gp");
      gp << "set terminal pngcairo size 800,560 noenhanced\n"
         << "set datafile separator ','\n"
         << "set output '" << dir << "/footing_pressure_settlement.png'\n"
         << "set xlabel 'settlement / 0.02 a'\nset ylabel 'q / c'\n"
         << "set key bottom right\nset grid\nset yrange [0:6]\n"
         << "f = '" << dir << "/footing_curves.csv'\n"
         << "plot f every ::1 using ($1 == 0 ? $2 : 1/0):3 w lp pt 7 ps 0.5 "
            "t 'smooth rigid footing', \\\n"
         << "     f every ::1 using ($1 == 1 ? $2 : 1/0):3 w lp pt 5 ps 0.5 "
            "t 'rough rigid footing', \\\n"
         << "     2 + pi w l dt 2 t 'Prandtl, 2 + pi'\n";
      gp.close();
      Utils::run_gnuplot(dir + "/footing.gp");
    }

    ConditionalOStream                          pcout;
    std::vector<std::array<double, 3>>          footing_curves;
    Parameters                                  settings;
    std::vector<std::pair<std::string, double>> summary;
  };
} // namespace Contact



int
main(int argc, char *argv[])
{
  unsigned int rank = 0;
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
      const std::string parameter_file =
        argc > 1 ?
          std::string(argv[1]) :
          (std::filesystem::path(argv[0]).parent_path() / "contact.prm")
            .string();
      AssertThrow(std::filesystem::exists(parameter_file),
                  dealii::ExcMessage("Cannot find the parameter file <" +
                                     parameter_file + ">."));
      Contact::ContactBenchmarks(parameter_file).run();
    }
  catch (std::exception &exc)
    {
      if (rank == 0)
        std::cerr << "contact stopped: " + qsmpm::Utils::error_message(exc) +
                       "\n"
                  << std::flush;
      return 1;
    }
  catch (...)
    {
      if (rank == 0)
        std::cerr << "contact stopped: unknown exception" << std::endl;
      return 1;
    }
  return 0;
}
