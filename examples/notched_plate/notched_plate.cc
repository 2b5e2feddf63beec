/* ---------------------------------------------------------------------
 *
 * qsmpm example: notched_plate
 *
 * Cracks where the material decides, and the grid does not: a
 * single-edge-notched plate pulled apart by two grips, rotated against the
 * background grid by 0, 15, 30 and 45 degrees, with the multi-crack smeared
 * model (`smeared cracks`) allowed to crack everywhere. The peak load, the
 * work of fracture and the direction of the cracks must not depend on the
 * grid's orientation.
 *
 * Usage:
 *   ./notched_plate [objectivity.prm]
 *   mpirun -np 2 ./notched_plate objectivity.prm
 *
 * ---------------------------------------------------------------------
 */

// @sect3{Include files}
//
// The plate and one run of it (Parameters, GripMotion, RotatedPlate) are in
// rotated_plate.h, which the test notched_plate_objectivity includes too.
#include "rotated_plate.h"

namespace NotchedPlate
{
  // @sect3{The study}
  template <int dim>
  class ObjectivityStudy
  {
  public:
    explicit ObjectivityStudy(const std::string &parameter_file)
      : pcout(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      prm.declare_entry("Dimension", "2", Patterns::Integer(2, 2), "");
      QuasiStaticProblem<dim>::Parameters::declare_parameters(prm);
      plate.add_parameters(prm);
      prm.parse_input(parameter_file);
      prm.enter_subsection("Material");
      const std::string model = prm.get("Model");
      AssertThrow(model == "smeared cracks" || model == "decohesion",
                  ExcMessage("notched_plate: Material/<Model> must be "
                             "<smeared cracks> or <decohesion>."));
      prm.enter_subsection(model);
      G_f = prm.get_double("Fracture energy");
      prm.leave_subsection();
      prm.leave_subsection();
    }

    void
    run()
    {
      const double ligament = plate.width - plate.notch_depth;
      pcout << "Notched plate " << plate.length << " x " << plate.width
            << ", notch " << plate.notch_depth
            << ", h = " << plate.width / plate.cells_across
            << ", G_f (W - a0) = " << G_f * ligament << std::endl;
      const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      std::ofstream csv, curves;
      if (root)
        {
          std::filesystem::create_directories(plate.output_directory);
          csv.open(plate.output_file);
          AssertThrow(csv,
                      ExcMessage("Cannot write <" + plate.output_file + ">."));
          // The objectivity figures first, then where the energy went.
          csv << "angle_deg,peak_N,work_over_Gf_area,crack_normal_deg,"
                 "crack_energy_over_Gf_area,path_angle_deg,"
                 "stored_energy_over_Gf_area\n";
          curves.open(plate.output_directory + "/load_displacement.csv");
          curves << "angle_deg,grip_displacement_m,load_N\n";
        }
      std::vector<double> stopped;
      for (const double angle : plate.angles)
        {
          RotatedPlate<dim> run(plate, prm, angle);
          const auto        r = run.run();
          pcout << "  angle " << std::setw(4) << angle << ": peak "
                << std::setprecision(6) << r.peak << ", work / (G_f (W - a0)) "
                << r.work / (G_f * ligament) << " (cracks "
                << r.crack_energy / (G_f * ligament) << ", held at the end "
                << r.stored_energy / (G_f * ligament) << "), crack normal "
                << r.normal << " deg, path angle " << r.path_angle << " deg, "
                << r.steps << " steps, " << std::setprecision(3) << r.wall_time
                << " s" << (r.failed ? " (stopped early)" : "") << std::endl;
          if (!root)
            continue;
          for (const auto &[delta, P] : r.curve)
            curves << angle << ',' << std::setprecision(8) << delta << ',' << P
                   << '\n';
          // A run that stopped early has no work of fracture: its row would
          // read as a result.
          if (r.failed)
            stopped.push_back(angle);
          else
            csv << angle << "," << std::setprecision(8) << r.peak << ","
                << r.work / (G_f * ligament) << "," << r.normal << ","
                << r.crack_energy / (G_f * ligament) << "," << r.path_angle
                << "," << r.stored_energy / (G_f * ligament) << "\n"
                << std::flush;
        }
      if (root)
        {
          curves.close();
          write_plots();
        }
      stopped = Utilities::MPI::broadcast(MPI_COMM_WORLD, stopped, 0);
      if (!stopped.empty())
        {
          std::ostringstream message;
          message << "the run(s) at";
          for (const double angle : stopped)
            message << ' ' << angle;
          message << " degrees stopped before the plate broke; "
                  << plate.output_file << " has no row for them.";
          AssertThrow(false, ExcMessage(message.str()));
        }
    }

  private:
    // gnuplot scripts next to the data, and the pictures if gnuplot is
    // installed: the load against the grip's displacement for every angle,
    // and the dissipated energy of the points in the plate's frame.
    void
    write_plots() const
    {
      const std::string &directory = plate.output_directory;
      std::ofstream      gp(directory + "/objectivity.gp");
      gp << "set terminal pngcairo size 800,560 noenhanced\n"
         << "set datafile separator ','\n"
         << "set output '" << directory << "/load_displacement.png'\n"
         << "set xlabel 'grip displacement (mm)'\n"
         << "set ylabel 'load (kN per m of thickness)'\n"
         << "set grid\nf = '" << directory << "/load_displacement.csv'\n"
         << "plot ";
      for (unsigned int i = 0; i < plate.angles.size(); ++i)
        gp << (i > 0 ? ", \\\n     " : "")
           << "f using ($1 == " << plate.angles[i]
           << " ? 1e3*$2 : 1/0):($3/1e3) w l lw 2 t '" << plate.angles[i]
           << " degrees'";
      gp << "\nset output '" << directory << "/cracks.png'\n"
         << "set terminal pngcairo size 1000," << 330 * plate.angles.size()
         << " noenhanced\n"
         << "set multiplot layout " << plate.angles.size() << ",1\n"
         << "set size ratio -1\nunset key\nset cbrange [0:1]\n"
         << "set xlabel 'xi (m), along the load axis'\n"
         << "set ylabel 'eta (m)'\nset cblabel 'dissipated energy / G_f'\n"
         << "set palette rgbformulae 33,13,10\n"
         << "set xrange [" << -0.5 * plate.length << ":" << 0.5 * plate.length
         << "]\nset yrange [" << -0.5 * plate.width << ":" << 0.5 * plate.width
         << "]\n";
      // Only the points that dissipated at least 2 % of G_f: the rest
      // started a crack that unloaded on its initial branch.
      for (const double angle : plate.angles)
        gp << "set title 'grid at " << angle
           << " degrees to the load axis (the plate is drawn in its own "
              "frame)'\n"
           << "plot '" << directory << "/angle-" << angle
           << "/cracks.csv' every ::1 using 1:2:($3 >= 0.02 ? $3 : 1/0) "
              "with points pt 5 ps 0.5 lc palette\n";
      gp << "unset multiplot\n";
      gp.close();
      if (Utils::run_gnuplot(directory + "/objectivity.gp"))
        pcout << "wrote " << directory << "/load_displacement.png and "
              << directory << "/cracks.png" << std::endl;
      else
        pcout << "wrote " << directory
              << "/objectivity.gp (gnuplot not found: no pictures)"
              << std::endl;
    }

    ConditionalOStream pcout;
    ParameterHandler   prm;
    Parameters         plate;
    double             G_f = 1.;
  };
} // namespace NotchedPlate



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
          (std::filesystem::path(argv[0]).parent_path() / "objectivity.prm")
            .string();
      AssertThrow(std::filesystem::exists(parameter_file),
                  dealii::ExcMessage("Cannot find the parameter file <" +
                                     parameter_file + ">."));
      NotchedPlate::ObjectivityStudy<2>(parameter_file).run();
    }
  catch (std::exception &exc)
    {
      if (rank == 0)
        std::cerr << "notched_plate stopped: " +
                       qsmpm::Utils::error_message(exc) + "\n"
                  << std::flush;
      return 1;
    }
  catch (...)
    {
      if (rank == 0)
        std::cerr << "notched_plate stopped: unknown exception" << std::endl;
      return 1;
    }
  return 0;
}
