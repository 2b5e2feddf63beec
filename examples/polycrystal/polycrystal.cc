/* ---------------------------------------------------------------------
 *
 * qsmpm example: polycrystal
 *
 * The effective elastic stiffness of a textured, columnar nickel
 * polycrystal from six virtual tests with the quasi-static material-point
 * method, following Section 4 of Sanchez, Schreyer, Sulsky and Wallstedt,
 * "Solving Quasi-Static Equations with the Material-Point Method".
 *
 * Usage:
 *   ./polycrystal [file.prm]
 *   mpirun -np 2 ./polycrystal [file.prm]
 *   ./polycrystal --make-odfs <directory>   (writes the shipped ODF files)
 *
 * Without an argument, polycrystal.prm next to the executable is read.
 *
 * ---------------------------------------------------------------------
 */

// @sect3{Include files}
//
// Besides the core of the library (reached through QuasiStaticProblem,
// which VirtualTests uses internally) we need the homogenization module:
// the grain structure, the orientation distribution and its
// discretization, the six virtual tests and the Voigt/Reuss/Hill
// estimates, and the cubic crystal model.
#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <numeric>
#include <qsmpm/base/parameter_file.h>
#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/base/rotation.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/homogenization/columnar_voronoi.h>
#include <qsmpm/homogenization/orientation_distribution.h>
#include <qsmpm/homogenization/stiffness_bounds.h>
#include <qsmpm/homogenization/texture_sampler.h>
#include <qsmpm/homogenization/virtual_tests.h>
#include <qsmpm/materials/cubic_elastic.h>
#include <sstream>
#include <string>
#include <vector>

namespace Polycrystal
{
  using namespace dealii;
  using namespace qsmpm;

  using Matrix6 = StiffnessBounds::Matrix6;

  // @sect3{The parameters}
  //
  // The program's own subsection "Polycrystal" holds the sample (size,
  // grains, resolution), the texture and the tests. The material constants
  // come from the library's subsection "Material/cubic elastic" and the
  // solver settings from "Nonlinear solver", so that the same entries mean
  // the same thing in every qsmpm program.
  //
  // The struct is a parameter struct in the manner of the library's
  // (ParameterStruct, deal.II's step-68): each member's initializer is its
  // default, add_parameters() declares the entry bound to it with
  // ParameterHandler::add_parameter() -- name, default and documentation
  // written once -- and check() tests what a single entry's pattern cannot.
  // ParameterStruct adds declare_parameters() (the entries with their
  // defaults) and parse_parameters() (the values of a parsed file into an
  // object, then check()).
  struct Parameters : ParameterStruct<Parameters>
  {
    double                   side_length             = 1.0;
    unsigned int             n_grains                = 1000;
    unsigned int             grain_seed              = 1;
    bool                     periodic_grains         = false;
    unsigned int             cells_in_plane          = 96;
    unsigned int             cells_through_thickness = 4;
    unsigned int             points_per_direction    = 2;
    std::string              odf_file = "odf/electrodeposited_ni.txt";
    unsigned int             n_elementary_volumes = 50000;
    double                   threshold_degrees    = 7;
    unsigned int             texture_seed         = 1;
    std::vector<std::string> boundary_conditions  = {"mixed"};
    double                   strain               = 0.004;
    unsigned int             n_load_steps         = 2;
    unsigned int             test_groups          = 0;
    unsigned int             n_realizations       = 1;
    std::string              output_directory     = "polycrystal-output";

    void
    add_parameters(ParameterHandler &prm);
    void
    check() const;
  };



  void
  Parameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Polycrystal");
    {
      prm.add_parameter("Side length",
                        side_length,
                        "L: edge of the cubic sample (the paper's 1 micron; "
                        "the stiffness does not depend on it).",
                        Patterns::Double(0.));
      prm.add_parameter("Number of grains",
                        n_grains,
                        "Voronoi generating points in the film plane (x, y); "
                        "grains are columns through the thickness z.",
                        Patterns::Integer(1));
      prm.add_parameter("Grain seed",
                        grain_seed,
                        "Seed of the generating points (realization r uses "
                        "seed + r).",
                        Patterns::Integer(0));
      prm.add_parameter("Periodic grains",
                        periodic_grains,
                        "Periodic tessellation of the film plane (grains cut "
                        "by one face continue on the opposite face).");
      prm.add_parameter("Cells in plane",
                        cells_in_plane,
                        "Background grid cells along x and along y.",
                        Patterns::Integer(1));
      prm.add_parameter("Cells through thickness",
                        cells_through_thickness,
                        "Background grid cells along z. The grains are "
                        "columns, so z may be coarser than the plane.",
                        Patterns::Integer(1));
      prm.add_parameter("Points per cell per direction",
                        points_per_direction,
                        "Regularly placed material points per cell and "
                        "direction.",
                        Patterns::Integer(1, 6));
      prm.add_parameter("ODF file",
                        odf_file,
                        "Orientation distribution on the 5 degree Bunge grid "
                        "(format: see OrientationDistribution); relative to "
                        "the directory of the parameter file.");
      prm.add_parameter("Elementary volumes",
                        n_elementary_volumes,
                        "N_u of the texture discretization (paper Sec. 4.3).",
                        Patterns::Integer(1));
      prm.add_parameter("Disorientation threshold",
                        threshold_degrees,
                        "Degrees; the orientations averaged into one grain "
                        "lie within this disorientation of a seed.",
                        Patterns::Double(0., 62.8));
      prm.add_parameter("Texture seed",
                        texture_seed,
                        "Seed of the texture sampling (realization r uses "
                        "seed + r).",
                        Patterns::Integer(0));
      prm.add_parameter("Boundary conditions",
                        boundary_conditions,
                        "mixed: the paper's tests (four confined faces free "
                        "to slide, two loaded faces); affine: the "
                        "macroscopic displacement on all faces; periodic: "
                        "periodic fluctuations about the macroscopic "
                        "displacement (meant for <Periodic grains> = true). "
                        "A list runs all of them on the first realization; "
                        "the first gives effective_stiffness.csv.",
                        Patterns::List(
                          Patterns::Selection("mixed|affine|periodic")));
      prm.add_parameter("Strain",
                        strain,
                        "Macroscopic strain of each test (the paper's "
                        "faces move by 0.002 L each: 0.004).",
                        Patterns::Double(0.));
      prm.add_parameter("Load steps",
                        n_load_steps,
                        "Load steps per test.",
                        Patterns::Integer(1));
      prm.add_parameter("Test groups",
                        test_groups,
                        "The six tests are independent and run at once in "
                        "this many groups of MPI ranks, each test on the "
                        "ranks of one group. 0: one group per rank (at most "
                        "six); 1: every test on all ranks, one after the "
                        "other. Each rank of a group of one holds a whole "
                        "sample (memory).",
                        Patterns::Integer(0));
      prm.add_parameter("Number of realizations",
                        n_realizations,
                        "M samples with seeds (grain seed + r, texture seed "
                        "+ r); M > 1 gives the mean, standard deviation and "
                        "histogram of the in-plane modulus.",
                        Patterns::Integer(1));
      prm.add_parameter("Output directory",
                        output_directory,
                        "Where results go (relative to the working "
                        "directory).");
    }
    prm.leave_subsection();
  }



  // What the patterns of single entries cannot check. ParameterStruct's
  // parse_parameters() calls it after reading the entries.
  void
  Parameters::check() const
  {
    AssertThrow(!boundary_conditions.empty(),
                ExcMessage("Polycrystal: <Boundary conditions> is empty."));
    AssertThrow(side_length > 0,
                ExcMessage("Polycrystal: <Side length> must be positive, "
                           "got " +
                           std::to_string(side_length) + "."));
    // A periodic direction needs two cells across (BackgroundGrid); say so
    // in this program's entries rather than in the library's
    // <Subdivisions>.
    for (const auto &bc : boundary_conditions)
      AssertThrow(bc != "periodic" ||
                    (cells_in_plane >= 2 && cells_through_thickness >= 2),
                  ExcMessage("Polycrystal: <Boundary conditions> = periodic "
                             "needs <Cells in plane> and <Cells through "
                             "thickness> of at least 2, got " +
                             std::to_string(cells_in_plane) + " and " +
                             std::to_string(cells_through_thickness) + "."));
    AssertThrow(strain > 0 && strain < 0.05,
                ExcMessage("Polycrystal: <Strain> must lie in (0, 0.05): the "
                           "model is small-strain elasticity."));
  }



  // @sect3{The shipped orientation distributions}
  //
  // Three ODFs come with the example, on the 5 degree grid of Bunge angles
  // in [0, 90] degrees:
  //
  // - uniform.txt: f = 1 (a random texture);
  // - fibre_001.txt: a <001> fibre along the film normal z, i.e. a Gaussian
  //   $f = \exp(-\theta^2 / (2 \cdot 10^\circ{}^2))$ of the angle $\theta$
  //   between z and the nearest crystal <001> direction. In Bunge's
  //   convention z has the crystal components
  //   $(\sin\varphi_2\sin\Phi, \cos\varphi_2\sin\Phi, \cos\Phi)$ (the third
  //   column of g), and $\cos\theta$ is the largest of their absolute
  //   values, which is invariant under all cubic and orthorhombic symmetry
  //   operations, as an ODF must be;
  // - electrodeposited_ni.txt: the fibre (normalized to mean 1) with weight
  //   w plus a random part 1 - w. The real films' texture is not public;
  //   what is known is their Hill in-plane modulus, 194.7 GPa (paper
  //   Table I). We choose w by bisection so that the Hill in-plane modulus
  //   of this ODF for the nickel constants is 194.7 GPa.
  //
  // The Hill modulus of an ODF is computed from the cell centres weighted
  // with the cells' volume fractions.
  double
  fibre_density(const double, const double Phi, const double phi2)
  {
    const double n[3] = {std::sin(phi2) * std::sin(Phi),
                         std::cos(phi2) * std::sin(Phi),
                         std::cos(Phi)};
    const double c = std::max({std::abs(n[0]), std::abs(n[1]), std::abs(n[2])});
    const double theta = std::acos(std::min(1., c));
    const double sigma = 10. * M_PI / 180.;
    return std::exp(-0.5 * theta * theta / (sigma * sigma));
  }



  StiffnessBounds
  odf_bounds(const OrientationDistribution &odf,
             const SymmetricTensor<4, 3>   &C_crystal)
  {
    std::vector<Tensor<2, 3>> g;
    std::vector<double>       w;
    for (unsigned int i = 0; i < OrientationDistribution::n_cells; ++i)
      if (odf.cell_fractions()[i] > 0)
        {
          g.push_back(OrientationDistribution::cell_orientation(i));
          w.push_back(odf.cell_fractions()[i]);
        }
    return StiffnessBounds(C_crystal, g, w);
  }



  void
  make_odfs(const std::string &directory)
  {
    std::filesystem::create_directories(directory);
    const auto C = Rotation::cubic_stiffness(249., 155., 114.);

    const OrientationDistribution uniform(
      [](double, double, double) { return 1.; });
    uniform.write(directory + "/uniform.txt",
                  "uniform (random) texture, f = 1");

    const OrientationDistribution fibre(fibre_density);
    fibre.write(directory + "/fibre_001.txt",
                "<001> fibre along the film normal z: f = exp(-theta^2 / (2 "
                "(10 deg)^2)), theta = angle between z and the nearest "
                "crystal <001>");

    // The mean of the fibre density over Euler space (dg-weighted), to
    // mix it with the uniform part in volume fractions.
    double fibre_mean = 0;
    {
      const auto &m = OrientationDistribution::cell_measures();
      for (unsigned int i = 0; i < OrientationDistribution::n_cells; ++i)
        {
          const auto a = OrientationDistribution::cell_centre(i);
          fibre_mean += m[i] * fibre_density(a[0], a[1], a[2]);
        }
    }
    auto mixed = [fibre_mean](const double w) {
      return OrientationDistribution(
        [w, fibre_mean](double a, double b, double c) {
          return w * fibre_density(a, b, c) / fibre_mean + (1. - w);
        });
    };
    const double target = 194.7;
    double       lo = 0., hi = 1.;
    for (unsigned int it = 0; it < 50; ++it)
      {
        const double w = 0.5 * (lo + hi);
        const double E_hill =
          StiffnessBounds::in_plane(odf_bounds(mixed(w), C).hill()).E_in_plane;
        (E_hill > target ? lo : hi) = w;
      }
    const double       w = 0.5 * (lo + hi);
    std::ostringstream comment;
    comment << std::setprecision(6)
            << "electrodeposited-Ni-like texture: fibre_001 with volume "
               "fraction w = "
            << w
            << " plus a random part 1 - w; w makes the Hill in-plane "
               "modulus 194.7 GPa (C11, C12, C44 = 249, 155, 114 GPa)";
    mixed(w).write(directory + "/electrodeposited_ni.txt", comment.str());
    std::cout << "Wrote uniform.txt, fibre_001.txt and electrodeposited_ni.txt "
                 "(fibre fraction w = "
              << w << ") to " << directory << std::endl;
  }



  // @sect3{Output}
  //
  // Matrices are written as plain CSV, six rows of six values in GPa,
  // Voigt order 11, 22, 33, 23, 13, 12 with engineering shear strains (the
  // paper's eq. 4.3).
  void
  write_matrix(const std::string &filename, const Matrix6 &C)
  {
    std::ofstream out(filename);
    AssertThrow(out, ExcMessage("Cannot write <" + filename + ">."));
    out << std::fixed << std::setprecision(4);
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = 0; b < 6; ++b)
        out << C[a][b] << (b < 5 ? "," : "\n");
  }



  std::string
  format_matrix(const Matrix6 &C, const std::string &indent)
  {
    std::ostringstream s;
    s << std::fixed << std::setprecision(2);
    for (unsigned int a = 0; a < 6; ++a)
      {
        s << indent;
        for (unsigned int b = 0; b < 6; ++b)
          s << std::setw(9) << C[a][b];
        s << '\n';
      }
    return s.str();
  }



  // The largest difference between the stiffness from the reactions and
  // from the volume average (both over the nominal strain), over the
  // entries the reactions measure in the first n_columns tests, relative to
  // the norm of C.
  double
  reaction_difference(const Matrix6                            &C,
                      const Matrix6                            &C_reaction,
                      const std::array<std::array<bool, 6>, 6> &mask,
                      const unsigned int                        n_columns)
  {
    double norm = 0, max_diff = 0;
    for (unsigned int a = 0; a < 6; ++a)
      for (unsigned int b = 0; b < 6; ++b)
        {
          norm += C[a][b] * C[a][b];
          if (mask[a][b] && b < n_columns)
            max_diff = std::max(max_diff, std::abs(C[a][b] - C_reaction[a][b]));
        }
    return max_diff / std::sqrt(norm);
  }



  // @sect3{The PolycrystalStudy class}
  //
  // One object per run of the program, one method per stage, like step-44's
  // Solid: read the parameters, the crystal constants and the ODF (the
  // constructor), run the first realization with every requested kind of
  // boundary condition and write its results, then run the other
  // realizations (with the first kind only) and write their statistics.
  //
  // A realization is one sample: its Voronoi grains, the orientation of
  // every grain and, for each requested kind of boundary condition, the
  // 6x6 stiffness from the six virtual tests. All ranks compute the grains
  // and the texture redundantly from the same seeds, so all agree on them
  // without communication.
  class PolycrystalStudy
  {
  public:
    explicit PolycrystalStudy(const std::string &parameter_file);

    void
    run();

  private:
    struct SampleResult
    {
      unsigned int                                       grain_seed;
      unsigned int                                       texture_seed;
      std::vector<double>                                grain_areas;
      TextureSampler::Result                             texture;
      std::unique_ptr<StiffnessBounds>                   bounds;
      std::vector<std::string>                           bc_names;
      std::vector<Matrix6>                               C;
      std::vector<Matrix6>                               C_reaction;
      std::vector<Matrix6>                               C_mean_strain;
      std::vector<std::array<std::array<bool, 6>, 6>>    reaction_mask;
      std::vector<std::vector<VirtualTests::TestReport>> reports;
      std::vector<double>                                wall_time;
      unsigned int                                       n_empty_grains = 0;
      unsigned long                                      n_points       = 0;
      unsigned long                                      n_cells        = 0;
    };

    // The in-plane moduli of the first realization that the summary and
    // the printed results both report.
    struct InPlaneModuli
    {
      StiffnessBounds::InPlane E, E_nominal, E_reactions;
      StiffnessBounds::InPlane voigt, reuss, hill, hill_odf;
      bool                     reactions;
    };

    // One row of realizations.csv: realization, E_x, E_y, E_in_plane,
    // E_hill, misfit in percent.
    using Row = std::array<double, 6>;

    Parameters
    parse_parameters(const std::string &parameter_file);
    CubicElastic<3>
    make_crystal();
    SampleResult
    run_sample(const unsigned int              realization,
               const std::vector<std::string> &bcs);
    InPlaneModuli
    in_plane_moduli(const SampleResult &first) const;
    void
    summarize_first_realization(const SampleResult  &first,
                                const InPlaneModuli &moduli);
    void
    write_first_realization(const SampleResult  &first,
                            const InPlaneModuli &moduli) const;
    void
    print_first_realization(const SampleResult  &first,
                            const InPlaneModuli &moduli);
    std::vector<Row>
    run_realizations(const SampleResult &first);
    void
    write_statistics(const std::vector<Row> &rows, Timer &total_timer);

    ParameterHandler              prm;
    NewtonParameters              solver;
    const Parameters              par;
    const CubicElastic<3>         crystal;
    const bool                    root;
    ConditionalOStream            pcout;
    const OrientationDistribution odf;

    // summary.txt, filled by the stages of run() and written at the end.
    std::ostringstream summary;
  };



  // @sect4{PolycrystalStudy::PolycrystalStudy}
  //
  // The members are made in the order of their declaration: the
  // ParameterHandler and the solver settings first, then the program's
  // parameters, which parse_parameters() reads into both, then the crystal
  // model from "Material/cubic elastic" and the ODF from its file. A bad
  // entry or file thus stops the program before anything is computed.
  PolycrystalStudy::PolycrystalStudy(const std::string &parameter_file)
    : par(parse_parameters(parameter_file))
    , crystal(make_crystal())
    , root(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    , pcout(std::cout, root)
    , odf(par.odf_file)
  {
    if (root)
      std::filesystem::create_directories(par.output_directory);
    summary << std::setprecision(6);
  }



  // @sect4{PolycrystalStudy::parse_parameters}
  //
  // Our subsection "Polycrystal", the library's "Material" and "Nonlinear
  // solver" in one ParameterHandler. The ODF file is relative to the
  // directory of the parameter file.
  Parameters
  PolycrystalStudy::parse_parameters(const std::string &parameter_file)
  {
    Parameters::declare_parameters(prm);
    ConstitutiveModelFactory<3>::declare_parameters(prm);
    NewtonParameters::declare_parameters(prm);
    prm.parse_input(parameter_file);

    Parameters parameters;
    parameters.parse_parameters(prm);
    if (!parameters.odf_file.empty() &&
        std::filesystem::path(parameters.odf_file).is_relative())
      parameters.odf_file =
        (std::filesystem::path(parameter_file).parent_path() /
         parameters.odf_file)
          .string();
    solver.parse_parameters(prm);
    return parameters;
  }



  // @sect4{PolycrystalStudy::make_crystal}
  //
  // The crystal model of "Material/cubic elastic" (its constructor checks
  // the constants); every test copies it and gives the copy the grains'
  // orientations.
  CubicElastic<3>
  PolycrystalStudy::make_crystal()
  {
    prm.enter_subsection("Material");
    AssertThrow(prm.get("Model") == "cubic elastic",
                ExcMessage("The polycrystal needs the cubic crystal model: "
                           "set Material/Model = cubic elastic."));
    prm.enter_subsection("cubic elastic");
    CubicElastic<3> model(prm);
    prm.leave_subsection();
    prm.leave_subsection();
    return model;
  }



  // @sect4{PolycrystalStudy::run_sample}
  //
  // One sample: grains, texture and the virtual tests for each kind of
  // boundary condition in @p bcs.
  PolycrystalStudy::SampleResult
  PolycrystalStudy::run_sample(const unsigned int              realization,
                               const std::vector<std::string> &bcs)
  {
    SampleResult result;
    result.grain_seed   = par.grain_seed + realization;
    result.texture_seed = par.texture_seed + realization;

    // The grains: planar Voronoi cells in the film plane (x, y), columns
    // through z. Their areas are counted on the in-plane lattice of the
    // material points, so that the grain volumes are exactly those the
    // points represent.
    const double          L = par.side_length;
    const ColumnarVoronoi grains(par.n_grains,
                                 {{0., 0.}},
                                 {{L, L}},
                                 result.grain_seed,
                                 par.periodic_grains);
    const unsigned int    n_lattice =
      par.cells_in_plane * par.points_per_direction;
    result.grain_areas = grains.areas(n_lattice, n_lattice);
    // A Voronoi cell smaller than the point spacing may hold no point at
    // all; such grains have zero volume and simply do not exist in the
    // sample.
    result.n_empty_grains =
      std::count(result.grain_areas.begin(), result.grain_areas.end(), 0.);

    // The texture: N_u elementary volumes sampled from the ODF, grouped
    // into grains largest first (Melchior and Delannay).
    const TextureSampler sampler(par.n_elementary_volumes,
                                 par.threshold_degrees * M_PI / 180.);
    result.texture =
      sampler.assign(odf, result.grain_areas, result.texture_seed);
    result.bounds =
      std::make_unique<StiffnessBounds>(crystal.crystal_stiffness(),
                                        result.texture.orientations,
                                        result.grain_areas);

    // The virtual tests. Each test builds its own problem and model; the
    // model asks for the orientation of each new point, which is that of
    // its grain.
    const auto &orientations = result.texture.orientations;
    for (const std::string &bc : bcs)
      {
        VirtualTests::Parameters vt;
        vt.boundary_type        = VirtualTests::parse_boundary_type(bc);
        vt.side_length          = L;
        vt.subdivisions         = {{par.cells_in_plane,
                                    par.cells_in_plane,
                                    par.cells_through_thickness}};
        vt.points_per_direction = par.points_per_direction;
        vt.strain               = par.strain;
        vt.n_load_steps         = par.n_load_steps;
        vt.test_groups          = par.test_groups;
        vt.solver               = solver;
        vt.output_directory     = par.output_directory + "/tests_" + bc + "_r" +
                              std::to_string(realization);
        VirtualTests tests(vt, MPI_COMM_WORLD);
        Timer        timer(MPI_COMM_WORLD, true);
        tests.run(
          [&]() {
            auto model = std::make_unique<CubicElastic<3>>(crystal);
            model->set_orientation(
              [&](const Point<3> &x) { return orientations[grains.grain(x)]; });
            return std::unique_ptr<ConstitutiveModel<3>>(std::move(model));
          },
          [&](const Point<3> &x) { return grains.grain(x); });
        timer.stop();
        static const char *const names[6] = {
          "11", "22", "33", "23", "13", "12"};
        for (unsigned int k = 0; k < 6; ++k)
          {
            const auto &r = tests.reports()[k];
            pcout << "    " << bc << " test " << names[k] << ": Newton "
                  << r.newton_iterations << ", GMRES " << r.gmres_iterations
                  << ", " << std::fixed << std::setprecision(1) << r.wall_time
                  << " s" << std::defaultfloat << std::endl;
          }
        result.bc_names.push_back(bc);
        result.C.push_back(tests.stiffness());
        result.C_reaction.push_back(tests.stiffness_from_reactions());
        result.C_mean_strain.push_back(tests.stiffness_from_mean_strains());
        result.reaction_mask.push_back(tests.reaction_mask());
        result.reports.push_back(tests.reports());
        result.wall_time.push_back(timer.wall_time());
        result.n_points = tests.n_points();
        result.n_cells  = tests.n_cells();
      }
    return result;
  }



  // @sect4{PolycrystalStudy::run}
  void
  PolycrystalStudy::run()
  {
    pcout << "Polycrystal: " << par.n_grains << " columnar grains, grid "
          << par.cells_in_plane << "x" << par.cells_in_plane << "x"
          << par.cells_through_thickness << ", " << par.points_per_direction
          << "^3 points per cell, ODF " << par.odf_file << ", "
          << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << " rank(s)"
          << std::endl;

    Timer total_timer(MPI_COMM_WORLD, true);

    // The first realization, with every kind of boundary condition.
    pcout << "  realization 0 (grain seed " << par.grain_seed
          << ", texture seed " << par.texture_seed << ")" << std::endl;
    const SampleResult  first  = run_sample(0, par.boundary_conditions);
    const InPlaneModuli moduli = in_plane_moduli(first);
    summarize_first_realization(first, moduli);
    write_first_realization(first, moduli);
    print_first_realization(first, moduli);

    const std::vector<Row> rows = run_realizations(first);
    write_statistics(rows, total_timer);
  }



  // @sect4{PolycrystalStudy::in_plane_moduli}
  //
  // The effective stiffness relates the mean stress to the mean strain
  // (paper eq. 4.3). For affine conditions the mean strain is the nominal
  // one; under the paper's mixed conditions the sample may rotate in the
  // shear tests (the confined faces slide), so we divide by the mean
  // strain of the points, not by the nominal strain. Both other variants
  // are written too. Periodic conditions have no loaded faces, hence no
  // reaction stress.
  PolycrystalStudy::InPlaneModuli
  PolycrystalStudy::in_plane_moduli(const SampleResult &first) const
  {
    InPlaneModuli m;
    m.voigt    = StiffnessBounds::in_plane(first.bounds->voigt());
    m.reuss    = StiffnessBounds::in_plane(first.bounds->reuss());
    m.hill     = StiffnessBounds::in_plane(first.bounds->hill());
    m.hill_odf = StiffnessBounds::in_plane(
      odf_bounds(odf, crystal.crystal_stiffness()).hill());
    m.E           = StiffnessBounds::in_plane(first.C_mean_strain[0]);
    m.E_nominal   = StiffnessBounds::in_plane(first.C[0]);
    m.reactions   = first.bc_names[0] != "periodic";
    m.E_reactions = m.reactions ?
                      StiffnessBounds::in_plane(first.C_reaction[0]) :
                      StiffnessBounds::InPlane{};
    return m;
  }



  // @sect4{PolycrystalStudy::summarize_first_realization}
  //
  // The results of the first realization as "name = value" lines of
  // summary.txt.
  void
  PolycrystalStudy::summarize_first_realization(const SampleResult  &first,
                                                const InPlaneModuli &m)
  {
    const Matrix6 &C = first.C_mean_strain[0];
    summary << "# polycrystal: effective stiffness of a columnar Ni "
               "polycrystal (paper Section 4)\n"
            << "# moduli in GPa; C in effective_stiffness.csv (Voigt order "
               "11, 22, 33, 23, 13, 12)\n"
            << "boundary_conditions = " << first.bc_names[0] << '\n'
            << "n_grains = " << par.n_grains << '\n'
            << "n_grains_without_points = " << first.n_empty_grains << '\n'
            << "n_points = " << first.n_points << '\n'
            << "n_cells = " << first.n_cells << '\n'
            << "grid = " << par.cells_in_plane << "x" << par.cells_in_plane
            << "x" << par.cells_through_thickness << '\n'
            << "points_per_cell_per_direction = " << par.points_per_direction
            << '\n'
            << "points_per_grain = "
            << static_cast<double>(first.n_points) / par.n_grains << '\n'
            << "odf_file = " << par.odf_file << '\n'
            << "grain_seed = " << first.grain_seed << '\n'
            << "texture_seed = " << first.texture_seed << '\n'
            << "E_in_plane_GPa = " << m.E.E_in_plane << '\n'
            << "E_x_GPa = " << m.E.E_x << '\n'
            << "E_y_GPa = " << m.E.E_y << '\n'
            << "E_in_plane_nominal_strain_GPa = " << m.E_nominal.E_in_plane
            << '\n'
            << "E_voigt_GPa = " << m.voigt.E_in_plane << '\n'
            << "E_reuss_GPa = " << m.reuss.E_in_plane << '\n'
            << "E_hill_GPa = " << m.hill.E_in_plane << '\n'
            << "E_voigt_x_GPa = " << m.voigt.E_x << '\n'
            << "E_voigt_y_GPa = " << m.voigt.E_y << '\n'
            << "E_reuss_x_GPa = " << m.reuss.E_x << '\n'
            << "E_reuss_y_GPa = " << m.reuss.E_y << '\n'
            << "E_hill_odf_GPa = " << m.hill_odf.E_in_plane << '\n'
            << "misfit_percent = " << 100. * first.texture.misfit_sampled
            << '\n'
            << "misfit_method = histogram of the N_u sampled orientations on "
               "the 5 degree cells (piecewise constant), paper formula\n"
            << "misfit_grains_percent = " << 100. * first.texture.misfit_grains
            << '\n'
            << "elementary_volumes = " << par.n_elementary_volumes << '\n'
            << "disorientation_threshold_degrees = " << par.threshold_degrees
            << '\n'
            << "fallback_grains = " << first.texture.n_fallback << '\n'
            << "fallback_max_disorientation_degrees = "
            << first.texture.max_fallback_angle * 180. / M_PI << '\n'
            << "C_asymmetry_relative = " << VirtualTests::relative_asymmetry(C)
            << '\n';
    if (m.reactions)
      summary << "E_in_plane_from_reactions_GPa = " << m.E_reactions.E_in_plane
              << '\n'
              << "reaction_vs_volume_difference_normal_tests_relative = "
              << reaction_difference(first.C[0],
                                     first.C_reaction[0],
                                     first.reaction_mask[0],
                                     3)
              << '\n'
              << "reaction_vs_volume_difference_all_tests_relative = "
              << reaction_difference(first.C[0],
                                     first.C_reaction[0],
                                     first.reaction_mask[0],
                                     6)
              << '\n';
    for (unsigned int b = 0; b < first.bc_names.size(); ++b)
      {
        const auto Eb     = StiffnessBounds::in_plane(first.C_mean_strain[b]);
        unsigned   newton = 0, gmres = 0;
        for (const auto &r : first.reports[b])
          {
            newton += r.newton_iterations;
            gmres += r.gmres_iterations;
          }
        summary << "E_in_plane_" << first.bc_names[b]
                << "_GPa = " << Eb.E_in_plane << '\n'
                << "E_x_" << first.bc_names[b] << "_GPa = " << Eb.E_x << '\n'
                << "E_y_" << first.bc_names[b] << "_GPa = " << Eb.E_y << '\n'
                << "wall_time_" << first.bc_names[b]
                << "_s = " << first.wall_time[b] << '\n'
                << "newton_iterations_" << first.bc_names[b] << " = " << newton
                << '\n'
                << "gmres_iterations_" << first.bc_names[b] << " = " << gmres
                << '\n';
      }
  }



  // @sect4{PolycrystalStudy::write_first_realization}
  //
  // On rank 0: the stiffness matrices, the grains with their orientations,
  // and a grain map of the in-plane point lattice.
  void
  PolycrystalStudy::write_first_realization(const SampleResult  &first,
                                            const InPlaneModuli &m) const
  {
    if (!root)
      return;
    const std::string dir = par.output_directory + "/";
    const Matrix6    &C   = first.C_mean_strain[0];
    write_matrix(dir + "effective_stiffness.csv", C);
    write_matrix(dir + "effective_stiffness_symmetric.csv",
                 VirtualTests::symmetric_part(C));
    if (m.reactions)
      write_matrix(dir + "effective_stiffness_reactions.csv",
                   first.C_reaction[0]);
    write_matrix(dir + "effective_stiffness_nominal_strain.csv", first.C[0]);
    write_matrix(dir + "voigt_stiffness.csv", first.bounds->voigt());
    write_matrix(dir + "reuss_stiffness.csv", first.bounds->reuss());
    for (unsigned int b = 1; b < first.bc_names.size(); ++b)
      write_matrix(dir + "effective_stiffness_" + first.bc_names[b] + ".csv",
                   first.C_mean_strain[b]);

    // The grains and their orientations.
    std::ofstream grains_out(dir + "grains.csv");
    grains_out << "grain,area,elementary_volumes,phi1_deg,Phi_deg,"
                  "phi2_deg\n"
               << std::setprecision(8);
    for (unsigned int g = 0; g < par.n_grains; ++g)
      {
        const auto a = Rotation::to_bunge(first.texture.orientations[g]);
        grains_out << g << ',' << first.grain_areas[g] << ','
                   << first.texture.n_elementary[g] << ',' << a[0] * 180. / M_PI
                   << ',' << a[1] * 180. / M_PI << ',' << a[2] * 180. / M_PI
                   << '\n';
      }

    // A grain map of the in-plane point lattice (x, y, grain) for
    // gnuplot, like the paper's Fig. 5.
    const ColumnarVoronoi grains(par.n_grains,
                                 {{0., 0.}},
                                 {{par.side_length, par.side_length}},
                                 first.grain_seed,
                                 par.periodic_grains);
    std::ofstream         map(dir + "grain_map.dat");
    const unsigned int    n = par.cells_in_plane * par.points_per_direction;
    const double          h = par.side_length / n;
    for (unsigned int j = 0; j < n; ++j)
      {
        for (unsigned int i = 0; i < n; ++i)
          map << (i + 0.5) * h << ' ' << (j + 0.5) * h << ' '
              << grains.grain((i + 0.5) * h, (j + 0.5) * h) << '\n';
        map << '\n';
      }
  }



  // @sect4{PolycrystalStudy::print_first_realization}
  void
  PolycrystalStudy::print_first_realization(const SampleResult  &first,
                                            const InPlaneModuli &m)
  {
    const Matrix6 &C = first.C_mean_strain[0];
    pcout << "\n  effective stiffness C (GPa, " << first.bc_names[0]
          << " boundary conditions, mean stress over mean strain of the "
             "points):\n"
          << format_matrix(C, "    ");
    if (m.reactions)
      pcout << "  paper's method: reaction forces over the nominal strain "
               "(entries no face measures are 0):\n"
            << format_matrix(first.C_reaction[0], "    ");
    pcout << "  volume-averaged point stress over the nominal strain:\n"
          << format_matrix(first.C[0], "    ") << std::setprecision(5)
          << "  E_x = " << m.E.E_x << ", E_y = " << m.E.E_y
          << ", E_in-plane = " << m.E.E_in_plane << " GPa (";
    if (m.reactions)
      pcout << "paper's method " << m.E_reactions.E_in_plane << ", ";
    pcout << "nominal strain " << m.E_nominal.E_in_plane << ")\n"
          << "  bounds of the assigned orientations: Reuss "
          << m.reuss.E_in_plane << ", Hill " << m.hill.E_in_plane << ", Voigt "
          << m.voigt.E_in_plane << " GPa (Hill of the ODF "
          << m.hill_odf.E_in_plane << ")\n"
          << "  misfit " << 100. * first.texture.misfit_sampled
          << " % (N_u sampled orientations), fallback grains "
          << first.texture.n_fallback << std::endl;
    for (unsigned int b = 1; b < first.bc_names.size(); ++b)
      pcout << "  " << first.bc_names[b]
            << " boundary conditions: E_in-plane = "
            << StiffnessBounds::in_plane(first.C_mean_strain[b]).E_in_plane
            << " GPa\n"
            << format_matrix(first.C_mean_strain[b], "    ");
  }



  // @sect4{PolycrystalStudy::run_realizations}
  //
  // Further samples differ in both seeds. Their in-plane moduli give the
  // distribution the paper names as its next step. The first row is that
  // of the first realization.
  std::vector<PolycrystalStudy::Row>
  PolycrystalStudy::run_realizations(const SampleResult &first)
  {
    std::vector<Row> rows;
    auto             record = [&](const SampleResult &s, const unsigned int r) {
      const auto e = StiffnessBounds::in_plane(s.C_mean_strain[0]);
      rows.push_back({{static_cast<double>(r),
                       e.E_x,
                       e.E_y,
                       e.E_in_plane,
                       StiffnessBounds::in_plane(s.bounds->hill()).E_in_plane,
                       100. * s.texture.misfit_sampled}});
    };
    record(first, 0);
    for (unsigned int r = 1; r < par.n_realizations; ++r)
      {
        pcout << "  realization " << r << std::endl;
        const SampleResult s = run_sample(r, {par.boundary_conditions[0]});
        record(s, r);
        pcout << "    E_in-plane = " << std::setprecision(6) << rows.back()[3]
              << " GPa" << std::endl;
      }
    return rows;
  }



  // @sect4{PolycrystalStudy::write_statistics}
  //
  // Mean and standard deviation of the in-plane modulus over the
  // realizations, the table realizations.csv and summary.txt.
  void
  PolycrystalStudy::write_statistics(const std::vector<Row> &rows,
                                     Timer                  &total_timer)
  {
    double mean = 0, var = 0;
    for (const auto &row : rows)
      mean += row[3] / rows.size();
    for (const auto &row : rows)
      var += (row[3] - mean) * (row[3] - mean);
    const double stddev =
      rows.size() > 1 ? std::sqrt(var / (rows.size() - 1)) : 0.;
    summary << "n_realizations = " << rows.size() << '\n'
            << "E_in_plane_mean_GPa = " << mean << '\n'
            << "E_in_plane_std_GPa = " << stddev << '\n';
    total_timer.stop();
    summary << "wall_time_total_s = " << total_timer.wall_time() << '\n'
            << "mpi_ranks = " << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
            << '\n';
    if (root)
      {
        std::ofstream out(par.output_directory + "/realizations.csv");
        out << "realization,E_x_GPa,E_y_GPa,E_in_plane_GPa,E_hill_GPa,"
               "misfit_percent\n"
            << std::setprecision(8);
        for (const auto &row : rows)
          for (unsigned int c = 0; c < 6; ++c)
            out << row[c] << (c < 5 ? "," : "\n");
        std::ofstream(par.output_directory + "/summary.txt") << summary.str();
      }
    pcout << std::setprecision(6) << "  realizations: " << rows.size()
          << ", E_in-plane mean " << mean << " GPa, standard deviation "
          << stddev << " GPa\n"
          << "  wall time " << total_timer.wall_time() << " s; results in "
          << par.output_directory << "/" << std::endl;
  }
} // namespace Polycrystal



// @sect3{The main function}
//
// As in the deal.II tutorials: MPI, the parameter file, and any exception
// turned into a message naming the cause and a non-zero exit code.
int
main(int argc, char *argv[])
{
  // The rank of this process, for the catch blocks below: by the time they
  // run, the MPI_InitFinalize object of the try block is gone, and MPI with
  // it.
  unsigned int rank = 0;
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
      if (argc > 1 && std::string(argv[1]) == "--make-odfs")
        {
          AssertThrow(argc > 2,
                      dealii::ExcMessage("--make-odfs needs a directory."));
          if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
            Polycrystal::make_odfs(argv[2]);
          return 0;
        }
      const std::string parameter_file =
        argc > 1 ?
          std::string(argv[1]) :
          (std::filesystem::path(argv[0]).parent_path() / "polycrystal.prm")
            .string();
      // A missing file, a directory or an unreadable file: one line that
      // names it.
      qsmpm::Utils::check_parameter_file(parameter_file);
      Polycrystal::PolycrystalStudy study(parameter_file);
      study.run();
    }
  catch (std::exception &exc)
    {
      // The errors of qsmpm are collective: every rank reads the same
      // parameter file and checks the same values, and a load step that
      // fails, fails on every rank with the same message (the library
      // broadcasts it). So one rank, rank 0, prints it, as one line
      // written at once: lines written piece by piece by several ranks
      // interleave ("polycrystal stopped: polycrystal stopped: ...").
      if (rank == 0)
        std::cerr << "polycrystal stopped: " +
                       qsmpm::Utils::error_message(exc) + "\n"
                  << std::flush;
      return 1;
    }
  catch (...)
    {
      if (rank == 0)
        std::cerr << "polycrystal stopped: unknown exception" << std::endl;
      return 1;
    }
  return 0;
}
