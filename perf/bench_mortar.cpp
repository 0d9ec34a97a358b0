// Cost of the mortar kernels per slave element on non-matching interfaces
// (perf/mortar_interfaces.hpp): 2D flat and curved LINE2 interfaces with 1e3 … 1e6 slave
// segments, 3D flat QUAD4 and TRI3 interfaces with 32² … 512² slave faces. Each case is timed
// in four stages, each its own benchmark "<case>/<n>/<stage>":
//   normals       compute_nodal_normals on the slave faces (owned + one halo layer)
//   search        coarse_search (reused CoarseSearchWorkspace and SearchCandidates)
//   integrate     mortar_integrate<Dim> over every candidate pair (exact, default rules)
//   weighted_gap  accumulate_weighted_gaps
// MPI: rank r of p owns the contiguous slave range [n r/p, n (r+1)/p) and every master face;
// the time of an iteration is the maximum over the ranks and "ns_per_slave" divides it by the
// global number of slave elements (bench_main.hpp). Results and commands:
// docs/performance.md ("Mortar kernels").

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "kernels/coarse_search.hpp"
#include "kernels/mortar_integrate.hpp"
#include "kernels/surface_normals.hpp"
#include "kernels/weighted_gap.hpp"
#include "perf/bench_main.hpp"
#include "perf/mortar_interfaces.hpp"

namespace grout {
namespace {

using bench::FaceShape;
using bench::MortarInterface;

constexpr double kSearchFactor = 0.1;  ///< box enlargement (fraction of the face size)

/// This rank's part of an interface, with every array the four stages need.
struct RankProblem {
  int dim = 2;
  long n_slave_global = 0;
  Kokkos::View<int**> slave, normal_faces, master;  ///< local node ids
  Kokkos::View<double**> coords, normals;
  Kokkos::View<double*> g_tilde;
  SearchCandidates<Kokkos::HostSpace> candidates;
  Kokkos::View<MortarPairResult<double>*> results;
  CoarseSearchWorkspace<Kokkos::HostSpace> workspace;
  MortarOptions options;
  double setup_seconds = 0.0, candidates_per_slave = 0.0, overlaps_per_slave = 0.0;

  MortarStatus normals_stage() { return compute_nodal_normals(normal_faces, coords, normals); }
  MortarStatus search_stage() {
    return coarse_search(workspace, slave, master, coords, kSearchFactor, candidates);
  }
  MortarStatus integrate_stage() {
    if (dim == 2)
      return mortar_integrate_2d(slave, master, coords, normals, candidates.offsets,
                                 candidates.masters, options, results);
    return mortar_integrate_3d(slave, master, coords, normals, candidates.offsets,
                               candidates.masters, options, results);
  }
  void weighted_gap_stage() {
    accumulate_weighted_gaps(slave, master, coords, normals, candidates.offsets, candidates.masters,
                             results, g_tilde);
  }
};

/// Sum over the ranks.
double sum_over_ranks(double local) {
  double global = 0.0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, bench::world());
  return global;
}

/// Builds this rank's part: owned slave faces, a halo layer of slave faces sharing a node with
/// them (for the nodal normals), all master faces, renumbered local nodes.
std::unique_ptr<RankProblem> make_rank_problem(const MortarInterface& mi) {
  auto p = std::make_unique<RankProblem>();
  p->dim = mi.dim;
  p->n_slave_global = mi.n_slave();
  const int rank = bench::world_rank(), size = bench::world_size(), cols = mi.cols;
  const long n_s = mi.n_slave();
  const int s0 = int(n_s * rank / size), s1 = int(n_s * (rank + 1) / size);
  std::vector<char> owned_node(mi.n_nodes(), 0);
  for (int f = s0; f < s1; ++f)
    for (int k = 0; k < cols; ++k)
      if (mi.slave[f * cols + k] >= 0) owned_node[mi.slave[f * cols + k]] = 1;
  std::vector<int> halo;
  for (int f = 0; f < n_s; ++f) {
    if (f >= s0 && f < s1) continue;
    bool touches = false;
    for (int k = 0; k < cols; ++k) {
      const int node = mi.slave[f * cols + k];
      touches = touches || (node >= 0 && owned_node[node]);
    }
    if (touches) halo.push_back(f);
  }
  std::vector<int> local(mi.n_nodes(), -1);
  int n_local = 0;
  auto number = [&](int node) {
    if (node >= 0 && local[node] < 0) local[node] = n_local++;
    return node < 0 ? -1 : local[node];
  };
  const int n_loc = s1 - s0, n_halo = int(halo.size()), n_m = mi.n_master();
  p->normal_faces = Kokkos::View<int**>("normal_faces", n_loc + n_halo, cols);
  p->master = Kokkos::View<int**>("master", n_m, cols);
  for (int r = 0; r < n_loc + n_halo; ++r) {
    const int f = r < n_loc ? s0 + r : halo[r - n_loc];
    for (int k = 0; k < cols; ++k) p->normal_faces(r, k) = number(mi.slave[f * cols + k]);
  }
  for (int f = 0; f < n_m; ++f)
    for (int k = 0; k < cols; ++k) p->master(f, k) = number(mi.master[f * cols + k]);
  p->slave = Kokkos::subview(p->normal_faces, Kokkos::make_pair(0, n_loc), Kokkos::ALL);
  p->coords = Kokkos::View<double**>("coords", n_local, mi.dim);
  for (int node = 0; node < mi.n_nodes(); ++node)
    if (local[node] >= 0)
      for (int d = 0; d < mi.dim; ++d) p->coords(local[node], d) = mi.coords[node * mi.dim + d];
  p->normals = Kokkos::View<double**>("normals", n_local, mi.dim);
  p->g_tilde = Kokkos::View<double*>("g_tilde", n_local);
  return p;
}

struct Case {
  std::string name;
  int n;  ///< slave segments (2D) or slave faces per direction (3D)
  MortarInterface make() const {
    if (name == "2d_flat") return bench::line_interface_2d(n, false);
    if (name == "2d_curved") return bench::line_interface_2d(n, true);
    if (name == "3d_quad4") return bench::flat_interface_3d(n, FaceShape::quad4, FaceShape::quad4);
    return bench::flat_interface_3d(n, FaceShape::tri3, FaceShape::tri3);
  }
  std::string key() const { return name + "/" + std::to_string(n); }
};

// One case at a time is kept (the four stages of a case run one after the other).
std::unique_ptr<RankProblem> g_problem;
std::string g_key;

RankProblem& problem(const Case& c) {
  if (g_key == c.key()) return *g_problem;
  g_problem.reset();
  MPI_Barrier(bench::world());
  const auto t0 = std::chrono::steady_clock::now();
  const MortarInterface mi = c.make();
  auto p = make_rank_problem(mi);
  p->normals_stage();
  p->search_stage();
  const int n_pairs = p->candidates.n_pairs;
  p->results = Kokkos::View<MortarPairResult<double>*>("results", n_pairs);
  p->integrate_stage();
  long overlaps = 0;
  for (int q = 0; q < n_pairs; ++q) overlaps += p->results(q).overlap > 0.0;
  p->candidates_per_slave = sum_over_ranks(n_pairs) / p->n_slave_global;
  p->overlaps_per_slave = sum_over_ranks(double(overlaps)) / p->n_slave_global;
  const double local = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  MPI_Allreduce(&local, &p->setup_seconds, 1, MPI_DOUBLE, MPI_MAX, bench::world());
  g_problem = std::move(p);
  g_key = c.key();
  return *g_problem;
}

enum class Stage { normals, search, integrate, weighted_gap };

void run_stage(benchmark::State& state, Case c, Stage stage) {
  RankProblem& p = problem(c);
  int worst = 0;
  for (auto _ : state) {
    bench::timed_iteration(state, [&] {
      MortarStatus s = MortarStatus::ok;
      switch (stage) {
        case Stage::normals:
          s = p.normals_stage();
          break;
        case Stage::search:
          s = p.search_stage();
          break;
        case Stage::integrate:
          s = p.integrate_stage();
          break;
        case Stage::weighted_gap:
          p.weighted_gap_stage();
          break;
      }
      worst = int(s) > worst ? int(s) : worst;
    });
  }
  if (worst != 0) state.SkipWithError(("status " + std::to_string(worst)).c_str());
  state.counters["ns_per_slave"] = bench::ns_per_item(double(p.n_slave_global));
  state.counters["n_slave"] = double(p.n_slave_global);
  state.counters["candidates_per_slave"] = p.candidates_per_slave;
  state.counters["overlaps_per_slave"] = p.overlaps_per_slave;
  state.counters["setup_s"] = p.setup_seconds;
  state.counters["ranks"] = bench::world_size();
}

void register_benchmarks() {
  std::vector<Case> cases;
  for (const char* name : {"2d_flat", "2d_curved"})
    for (int n : {1000, 10000, 100000, 1000000}) cases.push_back({name, n});
  for (const char* name : {"3d_quad4", "3d_tri3"})
    for (int n : {32, 64, 128, 256, 512}) cases.push_back({name, n});
  const std::pair<const char*, Stage> stages[] = {{"normals", Stage::normals},
                                                  {"search", Stage::search},
                                                  {"integrate", Stage::integrate},
                                                  {"weighted_gap", Stage::weighted_gap}};
  for (const Case& c : cases)
    for (const auto& [stage_name, stage] : stages)
      benchmark::RegisterBenchmark((c.key() + "/" + stage_name).c_str(), run_stage, c, stage)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
  bench::at_finalize().push_back([] { g_problem.reset(); });
}

}  // namespace
}  // namespace grout

GROUT_BENCHMARK_MAIN(grout::register_benchmarks)
