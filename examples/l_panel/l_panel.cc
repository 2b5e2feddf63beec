/* ---------------------------------------------------------------------
 *
 * qsmpm example: l_panel
 *
 * A mixed-mode fracture experiment with a curved crack: the L-shaped
 * concrete panel of Winkler, Hofstetter and Niederwanger (2001), pushed up
 * at the end of its arm until it breaks from the re-entrant corner. The
 * `smeared cracks` model may crack everywhere; the crack's path and the
 * load-deflection curve come out of the computation and are compared with
 * the experiment.
 *
 * Usage:
 *   ./l_panel [l_panel.prm]
 *   mpirun -np 2 ./l_panel l_panel.prm
 *
 * ---------------------------------------------------------------------
 */

// @sect3{Include files}
//
// The panel and one run of it (Parameters, LShapedPanel) are in l_panel.h,
// which the test l_panel_experiment includes too.
#include "l_panel.h"



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
          (std::filesystem::path(argv[0]).parent_path() / "l_panel.prm")
            .string();
      AssertThrow(std::filesystem::exists(parameter_file),
                  dealii::ExcMessage("Cannot find the parameter file <" +
                                     parameter_file + ">."));
      LPanel::LShapedPanel<2>(parameter_file).run();
    }
  catch (std::exception &exc)
    {
      if (rank == 0)
        std::cerr << "l_panel stopped: " + qsmpm::Utils::error_message(exc) +
                       "\n"
                  << std::flush;
      return 1;
    }
  catch (...)
    {
      if (rank == 0)
        std::cerr << "l_panel stopped: unknown exception" << std::endl;
      return 1;
    }
  return 0;
}
