#pragma once
// An MPI-aware Google Benchmark main for the perf/ binaries.
//
// Every rank runs every benchmark in lockstep; only rank 0 prints and writes the JSON.
// Lockstep holds because each iteration's time is the maximum over the ranks
// (MPI_Allreduce in timed_iteration), reported through manual timing: Google Benchmark
// then takes the same iteration-count decisions on every rank. A benchmark using this main
// must therefore be registered with ->UseManualTime() and time its work like
//
//   for (auto _ : state) {
//     grout::bench::timed_iteration(state, [&] { problem.assemble(u, f, &K); });
//   }
//
// Use: #include "perf/bench_main.hpp" in exactly one file of a binary, register the
// benchmarks in a function (called after MPI is up, so they may depend on the number of
// ranks), then GROUT_BENCHMARK_MAIN(register_function). Free anything holding Kokkos memory
// from at_finalize().

#include <benchmark/benchmark.h>
#include <mpi.h>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_Core.hpp>
#include <chrono>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "drivers/mpi_startup.hpp"

namespace grout::bench {

/// Functions run after the benchmarks, before Kokkos is finalised: free cached problems
/// (Kokkos Views and Tpetra objects must not outlive Kokkos).
inline std::vector<std::function<void()>>& at_finalize() {
  static std::vector<std::function<void()>> functions;
  return functions;
}

inline MPI_Comm world() {
  return MPI_COMM_WORLD;
}

inline int world_rank() {
  int rank = 0;
  MPI_Comm_rank(world(), &rank);
  return rank;
}

inline int world_size() {
  int size = 1;
  MPI_Comm_size(world(), &size);
  return size;
}

/// Run `work` once between a barrier and a max-over-ranks reduction of its wall time, and
/// report that maximum as this iteration's time (the benchmark must use ->UseManualTime()).
template <class Work>
void timed_iteration(benchmark::State& state, Work&& work) {
  MPI_Barrier(world());
  const auto start = std::chrono::steady_clock::now();
  work();
  const double local =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double slowest = 0.0;
  MPI_Allreduce(&local, &slowest, 1, MPI_DOUBLE, MPI_MAX, world());
  state.SetIterationTime(slowest);
}

/// Counter whose reported value is nanoseconds per item, for `items` items per iteration
/// (Google Benchmark divides by the benchmark's time, here the manual max-over-ranks time).
inline benchmark::Counter ns_per_item(double items) {
  return benchmark::Counter(
      items * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

/// Reporter for ranks other than 0: they run the benchmarks but say nothing.
class SilentReporter : public benchmark::BenchmarkReporter {
 public:
  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>&) override {}
};

/// On ranks other than 0, remove the output-file flags (only rank 0 writes the JSON).
/// Returns the new argc; argv is compacted in place.
inline int strip_arguments(int argc, char** argv, int rank) {
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const bool output = std::strncmp(argv[i], "--benchmark_out", 15) == 0;
    if (!(output && rank != 0)) argv[kept++] = argv[i];
  }
  argv[kept] = nullptr;
  return kept;
}

/// Initialise MPI, Kokkos and Tpetra, register with `register_benchmarks()` (which may
/// depend on the number of ranks) and run the benchmarks on every rank, reporting on rank 0.
inline int run(int argc, char** argv, void (*register_benchmarks)()) {
  prefer_local_mpi_startup();
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  no_delay_on_local_launcher_sockets();
  const int rank = world_rank();
  argc = strip_arguments(argc, argv, rank);
  benchmark::Initialize(&argc, argv);
  if (argc > 1) {  // the same leftovers on every rank: all stop
    if (rank == 0) benchmark::ReportUnrecognizedArguments(argc, argv);
    return 1;
  }
  benchmark::AddCustomContext("mpi_ranks", std::to_string(world_size()));
  register_benchmarks();
  if (rank == 0) {
    benchmark::RunSpecifiedBenchmarks();
  } else {
    SilentReporter silent;
    benchmark::RunSpecifiedBenchmarks(&silent);
  }
  for (const auto& f : at_finalize()) f();
  benchmark::Shutdown();
  return 0;
}

}  // namespace grout::bench

#define GROUT_BENCHMARK_MAIN(register_benchmarks)                \
  int main(int argc, char** argv) {                              \
    return grout::bench::run(argc, argv, (register_benchmarks)); \
  }
