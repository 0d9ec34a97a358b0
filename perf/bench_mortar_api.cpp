// Cost per slave element of the embedding API (grout::MortarCoupling::update, api/) against the
// internal path on the same interfaces (perf/mortar_interfaces.hpp, as perf/bench_mortar.cpp):
//   internal         the four kernel launches of bench_mortar in one iteration: nodal normals,
//                    coarse search (reused workspace), mortar_integrate<Dim>, weighted gap
//   api              MortarCoupling::update (values only) and the read of D, M (CRS), the
//                    gaps and the normals: gathers and checks the coordinates (finite, no
//                    degenerate face), the same four launches, then D, M (CRS), gaps and
//                    normals per slave row on the host (tangents and the dual D as CRS are
//                    computed on their first read, which this loop does not do)
//   api_standard     the same with standard multipliers (mortar_integrate_matrices: full D
//                    per pair, D read as CRS)
//   api_moving       api with the master moved along the interface by h/8 (h the slave
//                    element size) and back on alternate iterations: every update finds other
//                    candidate or overlapping pairs, so D and M are merged anew (the other
//                    loops repeat one configuration, whose pattern update keeps and scatters
//                    into)
//   api_derivatives  MortarCoupling::update with options.derivatives (evaluate_contact_mortar,
//                    Sacado), on the smaller cases
// GROUT_BENCH_ITERATIONS=n in the environment fixes the iteration count (for instruction counts
// by difference of two runs). Serial (one rank, no communicator): the API's distributed path adds
// the parallel search, which bench_mortar does not have. Counter ns_per_slave as in bench_mortar.
// Results: docs/performance.md ("Embedding API").

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "grout/mortar_coupling.hpp"
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

constexpr double kSearchFactor = 0.1;  ///< as bench_mortar

/// The internal path: bench_mortar's four stages on one rank.
struct InternalPath {
  int dim;
  Kokkos::View<int**> slave, master;
  Kokkos::View<double**> coords, normals;
  Kokkos::View<double*> g_tilde;
  SearchCandidates<Kokkos::HostSpace> candidates;
  CoarseSearchWorkspace<Kokkos::HostSpace> workspace;
  Kokkos::View<MortarPairResult<double>*> results;
  MortarOptions options;

  explicit InternalPath(const MortarInterface& mi) : dim(mi.dim) {
    slave = Kokkos::View<int**>("slave", mi.n_slave(), mi.cols);
    master = Kokkos::View<int**>("master", mi.n_master(), mi.cols);
    for (int f = 0; f < mi.n_slave(); ++f)
      for (int k = 0; k < mi.cols; ++k) slave(f, k) = mi.slave[f * mi.cols + k];
    for (int f = 0; f < mi.n_master(); ++f)
      for (int k = 0; k < mi.cols; ++k) master(f, k) = mi.master[f * mi.cols + k];
    coords = Kokkos::View<double**>("coords", mi.n_nodes(), dim);
    for (int i = 0; i < mi.n_nodes(); ++i)
      for (int d = 0; d < dim; ++d) coords(i, d) = mi.coords[i * dim + d];
    normals = Kokkos::View<double**>("normals", mi.n_nodes(), dim);
    g_tilde = Kokkos::View<double*>("g_tilde", mi.n_nodes());
  }
  MortarStatus run() {
    MortarStatus s = compute_nodal_normals(slave, coords, normals);
    if (s != MortarStatus::ok) return s;
    s = coarse_search(workspace, slave, master, coords, kSearchFactor, candidates);
    if (s != MortarStatus::ok) return s;
    if (results.extent(0) < std::size_t(candidates.n_pairs))
      results = Kokkos::View<MortarPairResult<double>*>("results", candidates.n_pairs);
    s = dim == 2 ? mortar_integrate_2d(slave, master, coords, normals, candidates.offsets,
                                       candidates.masters, options, results)
                 : mortar_integrate_3d(slave, master, coords, normals, candidates.offsets,
                                       candidates.masters, options, results);
    accumulate_weighted_gaps(slave, master, coords, normals, candidates.offsets, candidates.masters,
                             results, g_tilde);
    return s;
  }
};

/// The API path: the interface split into the host's two surfaces.
struct ApiPath {
  std::vector<double> xs, xm, xm_moved;  ///< xm_moved: master by h/8 along x (api_moving)
  std::unique_ptr<MortarCoupling> coupling;
  bool moving = false;
  long long step = 0;

  double sink = 0.0;  ///< keeps the reads of the results

  ApiPath(const MortarInterface& mi, bool derivatives, bool standard, bool moved = false)
      : moving(moved) {
    const int dim = mi.dim, ns = mi.n_slave_nodes;
    xs.assign(mi.coords.begin(), mi.coords.begin() + std::size_t(ns) * dim);
    xm.assign(mi.coords.begin() + std::size_t(ns) * dim, mi.coords.end());
    xm_moved = xm;
    const double h = dim == 2 ? 1.0 / mi.n_slave() : std::sqrt(1.0 / mi.n_slave());
    for (std::size_t i = 0; i < xm_moved.size(); i += dim) xm_moved[i] += 0.125 * h;
    std::vector<int> master = mi.master;
    for (int& node : master)
      if (node >= 0) node -= ns;
    MortarCouplingOptions o;
    o.search_factor = kSearchFactor;
    o.derivatives = derivatives;
    if (standard) o.multipliers = MultiplierBasis::standard;
    coupling = std::make_unique<MortarCoupling>(dim, surface_arrays(mi.cols, mi.slave, xs, dim),
                                                surface_arrays(mi.cols, master, xm, dim), o);
  }
  void run() {
    coupling->update(xs, moving && step++ % 2 == 0 ? xm_moved : xm);
    const MortarCoupling& c = *coupling;
    const std::vector<double>& D = c.multipliers() == MultiplierBasis::dual ? c.D() : c.D_values();
    sink += D.back() + c.M_values().back() + c.weighted_gaps().back() + c.normals().back() +
            double(c.M_columns().back() + c.M_offsets().back());
  }
};

struct Case {
  std::string name;
  int n;
  MortarInterface make() const {
    if (name == "2d_flat") return bench::line_interface_2d(n, false);
    if (name == "2d_curved") return bench::line_interface_2d(n, true);
    if (name == "3d_quad4") return bench::flat_interface_3d(n, FaceShape::quad4, FaceShape::quad4);
    return bench::flat_interface_3d(n, FaceShape::tri3, FaceShape::tri3);
  }
};

enum class Path { internal, api, api_standard, api_moving, api_derivatives };

// The current case's problems (one case at a time; freed before Kokkos is finalised).
std::unique_ptr<InternalPath> g_internal;
std::unique_ptr<ApiPath> g_api;

void run_path(benchmark::State& state, Case c, Path path) {
  const MortarInterface mi = c.make();
  g_internal.reset();
  g_api.reset();
  int worst = 0;
  if (path == Path::internal) {
    g_internal = std::make_unique<InternalPath>(mi);
    g_internal->run();
  } else {
    g_api = std::make_unique<ApiPath>(mi, path == Path::api_derivatives, path == Path::api_standard,
                                      path == Path::api_moving);
  }
  for (auto _ : state) {
    bench::timed_iteration(state, [&] {
      if (g_internal) {
        const MortarStatus s = g_internal->run();
        worst = int(s) > worst ? int(s) : worst;
      } else {
        g_api->run();
      }
    });
  }
  if (worst != 0) state.SkipWithError(("status " + std::to_string(worst)).c_str());
  state.counters["ns_per_slave"] = bench::ns_per_item(double(mi.n_slave()));
  state.counters["n_slave"] = double(mi.n_slave());
  if (g_api)
    state.counters["pairs_per_slave"] = double(g_api->coupling->overlapping_pairs()) / mi.n_slave();
}

void register_benchmarks() {
  // GROUT_BENCH_ITERATIONS=n: exactly n iterations in one run (no estimation runs), so that
  // instruction counts of two runs with different n give the cost of one iteration by
  // difference (valgrind; docs/performance.md, "Embedding API").
  const char* fixed = std::getenv("GROUT_BENCH_ITERATIONS");
  const int iterations = fixed ? std::atoi(fixed) : 0;
  std::vector<Case> cases;
  for (const char* name : {"2d_flat", "2d_curved"})
    for (int n : {10000, 100000}) cases.push_back({name, n});
  for (const char* name : {"3d_quad4", "3d_tri3"})
    for (int n : {64, 128}) cases.push_back({name, n});
  for (const Case& c : cases) {
    const std::string key = c.name + "/" + std::to_string(c.n) + "/";
    const bool small = c.n == 10000 || c.n == 64;
    for (Path path :
         {Path::internal, Path::api, Path::api_standard, Path::api_moving, Path::api_derivatives}) {
      if (path == Path::api_derivatives && !small) continue;
      const char* name = path == Path::internal       ? "internal"
                         : path == Path::api          ? "api"
                         : path == Path::api_standard ? "api_standard"
                         : path == Path::api_moving   ? "api_moving"
                                                      : "api_derivatives";
      auto* b = benchmark::RegisterBenchmark((key + name).c_str(), run_path, c, path)
                    ->UseManualTime()
                    ->Unit(benchmark::kMillisecond);
      if (iterations > 0) b->Iterations(iterations);
    }
  }
  bench::at_finalize().push_back([] {
    g_internal.reset();
    g_api.reset();
  });
}

}  // namespace
}  // namespace grout

GROUT_BENCHMARK_MAIN(grout::register_benchmarks)
