// Cost of the small-strain solid assembly per element: the element kernel alone, the scatter
// alone, and the full SolidProblem::assemble (kernel + scatter into the Tpetra matrix +
// fillComplete) on structured QUAD4 and HEX8 meshes of 1e4, 1e5 and 1e6 elements.
// Every benchmark reports "ns_per_element" per global element, the time being the maximum
// over the MPI ranks (bench_main.hpp). Results and commands: docs/performance.md.

#include <Teuchos_DefaultComm.hpp>
#include <chrono>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include "assembly/solid_problem.hpp"
#include "io/mesh_generators.hpp"
#include "kernels/linear_elastic.hpp"
#include "perf/bench_main.hpp"

namespace grout {
namespace {

// Random node perturbation, in cell sizes (0.3 inverts some elements of the larger meshes).
constexpr double kQuadDistortion = 0.2, kHexDistortion = 0.2;

Mesh structured_mesh(Topology topology, int n) {
  if (topology == Topology::quad4) return rectangle_mesh(n, n, 0, 1, 0, 1, false, kQuadDistortion);
  return box_mesh(n, n, n, BoxBounds{}, false, kHexDistortion);
}

Input elastic_input(int dimension) {
  Input input;
  input.file = "bench_solid_assembly";
  input.model.dimension = dimension;
  MaterialInput steel;
  steel.name = "steel";
  steel.block = "block";
  steel.youngs_modulus = 210e9;
  steel.poissons_ratio = 0.3;
  input.materials.push_back(steel);
  return input;
}

// (a) The element kernel on a batch of distinct distorted elements (coordinates and
// displacements gathered beforehand, about 0.4 MB for HEX8: in L2), f_int and K.
void element_kernel(benchmark::State& state, Topology topology) {
  const int dim = topology == Topology::quad4 ? 2 : 3;
  const Mesh mesh = structured_mesh(topology, dim == 2 ? 32 : 10);
  const ElementBlock& block = mesh.blocks.front();
  const int npe = block.nodes_per_element, n = npe * dim;
  const int count = int(block.num_elements());
  std::vector<double> X(std::size_t(count) * n), u(X.size());
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> small(-1e-3, 1e-3);
  for (int e = 0; e < count; ++e)
    for (int a = 0; a < npe; ++a)
      for (int d = 0; d < dim; ++d) {
        X[e * n + a * dim + d] = mesh.coordinates[block.connectivity[e * npe + a] * dim + d];
        u[e * n + a * dim + d] = small(random);
      }
  const ElasticConstants c = elastic_constants(210e9, 0.3, dim, false);
  double f[max_element_dofs], K[max_element_dofs * max_element_dofs];
  int failures = 0;
  for (auto _ : state) {
    bench::timed_iteration(state, [&] {
      for (int e = 0; e < count; ++e) {
        failures += linear_elastic_element<double>(topology, dim, &X[e * n], &u[e * n], c, f, K) !=
                    ElementStatus::ok;
        benchmark::DoNotOptimize(K);
        benchmark::DoNotOptimize(f);
        benchmark::ClobberMemory();
      }
    });
  }
  if (failures) state.SkipWithError("linear_elastic_element failed");
  state.counters["elements"] = count;
  state.counters["ns_per_element"] = bench::ns_per_item(count);
}

// One assembled problem at a time (the 1e6 cases take GBs): built on first use, kept while
// the benchmarks of the same mesh run, and freed before the next mesh is built.
struct AssemblyCase {
  Topology topology = Topology::quad4;
  int n = 0;
  Mesh mesh;
  Input input;
  std::unique_ptr<SolidProblem> problem;
  Teuchos::RCP<Matrix> K;
  Teuchos::RCP<Vector> u, f;
  double setup_seconds = 0.0;  ///< mesh + SolidProblem (graph) + matrix, max over ranks
};

AssemblyCase& assembly_case(Topology topology, int n) {
  static std::unique_ptr<AssemblyCase> cached;
  static const bool freed_at_finalize =
      (bench::at_finalize().push_back([] { cached.reset(); }), true);
  (void)freed_at_finalize;
  if (cached && cached->topology == topology && cached->n == n) return *cached;
  cached.reset();
  MPI_Barrier(bench::world());
  const auto start = std::chrono::steady_clock::now();
  auto c = std::make_unique<AssemblyCase>();
  c->topology = topology;
  c->n = n;
  c->mesh = structured_mesh(topology, n);
  c->input = elastic_input(c->mesh.dimension);
  c->problem = std::make_unique<SolidProblem>(c->mesh, c->input, Tpetra::getDefaultComm());
  c->K = c->problem->create_matrix();
  c->u = c->problem->create_vector();
  c->f = c->problem->create_vector();
  c->u->randomize(-1e-3, 1e-3);
  const double local =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  MPI_Allreduce(&local, &c->setup_seconds, 1, MPI_DOUBLE, MPI_MAX, bench::world());
  cached = std::move(c);
  return *cached;
}

void report_per_element(benchmark::State& state, const AssemblyCase& c) {
  const double elements = double(c.mesh.num_elements());
  state.counters["elements"] = elements;
  state.counters["ns_per_element"] = bench::ns_per_item(elements);
  state.counters["setup_s"] = c.setup_seconds;
}

// (b) The full assembly: import of u, kernel, scatter of f_int and K, fillComplete.
void assemble(benchmark::State& state, Topology topology) {
  AssemblyCase& c = assembly_case(topology, int(state.range(0)));
  for (auto _ : state) {
    bench::timed_iteration(state, [&] { c.problem->assemble(*c.u, *c.f, c.K.get()); });
  }
  report_per_element(state, c);
}

// The Tpetra bookkeeping of assemble alone: resumeFill, zeroing, fillComplete.
void refill_matrix(benchmark::State& state, Topology topology) {
  AssemblyCase& c = assembly_case(topology, int(state.range(0)));
  for (auto _ : state) {
    bench::timed_iteration(state, [&] {
      c.K->resumeFill();
      c.K->setAllToScalar(0.0);
      c.K->fillComplete(c.problem->owned_map(), c.problem->owned_map());
    });
  }
  report_per_element(state, c);
}

// The matrix scatter of assemble alone: its sumIntoValues loop with a fixed element matrix.
// sorted = false is assemble's code (element dofs in element node order, isSorted = false:
// a linear search of the row per node); sorted = true sorts the element's nodes first and
// permutes K_e accordingly (isSorted = true: a binary search), the change this measures.
// One rank only: there the column index of node k, component d is k * dim + d.
void scatter_matrix(benchmark::State& state, Topology topology, bool sorted) {
  AssemblyCase& c = assembly_case(topology, int(state.range(0)));
  const ElementBlock& block = c.mesh.blocks.front();
  const int dim = c.mesh.dimension, npe = block.nodes_per_element, n = npe * dim;
  std::vector<double> Ke(std::size_t(n) * n);
  for (std::size_t i = 0; i < Ke.size(); ++i) Ke[i] = 1.0 + 1e-3 * double(i);
  c.K->resumeFill();
  const auto local_matrix = c.K->getLocalMatrixHost();
  for (auto _ : state) {
    bench::timed_iteration(state, [&] {
      int order[max_element_nodes], cols[max_element_dofs], perm[max_element_dofs];
      double Ke_sorted[max_element_dofs * max_element_dofs];
      for (GlobalIndex e = 0; e < block.num_elements(); ++e) {
        const GlobalIndex* conn = &block.connectivity[e * npe];
        for (int a = 0; a < npe; ++a) order[a] = a;
        if (sorted)  // insertion sort of the element's nodes by column index
          for (int a = 1; a < npe; ++a)
            for (int b = a; b > 0 && conn[order[b]] < conn[order[b - 1]]; --b)
              std::swap(order[b], order[b - 1]);
        for (int a = 0; a < npe; ++a)
          for (int d = 0; d < dim; ++d) {
            cols[a * dim + d] = int(conn[order[a]] * dim + d);
            perm[a * dim + d] = order[a] * dim + d;
          }
        const double* values = Ke.data();
        if (sorted) {
          for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) Ke_sorted[i * n + j] = Ke[perm[i] * n + perm[j]];
          values = Ke_sorted;
        }
        for (int i = 0; i < n; ++i)
          local_matrix.sumIntoValues(cols[i], cols, n, &values[i * n], sorted, true);
      }
    });
  }
  c.K->fillComplete(c.problem->owned_map(), c.problem->owned_map());
  report_per_element(state, c);
}

void scatter_unsorted(benchmark::State& state, Topology t) {
  scatter_matrix(state, t, false);
}
void scatter_sorted(benchmark::State& state, Topology t) {
  scatter_matrix(state, t, true);
}

void register_benchmarks() {
  using benchmark::RegisterBenchmark;
  RegisterBenchmark("element_kernel/quad4", element_kernel, Topology::quad4)->UseManualTime();
  RegisterBenchmark("element_kernel/hex8", element_kernel, Topology::hex8)->UseManualTime();
  // 1e4, 1e5, 1e6 elements (HEX8: 1.06e4, 0.97e5, 1e6; the last needs ~10 s and 3.4 GB
  // of setup on one rank).
  const std::vector<int> quad_sizes = {100, 316, 1000}, hex_sizes = {22, 46, 100};
  const bool one_rank = bench::world_size() == 1;
  struct Family {
    std::string name;
    Topology topology;
    std::vector<int> sizes;
  };
  for (const Family& family :
       {Family{"quad4", Topology::quad4, quad_sizes}, Family{"hex8", Topology::hex8, hex_sizes}}) {
    const auto add = [&](const std::string& what, auto&&... args) {
      return RegisterBenchmark((what + "/" + family.name).c_str(), args..., family.topology)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
    };
    for (int size : family.sizes) {  // per mesh, so that each mesh is built once
      add("assemble", assemble)->Arg(size);
      add("refill_matrix", refill_matrix)->Arg(size);
      if (!one_rank) continue;
      add("scatter_unsorted", scatter_unsorted)->Arg(size);
      add("scatter_sorted", scatter_sorted)->Arg(size);
    }
  }
}

}  // namespace
}  // namespace grout

GROUT_BENCHMARK_MAIN(grout::register_benchmarks)
