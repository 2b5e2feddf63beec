// The general driver: runs any quasi-static problem described by a .prm file.
//
//   qsmpm problem.prm          run it
//   qsmpm --resume problem.prm continue from the newest checkpoint in the
//                              output directory (Output/Checkpoint interval)
//   qsmpm --print-parameters   every parameter, its default and documentation
#include <deal.II/base/mpi.h>
#include <iostream>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>

namespace
{
  using namespace dealii;

  template <int dim>
  void
  declare(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension of the problem: 2 or 3.");
    qsmpm::QuasiStaticProblem<dim>::Parameters::declare_parameters(prm);
  }

  template <int dim>
  void
  run(const std::string &filename, const bool resume)
  {
    ParameterHandler prm;
    declare<dim>(prm);
    prm.parse_input(filename);
    qsmpm::QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
    problem.initialize(prm);
    if (resume)
      problem.resume();
    problem.run();
  }
} // namespace

int
main(int argc, char *argv[])
{
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const bool        resume = argc > 2 && std::string(argv[1]) == "--resume";
      const std::string argument = argc > 1 ? argv[resume ? 2 : 1] : "";
      if (argument.empty() || argument == "--help" || argument == "-h" ||
          argument == "--resume")
        {
          std::cout
            << "Usage: qsmpm [--resume] <file.prm> | --print-parameters\n";
          return argument.empty() || argument == "--resume" ? 1 : 0;
        }
      if (argument == "--print-parameters")
        {
          ParameterHandler prm;
          declare<2>(prm);
          if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
            prm.print_parameters(std::cout, ParameterHandler::PRM);
          return 0;
        }
      if (qsmpm::Utils::read_dimension(argument) == 2)
        run<2>(argument, resume);
      else
        run<3>(argument, resume);
    }
  catch (std::exception &exc)
    {
      std::cerr << "qsmpm stopped: " << qsmpm::Utils::error_message(exc)
                << std::endl;
      return 1;
    }
  catch (...)
    {
      std::cerr << "qsmpm stopped: unknown exception" << std::endl;
      return 1;
    }
  return 0;
}
