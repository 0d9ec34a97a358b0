#pragma once
// Linear solves K x = b, chosen by the `solver/Linear Solver` sublist:
//   type: mumps              sparse direct MUMPS solve on the distributed matrix
//                            (nonlinear/mumps_solver.hpp; `MUMPS` sublist: ordering,
//                            symmetric).
//   type: amesos2 (default)  direct KLU2 solve. Debian's KLU2 is silently wrong on a
//                            communicator of more than one rank (TOOLCHAIN.md), so the
//                            system is gathered to rank 0 and solved on a 1-rank
//                            communicator, then scattered back.
//   type: belos              Krylov solver `Belos/Solver Type` (CG default, or GMRES) with a
//                            MueLu preconditioner (`MueLu` sublist passed through; on more than
//                            one rank the coarse solve defaults to relaxation, not KLU2).
// --- condensed multipliers (nonlinear/condensed_solve.hpp) ---
//   condense_multipliers: true   (default false) with either type: the paired multipliers
//                            (set_multiplier_pairing) are condensed per slave node and the
//                            displacement-only system is solved (Belos default: GMRES, the
//                            reduced matrix is not symmetric), then λ is recovered. A
//                            reduced system with a zero diagonal (prescribed slave dof on a
//                            tied/sticking node) is solved directly even with type: belos.
// --- end condensed multipliers ---

#include <Teuchos_ParameterList.hpp>
#include <memory>
#include <utility>
#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

class LinearSolver {
 public:
  /// `params` is the `Linear Solver` sublist (may be empty). Throws InputError on an
  /// unknown type.
  LinearSolver(const Teuchos::ParameterList& params, const std::string& where);
  ~LinearSolver();

  /// Solve K x = b; returns the number of linear iterations (1 for a direct solve).
  /// Throws std::runtime_error if the solve fails or does not converge.
  int solve(const Teuchos::RCP<const Matrix>& K, const Vector& b, Vector& x);

  // --- condensed multipliers ---
  /// The multiplier dofs and the slave dofs carrying them: (λ GID, slave u GID), the same
  /// complete list on every rank; slave dofs s of one node share s / dofs_per_node. Used by
  /// solve() when `condense_multipliers: true`; without pairs the system is solved as given.
  void set_multiplier_pairing(std::vector<std::pair<GO, GO>> lambda_to_slave_dof,
                              int dofs_per_node = 1);
  bool condenses_multipliers() const;
  // --- end condensed multipliers ---

 private:
  int solve_system(const Teuchos::RCP<const Matrix>& K, const Vector& b, Vector& x,
                   const std::string& belos_type);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace grout
