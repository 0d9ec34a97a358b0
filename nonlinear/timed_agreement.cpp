#include "nonlinear/timed_agreement.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "assembly/raw_mpi_comm.hpp"

namespace grout {

double stall_limit_seconds() {
  if (const char* env = std::getenv("GROUT_STALL_LIMIT"); env != nullptr && *env != '\0') {
    char* end = nullptr;
    const double value = std::strtod(env, &end);
    if (end != env && *end == '\0' && value > 0.0) return value;
  }
  return 30.0;
}

TimedAgreement::TimedAgreement(const Comm& comm) : parent_(raw_mpi_comm(comm)) {
  MPI_Comm_dup(parent_, &own_);
}

TimedAgreement::~TimedAgreement() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized && own_ != MPI_COMM_NULL) MPI_Comm_free(&own_);
}

bool TimedAgreement::built_on(const Comm& comm) const {
  return raw_mpi_comm(comm) == parent_;
}

int TimedAgreement::highest(int code, const std::string& message, int exit_code,
                            double limit_s) const {
  int size = 1;
  MPI_Comm_size(own_, &size);
  if (size == 1) return code;
  int highest = 0;
  MPI_Request request;
  MPI_Iallreduce(&code, &highest, 1, MPI_INT, MPI_MAX, own_, &request);
  if (code == 0) {
    MPI_Wait(&request, MPI_STATUS_IGNORE);
    return highest;
  }
  // Poll: MPI_Wait has no time limit. The usual wait is the other ranks' last local work
  // after the phase's last collective call (milliseconds).
  const auto start = std::chrono::steady_clock::now();
  auto pause = std::chrono::microseconds(50);
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return highest;
    const double waited =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (waited > limit_s) break;
    std::this_thread::sleep_for(pause);
    if (pause < std::chrono::milliseconds(10)) pause *= 2;
  }
  int rank = 0;
  MPI_Comm_rank(own_, &rank);
  std::fprintf(stderr,
               "grout: error: %s (rank %d; the other ranks did not answer within %g s: they "
               "wait inside the solve for this rank, which left it; ending the job; the output "
               "holds the converged steps)\n",
               message.c_str(), rank, limit_s);
  std::fflush(stderr);
  std::fflush(stdout);
  MPI_Abort(MPI_COMM_WORLD, exit_code);
  return highest;  // not reached
}

}  // namespace grout
