/* ---------------------------------------------------------------------
 *
 * qsmpm example: block_compression
 *
 * An elastic block squeezed between two frictionless plates with the
 * quasi-static material-point method of Sanchez, Schreyer, Sulsky and
 * Wallstedt, "Solving Quasi-Static Equations with the Material-Point
 * Method".
 *
 * Usage:
 *   ./block_compression [file.prm]
 *   mpirun -np 2 ./block_compression [file.prm]
 *
 * Without an argument, block_compression.prm next to the executable is read.
 *
 * ---------------------------------------------------------------------
 */

// @sect3{Include files}
//
// The whole library is reached through QuasiStaticProblem, which owns the
// background grid, the material points, the boundary conditions and the
// load-step loop. We only add the one constitutive model we use and a few
// deal.II utilities.
#include <array>
#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>
#include <string>

namespace BlockCompression
{
  using namespace dealii;
  using namespace qsmpm;

  // @sect3{The problem}
  //
  // A rectangular block (a brick in 3D) of width $W$, height $H$ (and depth
  // $D$) rests on a rigid, frictionless floor and is pressed down by a
  // rigid, frictionless top plate. The plate moves down by $\delta t$, where
  // $t$ is the load factor that the library raises from 0 to its final value
  // in a number of load steps. The block is the half (in 2D) or quarter (in
  // 3D) of a block of width $2W$ (and depth $2D$) that is symmetric about
  // the planes $x=0$ (and $z=0$). Symmetry planes act like frictionless
  // supports, so on every face of the box at its lower corner only the
  // normal displacement is fixed.
  //
  // The material-point method needs a background grid, and the interesting
  // part is that the body does not have to fill it: we make the grid wider
  // (and, in 3D, deeper) than the block, so that a band of cells beside the
  // block holds no material points. The grid nodes there are "inactive":
  // they have no equation, and the library fixes their increments to zero.
  // Which nodes are inactive is decided anew in every load step: a block
  // squeezed further than in the shipped parameter file expands sideways
  // until its points enter cells that were empty, whose nodes then become
  // active.
  //
  // The grid's bottom and top faces are the two plates (boundary ids 2 and
  // 3; see BackgroundGrid). The grid never deforms: at the start of each
  // load step it is, in effect, reset, and its top nodes, now a little
  // above the top of the body, are again moved down by the plate's
  // increment. They still have material points in their support, so they
  // carry the plate's load -- as long as the top row of points has not left
  // the top row of cells, i.e. for compressions below roughly 3/4 of a cell
  // with 2 points per cell direction. Larger compressions need finer cells.
  //
  // @sect3{The analytical solution}
  //
  // With frictionless plates and free sides the small-strain solution is a
  // uniform state of uniaxial stress: $\sigma_{yy}$ is the only non-zero
  // stress component (besides $\sigma_{zz} = \nu\sigma_{yy}$ in plane
  // strain) and
  // $\varepsilon_{yy} = -\delta/H$. In plane strain ($\varepsilon_{zz}=0$),
  // $\sigma_{xx}=0$ gives $\varepsilon_{xx} = -\frac{\nu}{1-\nu}
  // \varepsilon_{yy}$ and then
  // @f[
  //   \sigma_{yy} = \frac{E}{1-\nu^2}\,\varepsilon_{yy} = E'\varepsilon_{yy}.
  // @f]
  // In plane stress and in 3D, $E' = E$. The force on the top plate is the
  // stress times the cross-section $A$ of the block ($A = W$ per unit
  // thickness in 2D, $A = WD$ in 3D):
  // @f[
  //   F = E' \, \frac{\delta}{H} \, A .
  // @f]
  //
  // This holds for small strains. The material-point method as implemented
  // here updates the point volumes with $J = \det F$ (paper eqs. 2.23-2.24)
  // while the stress follows the sum of the strain increments. The internal
  // force of a point is proportional to its current volume, so the computed
  // force is $F\,J$ with $J - 1 \approx \mathrm{tr}\,\varepsilon$, that is
  // $-\frac{1-2\nu}{1-\nu}\frac{\delta}{H}$ in plane strain,
  // $-(1-\nu)\frac{\delta}{H}$ in plane stress and
  // $-(1-2\nu)\frac{\delta}{H}$ in 3D: a relative deviation of the order
  // of the strain, about -0.6% at 1% strain and $\nu = 0.3$ in plane
  // strain. With "Update volumes = false" (a geometrically linear
  // model) the deviation vanishes up to the solver tolerances, as long as
  // no point crosses a cell boundary. The program prints both comparisons
  // and checks the first against the tolerance given in the parameter file.
  //
  //
  // @sect3{The example's own parameters}
  //
  // Everything that is not specific to this example -- the material, the
  // material points, the load stepping, the nonlinear solver and the output
  // -- is read from the library's own .prm subsections (declared by
  // QuasiStaticProblem<dim>::Parameters::declare_parameters). The size of
  // the block and of the grid around it, and the plate displacement, come
  // from a subsection "Block compression" that we declare here. All its
  // entries are scalars, so switching between 2D and 3D only needs
  // "set Dimension = 3".
  //
  // The struct follows the pattern of the library's own parameter structs
  // (ParameterStruct, as in deal.II's step-68): each member's initializer
  // is its default, and add_parameters() declares the entry bound to it
  // with ParameterHandler::add_parameter(), so that name, default and
  // documentation are written once. ParameterStruct adds
  // declare_parameters(), which declares the entries with their defaults,
  // and parse_parameters(), which reads the values of the parsed file into
  // an object.
  struct Parameters : ParameterStruct<Parameters>
  {
    double       width              = 1.0;
    double       height             = 1.0;
    double       depth              = 1.0;
    unsigned int cells_over_height  = 8;
    unsigned int empty_cells        = 4;
    double       plate_displacement = 0.01;
    double       tolerance          = 0.01;

    void
    add_parameters(ParameterHandler &prm);
  };



  void
  Parameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Block compression");
    {
      prm.add_parameter("Block width",
                        width,
                        "W: extent of the block in x.",
                        Patterns::Double(0.));
      prm.add_parameter("Block height",
                        height,
                        "H: extent of the block in y, the distance between "
                        "the plates. The grid has the same height.",
                        Patterns::Double(0.));
      prm.add_parameter("Block depth",
                        depth,
                        "D: extent of the block in z (3D only).",
                        Patterns::Double(0.));
      prm.add_parameter("Cells over the height",
                        cells_over_height,
                        "Number of (square) grid cells over H.",
                        Patterns::Integer(1));
      prm.add_parameter("Empty cells beside the block",
                        empty_cells,
                        "The grid extends this many cells beyond the block "
                        "in x (and z); these cells start without points.",
                        Patterns::Integer(0));
      prm.add_parameter("Plate displacement",
                        plate_displacement,
                        "delta: the top plate moves down by delta * t, t = "
                        "load factor.",
                        Patterns::Double());
      prm.add_parameter("Tolerance",
                        tolerance,
                        "Largest accepted relative difference between the "
                        "computed plate force and the small-strain value; "
                        "the program fails if it is exceeded.",
                        Patterns::Double(0.));
    }
    prm.leave_subsection();
  }



  // @sect3{The top plate}
  //
  // Displacement conditions are deal.II Functions with dim components whose
  // "time" is the load factor $t$. The library evaluates them at the grid
  // nodes at the old and new load factors and prescribes the difference as
  // the increment of the step. Only the components selected when the
  // condition is added are used, here the y component.
  template <int dim>
  class PlateDisplacement : public Function<dim>
  {
  public:
    explicit PlateDisplacement(const double delta)
      : Function<dim>(dim)
      , delta(delta)
    {
    }

    void
    vector_value(const Point<dim> &, Vector<double> &values) const override
    {
      values    = 0.;
      values[1] = -delta * this->get_time();
    }

  private:
    const double delta;
  };



  // @sect3{The CompressedBlock class}
  //
  // This is the part that shows how to use the library from C++. The
  // sequence is always the same: make the grid, choose the constitutive
  // model, fill a region with material points, add boundary conditions, and
  // run(). As in deal.II's step-44 (the class Solid), each stage is a
  // method of one class; run() calls them in order and returns whether the
  // computed plate force agrees with the analytical value.
  template <int dim>
  class CompressedBlock
  {
  public:
    explicit CompressedBlock(const std::string &parameter_file);

    bool
    run();

  private:
    Parameters
    parse_parameters(const std::string &parameter_file);
    void
    make_grid();
    void
    setup_material();
    void
    setup_points();
    void
    setup_boundary_conditions();
    bool
    compare_with_analytical_solution(const double wall_time);

    ParameterHandler        prm;
    const Parameters        block;
    QuasiStaticProblem<dim> problem;

    // The upper corner of the block (its lower corner is the origin), the
    // elastic constants, the index of the plate among the displacement
    // conditions and the initial volume of the points.
    Point<dim>   block_corner;
    double       E = 0., nu = 0.;
    bool         plane_stress   = false;
    unsigned int plate          = 0;
    double       initial_volume = 0.;
  };



  // @sect4{CompressedBlock::CompressedBlock}
  //
  // The parameters are read by parse_parameters() in the initializer list
  // (prm is declared, hence made, before block); then the library reads
  // its own subsections: solver, load stepping, output and material-point
  // settings.
  template <int dim>
  CompressedBlock<dim>::CompressedBlock(const std::string &parameter_file)
    : block(parse_parameters(parameter_file))
    , problem(MPI_COMM_WORLD)
  {
    problem.return_large_blocks_to_system();
    problem.parameters().parse_parameters(prm);
  }



  // @sect4{CompressedBlock::parse_parameters}
  //
  // "Dimension" was read by main() already; it is declared so that the
  // file may hold it.
  template <int dim>
  Parameters
  CompressedBlock<dim>::parse_parameters(const std::string &parameter_file)
  {
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
    QuasiStaticProblem<dim>::Parameters::declare_parameters(prm);
    Parameters::declare_parameters(prm);
    prm.parse_input(parameter_file);

    Parameters parameters;
    parameters.parse_parameters(prm);
    return parameters;
  }



  // @sect4{CompressedBlock::make_grid}
  //
  // The grid: square cells of size h, as high as the block, and
  // `empty_cells` cells wider (and deeper) than it.
  template <int dim>
  void
  CompressedBlock<dim>::make_grid()
  {
    const double                  h = block.height / block.cells_over_height;
    Point<dim>                    grid_corner;
    std::array<unsigned int, dim> subdivisions;
    for (unsigned int d = 0; d < dim; ++d)
      {
        block_corner[d] = (d == 0 ? block.width :
                           d == 1 ? block.height :
                                    block.depth);
        subdivisions[d] =
          (d == 1 ?
             block.cells_over_height :
             static_cast<unsigned int>(std::ceil(block_corner[d] / h - 1e-9)) +
               block.empty_cells);
        grid_corner[d] = subdivisions[d] * h;
      }
    problem.grid().make_box(Point<dim>(), grid_corner, subdivisions);
  }



  // @sect4{CompressedBlock::setup_material}
  //
  // The material: linear elasticity, with E and nu from the subsection
  // "Material/linear elastic" of the parameter file. Any other model
  // could be set here; the comparison below needs this one.
  template <int dim>
  void
  CompressedBlock<dim>::setup_material()
  {
    prm.enter_subsection("Material");
    AssertThrow(prm.get("Model") == "linear elastic",
                ExcMessage("This example compares with linear elasticity: "
                           "set Material/Model = linear elastic."));
    prm.enter_subsection("linear elastic");
    E            = prm.get_double("Young's modulus");
    nu           = prm.get_double("Poisson's ratio");
    plane_stress = prm.get_bool("Plane stress");
    prm.leave_subsection();
    prm.leave_subsection();
    problem.set_model(
      std::make_unique<LinearElastic<dim>>(E, nu, plane_stress));
  }



  // @sect4{CompressedBlock::setup_points}
  //
  // The body: material points only inside the block. The predicate is
  // evaluated at every candidate point position of every cell; the grid
  // nodes that end up without points in their support are inactive.
  template <int dim>
  void
  CompressedBlock<dim>::setup_points()
  {
    const auto &mp = problem.parameters().material_points;
    problem.points().fill(
      [this](const Point<dim> &x) {
        for (unsigned int d = 0; d < dim; ++d)
          if (x[d] > block_corner[d])
            return false;
        return true;
      },
      mp.points_per_direction,
      mp.placement);
  }



  // @sect4{CompressedBlock::setup_boundary_conditions}
  //
  // Supports: on the faces at the lower corner of the box (ids 0, 2 and,
  // in 3D, 4) only the normal displacement is fixed, i.e. the block may
  // slide along them; the top plate (id 3) prescribes u_y. We remember
  // which condition is the plate to read its reaction later.
  template <int dim>
  void
  CompressedBlock<dim>::setup_boundary_conditions()
  {
    auto      &bcs  = problem.boundary_conditions();
    const auto zero = std::make_shared<Functions::ZeroFunction<dim>>(dim);
    for (unsigned int d = 0; d < dim; ++d)
      bcs.add_dirichlet_boundary(2 * d, {}, zero, /*normal_only=*/true);
    std::array<bool, dim> y_only{};
    y_only[1] = true;
    plate     = bcs.dirichlet_conditions().size();
    bcs.add_dirichlet_boundary(3,
                               y_only,
                               std::make_shared<PlateDisplacement<dim>>(
                                 block.plate_displacement));
  }



  // @sect4{CompressedBlock::run}
  //
  // The initial volume of the points gives the cross-section A = V/H of
  // the block as the points represent it, even if W is not a multiple of
  // the point spacing.
  template <int dim>
  bool
  CompressedBlock<dim>::run()
  {
    make_grid();
    setup_material();
    setup_points();
    setup_boundary_conditions();
    initial_volume = problem.points().total_volume();

    Timer timer;
    problem.run();
    timer.stop();

    return compare_with_analytical_solution(timer.wall_time());
  }



  // @sect4{CompressedBlock::compare_with_analytical_solution}
  //
  // reactions() holds, per displacement condition, the force that the
  // support exerts on the body at the end of the last step. The plate
  // pushes down, so its y component is negative; the floor (condition 1,
  // boundary id 2) must carry the same force upwards.
  template <int dim>
  bool
  CompressedBlock<dim>::compare_with_analytical_solution(const double wall_time)
  {
    const double delta = block.plate_displacement *
                         problem.parameters().load_stepping.final_load_factor;
    const double E_prime = (dim == 2 && !plane_stress) ? E / (1. - nu * nu) : E;
    const double area    = initial_volume / block.height;
    const double F_exact = E_prime * delta / block.height * area;
    const double F_plate = -problem.reactions()[plate][1];
    const double F_floor = problem.reactions()[1][1];
    const double J       = problem.points().total_volume() / initial_volume;
    const double error   = (F_plate - F_exact) / F_exact;
    const double error_J = (F_plate - F_exact * J) / (F_exact * J);
    unsigned int n_newton = 0, n_gmres = 0;
    for (const auto &step : problem.step_reports())
      {
        n_newton += step.newton.newton_iterations;
        n_gmres += step.newton.linear_iterations;
      }

    auto &out = problem.pcout();
    out << std::setprecision(6) << '\n'
        << "Block compression, " << dim << "D"
        << (dim == 2 ? (plane_stress ? " plane stress" : " plane strain") : "")
        << ", strain delta/H = " << delta / block.height << '\n'
        << "  plate force (computed)           F_h = " << F_plate << '\n'
        << "  floor force (computed)               = " << F_floor << '\n'
        << "  small-strain value E' delta/H A    F = " << F_exact << '\n'
        << "  relative difference        (F_h-F)/F = " << error << '\n'
        << "  volume change of the body      J - 1 = " << J - 1. << '\n'
        << "  difference to F J    (F_h-F J)/(F J) = " << error_J << '\n'
        << "  load steps " << problem.step_reports().size()
        << ", Newton iterations " << n_newton << ", GMRES iterations "
        << n_gmres << ", wall time " << std::setprecision(3) << wall_time
        << " s on " << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
        << " rank(s)\n";

    // The result is the same on every rank, so all ranks agree on the exit
    // code.
    const bool passed = std::abs(error) <= block.tolerance;
    out << (passed ? "  OK: |(F_h-F)/F| <= " : "  FAILED: |(F_h-F)/F| > ")
        << block.tolerance << " (Block compression/Tolerance)" << std::endl;
    return passed;
  }
} // namespace BlockCompression



// @sect3{The main function}
//
// As in the deal.II tutorials: initialize MPI (and nothing else: one thread
// per process), pick the parameter file, dispatch on the dimension, and turn
// any exception into a message and a non-zero exit code. A plate force
// outside the tolerance also gives a non-zero exit code, so the program can
// serve as a quick check of an installation.
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

      // The parameter file: the first argument, or the one next to the
      // executable (CMake copies it into the build directory).
      const std::string parameter_file =
        argc > 1 ? std::string(argv[1]) :
                   (std::filesystem::path(argv[0]).parent_path() /
                    "block_compression.prm")
                     .string();
      AssertThrow(std::filesystem::exists(parameter_file),
                  dealii::ExcMessage("Cannot find the parameter file <" +
                                     parameter_file + ">."));

      // The dimension is a template argument, so it is read from the file
      // before anything else can be declared.
      const bool passed =
        qsmpm::Utils::read_dimension(parameter_file) == 2 ?
          BlockCompression::CompressedBlock<2>(parameter_file).run() :
          BlockCompression::CompressedBlock<3>(parameter_file).run();
      if (!passed)
        return 1;
    }
  catch (std::exception &exc)
    {
      // The errors of qsmpm are collective: every rank reads the same
      // parameter file and checks the same values, and a load step that
      // fails, fails on every rank with the same message (the library
      // broadcasts it). So one rank, rank 0, prints it, as one line
      // written at once: lines written piece by piece by several ranks
      // interleave ("block_compression stopped: block_compression stopped:
      // ...").
      if (rank == 0)
        std::cerr << "block_compression stopped: " +
                       qsmpm::Utils::error_message(exc) + "\n"
                  << std::flush;
      return 1;
    }
  catch (...)
    {
      if (rank == 0)
        std::cerr << "block_compression stopped: unknown exception"
                  << std::endl;
      return 1;
    }
  return 0;
}
