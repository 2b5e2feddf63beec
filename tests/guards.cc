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
// phrases that name the cause and the entry to change (and not the motions
// that are held), one PASS/FAIL line each; the message itself goes to
// stdout only, so that its wording and numbers are not compared.
#include "tests.h"

#include <iostream>
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

  /**
   * Run @p input. With no @p expected phrases the run must finish; else it
   * must stop with a message that contains every phrase of @p expected
   * (the entry or condition to fix, not the exact wording) and none of
   * @p absent. One PASS/FAIL line per phrase goes to the output; the whole
   * message only to stdout, so that rewording it does not fail the test.
   */
  template <int dim>
  void
  run(const std::string              &what,
      const std::string              &input,
      const std::vector<std::string> &expected,
      const std::vector<std::string> &absent = {})
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
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << what << ": " << (stopped ? "stopped: " : "ran to the end")
                << message << std::endl;
    if (expected.empty())
      {
        check_that(what + ": runs to the end", !stopped);
        return;
      }
    check_that(what + ": stops", stopped);
    for (const auto &phrase : expected)
      check_that(what + ": the message names '" + phrase + "'",
                 stopped && message.find(phrase) != std::string::npos);
    for (const auto &phrase : absent)
      check_that(what + ": the message does not name '" + phrase + "'",
                 stopped && message.find(phrase) == std::string::npos);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::MPILogInitAll       log;

  run<2>("README block, top down by 1 %",
         block("0:n, 2:n, 3:y", "0; -0.01*t*y"),
         {});
  run<2>("README block, top down by twice the height",
         block("0:n, 2:n, 3:y", "0; -2*t*y"),
         {"<boundary_3>", "material point"});
  run<2>("tractions only",
         block("",
               "0; 0",
               "subsection Boundary conditions\n"
               "  set Traction boundaries = 3\n"
               "  subsection Traction\n"
               "    set Function expression = 0; -t\n"
               "  end\n"
               "end\n"),
         {"translation in x", "translation in y", "rotation about z"});
  // The plates hold y and the rotation; only x is free.
  run<2>("frictionless plates only",
         block("2:n, 3:n", "0; -0.01*t*y"),
         {"translation in x"},
         {"translation in y", "rotation"});
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
         {"translation in x", "translation in y", "rotation about z"},
         {"translation in z", "rotation about x", "rotation about y"});
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
         {"turned inside out", "Maximum cut-backs"});
}
