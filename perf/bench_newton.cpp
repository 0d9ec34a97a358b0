// Time to solution of one Newton iteration of a two-body contact problem, by linear solver:
// residual (solid assembly + contact search, integration and assembly), Jacobian ((u, λ)
// matrix), linear solve from scratch (MUMPS: analysis + factorisation + solve), and the solve
// again after the values changed but not the pattern (MUMPS: factorisation + solve, the
// analysis reused; what a Newton iteration with an unchanged active set costs).
//
// Meshes: `grout_mesh stacked_2d/stacked_3d` blocks, lower n × n (2D) or n × n × n/2 (3D)
// elements, upper (n+1) × (n+1) (× n/2), unit width, near-square elements; E = 200,
// ν = 0.3; the lower bottom fixed, the upper top moved down by δ = 0.01 (all components
// prescribed), frictionless contact upper_bottom (slave) on lower_top. State: the upper body
// moved down rigidly by δ and λ = −e_last on every slave node (all active), the prescribed
// values in place; one residual + Jacobian before timing (active set).
//
// Benchmarks newton/<2d|3d>/<solver>/<n>, one iteration each (Iterations(1); repetitions
// from tools/bench). Counters (seconds are the max over ranks):
//   dofs, active               unknowns (u and λ), active slave nodes
//   solid_s, contact_s         "grout: solid assembly" / "grout: contact (...)" timers in
//                              the residual
//   jacobian_s, solve_s        the Jacobian; the linear solve with a new solver
//   analysis_s                 the MUMPS analysis inside solve_s (0 for other solvers)
//   resolve_s                  the solve with changed values and the same solver object
//   resolve_condense_s, resolve_muelu_s, resolve_krylov_s   inside resolve_s, as below
//   iteration_cpu_s, solve_cpu_s, resolve_cpu_s   process CPU time (all threads) of the
//                              whole iteration / the two solves, max over ranks: on a loaded
//                              machine closer to the uncontended cost than the wall time
//   condense_s, muelu_s, krylov_s   inside solve_s (belos): the condensation of the
//                              multipliers (or the symmetric reduction, which the frictionless
//                              case passes: linear_solver.hpp), the MueLu set-up, the Belos
//                              iterations
//   symmetric                  1 if the solve took the symmetric reduction
//   linear_iterations          of the first solve (1 for a direct solver); resolve_iterations
//                              of the second
//   residual                   |J dx + F| / |F| of the first solve
//   diff_vs_mumps              max |dx − dx_mumps| / max |dx_mumps| (solvers after mumps)
//   maxrss_MB, maxrss_sum_MB   peak resident memory of the process so far (getrusage), max
//                              and sum over ranks: run one case per process for its own peak
//
// Environment:
//   GROUT_BENCH_NEWTON_LARGE=1        add the ~1e6-dof cases (2D n = 500, 3D n = 68)
//   GROUT_BENCH_NEWTON_SOLVERS=list   comma-separated `Linear Solver` types (default
//                                     "mumps,amesos2"; e.g. "mumps,amesos2,belos";
//                                     mumps-amd etc.: MUMPS with that ordering)
//   GROUT_BENCH_NEWTON_KLU2_ALL=1     amesos2 (KLU2) at every size (default: 2D up to 1e5
//                                     dofs, 3D n = 14 only: 3D n = 20 takes ~160 s per solve)
//   GROUT_BENCH_NEWTON_PARAMS=file.xml   a Teuchos XML `Linear Solver` list merged over the
//                                     bench's (e.g. a MueLu or Belos sublist to try)
//   GROUT_BENCH_NEWTON_RESOLVE=0      skip the second solve (resolve_s = 0)
//   GROUT_BENCH_NEWTON_RESOLVE=same   the second solve with the same values (a copy of J: the
//                                     next iteration or step with an unchanged active set)
//   GROUT_BENCH_NEWTON_SIZES_3D=list  comma-separated 3D n instead of 14,20,31 (+ 68)
// belos runs with condense_multipliers: true and its defaults.
//
// Benchmarks step/<2d|3d>/<quasi_static|dynamic>/<n>: whole steps on the same meshes and
// contact, with the linear solver `type: auto` (KLU2 in 2D, MUMPS in 3D at these sizes) and
// ρ = 1. The upper top moves down by δ = 0.01 in 4 equal steps, prescribed u_y = −δ t/t_end
// (upper top) with everything else as above:
//   quasi_static  4 load steps to t_end = 1 (solve_load_steps' work: Newton to convergence,
//                 the converged residual, commit);
//   dynamic       4 time steps of Newmark (average acceleration, consistent mass, stabilised
//                 contact) to t_end = 4 Δt with Δt = h/c (Courant number 1 on the element size
//                 h = 1/n, c = √(E/ρ)): solve_time_steps' work per step (Newton, the converged
//                 residual, the commit with its mass solve for the stabilised contact and the
//                 energies), after the start (mass matrix, initial acceleration) which is
//                 not timed.
// Counters: step_s, step_cpu_s (mean wall / process CPU time per step, max over ranks),
// newton_per_step, iteration_s (step_s / newton_per_step), dofs; the dynamic case adds
// step_ratio and iteration_ratio against the quasi-static case of the same size (run first).

#include <sys/resource.h>

#include <Teuchos_TimeMonitor.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "assembly/mass_matrix.hpp"
#include "assembly/solid_problem.hpp"
#include "io/contact_meshes.hpp"
#include "io/mesh_bodies.hpp"
#include "nonlinear/dynamic_problem.hpp"
#include "nonlinear/generalized_alpha_family.hpp"
#include "nonlinear/linear_solver.hpp"
#include "nonlinear/load_stepping.hpp"
#include "nonlinear/mechanics_problem.hpp"
#include "perf/bench_main.hpp"

namespace grout {
namespace {

constexpr double kDelta = 0.01;

struct CaseKey {
  int dim = 2;
  int n = 0;
  bool operator==(const CaseKey& o) const { return dim == o.dim && n == o.n; }
};

Input newton_input(int dim) {
  Input input;
  input.file = "bench_newton";
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
    d.value = Expression(value, "bench_newton: " + d.name);
    input.dirichlet.push_back(d);
  };
  for (int c = 0; c < dim; ++c) {
    fix("lower_bottom", c, "0");
    fix("upper_top", c, c == dim - 1 ? "-0.01" : "0");
  }
  ContactInput c;
  c.name = "interface";
  c.slave = "upper_bottom";
  c.master = "lower_top";
  input.contact.push_back(c);
  return input;
}

struct NewtonCase {
  CaseKey key;
  Mesh mesh;
  std::vector<int> bodies;  // io/mesh_bodies.hpp
  Input input;
  std::unique_ptr<SolidProblem> solid;
  std::unique_ptr<MechanicsProblem> problem;
  Teuchos::RCP<Vector> x, F, dx_mumps;
  Teuchos::RCP<Matrix> J;
  double setup_seconds = 0.0;
};

double max_over_ranks(double local) {
  double global = 0.0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, bench::world());
  return global;
}

double sum_over_ranks(double local) {
  double global = 0.0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, bench::world());
  return global;
}

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// Wall time of `work` (max over ranks); adds its process CPU time (max over ranks) to *cpu.
template <class Work>
double timed(Work&& work, double* cpu = nullptr) {
  MPI_Barrier(bench::world());
  const double cpu_start = process_cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  work();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (cpu) *cpu += max_over_ranks(process_cpu_seconds() - cpu_start);
  return max_over_ranks(wall);
}

bool env_flag(const char* name) {
  const char* v = std::getenv(name);
  return v && std::string(v) != "0" && !std::string(v).empty();
}

double timer_seconds(const char* name) {
  return Teuchos::TimeMonitor::getNewTimer(name)->totalElapsedTime();
}

// The upper body moved down by δ, λ = −e_last on the slave nodes; prescribed values set.
void fill_state(NewtonCase& c) {
  const int dim = c.mesh.dimension;
  const GO num_u = GO(c.mesh.num_nodes()) * dim;
  std::vector<char> upper(c.mesh.num_nodes(), 0);
  for (GlobalIndex node : c.mesh.find_block("upper")->connectivity) upper[node] = 1;
  const Map& map = *c.problem->map();
  {
    auto xv = c.x->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t i = 0; i < map.getNodeNumElements(); ++i) {
      const GO g = map.getGlobalElement(LO(i));
      const bool last = int(g % dim) == dim - 1;
      if (g < num_u)
        xv(i, 0) = last && upper[g / dim] ? -kDelta : 0.0;
      else
        xv(i, 0) = int((g - num_u) % dim) == dim - 1 ? -1.0 : 0.0;
    }
  }
  c.problem->begin_step(1.0, *c.x);
}

// One case at a time (built on first use, freed before the next).
NewtonCase& newton_case(const CaseKey& key) {
  static std::unique_ptr<NewtonCase> cached;
  static const bool freed_at_finalize =
      (bench::at_finalize().push_back([] { cached.reset(); }), true);
  (void)freed_at_finalize;
  if (cached && cached->key == key) return *cached;
  cached.reset();
  MPI_Barrier(bench::world());
  const auto start = std::chrono::steady_clock::now();
  auto c = std::make_unique<NewtonCase>();
  c->key = key;
  StackedBlocks spec;
  spec.nx_lower = spec.ny_lower = key.n;
  spec.nx_upper = spec.ny_upper = key.n + 1;
  if (key.dim == 3) {
    spec.nz_lower = spec.nz_upper = key.n / 2;
    spec.height_lower = spec.height_upper = 0.5;
  }
  c->mesh = key.dim == 2 ? stacked_blocks_2d(spec) : stacked_blocks_3d(spec);
  c->bodies = node_bodies(c->mesh);
  c->input = newton_input(key.dim);
  c->solid = std::make_unique<SolidProblem>(c->mesh, c->input, Tpetra::getDefaultComm());
  c->problem = std::make_unique<MechanicsProblem>(*c->solid, c->mesh, c->input);
  c->x = Teuchos::rcp(new Vector(c->problem->map()));
  c->F = Teuchos::rcp(new Vector(c->problem->map()));
  fill_state(*c);
  c->problem->residual(*c->x, *c->F);  // active set
  c->problem->jacobian(*c->x, c->J);
  c->setup_seconds = max_over_ranks(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  cached = std::move(c);
  return *cached;
}

// "mumps-<ordering>": MUMPS with that ordering.
Teuchos::ParameterList solver_params(const std::string& name) {
  Teuchos::ParameterList p;
  const std::string type = name.substr(0, name.find('-'));
  p.set("type", type);
  if (type != name) p.sublist("MUMPS").set("ordering", name.substr(type.size() + 1));
  if (type == "belos") {
    p.set("condense_multipliers", true);
    p.sublist("MueLu").set("verbosity", "none");
  }
  if (const char* file = std::getenv("GROUT_BENCH_NEWTON_PARAMS"))
    Teuchos::updateParametersFromXmlFile(file, Teuchos::outArg(p));
  return p;
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // KiB on Linux
}

// The linear solve's phases (seconds): the condensation or symmetric reduction, MueLu's
// set-up, the Belos iterations.
struct SolvePhases {
  double condense = 0, muelu = 0, krylov = 0;
};

// This rank's timer totals so far.
SolvePhases solve_phase_totals() {
  return {timer_seconds("grout: linear solve: condensation") +
              timer_seconds("grout: linear solve: symmetric reduction"),
          timer_seconds("grout: linear solve: MueLu set-up"),
          timer_seconds("grout: linear solve: Krylov iterations")};
}

// Each phase's time since `start` (solve_phase_totals before the solve), max over ranks.
SolvePhases solve_phases_since(const SolvePhases& start) {
  const SolvePhases now = solve_phase_totals();
  return {max_over_ranks(now.condense - start.condense), max_over_ranks(now.muelu - start.muelu),
          max_over_ranks(now.krylov - start.krylov)};
}

void newton_benchmark(benchmark::State& state, int dim, std::string solver_type) {
  NewtonCase& c = newton_case(CaseKey{dim, int(state.range(0))});
  MechanicsProblem& problem = *c.problem;
  Vector dx(problem.map()), rhs(problem.map());
  double solid = 0, contact = 0, jacobian = 0, solve = 0, analysis = 0, resolve = 0;
  SolvePhases phases, resolve_phases;  // of the first solve, of the second
  const char* resolve_env = std::getenv("GROUT_BENCH_NEWTON_RESOLVE");
  const bool resolve_wanted = !resolve_env || std::string(resolve_env) != "0";
  const bool resolve_same = resolve_env && std::string(resolve_env) == "same";
  double iteration_cpu = 0, solve_cpu = 0, resolve_cpu = 0;
  int iterations = 0, resolve_iterations = 0;
  bool ok = true, symmetric = false;
  std::string error;
  for (auto _ : state) {
    const double solid0 = timer_seconds("grout: solid assembly");
    const double contact0 = timer_seconds("grout: contact (search, integration, assembly)");
    const double analysis0 = timer_seconds("grout: MUMPS analysis");
    const SolvePhases phases0 = solve_phase_totals();
    iteration_cpu = solve_cpu = resolve_cpu = 0;
    const double t_residual = timed([&] { ok &= problem.residual(*c.x, *c.F); }, &iteration_cpu);
    solid = max_over_ranks(timer_seconds("grout: solid assembly") - solid0);
    contact =
        max_over_ranks(timer_seconds("grout: contact (search, integration, assembly)") - contact0);
    jacobian = timed([&] { ok &= problem.jacobian(*c.x, c.J); }, &iteration_cpu);
    rhs.update(-1.0, *c.F, 0.0);
    // As the driver (system_layout.hpp), with the case's bodies computed once: the iterative
    // path's MueLu defaults for elasticity (block size, rigid-body modes, bodies kept apart)
    // need the coordinates; without them MueLu ran with its scalar defaults.
    SystemLayout layout;
    layout.multiplier_pairing = problem.multiplier_pairing();
    layout.dofs_per_node = dim;
    layout.coordinates = c.mesh.coordinates;
    layout.dim = dim;
    layout.node_bodies = c.bodies;
    LinearSolver linear(solver_params(solver_type), "bench_newton", std::move(layout));
    try {
      solve = timed([&] { iterations = linear.solve(c.J, rhs, dx); }, &solve_cpu);
      symmetric = linear.last_solve_symmetric();
      iteration_cpu += solve_cpu;
      analysis = max_over_ranks(timer_seconds("grout: MUMPS analysis") - analysis0);
      phases = solve_phases_since(phases0);
      if (resolve_wanted) {
        // The same pattern, other values: a Newton iteration with an unchanged active set.
        Matrix J2(*c.J, Teuchos::Copy);
        J2.resumeFill();
        if (!resolve_same) J2.scale(1.0 + 1e-9);
        J2.fillComplete(c.J->getDomainMap(), c.J->getRangeMap());
        Vector dx2(problem.map());
        const auto J2_ptr = Teuchos::rcpFromRef(J2);
        const SolvePhases phases1 = solve_phase_totals();
        resolve = timed([&] { resolve_iterations = linear.solve(J2_ptr, rhs, dx2); }, &resolve_cpu);
        resolve_phases = solve_phases_since(phases1);
      }
    } catch (const std::exception& e) {
      ok = false;
      error = e.what();
    }
    state.SetIterationTime(t_residual + jacobian + solve);
  }
  // Every Teuchos timer (MueLu's per phase and level when its verbosity is high), on request.
  if (env_flag("GROUT_BENCH_NEWTON_TIMERS")) Teuchos::TimeMonitor::summarize();
  if (!ok) {
    state.SkipWithError(("failed: " + error).c_str());
    return;
  }
  // Accuracy: relative residual, and the difference from the MUMPS answer.
  Vector r(problem.map());
  c.J->apply(dx, r);
  r.update(-1.0, rhs, 1.0);
  state.counters["residual"] = r.norm2() / rhs.norm2();
  if (solver_type == "mumps") {
    c.dx_mumps = Teuchos::rcp(new Vector(dx, Teuchos::Copy));
  } else if (!c.dx_mumps.is_null()) {
    Vector d(problem.map());
    d.update(1.0, dx, -1.0, *c.dx_mumps, 0.0);
    state.counters["diff_vs_mumps"] = d.normInf() / c.dx_mumps->normInf();
  }
  state.counters["dofs"] = double(problem.map()->getGlobalNumElements());
  state.counters["active"] = problem.active_set_size();
  state.counters["solid_s"] = solid;
  state.counters["contact_s"] = contact;
  state.counters["jacobian_s"] = jacobian;
  state.counters["solve_s"] = solve;
  state.counters["analysis_s"] = analysis;
  state.counters["resolve_s"] = resolve;
  state.counters["resolve_iterations"] = resolve_iterations;
  state.counters["resolve_condense_s"] = resolve_phases.condense;
  state.counters["resolve_muelu_s"] = resolve_phases.muelu;
  state.counters["resolve_krylov_s"] = resolve_phases.krylov;
  state.counters["condense_s"] = phases.condense;
  state.counters["muelu_s"] = phases.muelu;
  state.counters["krylov_s"] = phases.krylov;
  state.counters["iteration_cpu_s"] = iteration_cpu;
  state.counters["solve_cpu_s"] = solve_cpu;
  state.counters["resolve_cpu_s"] = resolve_cpu;
  state.counters["linear_iterations"] = iterations;
  state.counters["symmetric"] = symmetric ? 1 : 0;
  state.counters["maxrss_MB"] = max_over_ranks(peak_rss_mb());
  state.counters["maxrss_sum_MB"] = sum_over_ranks(peak_rss_mb());
  state.counters["setup_s"] = c.setup_seconds;
}

// Whole steps, quasi-static or dynamic (file comment).
struct StepCost {
  double step_s = 0.0, step_cpu_s = 0.0, newton_per_step = 0.0;
};

void step_benchmark(benchmark::State& state, int dim, bool dynamic) {
  static std::map<std::pair<int, int>, StepCost> quasi_static_cost;
  const int n = int(state.range(0));
  constexpr int steps = 4;
  StackedBlocks spec;
  spec.nx_lower = spec.ny_lower = n;
  spec.nx_upper = spec.ny_upper = n + 1;
  if (dim == 3) {
    spec.nz_lower = spec.nz_upper = n / 2;
    spec.height_lower = spec.height_upper = 0.5;
  }
  const Mesh mesh = dim == 2 ? stacked_blocks_2d(spec) : stacked_blocks_3d(spec);
  Input input = newton_input(dim);
  const double c = std::sqrt(200.0 / 1.0), dt = 1.0 / n / c;
  const double t_end = dynamic ? steps * dt : 1.0;
  for (auto& m : input.materials) m.density = 1.0;
  for (auto& d : input.dirichlet)
    if (d.node_set == "upper_top" && d.component == dim - 1) {
      std::ostringstream e;
      e.precision(17);
      e << "-0.01*t/" << t_end;
      d.value = Expression(e.str(), "bench_newton: " + d.name);
    }
  if (dynamic) input.dynamics.enabled = true;
  const auto comm = Tpetra::getDefaultComm();
  SolidProblem solid(mesh, input, comm);
  MechanicsProblem problem(solid, mesh, input);
  NewtonOptions newton;
  newton.verbose = false;
  SteppingOptions stepping;
  stepping.end_time = t_end;
  stepping.steps = steps;
  // As the driver: `auto` picks by the layout's dimension (MUMPS in 3D).
  LinearSolver linear(Teuchos::ParameterList(), "bench_newton", system_layout(problem, mesh));
  LinearSolver mass_solver(Teuchos::ParameterList(), "bench_newton: mass",
                           mass_matrix_layout(mesh));
  std::unique_ptr<DynamicProblem> dyn;
  if (dynamic) {
    Vector v0(solid.owned_map());
    dyn = std::make_unique<DynamicProblem>(
        problem, dim, assemble_mass_matrix(solid, false), std::make_unique<Newmark>(),
        std::array<double, 3>{0.0, 0.0, 0.0}, v0, ContactTreatment::stabilized, node_bodies(mesh));
    Vector x0(dyn->map());
    dyn->start(x0, mass_solver);
  }
  NonlinearProblem& stepped = dynamic ? static_cast<NonlinearProblem&>(*dyn) : problem;
  Vector F(stepped.map());
  int newton_iterations = 0;
  double cpu = 0.0, wall = 0.0;
  bool ok = true;
  std::string error;
  for (auto _ : state) {
    wall = timed(
        [&] {
          try {
            march_steps(
                stepped, linear, newton, stepping,
                [&](double t, Vector& x) {
                  if (dynamic)
                    dyn->begin_step(t, x);
                  else
                    problem.begin_step(t, x);
                },
                [&](ConvergedStep& step) {
                  newton_iterations += step.newton->iterations;
                  stepped.residual(*step.state, F);
                  problem.commit_step();
                  if (dynamic) dyn->commit_step(*step.state);
                });
          } catch (const std::exception& e) {
            ok = false;
            error = e.what();
          }
        },
        &cpu);
    state.SetIterationTime(wall);
  }
  if (!ok) {
    state.SkipWithError(("failed: " + error).c_str());
    return;
  }
  StepCost cost;
  cost.step_s = wall / steps;
  cost.step_cpu_s = cpu / steps;
  cost.newton_per_step = double(newton_iterations) / steps;
  state.counters["dofs"] = double(problem.map()->getGlobalNumElements());
  state.counters["step_s"] = cost.step_s;
  state.counters["step_cpu_s"] = cost.step_cpu_s;
  state.counters["newton_per_step"] = cost.newton_per_step;
  state.counters["iteration_s"] = cost.step_s / cost.newton_per_step;
  if (!dynamic) {
    quasi_static_cost[{dim, n}] = cost;
  } else if (quasi_static_cost.count({dim, n})) {
    const StepCost& q = quasi_static_cost[{dim, n}];
    state.counters["step_ratio"] = cost.step_s / q.step_s;
    state.counters["iteration_ratio"] =
        (cost.step_s / cost.newton_per_step) / (q.step_s / q.newton_per_step);
  }
}

void register_benchmarks() {
  std::vector<std::string> solvers;
  {
    const char* env = std::getenv("GROUT_BENCH_NEWTON_SOLVERS");
    std::stringstream list(env ? env : "mumps,amesos2");
    for (std::string s; std::getline(list, s, ',');)
      if (!s.empty()) solvers.push_back(s);
  }
  for (const int dim : {2, 3})
    for (const int n : dim == 2 ? std::vector<int>{50, 160} : std::vector<int>{14, 20})
      for (const bool dynamic : {false, true}) {
        const std::string name = std::string("step/") + std::to_string(dim) + "d/" +
                                 (dynamic ? "dynamic" : "quasi_static");
        benchmark::RegisterBenchmark(name.c_str(), step_benchmark, dim, dynamic)
            ->Arg(n)
            ->Iterations(1)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
      }
  const bool large = env_flag("GROUT_BENCH_NEWTON_LARGE");
  const bool klu2_all = env_flag("GROUT_BENCH_NEWTON_KLU2_ALL");
  // dofs ≈ 2 (n+1)² · 2 (2D), 2 (n+1)² (n/2+1) · 3 (3D), plus the multipliers.
  for (const int dim : {2, 3}) {
    std::vector<int> sizes = dim == 2 ? std::vector<int>{50, 160} : std::vector<int>{14, 20, 31};
    if (const char* list = std::getenv("GROUT_BENCH_NEWTON_SIZES_3D"); list && dim == 3) {
      sizes.clear();
      std::stringstream items(list);
      for (std::string item; std::getline(items, item, ',');)
        if (!item.empty()) sizes.push_back(std::stoi(item));
    }
    if (large) sizes.push_back(dim == 2 ? 500 : 68);
    for (const int n : sizes) {  // per case, built once for all solvers
      for (const std::string& solver : solvers) {
        const bool klu2_feasible = dim == 2 ? n <= 160 : n <= 14;
        if (solver == "amesos2" && !klu2_feasible && !klu2_all) continue;
        const std::string name = "newton/" + std::to_string(dim) + "d/" + solver;
        benchmark::RegisterBenchmark(name.c_str(), newton_benchmark, dim, solver)
            ->Arg(n)
            ->Iterations(1)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
      }
    }
  }
}

}  // namespace
}  // namespace grout

GROUT_BENCHMARK_MAIN(grout::register_benchmarks)
