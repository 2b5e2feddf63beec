#ifndef qsmpm_base_huge_pages_h
#define qsmpm_base_huge_pages_h

// No deal.II here: the launcher `qsmpm` (apps/launcher.cc) includes this
// and links nothing but the C++ library.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#if defined(__GLIBC__)
#  include <gnu/libc-version.h>
#endif

namespace qsmpm
{
  namespace Utils
  {
    /**
     * Ask the C library of the program that this process executes next to
     * back its heap with transparent huge pages (2 MiB pages instead of
     * 4 KiB), where that helps and the user has not chosen: set the
     * environment variable GLIBC_TUNABLES to contain glibc.malloc.hugetlb=1.
     * glibc (from 2.35) reads it only when a program starts, so this is for
     * a launcher that then executes the program (apps/launcher.cc). Returns
     * whether it set the variable.
     *
     * Why: with transparent huge pages in "madvise" mode (the kernel's
     * default on many distributions) memory gets huge pages only where a
     * program asks for them. A run spends much of its time in memory it has
     * just allocated (the stiffness, the AMG hierarchy, the points' data)
     * and in sparse products over it; first touching a 4 KiB page and
     * translating its addresses is a large part of that. Measured with the
     * driver on the 256 x 256 strip (doc/benchmarks.md): 47,000 page
     * faults instead of 137,000 and the whole process about a quarter
     * faster, with 2 % more resident memory.
     *
     * Nothing is set where GLIBC_TUNABLES already mentions
     * glibc.malloc.hugetlb (the user's choice: glibc.malloc.hugetlb=0 keeps
     * 4 KiB pages), the C library is not glibc 2.35 or newer, the kernel's
     * mode (/sys/kernel/mm/transparent_hugepage/enabled) is not "madvise"
     * ("always" needs no request, "never" grants none), or LD_PRELOAD is
     * set (a preloaded allocator or a tool such as valgrind).
     */
    inline bool
    request_huge_pages()
    {
#if defined(__GLIBC__) && defined(__linux__)
      const std::string entry    = "glibc.malloc.hugetlb";
      const char       *tunables = std::getenv("GLIBC_TUNABLES");
      const std::string old_value(tunables != nullptr ? tunables : "");
      if (old_value.find(entry) != std::string::npos)
        return false;
      const char *preload = std::getenv("LD_PRELOAD");
      if (preload != nullptr && preload[0] != '\0')
        return false;
      int major = 0, minor = 0;
      if (std::sscanf(gnu_get_libc_version(), "%d.%d", &major, &minor) != 2 ||
          major * 1000 + minor < 2035)
        return false;
      std::ifstream mode_file("/sys/kernel/mm/transparent_hugepage/enabled");
      std::string   mode;
      if (!std::getline(mode_file, mode) ||
          mode.find("[madvise]") == std::string::npos)
        return false;
      const std::string value =
        (old_value.empty() ? "" : old_value + ":") + entry + "=1";
      return setenv("GLIBC_TUNABLES", value.c_str(), /*overwrite=*/1) == 0;
#else
      return false;
#endif
    }

    /**
     * Whether the user asked the launcher for huge pages: the environment
     * variable QSMPM_HUGE_PAGES is 1, on, yes or true. The launcher
     * (apps/launcher.cc) calls request_huge_pages() only then.
     *
     * Why not always: whether huge pages pay depends on the machine
     * (doc/benchmarks.md, "Huge pages", measures both kinds). Where memory
     * is cheap to touch they make large runs faster. In a virtual machine
     * whose balloon device reports free memory to its host, the 2 MiB pages
     * come from large free blocks whose memory the guest has handed back,
     * each first touch waits for the host, and the runs get slower.
     */
    inline bool
    huge_pages_wanted()
    {
      const char *value = std::getenv("QSMPM_HUGE_PAGES");
      if (value == nullptr)
        return false;
      const std::string v(value);
      return v == "1" || v == "on" || v == "yes" || v == "true";
    }
  } // namespace Utils
} // namespace qsmpm

#endif
