// Bad input must stop with a message that names the cause:
//  - an out-of-range value in a .prm file,
//  - an unknown entry,
//  - a malformed or impossible boundary condition (also periodic ones),
//  - a missing parameter file,
//  - finite strain with a small-strain model or without volume updates,
//    GIMP with a macroscopic displacement gradient,
//  - contact between bodies given wrongly (one body, an id that is no
//    number or in two bodies, points of no body, a negative friction
//    coefficient), a region expression that is none,
//  - a load step that does not converge (after the allowed cut-backs), and
//    nothing of that step is committed to the points; also one whose
//    contact set between bodies does not settle.
//
// The output records, per case, whether the input was refused and whether
// the message contains a keyword (the entry or file to fix), not the
// message itself: the wording of deal.II's messages (patterns, parser
// errors) changes between releases. A failing case prints the message.
// tests/bad_input/bad_input.sh runs the programs on many more inputs.
#include "tests.h"

#include <deal.II/base/function.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/linear_elastic.h>

void
report(const std::string &what,
       const std::string &keyword,
       const std::string &message)
{
  if (message.find(keyword) != std::string::npos)
    deallog << what << ": stopped, names <" << keyword << ">: PASS"
            << std::endl;
  else
    deallog << what << ": stopped, but does not name <" << keyword
            << ">: FAIL (" << message << ")" << std::endl;
}

void
try_input(const std::string &what,
          const std::string &keyword,
          const std::string &input,
          const bool         run = false)
{
  ParameterHandler prm;
  qsmpm::QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
  try
    {
      prm.parse_input_from_string(input);
      qsmpm::QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
      problem.pcout().set_condition(false);
      problem.initialize(prm);
      if (run)
        problem.run();
      deallog << what << ": accepted: FAIL" << std::endl;
    }
  catch (const std::exception &exc)
    {
      report(what, keyword, qsmpm::Utils::error_message(exc));
    }
}



int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  try_input("out-of-range value",
            "Poisson's ratio",
            "subsection Material\n"
            "  subsection linear elastic\n"
            "    set Poisson's ratio = 0.7\n"
            "  end\n"
            "end\n");
  try_input("unknown entry",
            "Youngs modulus",
            "subsection Material\n"
            "  set Youngs modulus = 1\n"
            "end\n");
  try_input("unknown model",
            "Model",
            "subsection Material\n"
            "  set Model = plasticity\n"
            "end\n");
  try_input("boundary id that does not exist",
            "Dirichlet boundaries",
            "subsection Boundary conditions\n"
            "  set Dirichlet boundaries = 7:xy\n"
            "end\n");
  try_input("unknown component",
            "Dirichlet boundaries",
            "subsection Boundary conditions\n"
            "  set Dirichlet boundaries = 0:xw\n"
            "end\n");
  try_input("wrong number of coordinates",
            "Upper corner",
            "subsection Geometry\n"
            "  set Upper corner = 1,1,1\n"
            "end\n");

  try_input("periodic direction that is not a letter x, y",
            "Periodic directions",
            "subsection Geometry\n"
            "  set Periodic directions = xq\n"
            "end\n");
  try_input("periodic direction with one cell across",
            "Subdivisions",
            "subsection Geometry\n"
            "  set Subdivisions = 1, 4\n"
            "  set Periodic directions = x\n"
            "end\n");
  try_input("macroscopic gradient with the wrong number of entries",
            "Macroscopic displacement gradient",
            "subsection Boundary conditions\n"
            "  set Macroscopic displacement gradient = 1e-3, 0, 0\n"
            "end\n");
  try_input("finite strain with a small-strain model",
            "Kinematics",
            "subsection Material points\n"
            "  set Kinematics = finite strain\n"
            "end\n");
  try_input("finite strain without volume updates",
            "Update volumes",
            "subsection Material points\n"
            "  set Kinematics = finite strain\n"
            "  set Update volumes = false\n"
            "end\n"
            "subsection Material\n"
            "  set Model = hencky\n"
            "end\n");
  try_input("points that do not move with updated volumes",
            "Update volumes",
            "subsection Material points\n"
            "  set Move points = false\n"
            "end\n");
  try_input("GIMP with a macroscopic displacement gradient",
            "Shape functions",
            "subsection Geometry\n"
            "  set Periodic directions = xy\n"
            "  set Subdivisions = 4, 4\n"
            "end\n"
            "subsection Material points\n"
            "  set Shape functions = cpGIMP\n"
            "end\n"
            "subsection Boundary conditions\n"
            "  set Macroscopic displacement gradient = 1e-3, 0, 0, 0\n"
            "end\n"
            "subsection Output\n"
            "  set Interval = 0\n"
            "  set Directory = bad-input-out\n"
            "end\n",
            /*run=*/true);

  // A saturated body (Pore fluid): impossible values and combinations.
  const std::string pore_fluid  = "subsection Pore fluid\n"
                                  "  set Enabled = true\n"
                                  "  set Drained boundaries = 3\n";
  const std::string run_briefly = "subsection Boundary conditions\n"
                                  "  set Dirichlet boundaries = 2:xy\n"
                                  "end\n"
                                  "subsection Output\n"
                                  "  set Interval = 0\n"
                                  "  set Directory = bad-input-out\n"
                                  "end\n"
                                  "subsection Load stepping\n"
                                  "  set Number of steps = 1\n";
  try_input("negative mobility",
            "Mobility",
            pore_fluid + "  set Mobility = -1\nend\n");
  try_input("zero mobility of a material id",
            "Mobility by material id",
            pore_fluid +
              "  set Mobility by material id = 0: 1e-6, 1: 0\nend\n");
  try_input("mobility by material id that is no map",
            "Mobility by material id",
            pore_fluid + "  set Mobility by material id = clay: 1e-6\nend\n");
  try_input("zero mobility",
            "Mobility",
            pore_fluid + "  set Mobility = 0\nend\n");
  try_input("Biot coefficient above 1",
            "Biot coefficient",
            pore_fluid + "  set Biot coefficient = 1.5\nend\n");
  try_input("drained boundary id that does not exist",
            "Drained boundaries",
            pore_fluid + "  set Drained boundaries = 3, 7\nend\n");
  try_input("flux boundary id that does not exist",
            "Flux boundaries",
            pore_fluid + "  set Flux boundaries = 9\nend\n");
  try_input("boundary both drained and with a flux",
            "Flux boundaries",
            pore_fluid + "  set Flux boundaries = 3\nend\n");
  try_input("boundary pore pressure that is no expression",
            "Boundary pore pressure",
            pore_fluid + "  set Boundary pore pressure = 1 +* y\nend\n");
  try_input("mobility factor that is no expression",
            "Mobility factor",
            pore_fluid + "  set Mobility factor = J^^2\nend\n");
  try_input("drained surface region that is no expression",
            "Drained surface region",
            pore_fluid + "  set Drained surface region = y >> 1\nend\n");
  try_input("drained surface region on no face of the body",
            "Drained surface region",
            pore_fluid + "  set Drained surface region = y > 5\nend\n" +
              run_briefly + "end\n",
            /*run=*/true);
  try_input("mobility factor that is not positive",
            "Mobility factor",
            pore_fluid + "  set Mobility factor = J - 2\nend\n" + run_briefly +
              "end\n",
            /*run=*/true);
  try_input("time that runs backwards",
            "time",
            pore_fluid + "end\n" + run_briefly +
              "  set Final load factor = -1\nend\n",
            /*run=*/true);
  try_input("drained boundary that no material touches",
            "Drained boundaries",
            pore_fluid +
              "end\n"
              "subsection Material points\n"
              "  set Region lower corner = 0, 0\n"
              "  set Region upper corner = 1, 0.5\n"
              "end\n" +
              run_briefly + "end\n",
            /*run=*/true);

  // Rigid plates (Boundary conditions/Rigid plate boundaries).
  try_input("rigid plate on a boundary a box does not have",
            "rigid plate",
            "subsection Boundary conditions\n"
            "  set Rigid plate boundaries = 9\n"
            "end\n");
  try_input("rigid plate that a displacement condition holds along its "
            "normal",
            "rigid plate",
            "subsection Boundary conditions\n"
            "  set Rigid plate boundaries = 3\n"
            "  set Traction boundaries = 3\n"
            "  subsection Traction\n"
            "    set Function expression = 0; -1\n"
            "  end\n"
            "end\n" +
              run_briefly + "end\n" +
              "subsection Boundary conditions\n"
              "  set Dirichlet boundaries = 2:xy, 3:n\n"
              "end\n",
            /*run=*/true);
  try_input("rigid plate with path following",
            "rigid plate",
            "subsection Boundary conditions\n"
            "  set Rigid plate boundaries = 3\n"
            "  set Traction boundaries = 3\n"
            "end\n" +
              run_briefly +
              "  set Control = dissipation\n"
              "  set Dissipation increment = 1\n"
              "end\n",
            /*run=*/true);
  try_input("rigid plate that no material touches",
            "rigid plate",
            "subsection Boundary conditions\n"
            "  set Rigid plate boundaries = 3\n"
            "  set Traction boundaries = 3\n"
            "end\n"
            "subsection Material points\n"
            "  set Region lower corner = 0, 0\n"
            "  set Region upper corner = 1, 0.5\n"
            "end\n" +
              run_briefly + "end\n",
            /*run=*/true);

  // Crack tracking of the smeared-crack model.
  const std::string tracking = "subsection Material\n"
                               "  set Model = smeared cracks\n"
                               "  subsection smeared cracks\n"
                               "    set Crack band width = 0.1\n"
                               "    set Crack tracking = true\n";
  try_input("crack tracking radius below one cell",
            "Crack tracking radius",
            tracking + "    set Crack tracking radius = 0.5\n  end\nend\n");
  try_input("crack tracking with a pore fluid",
            "Crack tracking",
            tracking + "  end\nend\n" + pore_fluid + "end\n");
  try_input("crack tracking in a material map",
            "Crack tracking",
            "subsection Material\n"
            "  set Models by material id = 1: smeared cracks\n"
            "  subsection smeared cracks\n"
            "    set Crack band width = 0.1\n"
            "    set Crack tracking = true\n"
            "  end\n"
            "end\n");

  // Contact between bodies (several bodies on a multi-field grid).
  const std::string two_bodies = "subsection Material points\n"
                                 "  set Material id = if(x < 0.5, 0, 1)\n"
                                 "end\n"
                                 "subsection Contact between bodies\n";
  try_input("contact between bodies with one body",
            "Contact between bodies",
            two_bodies + "  set Bodies = 0\nend\n");
  try_input("contact between bodies with a body that is no material id",
            "Contact between bodies",
            two_bodies + "  set Bodies = 0; x\nend\n");
  try_input("contact between bodies with a material id in two bodies",
            "Contact between bodies",
            two_bodies + "  set Bodies = 0; 0, 1\nend\n");
  try_input("contact between bodies with a negative friction coefficient",
            "Friction coefficient",
            two_bodies + "  set Bodies = 0; 1\n  set Friction = coulomb\n"
                         "  set Friction coefficient = -0.1\nend\n");
  try_input("contact between bodies with points of no body",
            "Contact between bodies",
            two_bodies + "  set Bodies = 0; 2\nend\n" + run_briefly + "end\n",
            /*run=*/true);
  // The contact example's sliding blocks (contact.prm, sliding_blocks())
  // with cpGIMP and at most one solve per step: in step 7, the first in
  // which B is pushed along A, the Coulomb contact set changes after the
  // first solve of every attempt (corners go from stick to slip). Each
  // attempt fails and is cut back until the run stops. The solves of an
  // attempt keep its preconditioner, so every attempt ends with a kept
  // one: the retry with a new preconditioner must come once per increment,
  // or the increment is never cut back and the run never stops.
  try_input(
    "contact between bodies whose contact set does not settle in one solve",
    "Max contact iterations",
    "subsection Geometry\n"
    "  set Upper corner = 2, 1\n"
    "  set Subdivisions = 16, 8\n"
    "end\n"
    "subsection Material points\n"
    "  set Region expression = if(y < 0.5 || (y > 0.5625 && x > 0.5 && x < "
    "1.5), 1, 0)\n"
    "  set Material id = if(y < 0.5, 0, 1)\n"
    "  set Shape functions = cpGIMP\n"
    "end\n"
    "subsection Contact between bodies\n"
    "  set Bodies = 0; 1\n"
    "  set Friction = coulomb\n"
    "  set Friction coefficient = 0.3\n"
    "  set Max contact iterations = 1\n"
    "end\n"
    "subsection Material\n"
    "  set Model = linear elastic\n"
    "  subsection linear elastic\n"
    "    set Young's modulus = 1000\n"
    "    set Poisson's ratio = 0.3\n"
    "  end\n"
    "end\n"
    "subsection Boundary conditions\n"
    "  set Dirichlet boundaries = 2:xy, 3:xy\n"
    "  subsection Displacement\n"
    "    set Function constants = g = 0.0625\n"
    "    set Function expression = if(y > 0.99, if(12 * t <= 4, 0, 0.001 * "
    "(12 * t - 4)), 0); if(y > 0.99, if(12 * t <= 2, -g * 6 * t, if(12 * t "
    "<= 4, -g - 0.0025 * (12 * t - 2), -g - 0.005)), 0)\n"
    "  end\n"
    "end\n"
    "subsection Load stepping\n"
    "  set Number of steps = 12\n"
    "end\n"
    "subsection Nonlinear solver\n"
    "  set Tolerance = 1e-10\n"
    "end\n"
    "subsection Output\n"
    "  set Interval = 0\n"
    "  set Directory = bad-input-out\n"
    "end\n",
    /*run=*/true);
  try_input("region expression that is no expression",
            "Region expression",
            "subsection Material points\n"
            "  set Region expression = x <\n"
            "end\n");

  // A missing file: deal.II's message names it.
  try
    {
      ParameterHandler prm;
      qsmpm::QuasiStaticProblem<2>::Parameters::declare_parameters(prm);
      prm.parse_input("no-such-file.prm");
      deallog << "missing file: accepted (FAIL)" << std::endl;
    }
  catch (const std::exception &exc)
    {
      report("missing file", "no-such-file.prm", exc.what());
    }

  // A step that cannot converge: one Newton iteration allowed, a tolerance
  // GMRES cannot reach in one, and two cut-backs. The run must stop, and the
  // points must still hold their initial (zero) displacement.
  {
    qsmpm::QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    problem.pcout().set_condition(false);
    problem.grid().make_box(Point<2>(), Point<2>(1, 1), {{4, 4}});
    problem.set_model(std::make_unique<qsmpm::LinearElastic<2>>(100., 0.3));
    problem.points().fill([](const Point<2> &) { return true; },
                          2,
                          qsmpm::MaterialPointSet<2>::Placement::regular);
    problem.boundary_conditions().add_dirichlet_boundary(
      0, {{true, true}}, std::make_shared<Functions::ZeroFunction<2>>(2));
    problem.boundary_conditions().set_body_force(
      std::make_shared<Functions::ConstantFunction<2>>(
        std::vector<double>{0., -100.}));
    auto &prm                             = problem.parameters();
    prm.nonlinear_solver.max_iterations   = 1;
    prm.nonlinear_solver.tolerance        = 1e-12;
    prm.nonlinear_solver.residual_floor   = 0.;
    prm.nonlinear_solver.linear_tolerance = 1e-2;
    prm.load_stepping.max_cut_backs       = 2;
    prm.output.directory                  = "results";
    prm.output.interval                   = 0;
    try
      {
        problem.run();
        deallog << "non-converging step: accepted (FAIL)" << std::endl;
      }
    catch (const std::exception &exc)
      {
        report("non-converging step",
               "Maximum cut-backs",
               qsmpm::Utils::error_message(exc));
      }
    double max_u = 0;
    for (const auto &particle : problem.points().get_particle_handler())
      for (unsigned int d = 0; d < 2; ++d)
        max_u =
          std::max(max_u,
                   std::abs(
                     particle.get_properties()
                       [problem.points().get_offsets().displacement + d]));
    check("  displacement committed by the failed step", max_u, 0.);
  }
}
