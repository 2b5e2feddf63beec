/* ---------------------------------------------------------------------
 *
 * qsmpm example: column
 *
 * An elastic column compacting under its own weight: the standard
 * verification problem of implicit quasi-static MPM at large deformation
 * (Coombs & Augarde 2020, AMPLE; reproduced by GeoWarp and AMPSSIE). The
 * program runs a grid-convergence study for linear and GIMP shape
 * functions at finite strain and writes convergence.csv.
 *
 * Usage:
 *   ./column [column.prm]
 *   mpirun -np 2 ./column column.prm
 *
 * ---------------------------------------------------------------------
 */

// @sect3{Include files}
#include <array>
#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <sstream>
#include <string>
#include <vector>

namespace Column
{
  using namespace dealii;
  using namespace qsmpm;

  // @sect3{The problem and its exact solution}
  //
  // A column of initial height $l_0$, one cell wide, on rollers at its base
  // and its sides (plane strain in 2D; in 3D all four sides), is loaded by
  // its own weight $\rho_0 g$ (per unit initial volume), raised from zero in
  // a number of load steps. Nothing moves sideways, so the vertical force
  // carried by a horizontal section is the weight of the material above it,
  // and the section's area does not change. Hence, for any material law,
  // the Cauchy stress at a point of initial height $Y$ is
  // @f[
  //   \sigma_{yy} = -\rho_0 g\,(l_0 - Y), \qquad
  //   \sigma_{xx} = \sigma_{zz} = 0 \quad (\nu = 0),
  // @f]
  // no matter how much the column compacts. With Hencky elasticity and
  // $\nu = 0$ the stretch $\lambda$ of a fibre follows from
  // $E \ln\lambda / \lambda = \sigma_{yy}$; the compaction of the column is
  // the mean of $1 - \lambda$ over its height.
  //
  // With linear shape functions the stress jumps whenever a point crosses a
  // cell face ("cell-crossing error"), and the error does not vanish under
  // refinement: more cells mean more crossings. GIMP weights are smooth
  // across faces and converge.

  // @sect3{Parameters}
  //
  // One struct per subsection of the .prm file; entries are bound to the
  // members with add_parameter(), as in step-68. The library's own
  // subsections (solver, load stepping, material) are read by
  // QuasiStaticProblem.
  struct Parameters
  {
    double                    height          = 50.;
    double                    weight          = 800.;
    std::vector<unsigned int> cells           = {4, 8, 16, 32, 64, 128};
    std::vector<std::string>  shape_functions = {"linear", "cpGIMP"};
    std::string               output_file     = "convergence.csv";
    unsigned int              points          = 2;
    std::string               prefix          = "";

    void
    add_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Column");
      prm.add_parameter("Height", height, "Initial height l0 of the column.");
      prm.add_parameter("Weight density",
                        weight,
                        "rho0 g, force per unit initial volume.");
      prm.add_parameter("Cells over the height",
                        cells,
                        "The grids of the convergence study; the column is "
                        "one (square) cell wide.");
      prm.add_parameter("Shape functions list",
                        shape_functions,
                        "The shape functions to compare (linear, uGIMP, "
                        "cpGIMP).");
      prm.add_parameter("Points per cell per direction", points);
      prm.add_parameter("Output file",
                        output_file,
                        "The convergence table (CSV).");
      prm.add_parameter("Case name",
                        prefix,
                        "A label printed in front of every result line.");
      prm.leave_subsection();
    }
  };

  // @sect3{The weight}
  //
  // A body force per unit initial volume, (0, -rho0 g t[, 0]); the time of
  // a Function is the load factor t.
  template <int dim>
  class Weight : public Function<dim>
  {
  public:
    explicit Weight(const double weight)
      : Function<dim>(dim)
      , weight(weight)
    {
    }

    double
    value(const Point<dim> &, const unsigned int component) const override
    {
      return component == 1 ? -weight * this->get_time() : 0.;
    }

  private:
    const double weight;
  };



  // @sect3{The column class}
  //
  // One object per run (shape functions, number of cells): it builds the
  // problem, runs it and measures the stress error, one method per stage,
  // like step-44's Solid.
  template <int dim>
  class SelfWeightColumn
  {
  public:
    SelfWeightColumn(const Parameters  &column,
                     ParameterHandler  &prm,
                     const std::string &shape_functions,
                     const unsigned int cells);

    struct Errors
    {
      double       l2;
      double       max;
      double       compaction;
      unsigned int steps;
      unsigned int newton_min, newton_max;
      unsigned int gmres_per_newton_min, gmres_per_newton_max;
      double       wall_time;
    };

    Errors
    run();

  private:
    void
    make_grid();
    void
    setup_points_and_loads();
    Errors
    measure_errors() const;

    const Parameters       &column;
    const unsigned int      cells;
    const double            h;
    QuasiStaticProblem<dim> problem;
  };



  template <int dim>
  SelfWeightColumn<dim>::SelfWeightColumn(const Parameters  &column,
                                          ParameterHandler  &prm,
                                          const std::string &shape_functions,
                                          const unsigned int cells)
    : column(column)
    , cells(cells)
    , h(column.height / cells)
    , problem(MPI_COMM_WORLD)
  {
    problem.return_large_blocks_to_system();
    // Solver, load stepping and output from the file; the formulation
    // from the study. The material model is the one in the file.
    problem.parameters().parse_parameters(prm);
    auto &mp                       = problem.parameters().material_points;
    mp.points_per_direction        = column.points;
    mp.formulation.shape_functions = parse_shape_functions(shape_functions);
    problem.parameters().output.interval = 0;
    // One line per run is printed by the study; the problem stays quiet.
    problem.pcout().set_condition(false);
    make_grid();
    problem.set_model(ConstitutiveModelFactory<dim>::create(prm));
    setup_points_and_loads();
  }



  // @sect4{SelfWeightColumn::make_grid}
  //
  // The grid is exactly the column: one cell of size h across, cells cells
  // up. When the column compacts, its top leaves the top cells, which then
  // hold few or no points.
  template <int dim>
  void
  SelfWeightColumn<dim>::make_grid()
  {
    Point<dim>                    upper;
    std::array<unsigned int, dim> subdivisions;
    for (unsigned int d = 0; d < dim; ++d)
      {
        upper[d]        = (d == 1) ? column.height : h;
        subdivisions[d] = (d == 1) ? cells : 1;
      }
    problem.grid().make_box(Point<dim>(), upper, subdivisions);
  }



  // @sect4{SelfWeightColumn::setup_points_and_loads}
  //
  // Rollers: the normal displacement is zero on every face but the top.
  // The weight grows linearly with the load factor t.
  template <int dim>
  void
  SelfWeightColumn<dim>::setup_points_and_loads()
  {
    const auto &mp = problem.parameters().material_points;
    problem.points().fill([](const Point<dim> &) { return true; },
                          mp.points_per_direction,
                          mp.placement);
    auto      &bcs  = problem.boundary_conditions();
    const auto zero = std::make_shared<Functions::ZeroFunction<dim>>(dim);
    for (unsigned int d = 0; d < dim; ++d)
      {
        bcs.add_dirichlet_boundary(2 * d, {}, zero, /*normal_only=*/true);
        if (d != 1)
          bcs.add_dirichlet_boundary(2 * d + 1, {}, zero, /*normal_only=*/true);
      }
    bcs.set_body_force(std::make_shared<Weight<dim>>(column.weight));
  }



  // @sect4{SelfWeightColumn::run}
  template <int dim>
  typename SelfWeightColumn<dim>::Errors
  SelfWeightColumn<dim>::run()
  {
    Timer timer;
    problem.run();
    timer.stop();
    Errors errors     = measure_errors();
    errors.wall_time  = timer.wall_time();
    errors.steps      = problem.step_reports().size();
    errors.newton_min = errors.gmres_per_newton_min = 1000000;
    errors.newton_max = errors.gmres_per_newton_max = 0;
    for (const auto &report : problem.step_reports())
      {
        const auto &n     = report.newton;
        errors.newton_min = std::min(errors.newton_min, n.newton_iterations);
        errors.newton_max = std::max(errors.newton_max, n.newton_iterations);
        const unsigned int g =
          n.newton_iterations > 0 ?
            (n.linear_iterations + n.newton_iterations - 1) /
              n.newton_iterations :
            0;
        errors.gmres_per_newton_min = std::min(errors.gmres_per_newton_min, g);
        errors.gmres_per_newton_max = std::max(errors.gmres_per_newton_max, g);
      }
    return errors;
  }



  // @sect4{SelfWeightColumn::measure_errors}
  //
  // The error of the Cauchy stress at the points against the exact
  // solution, all components (Frobenius norm), relative to rho0 g l0: the
  // volume-weighted L2 mean over the points, and the maximum. A point's
  // initial height is its current height minus its displacement.
  template <int dim>
  typename SelfWeightColumn<dim>::Errors
  SelfWeightColumn<dim>::measure_errors() const
  {
    const auto  &points  = problem.points();
    const auto  &offsets = points.get_offsets();
    const double scale   = column.weight * column.height;
    double       sum = 0, volume = 0, max = 0, initial_height = 0;
    for (const auto &particle : points.get_particle_handler())
      {
        const auto   data = particle.get_properties();
        const double Y =
          particle.get_location()[1] - data[offsets.displacement + 1];
        SymmetricTensor<2, dim> error =
          Utils::read_symmetric<dim>(&data[offsets.stress]);
        error[1][1] += column.weight * (column.height - Y);
        const double V = data[offsets.initial_volume];
        sum += V * error.norm() * error.norm();
        volume += V;
        max            = std::max(max, error.norm());
        initial_height = std::max(initial_height, particle.get_location()[1]);
      }
    const MPI_Comm comm = MPI_COMM_WORLD;
    sum                 = Utilities::MPI::sum(sum, comm);
    volume              = Utilities::MPI::sum(volume, comm);
    max                 = Utilities::MPI::max(max, comm);

    // Compaction: 1 - (current volume / initial volume).
    const double current_volume = points.total_volume();
    Errors       errors;
    errors.l2         = std::sqrt(sum / volume) / scale;
    errors.max        = max / scale;
    errors.compaction = 1. - current_volume / volume;
    return errors;
  }



  // @sect3{The exact compaction of a Hencky column}
  //
  // For Hencky elasticity with nu = 0 a horizontal fibre at initial height
  // Y has the vertical stretch lambda(Y) with
  // E ln(lambda) / lambda = -rho0 g (l0 - Y) (the Cauchy stress is
  // tau / J and J = lambda). The compaction 1 - (1/l0) int lambda dY is
  // computed here independently of the material-point method: bisection
  // for lambda at the nodes of a 2000-interval Simpson rule.
  double
  exact_hencky_compaction(const double E, const double weight, const double l0)
  {
    const unsigned int n   = 2000;
    double             sum = 0;
    for (unsigned int i = 0; i <= n; ++i)
      {
        const double s = -weight * l0 * (1. - double(i) / n) / E;
        // ln(lambda) / lambda increases monotonically on (0, 1]: bisection.
        double low = 1e-12, high = 1.;
        for (unsigned int k = 0; k < 200; ++k)
          {
            const double mid                       = 0.5 * (low + high);
            (std::log(mid) / mid < s ? low : high) = mid;
          }
        const double lambda = 0.5 * (low + high);
        sum += (i == 0 || i == n ? 1. : (i % 2 ? 4. : 2.)) * lambda;
      }
    return 1. - sum / (3. * n);
  }



  // @sect3{The ConvergenceStudy class}
  //
  // The program itself is a class, like step-44's Solid: the constructor
  // reads the parameter file, run() does all runs of the study -- one
  // SelfWeightColumn per kind of shape functions and grid -- and writes
  // their results, one method per stage.
  template <int dim>
  class ConvergenceStudy
  {
  public:
    explicit ConvergenceStudy(const std::string &parameter_file);

    void
    run();

  private:
    void
    print_exact_compaction();
    void
    open_table();
    void
    run_shape_functions(const std::string &shape_functions);
    void
    write_plot() const;

    // The parameter handler keeps the library's subsections, which every
    // SelfWeightColumn reads again; the entries of "Column" are bound to
    // the members of column (add_parameter()), which parsing the file
    // fills.
    ParameterHandler   prm;
    Parameters         column;
    ConditionalOStream pcout;
    std::ofstream      csv;
  };



  // @sect4{ConvergenceStudy::ConvergenceStudy}
  //
  // "Dimension" was read by main() already; it is declared so that the
  // file may hold it.
  template <int dim>
  ConvergenceStudy<dim>::ConvergenceStudy(const std::string &parameter_file)
    : pcout(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
  {
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
    QuasiStaticProblem<dim>::Parameters::declare_parameters(prm);
    column.add_parameters(prm);
    prm.parse_input(parameter_file);
  }



  // @sect4{ConvergenceStudy::run}
  //
  // All runs of the study, a line per run on the screen and in the CSV
  // file, then the observed rates between successive grids.
  template <int dim>
  void
  ConvergenceStudy<dim>::run()
  {
    print_exact_compaction();
    open_table();
    for (const auto &shape_functions : column.shape_functions)
      run_shape_functions(shape_functions);
    if (csv.is_open())
      {
        csv.close();
        write_plot();
      }
  }



  // @sect4{ConvergenceStudy::print_exact_compaction}
  //
  // For a Hencky material with nu = 0 the exact compaction is known (see
  // exact_hencky_compaction()); for other models there is no reference.
  template <int dim>
  void
  ConvergenceStudy<dim>::print_exact_compaction()
  {
    prm.enter_subsection("Material");
    const std::string model = prm.get("Model");
    if (model == "hencky")
      {
        prm.enter_subsection("hencky");
        const double E = prm.get_double("Young's modulus");
        if (prm.get_double("Poisson's ratio") == 0.)
          pcout << column.prefix
                << "exact compaction (Hencky, nu = 0): " << std::setprecision(5)
                << exact_hencky_compaction(E, column.weight, column.height)
                << std::endl;
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }



  // @sect4{ConvergenceStudy::open_table}
  //
  // The CSV file is written by rank 0 only.
  template <int dim>
  void
  ConvergenceStudy<dim>::open_table()
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    csv.open(column.output_file);
    AssertThrow(csv, ExcMessage("Cannot write <" + column.output_file + ">."));
    csv << "shape_functions,cells,l2_stress_error,max_stress_error\n";
  }



  // @sect4{ConvergenceStudy::run_shape_functions}
  //
  // One kind of shape functions on every grid of the study: a line per run,
  // then the rates of the L2 error between successive grids.
  template <int dim>
  void
  ConvergenceStudy<dim>::run_shape_functions(const std::string &shape_functions)
  {
    std::vector<double> l2;
    for (const unsigned int cells : column.cells)
      {
        SelfWeightColumn<dim> run(column, prm, shape_functions, cells);
        const auto            e = run.run();
        l2.push_back(e.l2);
        pcout << column.prefix << std::setw(7) << shape_functions << "  cells "
              << std::setw(4) << cells << "  L2 " << std::scientific
              << std::setprecision(3) << e.l2 << "  max " << e.max
              << std::defaultfloat << std::setprecision(4) << "  compaction "
              << e.compaction << "  steps " << e.steps << "  newton "
              << e.newton_min << "-" << e.newton_max << "  gmres/newton "
              << e.gmres_per_newton_min << "-" << e.gmres_per_newton_max << "  "
              << std::fixed << std::setprecision(2) << e.wall_time << " s"
              << std::defaultfloat << std::endl;
        if (csv.is_open())
          csv << shape_functions << ',' << cells << ',' << std::setprecision(8)
              << e.l2 << ',' << e.max << '\n';
      }
    for (unsigned int i = 1; i < l2.size(); ++i)
      pcout << column.prefix << std::setw(7) << shape_functions << "  rate "
            << column.cells[i - 1] << " -> " << column.cells[i] << ": "
            << std::setprecision(3)
            << std::log(l2[i - 1] / l2[i]) /
                 std::log(double(column.cells[i]) / column.cells[i - 1])
            << std::endl;
  }



  // @sect4{ConvergenceStudy::write_plot}
  //
  // Next to the CSV file, a gnuplot script of the same name with ".gp", and,
  // if gnuplot is installed, the plot itself (".png"): the L2 and maximum
  // errors of each kind of shape functions against the number of cells.
  template <int dim>
  void
  ConvergenceStudy<dim>::write_plot() const
  {
    const std::string &csv_file = column.output_file;
    const std::string  stem =
      std::filesystem::path(csv_file).replace_extension().string();
    std::ofstream gp(stem + ".gp");
    gp << "set terminal pngcairo size 800,560 noenhanced\n"
       << "set output '" << stem << ".png'\n"
       << "set datafile separator ','\n"
       << "set logscale xy\n"
       << "set xlabel 'cells over the height'\n"
       << "set ylabel 'stress error / (rho0 g l0)'\n"
       << "set key top right\nset grid\n"
       << "f = '" << csv_file << "'\n"
       << "plot f using 2:(strcol(1) eq 'linear' ? $3 : 1/0) w lp lw 2 pt 7 "
          "t 'linear, L2', \\\n"
       << "     f using 2:(strcol(1) eq 'linear' ? $4 : 1/0) w lp dt 2 pt 6 "
          "t 'linear, max', \\\n"
       << "     f using 2:(strcol(1) ne 'linear' ? $3 : 1/0) w lp lw 2 pt 5 "
          "t 'GIMP, L2', \\\n"
       << "     f using 2:(strcol(1) ne 'linear' ? $4 : 1/0) w lp dt 2 pt 4 "
          "t 'GIMP, max', \\\n"
       << "     0.03*(8.0/x)**1.5 w l lc rgb 'gray' dt 3 t 'slope 1.5'\n";
    gp.close();
    if (qsmpm::Utils::run_gnuplot(stem + ".gp"))
      std::cout << "wrote " << csv_file << " and " << stem << ".png"
                << std::endl;
    else
      std::cout << "wrote " << csv_file << " and " << stem
                << ".gp (gnuplot not found: no picture)" << std::endl;
  }
} // namespace Column



// @sect3{The main function}
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
      const std::string parameter_file =
        argc > 1 ? std::string(argv[1]) :
                   (std::filesystem::path(argv[0]).parent_path() / "column.prm")
                     .string();
      AssertThrow(std::filesystem::exists(parameter_file),
                  dealii::ExcMessage("Cannot find the parameter file <" +
                                     parameter_file + ">."));
      if (qsmpm::Utils::read_dimension(parameter_file) == 2)
        Column::ConvergenceStudy<2>(parameter_file).run();
      else
        Column::ConvergenceStudy<3>(parameter_file).run();
    }
  catch (std::exception &exc)
    {
      // The errors of qsmpm are collective: every rank reads the same
      // parameter file and checks the same values, and a load step that
      // fails, fails on every rank with the same message (the library
      // broadcasts it). So one rank, rank 0, prints it, as one line
      // written at once: lines written piece by piece by several ranks
      // interleave ("column stopped: column stopped: ...").
      if (rank == 0)
        std::cerr << "column stopped: " + qsmpm::Utils::error_message(exc) +
                       "\n"
                  << std::flush;
      return 1;
    }
  catch (...)
    {
      if (rank == 0)
        std::cerr << "column stopped: unknown exception" << std::endl;
      return 1;
    }
  return 0;
}
