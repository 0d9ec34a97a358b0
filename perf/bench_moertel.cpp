// Anchor for perf/bench_mortar.cpp: the same interfaces (perf/mortar_interfaces.hpp) integrated
// by Trilinos Moertel (MOERTEL::Interface + MOERTEL::Manager::Mortar_Integrate, linear primal and
// dual linear Lagrange-multiplier functions), next to Grout's normals + search + integration on
// the same interface, one rank. Each benchmark "moertel/<case>/<n>" times Mortar_Integrate (the
// interface and manager are rebuilt, untimed, before each iteration) and then times Grout's
// pipeline; counters:
//   moertel_ns_per_slave, grout_ns_per_slave (normals + search + integrate),
//   grout_integrate_ns_per_slave, ratio = moertel / grout (Grout's speed-up per slave element),
//   moertel_sum_D, grout_sum_D (Σ D: both must equal the slave length/area),
//   moertel_complete_ms (Interface::Complete, untimed).
// Moertel's Mortar_Integrate also assembles D and M into Epetra_CrsMatrix objects, which
// Grout leaves to a later scatter: see docs/performance.md ("Mortar kernels"). Moertel's default
// Gauss rules are set to Grout's: 5 points per 2D overlap segment, 12 per 3D integration triangle.

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>
#include <Epetra_Vector.h>
#include <mrtr_manager.H>
#include <mrtr_node.H>
#include <mrtr_segment_bilinearquad.H>
#include <mrtr_segment_bilineartri.H>
#include <mrtr_segment_linear1D.H>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "kernels/coarse_search.hpp"
#include "kernels/mortar_integrate.hpp"
#include "kernels/surface_normals.hpp"
#include "perf/bench_main.hpp"
#include "perf/mortar_interfaces.hpp"

namespace grout {
namespace {

using bench::FaceShape;
using bench::MortarInterface;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Moertel's view of one interface: side 0 slave (dual multipliers), side 1 master (mortar).
struct MoertelProblem {
  Epetra_MpiComm comm{bench::world()};
  std::unique_ptr<Epetra_Map> map;
  std::unique_ptr<MOERTEL::Interface> interface;
  std::unique_ptr<MOERTEL::Manager> manager;
  double complete_seconds = 0.0;
};

std::unique_ptr<MoertelProblem> make_moertel(const MortarInterface& mi, FaceShape shape) {
  auto p = std::make_unique<MoertelProblem>();
  const bool one_d = mi.dim == 2;
  p->map = std::make_unique<Epetra_Map>(mi.n_nodes(), 0, p->comm);
  p->interface = std::make_unique<MOERTEL::Interface>(0, one_d, p->comm, 0);
  for (int node = 0; node < mi.n_nodes(); ++node) {
    double x[3] = {0.0, 0.0, 0.0};
    for (int d = 0; d < mi.dim; ++d) x[d] = mi.coords[node * mi.dim + d];
    int dof = node;
    MOERTEL::Node n(node, x, 1, &dof, false, 0);
    p->interface->AddNode(n, node < mi.n_slave_nodes ? 0 : 1);
  }
  for (int side = 0; side < 2; ++side) {
    const std::vector<int>& faces = side == 0 ? mi.slave : mi.master;
    const int n_faces = static_cast<int>(faces.size()) / mi.cols;
    for (int f = 0; f < n_faces; ++f) {
      int ids[4];
      int n_nodes = 0;
      for (int k = 0; k < mi.cols; ++k)
        if (faces[f * mi.cols + k] >= 0) ids[n_nodes++] = faces[f * mi.cols + k];
      const int id = side == 0 ? f : mi.n_slave() + f;
      if (one_d) {
        MOERTEL::Segment_Linear1D seg(id, n_nodes, ids, 0);
        p->interface->AddSegment(seg, side);
      } else if (n_nodes == 4) {
        MOERTEL::Segment_BiLinearQuad seg(id, n_nodes, ids, 0);
        p->interface->AddSegment(seg, side);
      } else {
        MOERTEL::Segment_BiLinearTri seg(id, n_nodes, ids, 0);
        p->interface->AddSegment(seg, side);
      }
    }
  }
  p->interface->SetMortarSide(1);
  using F = MOERTEL::Function;
  if (one_d)
    p->interface->SetFunctionTypes(F::func_Linear1D, F::func_DualLinear1D);
  else if (shape == FaceShape::quad4)
    p->interface->SetFunctionTypes(F::func_BiLinearQuad, F::func_DualBiLinearQuad);
  else
    p->interface->SetFunctionTypes(F::func_LinearTri, F::func_DualLinearTri);
  const auto t0 = Clock::now();
  if (!p->interface->Complete()) throw std::runtime_error("MOERTEL::Interface::Complete failed");
  p->complete_seconds = seconds_since(t0);
  p->manager = std::make_unique<MOERTEL::Manager>(p->comm, 0);
  p->manager->SetDimension(one_d ? MOERTEL::Manager::manager_2D : MOERTEL::Manager::manager_3D);
  p->manager->AddInterface(*p->interface);
  p->manager->SetProblemMap(p->map.get());
  Teuchos::ParameterList& params = p->manager->Default_Parameters();
  params.set("exact values at gauss points", true);
  params.set("number gaussian points 1D", mortar_2d_gauss_points);
  params.set("number gaussian points 2D", 12);
  return p;
}

/// Σ of all entries of a matrix (A · 1 summed).
double sum_of_entries(const Epetra_CrsMatrix* a) {
  if (a == nullptr) return 0.0;
  Epetra_Vector ones(a->DomainMap()), y(a->RangeMap());
  ones.PutScalar(1.0);
  a->Multiply(false, ones, y);
  double s = 0.0;
  for (int i = 0; i < y.MyLength(); ++i) s += y[i];
  return s;
}

/// Grout's normals + search + integration on one rank (as in bench_mortar.cpp).
struct GroutProblem {
  int dim;
  Kokkos::View<int**> slave, master;
  Kokkos::View<double**> coords, normals;
  SearchCandidates<Kokkos::HostSpace> candidates;
  Kokkos::View<MortarPairResult<double>*> results;
  CoarseSearchWorkspace<Kokkos::HostSpace> workspace;
  double integrate_seconds = 0.0;

  explicit GroutProblem(const MortarInterface& mi) : dim(mi.dim) {
    auto faces = [&](const std::vector<int>& rows, const char* label) {
      Kokkos::View<int**> v(std::string(label), rows.size() / mi.cols, mi.cols);
      for (size_t f = 0; f < v.extent(0); ++f)
        for (int k = 0; k < mi.cols; ++k) v(f, k) = rows[f * mi.cols + k];
      return v;
    };
    slave = faces(mi.slave, "slave");
    master = faces(mi.master, "master");
    coords = Kokkos::View<double**>("coords", mi.n_nodes(), mi.dim);
    for (int i = 0; i < mi.n_nodes(); ++i)
      for (int d = 0; d < mi.dim; ++d) coords(i, d) = mi.coords[i * mi.dim + d];
    normals = Kokkos::View<double**>("normals", mi.n_nodes(), mi.dim);
  }
  /// One pass; returns its wall time (integration alone in integrate_seconds).
  double run() {
    const auto t0 = Clock::now();
    compute_nodal_normals(slave, coords, normals);
    coarse_search(workspace, slave, master, coords, 0.1, candidates);
    const int n_pairs = candidates.n_pairs;
    if (static_cast<int>(results.extent(0)) < n_pairs)
      results = Kokkos::View<MortarPairResult<double>*>("results", n_pairs);
    const auto t1 = Clock::now();
    if (dim == 2)
      mortar_integrate_2d(slave, master, coords, normals, candidates.offsets, candidates.masters,
                          MortarOptions{}, results);
    else
      mortar_integrate_3d(slave, master, coords, normals, candidates.offsets, candidates.masters,
                          MortarOptions{}, results);
    integrate_seconds = seconds_since(t1);
    return seconds_since(t0);
  }
  double sum_D() const {
    double s = 0.0;
    for (size_t q = 0; q < results.extent(0); ++q)
      for (int j = 0; j < results(q).n_slave; ++j) s += results(q).D[j];
    return s;
  }
};

struct Case {
  std::string name;
  int n;
  FaceShape shape() const {
    return name == "3d_quad4" ? FaceShape::quad4
                              : (name == "3d_tri3" ? FaceShape::tri3 : FaceShape::line2);
  }
  MortarInterface make() const {
    if (name == "2d_flat") return bench::line_interface_2d(n, false);
    if (name == "2d_curved") return bench::line_interface_2d(n, true);
    return bench::flat_interface_3d(n, shape(), shape());
  }
};

struct Row {
  std::string name;
  double moertel_ns, grout_ns, grout_integrate_ns;
};
std::vector<Row> g_rows;

void run_case(benchmark::State& state, Case c) {
  const MortarInterface mi = c.make();
  const double n_s = mi.n_slave();
  double sum_d_moertel = 0.0, complete = 0.0, moertel_total = 0.0;
  long moertel_iterations = 0;
  try {
    for (auto _ : state) {
      state.PauseTiming();
      auto p = make_moertel(mi, c.shape());
      state.ResumeTiming();
      const auto t0 = Clock::now();
      const bool ok = p->manager->Mortar_Integrate();
      const double t = seconds_since(t0);
      state.SetIterationTime(t);
      if (!ok) throw std::runtime_error("MOERTEL::Manager::Mortar_Integrate returned false");
      moertel_total += t;
      ++moertel_iterations;
      complete = p->complete_seconds;
      sum_d_moertel = sum_of_entries(p->manager->D());
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  } catch (...) {
    state.SkipWithError("Moertel threw a non-standard exception");
    return;
  }
  // Grout on the same interface: median of repeated passes (≥ 0.2 s, ≥ 5 passes).
  GroutProblem g(mi);
  g.run();  // warm-up (first touch, results allocation)
  std::vector<double> total, integrate;
  const auto t0 = Clock::now();
  while (total.size() < 5 || seconds_since(t0) < 0.2) {
    total.push_back(g.run());
    integrate.push_back(g.integrate_seconds);
  }
  auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  const double moertel_ns = 1e9 * moertel_total / moertel_iterations / n_s;
  const double grout_ns = 1e9 * median(total) / n_s;
  const double grout_int_ns = 1e9 * median(integrate) / n_s;
  state.counters["n_slave"] = n_s;
  state.counters["moertel_ns_per_slave"] = moertel_ns;
  state.counters["grout_ns_per_slave"] = grout_ns;
  state.counters["grout_integrate_ns_per_slave"] = grout_int_ns;
  state.counters["ratio"] = moertel_ns / grout_ns;
  state.counters["moertel_sum_D"] = sum_d_moertel;
  state.counters["grout_sum_D"] = g.sum_D();
  state.counters["moertel_complete_ms"] = 1e3 * complete;
  g_rows.push_back({c.name + "/" + std::to_string(c.n), moertel_ns, grout_ns, grout_int_ns});
}

void print_ratios() {
  if (bench::world_rank() != 0 || g_rows.empty()) return;
  std::printf("\n%-18s %16s %16s %12s %22s\n", "case", "Moertel ns/slave", "Grout ns/slave",
              "ratio", "ratio (integrate only)");
  for (const Row& r : g_rows)
    std::printf("%-18s %16.0f %16.0f %12.1f %22.1f\n", r.name.c_str(), r.moertel_ns, r.grout_ns,
                r.moertel_ns / r.grout_ns, r.moertel_ns / r.grout_integrate_ns);
}

void register_benchmarks() {
  if (bench::world_size() > 1) {
    if (bench::world_rank() == 0)
      std::printf("bench_moertel: Moertel anchor runs on one rank only; nothing registered.\n");
    return;
  }
  const Case cases[] = {{"2d_flat", 1000},   {"2d_flat", 4000}, {"2d_curved", 1000},
                        {"2d_curved", 4000}, {"3d_quad4", 16},  {"3d_quad4", 32},
                        {"3d_tri3", 16},     {"3d_tri3", 32}};
  for (const Case& c : cases)
    benchmark::RegisterBenchmark(("moertel/" + c.name + "/" + std::to_string(c.n)).c_str(),
                                 run_case, c)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond)
        ->Iterations(c.name[0] == '3' ? 1 : 3);
  bench::at_finalize().push_back(print_ratios);
}

}  // namespace
}  // namespace grout

GROUT_BENCHMARK_MAIN(grout::register_benchmarks)
