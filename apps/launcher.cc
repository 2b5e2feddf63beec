// The command `qsmpm`: starts the general driver `qsmpm-driver`
// (apps/qsmpm.cc), which lies in the same directory, with the same
// arguments, after asking its C library for huge pages where that helps
// (Utils::request_huge_pages()). glibc reads that request only when a
// program starts, and the driver links deal.II, Trilinos, PETSc and their
// dependencies, whose loading takes about half a second: this small
// program, which links none of them, makes the request instead of the
// driver restarting itself. `qsmpm-driver` may be run directly; it then
// runs with the C library's defaults.
#include <cerrno>
#include <cstring>
#include <iostream>
#include <qsmpm/base/huge_pages.h>
#include <string>
#include <unistd.h>

int
main(int /*argc*/, char *argv[])
{
  // The directory of this executable, wherever it was installed or called
  // from.
  std::string   self(4096, '\0');
  const ssize_t length =
    readlink("/proc/self/exe", self.data(), self.size() - 1);
  if (length <= 0)
    {
      std::cerr << "qsmpm: cannot find its own executable (/proc/self/exe): "
                << std::strerror(errno) << std::endl;
      return 1;
    }
  self.resize(length);
  const std::string driver =
    self.substr(0, self.find_last_of('/') + 1) + "qsmpm-driver";

  qsmpm::Utils::request_huge_pages();
  execv(driver.c_str(), argv);
  std::cerr << "qsmpm: cannot start " << driver << ": " << std::strerror(errno)
            << std::endl;
  return 1;
}
