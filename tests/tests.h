// A small stand-in for deal.II's tests/tests.h (Debian does not install it):
// deallog goes to the file "output" that the test harness compares with the
// .output file, and MPI tests log from rank 0 only.
#ifndef qsmpm_tests_h
#define qsmpm_tests_h

#include <cmath>
#include <cstdlib>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

using namespace dealii;

namespace qsmpm_tests
{
  inline std::ofstream &
  logfile()
  {
    static std::ofstream file;
    return file;
  }

  /// Serial tests: log to "output".
  inline void
  initlog()
  {
    logfile().open("output");
    logfile() << std::setprecision(6);
    deallog.attach(logfile(), /*print_job_id=*/false);
    deallog.depth_console(0);
  }

  /// MPI tests: rank 0 logs to "output", the others stay silent.
  class MPILogInitAll
  {
  public:
    MPILogInitAll()
    {
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        initlog();
      else
        deallog.depth_console(0);
    }
    ~MPILogInitAll()
    {
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        deallog.detach();
    }
  };

  /// A tolerance as written by a person: 1e-10, 0.05, 1.8.
  inline std::string
  format(const double value)
  {
    std::ostringstream s;
    s << std::setprecision(3) << value;
    return s.str();
  }

  /// With QSMPM_VERBOSE set, the measured value also goes to stdout (never
  /// to the compared output).
  inline void
  print_value(const std::string &what, const double value)
  {
    if (std::getenv("QSMPM_VERBOSE") != nullptr &&
        (!Utilities::MPI::job_supports_mpi() ||
         Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0))
      std::cout << "value of " << what << ": " << std::setprecision(6) << value
                << std::endl;
  }

  /**
   * "PASS" if |value| <= tolerance, else "FAIL" with the value. The value
   * itself is printed only on failure, so that the output does not depend on
   * round-off (and to stdout with QSMPM_VERBOSE set).
   */
  inline void
  check(const std::string &what, const double value, const double tolerance)
  {
    print_value(what, value);
    const bool pass = std::isfinite(value) && std::abs(value) <= tolerance;
    deallog << what << " <= " << format(tolerance) << ": "
            << (pass ? "PASS" : "FAIL");
    if (!pass)
      deallog << " (value " << value << ")";
    deallog << std::endl;
  }

  /// "PASS" if value >= bound, else "FAIL" with the value.
  inline void
  check_at_least(const std::string &what,
                 const double       value,
                 const double       bound)
  {
    print_value(what, value);
    const bool pass = std::isfinite(value) && value >= bound;
    deallog << what << " >= " << format(bound) << ": "
            << (pass ? "PASS" : "FAIL");
    if (!pass)
      deallog << " (value " << value << ")";
    deallog << std::endl;
  }

  /// The motion (0, -s t) (in 3D (0, -s t, 0)) of a footing pushed down
  /// by @p s per unit of the load factor t (the time of the functions the
  /// problem evaluates).
  template <int dim = 2>
  inline std::shared_ptr<Function<dim>>
  downward_motion(const double s)
  {
    auto motion = std::make_shared<FunctionParser<dim>>(dim);
    motion->initialize(dim == 2 ? "x,y,t" : "x,y,z,t",
                       dim == 2 ? "0; -s*t" : "0; -s*t; 0",
                       {{"s", s}},
                       true);
    return motion;
  }

  /// "PASS" or "FAIL" for a boolean condition.
  inline void
  check_that(const std::string &what, const bool condition)
  {
    deallog << what << ": " << (condition ? "PASS" : "FAIL") << std::endl;
  }
} // namespace qsmpm_tests

using namespace qsmpm_tests;

#endif
