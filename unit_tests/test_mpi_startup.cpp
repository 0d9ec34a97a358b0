// Open MPI start-up settings chosen before MPI_Init (drivers/mpi_startup.hpp): which environment
// gets the shared-memory transports, and that a value the user set is never replaced. Each test
// sets the launcher's variables itself and restores the whole environment it touched afterwards
// (MPI is already initialised here, so the variables only feed the function under test).
// Also TCP_NODELAY on loopback connections under a local mpirun (no_delay_on_local_launcher_
// sockets), on a connection this test opens itself.

#include <gtest/gtest.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <map>
#include <optional>
#include <string>

#include "drivers/mpi_startup.hpp"

namespace grout {
namespace {

const char* const kVariables[] = {"OMPI_COMM_WORLD_SIZE",
                                  "OMPI_COMM_WORLD_LOCAL_SIZE",
                                  "PMIX_RANK",
                                  "PMI_RANK",
                                  "PMI_SIZE",
                                  "OMPI_MCA_pml",
                                  "OMPI_MCA_btl",
                                  "OMPI_MCA_ess_singleton_isolated",
                                  "OMPI_MCA_orte_create_session_dirs",
                                  "OMPI_MCA_coll",
                                  "OMPI_MCA_state",
                                  "OMPI_MCA_errmgr",
                                  "OMPI_MCA_schizo",
                                  "OMPI_MCA_reachable",
                                  "OMPI_MCA_shmem",
                                  "HWLOC_COMPONENTS",
                                  "HWLOC_PLUGINS_BLACKLIST"};

// Saves the variables above, clears them, and puts them back at the end of the test.
class MpiStartup : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* name : kVariables) {
      const char* value = std::getenv(name);
      saved_[name] = value ? std::optional<std::string>(value) : std::nullopt;
      unsetenv(name);
    }
  }
  void TearDown() override {
    for (const auto& [name, value] : saved_) {
      if (value)
        setenv(name.c_str(), value->c_str(), 1);
      else
        unsetenv(name.c_str());
    }
  }
  static std::string get(const char* name) {
    const char* value = std::getenv(name);
    return value ? value : "<unset>";
  }

 private:
  std::map<std::string, std::optional<std::string>> saved_;
};

TEST_F(MpiStartup, SingletonGetsSharedMemoryAndNoDaemon) {
  prefer_local_mpi_startup();
  EXPECT_EQ(get("OMPI_MCA_pml"), "ob1");
  EXPECT_EQ(get("OMPI_MCA_btl"), "self,vader");
  EXPECT_EQ(get("OMPI_MCA_ess_singleton_isolated"), "1");
  EXPECT_EQ(get("OMPI_MCA_orte_create_session_dirs"), "0");
}

TEST_F(MpiStartup, SingletonOpensOnlyTheComponentsItUses) {
  prefer_local_mpi_startup();
  EXPECT_EQ(get("OMPI_MCA_coll"), "self,basic,libnbc");
  EXPECT_EQ(get("OMPI_MCA_state"), "app");
  EXPECT_EQ(get("OMPI_MCA_errmgr"), "default_app");
  EXPECT_EQ(get("OMPI_MCA_schizo"), "orte");
  EXPECT_EQ(get("OMPI_MCA_reachable"), "netlink");
  EXPECT_EQ(get("OMPI_MCA_shmem"), "mmap");
  EXPECT_EQ(get("HWLOC_COMPONENTS"), "-linuxio");
  EXPECT_NE(get("HWLOC_PLUGINS_BLACKLIST").find("hwloc_pci"), std::string::npos);
}

TEST_F(MpiStartup, MpirunWithEveryRankHereGetsSharedMemoryOnly) {
  setenv("OMPI_COMM_WORLD_SIZE", "2", 1);
  setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "2", 1);
  prefer_local_mpi_startup();
  EXPECT_EQ(get("OMPI_MCA_pml"), "ob1");
  EXPECT_EQ(get("OMPI_MCA_btl"), "self,vader");
  // The singleton settings would break a launched job: they stay unset.
  EXPECT_EQ(get("OMPI_MCA_ess_singleton_isolated"), "<unset>");
  EXPECT_EQ(get("OMPI_MCA_orte_create_session_dirs"), "<unset>");
  // A launched rank's components are mpirun's business (state, errmgr differ there).
  for (const char* name : {"OMPI_MCA_coll", "OMPI_MCA_state", "OMPI_MCA_errmgr", "OMPI_MCA_schizo",
                           "HWLOC_COMPONENTS", "HWLOC_PLUGINS_BLACKLIST"})
    EXPECT_EQ(get(name), "<unset>") << name;
}

TEST_F(MpiStartup, RanksOnSeveralMachinesKeepTheNetwork) {
  setenv("OMPI_COMM_WORLD_SIZE", "4", 1);
  setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "2", 1);
  prefer_local_mpi_startup();
  EXPECT_EQ(get("OMPI_MCA_pml"), "<unset>");
  EXPECT_EQ(get("OMPI_MCA_btl"), "<unset>");
}

TEST_F(MpiStartup, OtherLaunchersAreLeftAlone) {
  setenv("PMIX_RANK", "0", 1);
  prefer_local_mpi_startup();
  EXPECT_EQ(get("OMPI_MCA_btl"), "<unset>");
  EXPECT_EQ(get("OMPI_MCA_ess_singleton_isolated"), "<unset>");
}

TEST_F(MpiStartup, TheUsersValuesWin) {
  setenv("OMPI_COMM_WORLD_SIZE", "2", 1);
  setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "2", 1);
  setenv("OMPI_MCA_btl", "self,tcp", 1);
  prefer_local_mpi_startup();
  EXPECT_EQ(get("OMPI_MCA_btl"), "self,tcp");
  EXPECT_EQ(get("OMPI_MCA_pml"), "ob1");
  unsetenv("OMPI_COMM_WORLD_SIZE");
  unsetenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  setenv("OMPI_MCA_ess_singleton_isolated", "0", 1);
  setenv("OMPI_MCA_coll", "tuned,self", 1);
  setenv("HWLOC_COMPONENTS", "linux", 1);
  prefer_local_mpi_startup();
  EXPECT_EQ(get("OMPI_MCA_ess_singleton_isolated"), "0");
  EXPECT_EQ(get("OMPI_MCA_btl"), "self,tcp");
  EXPECT_EQ(get("OMPI_MCA_coll"), "tuned,self");
  EXPECT_EQ(get("HWLOC_COMPONENTS"), "linux");
}

// A connected pair of loopback TCP sockets (listener closed), or {-1, -1}.
struct LoopbackPair {
  int client = -1, server = -1;
  LoopbackPair() {
    const int listener = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    if (listener < 0 || bind(listener, reinterpret_cast<sockaddr*>(&address), length) != 0 ||
        listen(listener, 1) != 0 ||
        getsockname(listener, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
      if (listener >= 0) close(listener);
      return;
    }
    client = socket(AF_INET, SOCK_STREAM, 0);
    if (connect(client, reinterpret_cast<sockaddr*>(&address), length) == 0)
      server = accept(listener, nullptr, nullptr);
    close(listener);
  }
  ~LoopbackPair() {
    if (client >= 0) close(client);
    if (server >= 0) close(server);
  }
  static int no_delay(int fd) {
    int value = -1;
    socklen_t length = sizeof value;
    getsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &value, &length);
    return value;
  }
};

TEST_F(MpiStartup, LocalMpirunGetsNoDelayOnLoopbackConnections) {
  LoopbackPair pair;
  ASSERT_GE(pair.server, 0) << "no loopback TCP connection on this machine";
  setenv("OMPI_COMM_WORLD_SIZE", "2", 1);
  setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "2", 1);
  EXPECT_EQ(LoopbackPair::no_delay(pair.client), 0);   // the kernel's default: Nagle on
  EXPECT_GE(no_delay_on_local_launcher_sockets(), 2);  // both ends are this process's
  EXPECT_EQ(LoopbackPair::no_delay(pair.client), 1);
  EXPECT_EQ(LoopbackPair::no_delay(pair.server), 1);
}

TEST_F(MpiStartup, NoDelayOnlyUnderALocalMpirun) {
  LoopbackPair pair;
  ASSERT_GE(pair.server, 0) << "no loopback TCP connection on this machine";
  EXPECT_EQ(no_delay_on_local_launcher_sockets(), 0);  // a singleton
  setenv("OMPI_COMM_WORLD_SIZE", "4", 1);              // ranks on other machines
  setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "2", 1);
  EXPECT_EQ(no_delay_on_local_launcher_sockets(), 0);
  EXPECT_EQ(LoopbackPair::no_delay(pair.client), 0);
}

}  // namespace
}  // namespace grout
