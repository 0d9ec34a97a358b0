#pragma once
// Open MPI start-up for a process that was not launched by mpirun (a singleton run,
// `grout input.yaml`). Open MPI 4.1's defaults probe every transport component and start a
// helper daemon, ~0.3 s per process; a single process needs neither. Before MPI_Init, and
// only for variables the user has not set (their values always win):
//   OMPI_MCA_pml=ob1, OMPI_MCA_btl=self,vader     shared-memory transports only
//   OMPI_MCA_ess_singleton_isolated=1            no daemon for a singleton
//   OMPI_MCA_orte_create_session_dirs=0          no session directory for a singleton
// The last one is a fix, not a speed-up: every Open MPI 4.1 singleton uses the same session
// directory, /tmp/ompi.<host>.<uid>/jf.0/1, and removes it at MPI_Finalize. Singletons that
// start while another one finishes then fail in MPI_Init ("A call to mkdir was unable to
// create the desired directory ... jf.0/1", open-mpi/ompi issues 3818 and 8510): 5 in 300
// when 60 start at once on this 2-core machine, 0 in 300 without the directory. ctest -j 2
// runs singletons side by side, and CI failed once on it. An isolated singleton has no peer
// to share memory with and writes nothing there.
// A singleton also opens only the components it selects anyway, instead of loading every
// installed one to query it (each dlopen resolves the component's symbols through the ~90
// libraries already loaded), and hwloc skips the I/O devices, whose discovery reads each PCI
// device's config space (slow under a hypervisor) and loads the GL/OpenCL plugins with libX11:
//   OMPI_MCA_coll=self,basic,libnbc   the modules a 1-rank communicator gets by default
//   OMPI_MCA_state=app, OMPI_MCA_errmgr=default_app, OMPI_MCA_schizo=orte,
//   OMPI_MCA_reachable=netlink, OMPI_MCA_shmem=mmap      what Open MPI 4.1 selects for a singleton
//   HWLOC_COMPONENTS=-linuxio, HWLOC_PLUGINS_BLACKLIST=hwloc_pci,hwloc_gl,...   CPUs and memory
//   only
// The same components do the same work, so nothing else changes (the selections above are
// Open MPI 4.1's, Debian 12's; with them a singleton's MPI start-up takes 0.02 s:
// docs/performance.md, "Process start-up and Open MPI settings").
// Under Open MPI's mpirun with every rank on this machine (OMPI_COMM_WORLD_LOCAL_SIZE equal
// to OMPI_COMM_WORLD_SIZE, both set by mpirun for each rank) the first two are set as well:
// the ranks need no network transport, and a plain `mpirun -np 2` then starts in 0.22 s
// instead of 0.44 s (bare MPI_Init + MPI_Finalize, 2 ranks, this 2-core machine under load;
// docs/performance.md, "Process start-up and Open MPI settings"). Under any other launcher
// (srun, a PMI/PMIx environment) and for ranks on several machines nothing is set: a run
// over several machines needs its network transports. tools/local_mpi_env does the same for
// local mpirun.

#include <arpa/inet.h>
#include <dirent.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>

#include <cstdlib>
#include <cstring>

namespace grout {

/// True when a launcher started this process (Open MPI's mpirun, or any PMI/PMIx launcher).
inline bool launched_by_mpi_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(name)) return true;
  return false;
}

/// True when Open MPI's mpirun started this process and every rank of the job on this
/// machine: mpirun sets OMPI_COMM_WORLD_SIZE and OMPI_COMM_WORLD_LOCAL_SIZE for each rank.
inline bool every_open_mpi_rank_on_this_machine() {
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  const char* local_size = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  return size && local_size && *size && std::strcmp(size, local_size) == 0;
}

/// Call before MPI_Init (e.g. before Tpetra::ScopeGuard).
inline void prefer_local_mpi_startup() {
  const bool launched = launched_by_mpi_launcher();
  if (launched && !every_open_mpi_rank_on_this_machine()) return;
  setenv("OMPI_MCA_pml", "ob1", 0);  // 0: keep the user's value
  setenv("OMPI_MCA_btl", "self,vader", 0);
  if (launched) return;  // the rest is for a singleton only
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  setenv("OMPI_MCA_orte_create_session_dirs", "0", 0);
  setenv("OMPI_MCA_coll", "self,basic,libnbc", 0);
  setenv("OMPI_MCA_state", "app", 0);
  setenv("OMPI_MCA_errmgr", "default_app", 0);
  setenv("OMPI_MCA_schizo", "orte", 0);
  setenv("OMPI_MCA_reachable", "netlink", 0);
  setenv("OMPI_MCA_shmem", "mmap", 0);
  setenv("HWLOC_COMPONENTS", "-linuxio", 0);
  setenv("HWLOC_PLUGINS_BLACKLIST",
         "hwloc_pci,hwloc_gl,hwloc_opencl,hwloc_cuda,hwloc_nvml,hwloc_rsmi,hwloc_levelzero,"
         "hwloc_xml_libxml",
         0);
}

/// True for a loopback address (127.0.0.0/8, ::1, or ::ffff:127.x.y.z).
inline bool is_loopback(const sockaddr_storage& address) {
  if (address.ss_family == AF_INET) {
    const auto& v4 = reinterpret_cast<const sockaddr_in&>(address);
    return (ntohl(v4.sin_addr.s_addr) >> 24) == 127;
  }
  if (address.ss_family == AF_INET6) {
    const in6_addr& v6 = reinterpret_cast<const sockaddr_in6&>(address).sin6_addr;
    return IN6_IS_ADDR_LOOPBACK(&v6) || (IN6_IS_ADDR_V4MAPPED(&v6) && v6.s6_addr[12] == 127);
  }
  return false;
}

/// Call after MPI_Init. Under Open MPI's mpirun with every rank on this machine, each rank
/// talks to mpirun's PMIx server over a loopback TCP connection that PMIx 4.2 (Debian 12)
/// opens without TCP_NODELAY. MPI_Finalize sends it a few small messages in a row, then waits
/// for the fence's answer: Nagle's algorithm holds the last one back until the server's delayed
/// ACK, 40 ms on Linux, in every run (measured: MPI_Finalize 45 ms, 2.5 ms with TCP_NODELAY;
/// a 2-rank MPI_Init + MPI_Finalize under tools/local_mpi_env 90 -> 48 ms; docs/performance.md,
/// "Process start-up and Open MPI settings"). Sets TCP_NODELAY on the process's TCP
/// sockets whose peer is a loopback address: the shared-memory transports (the settings above)
/// open no other, and on loopback the option only changes when small messages leave. Returns
/// the number of sockets set.
inline int no_delay_on_local_launcher_sockets() {
  if (!every_open_mpi_rank_on_this_machine()) return 0;
  DIR* fds = opendir("/proc/self/fd");
  if (fds == nullptr) return 0;
  const int own = dirfd(fds);
  int count = 0;
  while (const dirent* entry = readdir(fds)) {
    char* end = nullptr;
    const long fd = std::strtol(entry->d_name, &end, 10);
    if (end == entry->d_name || *end != '\0' || fd == own) continue;
    int type = 0;
    socklen_t length = sizeof type;
    if (getsockopt(static_cast<int>(fd), SOL_SOCKET, SO_TYPE, &type, &length) != 0 ||
        type != SOCK_STREAM)
      continue;
    sockaddr_storage peer{};
    socklen_t peer_length = sizeof peer;
    if (getpeername(static_cast<int>(fd), reinterpret_cast<sockaddr*>(&peer), &peer_length) != 0 ||
        !is_loopback(peer))
      continue;
    const int on = 1;
    if (setsockopt(static_cast<int>(fd), IPPROTO_TCP, TCP_NODELAY, &on, sizeof on) == 0) ++count;
  }
  closedir(fds);
  return count;
}

}  // namespace grout
