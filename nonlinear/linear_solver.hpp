#pragma once
// Linear solves K x = b, chosen by the `solver/Linear Solver` sublist (read and validated by
// io/solver_settings.hpp into LinearSolverSettings):
//   type: auto (default)     the direct solver default_direct_type(dim) (MUMPS in 3D; in 2D
//                            MUMPS on the system gathered to rank 0, "mumps_gathered") for a
//                            system of fewer than auto_iterative_threshold(dim) global
//                            unknowns, otherwise the iterative path (type: belos with its
//                            defaults); in 2D below auto_small_direct_threshold(2) unknowns
//                            the gathered KLU2 (amesos2), cheaper there.
//   type: mumps              sparse direct MUMPS solve on the distributed matrix
//                            (nonlinear/mumps_solver.hpp; `MUMPS` sublist: ordering,
//                            symmetric, gather). With `gather: true` (what auto does in 2D) the
//                            system is gathered to rank 0 and factorised there on one BLAS
//                            thread: the same answer bit for bit on any number of ranks.
//   type: amesos2            direct KLU2 solve. Debian's KLU2 is silently wrong on a
//                            communicator of more than one rank (docs/design.md, "Toolchain
//                            notes"), so the system is gathered to rank 0 and solved on a 1-rank
//                            communicator, then scattered back. KLU2 is called from its
//                            headers as Amesos2 calls it there (nonlinear/klu_solve.hpp):
//                            the same bits, without loading Amesos2.
//   type: belos              Krylov solver `Belos/Solver Type` with a MueLu preconditioner.
//                            Defaults: the multipliers are condensed (below), CG on a system
//                            without multipliers (symmetric positive definite), GMRES on the
//                            condensed one (not symmetric: condensed_solve.hpp); MueLu smoothed
//                            aggregation for elasticity (elasticity_preconditioner.hpp) when
//                            the layout has coordinates (system_layout.hpp). The `MueLu` sublist
//                            overrides any of these settings.
//                            In the module grout_iterative, loaded at the first
//                            iterative solve (nonlinear/iterative_module.hpp).
//   reuse_preconditioner: true   (type: belos) the hierarchy is kept between solves: a
//                            system equal to the last one value for value (small strain,
//                            unchanged active set) keeps all of it, no set-up; one with the
//                            same unknowns and sparsity pattern reuses its prolongators (MueLu
//                            `reuse: type: RP`; coarse operators and smoothers recomputed).
//                            false: a new hierarchy every solve. Not given (the default): a
//                            system without multipliers (CG on the symmetric reduction or
//                            without contact) with the last one's unknowns keeps the last
//                            hierarchy's prolongators, coarse operators and coarse smoothers
//                            and rebuilds the fine smoother from the new matrix (MueLu
//                            `reuse: type: RAP`), whatever its pattern: the Newton iterations
//                            change the contact rows, where the fine smoother acts. A new
//                            hierarchy is built when the iterations the kept one added since
//                            its build exceed twice its first solve's (the set-up costs 1-2
//                            solves' iterations: docs/performance.md, "Iterative solver").
//                            The condensed system (GMRES) gets a new hierarchy every solve.
//   symmetric_reduction: true    (default true) condensed solves on the distributed MUMPS path
//                            and on the iterative path first try the symmetric reduction
//                            (below); false: always the condensation.
//   near_null_space: rigid_body  (default) MueLu's near-null space on the iterative path: the
//                            rigid-body modes of the coordinates; `translations`: the
//                            translations only, a cheaper set-up for more CG iterations
//                            (docs/input.md).
// --- condensed multipliers (nonlinear/condensed_solve.hpp) ---
//   condense_multipliers: true   (default: true on the iterative path and the distributed
//                            MUMPS path, 3D's default; false on the gathered direct solves
//                            and amesos2) the paired multipliers (SystemLayout) are
//                            condensed per slave node and the displacement-only system is
//                            solved, then λ is recovered. A reduced system left with a zero
//                            diagonal (not produced by Grout's contact rows) is solved
//                            directly even with type: belos. On the distributed MUMPS path
//                            and the iterative path the symmetric reduction
//                            (symmetric_condensation.hpp) is tried first: frictionless, tied or
//                            sticking contact on the reference geometry gives a symmetric K̃,
//                            factorised as LDLᵀ by a MumpsSolver of its own, or solved by CG
//                            with MueLu smoothed by Gauss–Seidel (as a system without
//                            contact); any other system falls back to the condensation and LU
//                            or GMRES with ILU(0).
// --- end condensed multipliers ---

#include <Teuchos_ParameterList.hpp>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "assembly/tpetra_types.hpp"
#include "io/solver_settings.hpp"
#include "nonlinear/multiplier_rows.hpp"
#include "nonlinear/system_layout.hpp"

namespace grout {

/// The direct solver that `type: auto` picks for small systems in `dim` dimensions: mumps in
/// 3D, mumps_gathered in 2D (MUMPS on rank 0, as `type: mumps` with `MUMPS/gather: true`).
std::string default_direct_type(int dim);
/// `type: auto` uses the iterative path from this many global unknowns (u and λ) on.
long long auto_iterative_threshold(int dim);
/// `type: auto` uses the gathered KLU2 (amesos2) below this many global unknowns (2000 in 2D,
/// 0 in 3D: never).
long long auto_small_direct_threshold(int dim);
/// The type `type: auto` resolves to for a system of `global_unknowns` in `dim` dimensions.
std::string auto_linear_solver_type(long long global_unknowns, int dim);

class LinearSolver {
 public:
  /// A solver with `settings` (io/solver_settings.hpp) for systems laid out as `layout`
  /// (system_layout.hpp: multiplier pairing, coordinates, bodies; system_layout(problem, mesh)
  /// builds it for a MechanicsProblem). Asks Belos (loading the iterative module) whether it
  /// has `belos_solver` and, with type belos, whether that solver takes the `Belos` keys;
  /// throws InputError naming `settings.where` when not.
  LinearSolver(LinearSolverSettings settings, SystemLayout layout);
  /// The same with the settings read from a `Linear Solver` sublist (may be empty), named
  /// `where` in errors (linear_solver_settings_from).
  LinearSolver(const Teuchos::ParameterList& params, const std::string& where, SystemLayout layout);
  ~LinearSolver();

  /// Solve K x = b; returns the number of linear iterations (1 for a direct solve).
  /// Throws std::runtime_error if the solve fails or does not converge.
  /// `rows` (optional): the kinds of K's multiplier rows as the problem declares them
  /// (multiplier_rows.hpp), from which the condensations are built.
  int solve(const Teuchos::RCP<const Matrix>& K, const Vector& b, Vector& x,
            const MultiplierRows* rows = nullptr);

  // --- condensed multipliers ---
  /// Whether solve() condenses the layout's paired multipliers (`condense_multipliers`, or its
  /// default for the configured type); without pairs the system is solved as given.
  bool condenses_multipliers() const;
  // --- end condensed multipliers ---

  /// The iterative path's relative tolerance (Belos `Convergence Tolerance`) for the solves
  /// that follow: an inexact Newton step's forcing term (nonlinear/nox_group.cpp). 0 (the
  /// default): the `Belos` settings' own. Direct solves ignore it.
  void set_relative_tolerance(double tolerance);

  /// Solves that reused a MueLu hierarchy (`reuse_preconditioner: true`), since construction.
  int reused_hierarchies() const;
  /// Of those, the solves of a system equal to the last one value for value (the whole
  /// hierarchy kept, no set-up).
  int kept_hierarchies() const;
  /// The damping of the Jacobi smoother of the last MueLu hierarchy built
  /// (nonlinear/jacobi_smoother.hpp), 0 when it smooths otherwise or before any iterative solve.
  double jacobi_damping() const;
  /// The type of the last solve (auto resolved): mumps, mumps_gathered, amesos2 or belos;
  /// empty before any solve.
  const std::string& last_type() const;
  /// Whether the last solve went through the symmetric reduction (symmetric_condensation.hpp;
  /// multipliers condensed; type mumps, distributed: MUMPS's LDLᵀ; type belos: CG + MueLu).
  bool last_solve_symmetric() const;

 private:
  /// `multipliers`: K may hold condensed multiplier rows (false: the symmetric reduction's K̃,
  /// smoothed as a system without contact; iterative_solver.hpp).
  int solve_system(const Teuchos::RCP<const Matrix>& K, const Vector& b, Vector& x,
                   const std::string& type, const std::string& belos_type, bool multipliers = true);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace grout
