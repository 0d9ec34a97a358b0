#include "nonlinear/linear_solver.hpp"

#include <mpi.h>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "io/errors.hpp"
#include "nonlinear/condensed_solve.hpp"
#include "nonlinear/gathered_solve.hpp"
#include "nonlinear/iterative_module.hpp"
#include "nonlinear/klu_solve.hpp"
#include "nonlinear/mumps_solver.hpp"
#include "nonlinear/symmetric_condensation.hpp"
#include "nonlinear/timed_agreement.hpp"

namespace grout {

struct LinearSolver::Impl {
  LinearSolverSettings settings;
  std::string type;  // linear_solver_type_name(settings.type)
  std::string belos_type = "CG";
  std::unique_ptr<MumpsSolver> mumps;  // type: mumps
  // LDLᵀ of the symmetric reductions (symmetric_condensation.hpp), kept apart from `mumps` so
  // that each keeps its analysis while its pattern does not change.
  std::unique_ptr<MumpsSolver> mumps_symmetric;
  bool last_symmetric = false;
  double relative_tolerance = 0.0;  // set_relative_tolerance; 0: settings.belos's own
  MumpsOptions gathered_options;    // settings.mumps for the gathered solves (ordering: amd)
  // Rank 0's 1-rank communicator for the gathered direct solves (split from `parent` once:
  // MUMPS keeps its analysis per communicator).
  Teuchos::RCP<const Comm> parent, self;

  // Collective on `comm` the first time it is seen (every rank solves with the same maps).
  Teuchos::RCP<const Comm> self_communicator(const Teuchos::RCP<const Comm>& comm) {
    if (parent.get() != comm.get()) {
      parent = comm;
      self = comm->split(comm->getRank() == 0 ? 0 : 1, comm->getRank());
    }
    return self;
  }
  // The system's layout (system_layout.hpp), with node_bodies emptied when every node is in
  // one body (replicated layouts; a distributed one comes so).
  SystemLayout layout;
  // The iterative path (type: belos), from the module grout_iterative loaded at the first
  // iterative solve (iterative_module.hpp); it keeps the MueLu hierarchy between solves.
  std::unique_ptr<IterativeSolver> iterative;
  IterativeSolver& iterative_solver() {
    if (!iterative) iterative = create_iterative_solver();
    return *iterative;
  }
  // The iterative solve, its outcome agreed over the ranks (timed_agreement.hpp): a rank
  // whose Krylov solve or MueLu set-up threw while the others wait inside it for this rank
  // ends the job after stall_limit_seconds(); otherwise every rank throws when any rank
  // failed, so that every rank cuts the step back, or falls back to the direct solver, alike.
  // Where the kinds differ, an error with an exit code of its own (no module) or an InputError
  // ranks above a failed solve: the ranks that hold one rethrow it, the others throw
  // ErrorOnOtherRank with its code.
  std::unique_ptr<TimedAgreement> agreement;
  int agreed_iterative_solve(const Teuchos::RCP<const Matrix>& K, const Vector& b, Vector& x,
                             const std::string& belos_type, const IterativeSettings& settings) {
    const Comm& comm = *K->getRowMap()->getComm();
    if (comm.getSize() == 1) return iterative_solver().solve(K, b, x, belos_type, settings);
    if (!agreement || !agreement->built_on(comm))  // every rank's first iterative solve
      agreement = std::make_unique<TimedAgreement>(comm);
    std::exception_ptr error;
    int iterations = 0;
    try {
      iterations = iterative_solver().solve(K, b, x, belos_type, settings);
    } catch (...) {
      error = std::current_exception();
    }
    // Kind: 2 an error with its own exit code or an InputError, 1 any other (a failed solve).
    int kind = 0;
    if (error) {
      try {
        std::rethrow_exception(error);
      } catch (const ExitCodeError&) {
        kind = 2;
      } catch (const InputError&) {
        kind = 2;
      } catch (...) {
        kind = 1;
      }
    }
    const int code = error ? exit_code_of(error) : 0;
    const int highest =
        agreement->highest(kind * 256 + code, error ? without_source_paths(message_of(error)) : "",
                           code, stall_limit_seconds());
    if (highest == 0) return iterations;
    if (error && kind == highest / 256) std::rethrow_exception(error);
    if (highest / 256 == 2) throw ErrorOnOtherRank(highest % 256);
    throw std::runtime_error("the iterative solve failed on another rank");
  }
  std::string last_type;
  // type: auto took the iterative path and it failed: the direct solver from then on.
  bool iterative_failed = false;

  // Whether a solve of `type` condenses the multipliers: as told, else on the iterative path
  // (the point of the condensation) and on the distributed MUMPS path: on the 3D Hertz
  // spheres (10 987 nodes) the condensed system's factorisation takes 30.7 GFlop against 47.1
  // for the (u, λ) system, 0.68x of its time (docs/performance.md, "Condensed, symmetric
  // and Schur-updated direct solves"). The gathered direct solves (2D) keep the (u, λ) system.
  bool condenses(const std::string& type) const {
    if (settings.condense_multipliers) return *settings.condense_multipliers;
    return type == "belos" || (type == "mumps" && !settings.mumps.gather);
  }
};

// 3D: MUMPS, distributed, 18-50x faster than KLU2 on 3D systems of 1e4-3e4 unknowns. 2D:
// MUMPS on the system gathered to rank 0 (gathered_solve.hpp; AMD, one BLAS thread): the
// same answer bit for bit on any number of ranks, which the 2D point-contact and Hertz cases
// need (their nearly free modes amplify the rounding of a distributed factorisation), and
// 0.46x the instructions of the gathered KLU2 it replaced (docs/performance.md, "2D speed and
// the demo on 2 ranks").
std::string default_direct_type(int dim) {
  return dim == 3 ? "mumps" : "mumps_gathered";
}

// 3D: MUMPS against Belos (docs/performance.md, "MUMPS as the default direct solver in 3D" and
// "Side by side with GetFEM (Hertz spheres, 3D)"); 2D: the direct solve against Belos
// ("Iterative solver"). docs/input.md, "type: auto".
long long auto_iterative_threshold(int dim) {
  return dim == 3 ? 50000 : 200000;
}

// 2D below 2 000 unknowns: KLU2, gathered like the MUMPS solve (the same answer on any number
// of ranks). On such systems MUMPS's fixed costs (its analysis, scaling and redistribution)
// outweigh its supernodes: 2D Hertz level 1 (~1.3 k unknowns, 2 solves) took 5 ms less CPU
// with KLU2, level 2 (~4.9 k) the same, level 3 (~19.5 k) 1.4x more; stacked blocks: KLU2
// ahead at ~1.3 k unknowns, even at ~2.7 k (docs/performance.md, "2D speed and the
// demo on 2 ranks").
long long auto_small_direct_threshold(int dim) {
  return dim == 2 ? 2000 : 0;
}

std::string auto_linear_solver_type(long long global_unknowns, int dim) {
  if (global_unknowns >= auto_iterative_threshold(dim)) return "belos";
  if (global_unknowns < auto_small_direct_threshold(dim)) return "amesos2";
  return default_direct_type(dim);
}

LinearSolver::LinearSolver(LinearSolverSettings settings, SystemLayout layout)
    : impl_(std::make_unique<Impl>()) {
  impl_->settings = std::move(settings);
  impl_->layout = std::move(layout);
  std::vector<int>& bodies = impl_->layout.node_bodies;
  // Each rank holds every node's body only on the replicated mesh (system_layout.hpp).
  if (impl_->layout.nodes.empty() &&
      std::all_of(bodies.begin(), bodies.end(), [&](int b) { return b == bodies.front(); }))
    bodies.clear();
  const LinearSolverSettings& s = impl_->settings;
  impl_->type = linear_solver_type_name(s.type);
  // The gathered solve orders with AMD unless told otherwise: on 2D Hertz (19 k and 75 k
  // unknowns) SCOTCH's nested dissection cost more in its analyses than it saved in the
  // factorisations (docs/performance.md, "2D speed and the demo on 2 ranks").
  impl_->gathered_options = s.mumps;
  impl_->gathered_options.gather = true;
  if (!s.mumps_ordering_given) impl_->gathered_options.ordering = "amd";
  if (!s.belos_solver.empty()) impl_->belos_type = s.belos_solver;
  // Belos names its own solvers (case-insensitive): ask it, so that a misspelt name is an
  // input error here and not an exception from inside Belos at the first solve. Asking
  // loads the iterative module: done when the input asks for the iterative path or has Belos
  // settings to check, so that an installation without the module fails before any step.
  if (!s.belos_solver.empty() || s.type == LinearSolverType::belos) {
    IterativeSolver& belos = impl_->iterative_solver();
    if (!belos.is_belos_solver(impl_->belos_type)) {
      std::string names;
      for (const std::string& name : belos.belos_solver_names())
        names += (names.empty() ? "" : ", ") + name;
      throw InputError(s.where + "/Belos/Solver Type: unknown Belos solver '" + impl_->belos_type +
                       "' (Belos has: " + names + ")");
    }
    // Belos checks the names and values of its parameters when it sets them.
    if (s.type == LinearSolverType::belos) {
      const std::string rejected = belos.belos_rejects(impl_->belos_type, s.belos);
      if (!rejected.empty())
        throw InputError(s.where +
                         "/Belos: Belos rejects these settings: " + without_source_paths(rejected));
    }
  }
}

LinearSolver::LinearSolver(const Teuchos::ParameterList& params, const std::string& where,
                           SystemLayout layout)
    : LinearSolver(linear_solver_settings_from(params, where), std::move(layout)) {}

LinearSolver::~LinearSolver() = default;

// --- condensed multipliers ---
bool LinearSolver::condenses_multipliers() const {
  return impl_->condenses(impl_->type);
}

int LinearSolver::reused_hierarchies() const {
  return impl_->iterative ? impl_->iterative->reused_hierarchies() : 0;
}

int LinearSolver::kept_hierarchies() const {
  return impl_->iterative ? impl_->iterative->kept_hierarchies() : 0;
}

double LinearSolver::jacobi_damping() const {
  return impl_->iterative ? impl_->iterative->jacobi_damping() : 0.0;
}

const std::string& LinearSolver::last_type() const {
  return impl_->last_type;
}

bool LinearSolver::last_solve_symmetric() const {
  return impl_->last_symmetric;
}

void LinearSolver::set_relative_tolerance(double tolerance) {
  impl_->relative_tolerance = tolerance;
}

int LinearSolver::solve(const Teuchos::RCP<const Matrix>& K, const Vector& b, Vector& x,
                        const MultiplierRows* rows) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: linear solve"));
  const SystemLayout& layout = impl_->layout;
  const int dim = layout.dim > 0 ? layout.dim : 2;  // 2 when the layout has no dimension
  std::string type = impl_->type != "auto"
                         ? impl_->type
                         : auto_linear_solver_type((long long)K->getGlobalNumRows(), dim);
  // A `MUMPS` sublist asks for MUMPS: auto then keeps it for the smallest 2D systems too.
  if (impl_->type == "auto" && type == "amesos2" && impl_->settings.mumps_given)
    type = default_direct_type(dim);
  if (impl_->type == "auto" && type == "belos" && impl_->iterative_failed)
    type = default_direct_type(dim);
  impl_->last_type = type;
  impl_->last_symmetric = false;
  if (!impl_->condenses(type) || layout.multiplier_pairing.empty())
    return solve_system(K, b, x, type,
                        impl_->settings.belos_solver.empty() ? "CG" : impl_->belos_type);
  // The distributed MUMPS path and the iterative path first try the symmetric (null-space)
  // reduction: for frictionless or tied contact with a fixed pairing and a symmetric
  // stiffness it gives a symmetric positive (semi)definite K̃. MUMPS factorises it as LDLᵀ
  // with about half the flops of the LU of the condensed system (docs/performance.md,
  // "Condensed, symmetric and Schur-updated direct solves"); Belos solves it with CG and MueLu
  // with the smoother of a system without multipliers (Gauss–Seidel, forward before the
  // coarse correction and backward after, no factorisation to set up:
  // elasticity_preconditioner.hpp), where the condensed system needs GMRES and ILU(0)
  // (docs/performance.md, "Iterative solver"). Anything else (slip, geometry: current) fails its
  // checks and takes the condensation below.
  const bool symmetric_path =
      impl_->settings.symmetric_reduction &&
      ((type == "mumps" && !impl_->settings.mumps.gather) || type == "belos");
  if (symmetric_path) {
    SymmetricCondensation reduction(layout.multiplier_pairing, layout.dofs_per_node);
    bool applies = false;
    {
      Teuchos::TimeMonitor reduce_timer(
          *Teuchos::TimeMonitor::getNewTimer("grout: linear solve: symmetric reduction"));
      applies = reduction.condense(*K, b, rows);
    }
    if (applies) {
      Vector y(reduction.matrix()->getRowMap());
      int iterations = 1;
      if (type == "belos") {
        iterations =
            solve_system(reduction.matrix(), reduction.rhs(), y, type,
                         impl_->settings.belos_solver.empty() ? "CG" : impl_->belos_type, false);
      } else {
        Teuchos::TimeMonitor solve_timer(
            *Teuchos::TimeMonitor::getNewTimer("grout: linear solve: symmetric MUMPS"));
        if (!impl_->mumps_symmetric) {
          MumpsOptions options = impl_->settings.mumps;
          options.symmetric = true;
          // K̃ is SPD and changes between Newton iterations only near the contact interface.
          options.schur_updates = true;
          impl_->mumps_symmetric = std::make_unique<MumpsSolver>(options);
        }
        impl_->mumps_symmetric->solve(reduction.matrix(), reduction.rhs(), y);
      }
      reduction.expand(y, x);
      impl_->last_symmetric = true;
      return iterations;
    }
  }
  MultiplierCondensation condensation(layout.multiplier_pairing, layout.dofs_per_node);
  {
    Teuchos::TimeMonitor condense_timer(
        *Teuchos::TimeMonitor::getNewTimer("grout: linear solve: condensation"));
    condensation.condense(*K, b, rows);
  }
  Vector y(condensation.matrix()->getRowMap());
  // A reduced row with a zero diagonal (a prescribed slave dof whose node's multiplier rows
  // do not involve that multiplier: tied or sticking) defeats relaxation smoothers: such a
  // reduced system goes to the direct solver.
  const int iterations =
      condensation.statistics().zero_diagonals > 0
          ? solve_system(condensation.matrix(), condensation.rhs(), y, default_direct_type(dim), "")
          : solve_system(condensation.matrix(), condensation.rhs(), y, type,
                         impl_->settings.belos_solver.empty() ? "GMRES" : impl_->belos_type);
  condensation.expand(y, x);
  return iterations;
}
// --- end condensed multipliers ---

int LinearSolver::solve_system(const Teuchos::RCP<const Matrix>& K, const Vector& b, Vector& x,
                               const std::string& type, const std::string& belos_type,
                               bool multipliers) {
  if (type == "amesos2") {
    solve_gathered(K, b, x, impl_->self_communicator(K->getRowMap()->getComm()),
                   [](const Teuchos::RCP<Matrix>& K_self, Vector& b_self, Vector& x_self) {
                     klu_solve(*K_self, b_self, x_self);
                   });
    return 1;
  }
  if (type == "mumps" || type == "mumps_gathered") {
    const bool gather = type == "mumps_gathered" || impl_->settings.mumps.gather;
    if (!impl_->mumps)
      impl_->mumps =
          std::make_unique<MumpsSolver>(gather ? impl_->gathered_options : impl_->settings.mumps);
    if (!gather) {
      impl_->mumps->solve(K, b, x);
      return 1;
    }
    // Rank 0 alone, on one BLAS thread: the same operations in the same order on any number
    // of ranks (MumpsOptions::gather).
    const SingleBlasThread one_thread;
    solve_gathered(K, b, x, impl_->self_communicator(K->getRowMap()->getComm()),
                   [&](const Teuchos::RCP<Matrix>& K_self, Vector& b_self, Vector& x_self) {
                     impl_->mumps->solve(K_self, b_self, x_self);
                   });
    return 1;
  }

  // Belos + MueLu, in the module grout_iterative (loaded here at the first iterative solve).
  // A forcing term (set_relative_tolerance) replaces the tolerance for this solve; on a
  // reduced or condensed system it is relative to that system's right-hand side.
  Teuchos::ParameterList belos = impl_->settings.belos;
  if (impl_->relative_tolerance > 0.0)
    belos.set("Convergence Tolerance", impl_->relative_tolerance);
  const bool with_multipliers = multipliers && !impl_->layout.multiplier_pairing.empty();
  // Not told: a system without multipliers (CG, Gauss-Seidel) keeps the coarse levels; the
  // condensed system (GMRES, ILU(0)) gets a new hierarchy every solve (linear_solver.hpp).
  const auto& told = impl_->settings.reuse_preconditioner;
  const HierarchyReuse reuse = told ? (*told ? HierarchyReuse::prolongators : HierarchyReuse::none)
                               : with_multipliers ? HierarchyReuse::none
                                                  : HierarchyReuse::coarse_levels;
  const IterativeSettings settings{belos,
                                   impl_->settings.muelu,
                                   reuse,
                                   impl_->layout.dim,
                                   impl_->layout.coordinates,
                                   impl_->layout.node_bodies,
                                   impl_->layout.nodes,
                                   impl_->layout.num_global_nodes,
                                   with_multipliers,
                                   impl_->settings.translations_only};
  try {
    return impl_->agreed_iterative_solve(K, b, x, belos_type, settings);
  } catch (const ExitCodeError&) {  // no module, or an error with its own exit code
    throw;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    // Under type: auto a failed iterative solve (Krylov not converged, loss of accuracy, a
    // MueLu set-up that breaks down on a body held only by contact) is not the step's fault:
    // a cut-back would fail the same way. The direct solver takes this system and the rest
    // of the run, with a note.
    if (impl_->type != "auto") throw;
    const int dim = impl_->layout.dim > 0 ? impl_->layout.dim : 2;
    const std::string direct = default_direct_type(dim);
    if (K->getRowMap()->getComm()->getRank() == 0) {
      std::printf(
          "grout: note: %s: the iterative solve of %lld unknowns failed (%s); type auto uses "
          "the direct solver (%s) from now on\n",
          impl_->settings.where.c_str(), (long long)K->getGlobalNumRows(), e.what(),
          direct.c_str());
      std::fflush(stdout);
    }
    impl_->iterative_failed = true;
    impl_->last_type = direct;
    return solve_system(K, b, x, direct, "");
  }
}

}  // namespace grout
