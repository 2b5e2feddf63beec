// The general driver: runs any quasi-static problem described by a .prm file.
//
//   qsmpm problem.prm          run it
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
  run(const std::string &filename)
  {
    ParameterHandler prm;
    declare<dim>(prm);
    prm.parse_input(filename);
    qsmpm::QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
    problem.initialize(prm);
    problem.run();
  }
} // namespace

int
main(int argc, char *argv[])
{
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const std::string                argument = argc > 1 ? argv[1] : "";
      if (argument.empty() || argument == "--help" || argument == "-h")
        {
          std::cout << "Usage: qsmpm <file.prm> | --print-parameters\n";
          return argument.empty() ? 1 : 0;
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
        run<2>(argument);
      else
        run<3>(argument);
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
