#ifndef qsmpm_base_mpi_transport_h
#define qsmpm_base_mpi_transport_h

// No deal.II here: used before main(), before MPI starts.
#include <cstdlib>
#include <string>

namespace qsmpm
{
  namespace Utils
  {
    /// What choose_mpi_startup() set.
    enum class MpiStartup
    {
      /// Nothing: the user's choice, another launcher, or ranks on
      /// several machines.
      unchanged,
      /// A process that no launcher started: ob1, no daemon.
      singleton,
      /// All ranks of an mpirun job on this machine: ob1.
      one_machine
    };

    /**
     * Open MPI's settings for how MPI starts, chosen from the environment
     * before MPI_Init (libqsmpm calls this when it is loaded, before main(),
     * in source/base/utilities.cc). Open MPI reads them from environment
     * variables, which are set only where the user has not set them; other
     * MPI libraries ignore them. What each saves is measured in
     * doc/benchmarks.md, "Start-up".
     *
     * - A process that no MPI launcher started (`./compact_tension
     *   b15.prm`) is a singleton: MPI_COMM_WORLD is this one process. Open
     *   MPI treats it as if it might grow and pays for that twice: it tries
     *   all its point-to-point layers (the cm layer probes the high-speed
     *   networks, libfabric, PSM), and it starts a daemon (orted) beside
     *   itself, which only MPI_Comm_spawn would use. Such a process sends
     *   messages only to itself: OMPI_MCA_pml = ob1 and
     *   OMPI_MCA_ess_singleton_isolated = 1 (no daemon).
     * - All ranks of a job that Open MPI's mpirun started on this machine
     *   (OMPI_COMM_WORLD_LOCAL_SIZE, the ranks here, equals
     *   OMPI_COMM_WORLD_SIZE, all of them): Open MPI prefers UCX wherever it
     *   is installed (Debian's is built with it), and UCX looks for every
     *   network device it could use; between ranks of one machine Open
     *   MPI's own ob1 layer moves messages through shared memory as well:
     *   OMPI_MCA_pml = ob1.
     * - Anything else is left alone: ranks on other machines (there UCX is
     *   the fast way), and processes of another launcher (srun: PMIX_RANK
     *   or PMI_RANK without OMPI_COMM_WORLD_SIZE), whose placement is not
     *   known here.
     */
    inline MpiStartup
    choose_mpi_startup()
    {
      const char *size  = std::getenv("OMPI_COMM_WORLD_SIZE");
      const char *local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
      if (size != nullptr)
        {
          if (local == nullptr || std::string(size) != std::string(local) ||
              std::getenv("OMPI_MCA_pml") != nullptr)
            return MpiStartup::unchanged;
          setenv("OMPI_MCA_pml", "ob1", /*overwrite=*/0);
          return MpiStartup::one_machine;
        }
      for (const char *launched : {"PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
        if (std::getenv(launched) != nullptr)
          return MpiStartup::unchanged;
      setenv("OMPI_MCA_pml", "ob1", /*overwrite=*/0);
      setenv("OMPI_MCA_ess_singleton_isolated", "1", /*overwrite=*/0);
      return MpiStartup::singleton;
    }
  } // namespace Utils
} // namespace qsmpm

#endif
