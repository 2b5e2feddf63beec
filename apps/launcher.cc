// The command `qsmpm`: starts the general driver `qsmpm-driver`
// (apps/qsmpm.cc), which lies in the same directory, with the same
// arguments. If the user set QSMPM_HUGE_PAGES=1 it first asks the C library
// for huge pages (Utils::request_huge_pages(); Utils::huge_pages_wanted()
// says why that is not the default). glibc reads that request only when a
// program starts, and the driver links deal.II, Trilinos, PETSc and their
// dependencies, whose loading takes about half a second: this small
// program, which links none of them, makes the request instead of the
// driver restarting itself. `qsmpm-driver` may be run directly; it then
// runs with the C library's defaults.
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <qsmpm/base/huge_pages.h>
#include <unistd.h>

int
main(int /*argc*/, char *argv[])
{
  // Next to this executable, wherever it was installed or called from.
  std::error_code             error;
  const std::filesystem::path driver =
    std::filesystem::read_symlink("/proc/self/exe", error).parent_path() /
    "qsmpm-driver";
  if (!error)
    {
      if (qsmpm::Utils::huge_pages_wanted())
        qsmpm::Utils::request_huge_pages();
      execv(driver.c_str(), argv);
    }
  std::cerr << "qsmpm: cannot start " << driver.string() << ": "
            << (error ? error.message() : std::strerror(errno)) << std::endl;
  return 1;
}
