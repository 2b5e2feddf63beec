// Guards against nonsense states (issue 12): runs that used to finish with
// exit 0 (or a message that did not name the cause) must stop with a message
// that names it, and a sound problem must not be stopped by them.
//  - The README's block with the top plate moved down by twice the block's
//    height: once the body has left the plate's nodes the condition no
//    longer acts; the run stops naming the condition.
//  - Tractions only, or frictionless plates only: the body is free to move
//    as a rigid body; the free motions are named before the first solve
//    (2D and 3D).
//  - A confined block compressed by 1.5 times its height in one small-strain
//    step: the linear step converges with J = 1 + tr d eps = -0.5; it is
//    rejected, and with no cut-back allowed the run stops naming it.
// Each case checks that the run stopped and that the message contains the
// phrase that names the cause (not the exact wording).
#include "tests.h"

#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>

namespace
{
  // The README's frictionless block: a 1 x 1 block in a 1.5 x 1 grid.
  std::string
  block(const std::string &dirichlet,
        const std::string &displacement,
        const std::string &extra = "")
  {
    return "subsection Geometry\n"
           "  set Lower corner = 0,0\n"
           "  set Upper corner = 1.5,1\n"
           "  set Subdivisions = 6,4\n"
           "end\n"
           "subsection Material points\n"
           "  set Region lower corner = 0,0\n"
           "  set Region upper corner = 1,1\n"
           "end\n"
           "subsection Material\n"
           "  set Model = linear elastic\n"
           "  subsection linear elastic\n"
           "    set Young's modulus = 10000\n"
           "    set Poisson's ratio = 0.3\n"
           "  end\n"
           "end\n"
           "subsection Boundary conditions\n"
           "  set Dirichlet boundaries = " +
           dirichlet +
           "\n"
           "  subsection Displacement\n"
           "    set Function expression = " +
           displacement +
           "\n"
           "  end\n"
           "end\n"
           "subsection Load stepping\n"
           "  set Number of steps = 5\n"
           "end\n"
           "subsection Output\n"
           "  set Interval = 0\n"
           "  set Directory = guards-out\n"
           "end\n" +
           extra;
  }

  template <int dim>
  void
  run(const std::string &what,
      const std::string &input,
      const std::string &expected_phrase)
  {
    ParameterHandler prm;
    qsmpm::QuasiStaticProblem<dim>::Parameters::declare_parameters(prm);
    std::string message;
    bool        stopped = false;
    try
      {
        prm.parse_input_from_string(input);
        qsmpm::QuasiStaticProblem<dim> problem(MPI_COMM_WORLD);
        problem.pcout().set_condition(false);
        problem.initialize(prm);
        problem.run();
      }
    catch (const std::exception &exc)
      {
        stopped = true;
        message = qsmpm::Utils::error_message(exc);
      }
    if (expected_phrase.empty())
      deallog << what << ": " << (stopped ? "stopped (FAIL): " : "ran (PASS)")
              << message << std::endl;
    else
      deallog << what << ": "
              << (stopped &&
                      message.find(expected_phrase) != std::string::npos ?
                    "stopped, names it (PASS): " :
                    "(FAIL): ")
              << message << std::endl;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::MPILogInitAll       log;

  run<2>("README block, top down by 1 %",
         block("0:n, 2:n, 3:y", "0; -0.01*t*y"),
         "");
  run<2>("README block, top down by twice the height",
         block("0:n, 2:n, 3:y", "0; -2*t*y"),
         "displacement condition <boundary_3>");
  run<2>("tractions only",
         block("",
               "0; 0",
               "subsection Boundary conditions\n"
               "  set Traction boundaries = 3\n"
               "  subsection Traction\n"
               "    set Function expression = 0; -t\n"
               "  end\n"
               "end\n"),
         "translation in x, translation in y, rotation about z");
  run<2>("frictionless plates only",
         block("2:n, 3:n", "0; -0.01*t*y"),
         "prevents translation in x");
  run<3>("3D: a frictionless floor only",
         "subsection Geometry\n"
         "  set Lower corner = 0,0,0\n"
         "  set Upper corner = 1,1,1\n"
         "  set Subdivisions = 2,2,2\n"
         "end\n"
         "subsection Boundary conditions\n"
         "  set Dirichlet boundaries = 4:n\n"
         "end\n"
         "subsection Load stepping\n"
         "  set Number of steps = 1\n"
         "end\n"
         "subsection Output\n"
         "  set Interval = 0\n"
         "  set Directory = guards-out\n"
         "end\n",
         "translation in x, translation in y, rotation about z");
  run<2>("confined block compressed by 1.5 times its height in one step",
         block("0:n, 1:n, 2:n, 3:y",
               "0; -1.5*t*y",
               "subsection Geometry\n"
               "  set Upper corner = 1,1\n"
               "  set Subdivisions = 4,4\n"
               "end\n"
               "subsection Material points\n"
               "  set Region lower corner =\n"
               "  set Region upper corner =\n"
               "end\n"
               "subsection Load stepping\n"
               "  set Number of steps = 1\n"
               "  set Maximum cut-backs = 0\n"
               "end\n"),
         "turned inside out");
}
