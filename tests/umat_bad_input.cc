// The UMAT adapter's answers to bad input and to a UMAT that fails.
//
// 1. Set-up errors: each stops with one line that names the entry of
//    subsection Material/umat that is wrong: a library that does not
//    exist, a symbol that is not in the library, too few Properties (the
//    elastic UMAT reads PROPS(2), the probe call finds it NaN), NSTATV = 0
//    for the von Mises UMAT (it writes STATEV(1) beyond the guard), and
//    Initial state variables of the wrong length.
// 2. PNEWDT: tests/umat/umat_fails.c (linear elastic) asks for a smaller
//    increment (PNEWDT = 0.5) when a strain increment exceeds 2e-4. The
//    strip of umat_small_strain in one load step (strains about 1e-3)
//    must be cut back, finish, and give the displacements of `linear
//    elastic` over the same load steps to 1e-8 (both to a Newton tolerance
//    of 1e-12).
// 3. NaN: the same UMAT returns a stress of NaN once a strain exceeds
//    5e-4: the run must stop (cut-backs do not help) with the report of
//    the point on stderr, naming the material and the point's NOEL.
#include "prm_text.h"
#include "tests.h"

#include <qsmpm/core/quasi_static_problem.h>
#include <qsmpm/materials/umat.h>

using namespace qsmpm;

namespace
{
  const std::string umat_dir = QSMPM_UMAT_DIR;

  Umat<2>::Parameters
  elastic()
  {
    Umat<2>::Parameters p;
    p.library       = umat_dir + "/libumat_elastic.so";
    p.material_name = "ELASTIC";
    p.properties    = {1e6, 0.3};
    return p;
  }

  void
  expect_error(const std::string         &name,
               const Umat<2>::Parameters &p,
               const std::string         &entry)
  {
    std::string message = "(no error)";
    try
      {
        Umat<2> model(p);
      }
    catch (const std::exception &exc)
      {
        message = Utils::error_message(exc);
      }
    if (std::getenv("QSMPM_VERBOSE") != nullptr)
      std::cout << name << ": " << message << std::endl;
    check_that(name + ": one line naming <" + entry + ">",
               message.find(entry) != std::string::npos &&
                 message.find('\n') == std::string::npos);
  }

  std::string
  strip_prm(const std::string &properties, const unsigned int n_steps)
  {
    std::ostringstream prm;
    prm << "set Dimension = 2\n"
        << "subsection Geometry\n  set Subdivisions = 16,16\nend\n"
        << "subsection Material\n";
    if (properties.empty())
      prm << "  set Model = linear elastic\n  subsection linear elastic\n"
          << "    set Young's modulus = 1e6\n    set Poisson's ratio = 0.3\n";
    else
      prm << "  set Model = umat\n  subsection umat\n"
          << "    set UMAT library = " << umat_dir << "/libumat_fails.so\n"
          << "    set Material name = FAILS\n"
          << "    set Properties = " << properties << "\n";
    prm << "  end\nend\n"
        << "subsection Boundary conditions\n"
        << "  set Dirichlet boundaries = 0:x, 1:x, 2:y\n"
        << "  set Traction boundaries = 3\n"
        << "  subsection Traction\n"
        << "    set Function expression = 0; -1e3*t*(x<0.5 ? 1 : 0)\n"
        << "  end\nend\n"
        << "subsection Load stepping\n  set Number of steps = " << n_steps
        << "\nend\n"
        << "subsection Nonlinear solver\n  set Tolerance = 1e-12\nend\n"
        << "subsection Output\n  set Interval = 0\n"
        << "  set Directory = umat-out\nend\n";
    return prm.str();
  }

} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPILogInitAll                    log;

  deallog << "1. Set-up errors" << std::endl;
  {
    auto p    = elastic();
    p.library = "/no/such/dir/libnothing.so";
    expect_error("missing library", p, "UMAT library");
  }
  {
    auto p   = elastic();
    p.symbol = "no_such_umat_";
    expect_error("missing symbol", p, "Symbol");
  }
  {
    auto p       = elastic();
    p.properties = {1e6};
    expect_error("NPROPS too small", p, "Properties");
  }
  {
    auto p          = elastic();
    p.library       = umat_dir + "/libumat_von_mises.so";
    p.properties    = {1e6, 0.3, 600., 1e4};
    p.material_name = "VON_MISES";
    expect_error("NSTATV = 0 for von Mises", p, "Number of state variables");
  }
  {
    auto p                    = elastic();
    p.n_state_variables       = 2;
    p.initial_state_variables = {1.};
    expect_error("initial state of the wrong length",
                 p,
                 "Initial state variables");
  }

  deallog << "2. PNEWDT < 1 cuts the step back" << std::endl;
  {
    QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
    initialize_from_text(problem, strip_prm("1e6, 0.3, 1, 2e-4", 1));
    problem.run();
    const auto  &reports   = problem.step_reports();
    unsigned int cut_backs = 0;
    bool         uniform   = true;
    for (unsigned int s = 0; s < reports.size(); ++s)
      {
        cut_backs += reports[s].cut_backs;
        uniform = uniform && std::abs(reports[s].load_factor -
                                      (s + 1.) / reports.size()) < 1e-12;
      }
    check_that("the load step was cut back and the run reached t = 1 in "
               "equal steps",
               cut_backs > 0 && uniform);
    // The points move with every step, so the reference takes the same
    // steps.
    QuasiStaticProblem<2> reference(MPI_COMM_WORLD);
    initialize_from_text(reference, strip_prm("", reports.size()));
    reference.run();
    const auto u     = point_displacements(problem),
               u_ref = point_displacements(reference);
    double largest = 0., diff = 0.;
    for (const auto &[id, v] : u_ref)
      {
        largest = std::max(largest, v.norm());
        diff    = std::max(diff, (v - u.at(id)).norm());
      }
    check("max |u - u_linear elastic| / max |u|", diff / largest, 1e-8);
  }

  deallog << "3. A stress of NaN stops the run" << std::endl;
  {
    std::ostringstream captured;
    std::streambuf    *cerr_buffer = std::cerr.rdbuf(captured.rdbuf());
    bool               stopped     = false;
    try
      {
        QuasiStaticProblem<2> problem(MPI_COMM_WORLD);
        initialize_from_text(problem, strip_prm("1e6, 0.3, 5e-4, 1", 5));
        problem.run();
      }
    catch (const std::exception &)
      {
        stopped = true;
      }
    std::cerr.rdbuf(cerr_buffer);
    if (std::getenv("QSMPM_VERBOSE") != nullptr)
      std::cout << captured.str();
    check_that("the run stopped", stopped);
    check_that("stderr names the material and the point",
               captured.str().find("UMAT 'FAILS' returned a stress that is "
                                   "not a finite number at point NOEL = ") !=
                 std::string::npos);
  }
}
