// Utils::choose_mpi_startup(), which libqsmpm calls when it is loaded,
// before MPI starts: Open MPI's ob1 layer (OMPI_MCA_pml) and no daemon
// (OMPI_MCA_ess_singleton_isolated) for a process that no launcher
// started; ob1 alone where Open MPI's mpirun started every rank of the job
// on this machine (OMPI_COMM_WORLD_LOCAL_SIZE equal to
// OMPI_COMM_WORLD_SIZE); nothing over the user's own settings, where ranks
// run on other machines, or under another launcher (PMIX_RANK without
// OMPI_COMM_WORLD_SIZE, as srun sets it). The environment is set here for
// each case; the output is the same however the test is run. (What the
// choices save is measured in doc/benchmarks.md, not here.)
#include "tests.h"

#include <qsmpm/base/mpi_transport.h>

namespace
{
  using qsmpm::Utils::MpiStartup;

  std::string
  get(const char *name)
  {
    const char *value = std::getenv(name);
    return value != nullptr ? value : "<unset>";
  }

  void
  set(const char *name, const char *value)
  {
    if (value != nullptr)
      setenv(name, value, 1);
    else
      unsetenv(name);
  }

  /// The environment of one case: mpirun's sizes, another launcher's rank,
  /// the user's pml.
  void
  environment(const char *size,
              const char *local,
              const char *pmix_rank,
              const char *user_pml)
  {
    set("OMPI_COMM_WORLD_SIZE", size);
    set("OMPI_COMM_WORLD_LOCAL_SIZE", local);
    set("PMIX_RANK", pmix_rank);
    set("PMI_RANK", nullptr);
    set("PMI_SIZE", nullptr);
    set("OMPI_MCA_pml", user_pml);
    set("OMPI_MCA_ess_singleton_isolated", nullptr);
  }

  void
  expect(const std::string &what,
         const MpiStartup   expected,
         const std::string &pml,
         const std::string &isolated)
  {
    const MpiStartup chosen = qsmpm::Utils::choose_mpi_startup();
    check_that(what + ": OMPI_MCA_pml " + pml +
                 ", OMPI_MCA_ess_singleton_isolated " + isolated,
               chosen == expected && get("OMPI_MCA_pml") == pml &&
                 get("OMPI_MCA_ess_singleton_isolated") == isolated);
  }
} // namespace

int
main()
{
  initlog();
  environment(nullptr, nullptr, nullptr, nullptr);
  expect("no launcher", MpiStartup::singleton, "ob1", "1");
  environment(nullptr, nullptr, nullptr, "ucx");
  expect("no launcher, the user's pml", MpiStartup::singleton, "ucx", "1");
  environment("2", "2", "0", nullptr);
  expect("mpirun, 2 ranks on this machine",
         MpiStartup::one_machine,
         "ob1",
         "<unset>");
  environment("1", "1", "0", nullptr);
  expect("mpirun, 1 rank", MpiStartup::one_machine, "ob1", "<unset>");
  environment("2", "2", "0", "ucx");
  expect("mpirun, the user's pml", MpiStartup::unchanged, "ucx", "<unset>");
  environment("8", "4", "0", nullptr);
  expect("mpirun, 4 of 8 ranks on this machine",
         MpiStartup::unchanged,
         "<unset>",
         "<unset>");
  environment(nullptr, nullptr, "0", nullptr);
  expect("another launcher", MpiStartup::unchanged, "<unset>", "<unset>");
}
