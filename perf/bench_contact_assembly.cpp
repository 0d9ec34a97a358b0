// Cost of the contact terms of the mechanics problem per slave element: the contact part of
// MechanicsProblem::residual (gather of the interface dofs, search + AD mortar integration on
// the current geometry, the loops over D, M and the slave nodes that add F and record the
// Jacobian triplets) and of MechanicsProblem::jacobian (the (u, λ) CrsMatrix: solid rows
// copied, contact triplets inserted, fillComplete, Dirichlet elimination).
//
// Meshes: stacked_blocks_2d/3d, one element layer per body (so the solid part that has to be
// subtracted stays small), slave = "upper_bottom" with n segments (2D) or n × n QUAD4 faces
// (3D), master = "lower_top" with ⌊1.3 n⌋ + 1 per direction (non-matching). State: the lower
// bottom is fixed, the upper top pushed down by δ = 0.1 h (h = 1/n) so the interface overlaps
// by δ, plus u_y (u_z) = 0.2 δ (sin 2πx [+ sin 2πy]) on every node (a curved current
// interface, so the current-geometry integration is not the flat special case), and λ = −p e_y
// (e_z) on every slave node: every slave node is active (checked: "active" counter).
//
// Benchmarks "<what>/<case>/<n>", <case> = 2d_reference, 2d_current, 3d_reference, 3d_current
// (ContactInput::geometry). Each iteration times the call on the problem with the contact
// interface AND, interleaved, the same call on a problem over the same mesh and state without
// contact (solid only); the manual time is the former, and the counters (ns per global slave
// element, max over ranks per call) are
//   ns_per_slave          the call with contact (the benchmark's time)
//   solid_ns_per_slave    the same call without contact
//   contact_ns_per_slave  the difference: the cost the contact adds
//   timer_ns_per_slave    (residual only) the "grout: contact (search, integration,
//                         assembly)" Teuchos timer inside residual, i.e. the contact part
//                         measured directly (what `grout --timers` reports).
// MPI: the solid and the contact are distributed (each rank evaluates the slave faces around
// the slave nodes it owns; MechanicsProblem). Results and commands: docs/performance.md,
// "Contact assembly".

#include <Teuchos_TimeMonitor.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "assembly/solid_problem.hpp"
#include "io/contact_meshes.hpp"
#include "nonlinear/mechanics_problem.hpp"
#include "perf/bench_main.hpp"

namespace grout {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct CaseKey {
  int dim = 2;
  bool current = false;
  int n = 0;
  bool frictional = false;  ///< Coulomb, μ = 0.3 (mixed stick and slip), else frictionless
  bool operator==(const CaseKey& o) const {
    return dim == o.dim && current == o.current && n == o.n && frictional == o.frictional;
  }
};

Input contact_input(int dim, bool with_contact, bool current, double delta, bool frictional) {
  Input input;
  input.file = "bench_contact_assembly";
  input.model.dimension = dim;
  for (const char* block : {"lower", "upper"}) {
    MaterialInput m;
    m.name = block;
    m.block = block;
    m.youngs_modulus = 200.0;
    m.poissons_ratio = 0.3;
    input.materials.push_back(m);
  }
  const auto fix = [&](const std::string& set, int component, const std::string& value) {
    DirichletInput d;
    d.name = set + "_" + std::to_string(component);
    d.node_set = set;
    d.component = component;
    d.value = Expression(value, "bench_contact_assembly: " + d.name);
    input.dirichlet.push_back(d);
  };
  for (int c = 0; c < dim; ++c) fix("lower_bottom", c, "0");
  char value[32];
  std::snprintf(value, sizeof value, "%.17g", -delta);
  fix("upper_top", dim - 1, value);
  if (with_contact) {
    ContactInput c;
    c.name = "interface";
    c.slave = "upper_bottom";
    c.master = "lower_top";
    c.geometry = current ? ContactGeometry::current : ContactGeometry::reference;
    if (frictional) {
      c.type = ContactKind::frictional;
      c.friction_coefficient = 0.3;
    }
    input.contact.push_back(c);
  }
  return input;
}

/// One mechanics problem (the solid shared) with its state vector.
struct ProblemState {
  Input input;
  std::unique_ptr<SolidProblem> solid;
  std::unique_ptr<MechanicsProblem> problem;
  Teuchos::RCP<Vector> x, F;
  Teuchos::RCP<Matrix> J;
};

struct ContactCase {
  CaseKey key;
  Mesh mesh;
  double delta = 0.0;
  std::vector<char> upper;  ///< per node: belongs to block "upper"
  long slave_elements = 0;
  int slave_nodes = 0;
  ProblemState with, without;  ///< with and without the contact interface
  double setup_seconds = 0.0;  ///< mesh + both problems + first residual/Jacobian, max over ranks
};

// u: the upper body pushed down by δ, plus a smooth bump; λ = −p e_last on every slave node.
void fill_state(const ContactCase& c, ProblemState& p) {
  const int dim = c.mesh.dimension;
  const GO num_u = GO(c.mesh.num_nodes()) * dim;
  const Map& map = *p.problem->map();
  {
    auto xv = p.x->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t i = 0; i < map.getNodeNumElements(); ++i) {
      const GO g = map.getGlobalElement(LO(i));
      double value = 0.0;
      if (g < num_u) {
        const GO node = g / dim;
        const int component = int(g % dim);
        if (component == dim - 1) {
          const double* X = &c.mesh.coordinates[node * dim];
          double bump = std::sin(2 * kPi * X[0]);
          if (dim == 3) bump += std::sin(2 * kPi * X[1]);
          value = (c.upper[node] ? -c.delta : 0.0) + 0.2 * c.delta * bump;
        }
      } else {
        value = int((g - num_u) % dim) == dim - 1 ? -1.0 : 0.0;  // compressive multiplier
      }
      xv(i, 0) = value;
    }
  }
  p.problem->begin_step(1.0, *p.x);  // prescribed values into x
}

void build(ContactCase& c, ProblemState& p, bool with_contact) {
  p.input = contact_input(c.mesh.dimension, with_contact, c.key.current, c.delta, c.key.frictional);
  p.solid = std::make_unique<SolidProblem>(c.mesh, p.input, Tpetra::getDefaultComm());
  p.problem = std::make_unique<MechanicsProblem>(*p.solid, c.mesh, p.input);
  p.x = Teuchos::rcp(new Vector(p.problem->map()));
  p.F = Teuchos::rcp(new Vector(p.problem->map()));
  fill_state(c, p);
  p.problem->residual(*p.x, *p.F);  // first evaluation: active set, triplets
  p.problem->jacobian(*p.x, p.J);
}

// One case at a time (built on first use, freed before the next).
ContactCase& contact_case(const CaseKey& key) {
  static std::unique_ptr<ContactCase> cached;
  static const bool freed_at_finalize =
      (bench::at_finalize().push_back([] { cached.reset(); }), true);
  (void)freed_at_finalize;
  if (cached && cached->key == key) return *cached;
  cached.reset();
  MPI_Barrier(bench::world());
  const auto start = std::chrono::steady_clock::now();
  auto c = std::make_unique<ContactCase>();
  c->key = key;
  const int n = key.n, m = int(1.3 * n) + 1;
  StackedBlocks spec;
  spec.nx_upper = spec.ny_upper = n;
  spec.nx_lower = spec.ny_lower = m;
  spec.nz_lower = spec.nz_upper = 1;
  if (key.dim == 2) spec.ny_lower = spec.ny_upper = 1;
  spec.height_lower = spec.height_upper = 1.0 / n;  // one layer of near-cubic elements
  c->mesh = key.dim == 2 ? stacked_blocks_2d(spec) : stacked_blocks_3d(spec);
  c->delta = 0.1 / n;
  c->upper.assign(c->mesh.num_nodes(), 0);
  for (GlobalIndex node : c->mesh.find_block("upper")->connectivity) c->upper[node] = 1;
  c->slave_elements = key.dim == 2 ? long(n) : long(n) * n;
  c->slave_nodes = key.dim == 2 ? n + 1 : (n + 1) * (n + 1);
  build(*c, c->with, true);
  build(*c, c->without, false);
  const double local =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  MPI_Allreduce(&local, &c->setup_seconds, 1, MPI_DOUBLE, MPI_MAX, bench::world());
  cached = std::move(c);
  return *cached;
}

double max_over_ranks(double local) {
  double global = 0.0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, bench::world());
  return global;
}

template <class Work>
double timed(Work&& work) {
  MPI_Barrier(bench::world());
  const auto start = std::chrono::steady_clock::now();
  work();
  return max_over_ranks(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

enum class What { residual, jacobian };

void contact_benchmark(benchmark::State& state, int dim, bool current, What what,
                       bool frictional = false) {
  ContactCase& c = contact_case(CaseKey{dim, current, int(state.range(0)), frictional});
  Teuchos::Time& contact_timer =
      *Teuchos::TimeMonitor::getNewTimer("grout: contact (search, integration, assembly)");
  double with_total = 0.0, without_total = 0.0, timer_total = 0.0;
  bool ok = true;
  for (auto _ : state) {
    const auto call = [&](ProblemState& p) {
      if (what == What::residual)
        ok &= p.problem->residual(*p.x, *p.F);
      else
        ok &= p.problem->jacobian(*p.x, p.J);
    };
    const double timer_before = contact_timer.totalElapsedTime();
    const double t_with = timed([&] { call(c.with); });
    timer_total += max_over_ranks(contact_timer.totalElapsedTime() - timer_before);
    const double t_without = timed([&] { call(c.without); });
    state.SetIterationTime(t_with);
    with_total += t_with;
    without_total += t_without;
  }
  if (!ok) state.SkipWithError("residual/jacobian failed");
  const double per = 1e9 / (double(state.iterations()) * double(c.slave_elements));
  state.counters["slave_elements"] = double(c.slave_elements);
  state.counters["ns_per_slave"] = with_total * per;
  state.counters["solid_ns_per_slave"] = without_total * per;
  state.counters["contact_ns_per_slave"] = (with_total - without_total) * per;
  if (what == What::residual) state.counters["timer_ns_per_slave"] = timer_total * per;
  state.counters["active"] =
      double(c.with.problem->active_set_size()) / double(c.slave_nodes);  // 1 = all active
  state.counters["setup_s"] = c.setup_seconds;
}

void residual_benchmark(benchmark::State& state, int dim, bool current) {
  contact_benchmark(state, dim, current, What::residual);
}
void jacobian_benchmark(benchmark::State& state, int dim, bool current) {
  contact_benchmark(state, dim, current, What::jacobian);
}
void frictional_residual_benchmark(benchmark::State& state, int dim, bool current) {
  contact_benchmark(state, dim, current, What::residual, true);
}
void frictional_jacobian_benchmark(benchmark::State& state, int dim, bool current) {
  contact_benchmark(state, dim, current, What::jacobian, true);
}

void register_benchmarks() {
  using benchmark::RegisterBenchmark;
  // 2D: 1e2 … 1e5 slave segments; 3D: 8² … 64² slave faces. The current geometry stops one
  // size earlier: its Jacobian costs ~0.4 ms per 2D segment and ~2.5 ms per 3D face (40 s and
  // 10 s per call at 1e5 / 64²).
  for (const int dim : {2, 3}) {
    for (const bool current : {false, true}) {
      const std::string name = std::to_string(dim) + "d_" + (current ? "current" : "reference");
      std::vector<int> sizes =
          dim == 2 ? std::vector<int>{100, 1000, 10000, 100000} : std::vector<int>{8, 16, 32, 64};
      if (current) sizes.pop_back();
      for (const int n : sizes) {  // per case, built once
        RegisterBenchmark(("residual/" + name).c_str(), residual_benchmark, dim, current)
            ->Arg(n)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
        RegisterBenchmark(("jacobian/" + name).c_str(), jacobian_benchmark, dim, current)
            ->Arg(n)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
      }
    }
    // Coulomb friction (μ = 0.3) on the reference geometry: the frictional NCP rows.
    const std::string name = std::to_string(dim) + "d_reference_frictional";
    for (const int n :
         dim == 2 ? std::vector<int>{100, 1000, 10000} : std::vector<int>{8, 16, 32}) {
      RegisterBenchmark(("residual/" + name).c_str(), frictional_residual_benchmark, dim, false)
          ->Arg(n)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
      RegisterBenchmark(("jacobian/" + name).c_str(), frictional_jacobian_benchmark, dim, false)
          ->Arg(n)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace
}  // namespace grout

GROUT_BENCHMARK_MAIN(grout::register_benchmarks)
