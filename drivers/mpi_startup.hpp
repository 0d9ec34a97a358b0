#pragma once
// Open MPI start-up for a process that was not launched by mpirun (a singleton run,
// `grout input.yaml`). Open MPI 4.1's defaults probe every transport component and start a
// helper daemon, ~0.3 s per process; a single process needs neither. Before MPI_Init, and
// only for variables the user has not set (their values always win):
//   OMPI_MCA_pml=ob1, OMPI_MCA_btl=self,vader     shared-memory transports only
//   OMPI_MCA_ess_singleton_isolated=1            no daemon for a singleton
// Under a launcher (mpirun, srun, a PMI/PMIx environment) nothing is set: a run over several
// machines needs its network transports. tools/local_mpi_env does the same for local mpirun.

#include <cstdlib>

namespace grout {

/// True when a launcher started this process (Open MPI's mpirun, or any PMI/PMIx launcher).
inline bool launched_by_mpi_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(name)) return true;
  return false;
}

/// Call before MPI_Init (e.g. before Tpetra::ScopeGuard).
inline void prefer_local_mpi_startup() {
  if (launched_by_mpi_launcher()) return;
  setenv("OMPI_MCA_pml", "ob1", 0);  // 0: keep the user's value
  setenv("OMPI_MCA_btl", "self,vader", 0);
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
}

}  // namespace grout
