// Utils::request_huge_pages(), which the launcher `qsmpm` calls before it
// starts the driver if Utils::huge_pages_wanted() (QSMPM_HUGE_PAGES=1): it
// adds glibc.malloc.hugetlb=1 to GLIBC_TUNABLES only
// where the kernel grants transparent huge pages on request ("madvise") and
// the C library is glibc 2.35 or newer, keeps what the variable held, never
// overrides the user's own hugetlb entry, leaves a process with LD_PRELOAD
// alone, and does nothing the second time (the driver it starts does not
// ask again). The expectation of the third check is derived here from the
// kernel's mode file; the output is the same on every machine.
#include "tests.h"

#include <qsmpm/base/huge_pages.h>

namespace
{
  void
  check(const bool ok, const std::string &what)
  {
    deallog << what << ": " << (ok ? "pass" : "FAIL") << std::endl;
  }

  std::string
  tunables()
  {
    const char *value = std::getenv("GLIBC_TUNABLES");
    return value != nullptr ? value : "<unset>";
  }
} // namespace

int
main()
{
  initlog();
  unsetenv("LD_PRELOAD");

  // 1. The user's choice stands.
  setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=0", 1);
  check(!qsmpm::Utils::request_huge_pages() &&
          tunables() == "glibc.malloc.hugetlb=0",
        "a hugetlb entry of the user is kept");

  // 2. A preloaded library (an allocator, valgrind): nothing is set.
  unsetenv("GLIBC_TUNABLES");
  setenv("LD_PRELOAD", "libsomething.so", 1);
  check(!qsmpm::Utils::request_huge_pages() && tunables() == "<unset>",
        "with LD_PRELOAD nothing is set");
  unsetenv("LD_PRELOAD");

  // 3. Other tunables are kept; the entry is appended where the system
  // grants huge pages on request.
  bool expected = false;
#if defined(__GLIBC__) && defined(__linux__)
  {
    std::ifstream file("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string   mode;
    int           major = 0, minor = 0;
    std::sscanf(gnu_get_libc_version(), "%d.%d", &major, &minor);
    expected = std::getline(file, mode) &&
               mode.find("[madvise]") != std::string::npos &&
               (major > 2 || (major == 2 && minor >= 35));
  }
#endif
  setenv("GLIBC_TUNABLES", "glibc.malloc.arena_max=2", 1);
  const bool set = qsmpm::Utils::request_huge_pages();
  check(set == expected &&
          tunables() == (expected ? "glibc.malloc.arena_max=2:"
                                    "glibc.malloc.hugetlb=1" :
                                    "glibc.malloc.arena_max=2"),
        "other tunables are kept, the entry added where it helps");

  // 4. Asked again (the started driver): nothing changes.
  const std::string before = tunables();
  check(!qsmpm::Utils::request_huge_pages() && tunables() == before,
        "a second request changes nothing");

  // 5. The launcher asks only if the user wants huge pages.
  unsetenv("QSMPM_HUGE_PAGES");
  bool opt_in_only = !qsmpm::Utils::huge_pages_wanted();
  for (const char *no : {"0", "off", "", "2"})
    {
      setenv("QSMPM_HUGE_PAGES", no, 1);
      opt_in_only = opt_in_only && !qsmpm::Utils::huge_pages_wanted();
    }
  for (const char *yes : {"1", "on", "yes", "true"})
    {
      setenv("QSMPM_HUGE_PAGES", yes, 1);
      opt_in_only = opt_in_only && qsmpm::Utils::huge_pages_wanted();
    }
  check(opt_in_only, "huge pages only where QSMPM_HUGE_PAGES asks for them");
}
