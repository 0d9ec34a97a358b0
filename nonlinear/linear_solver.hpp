#pragma once
// Linear solves K x = b, chosen by the `solver/Linear Solver` sublist:
//   type: amesos2 (default)  direct KLU2 solve. Debian's KLU2 is silently wrong on a
//                            communicator of more than one rank (TOOLCHAIN.md), so the
//                            system is gathered to rank 0 and solved on a 1-rank
//                            communicator, then scattered back.
//   type: belos              Krylov solver `Belos/Solver Type` (CG default, or GMRES) with a
//                            MueLu preconditioner (`MueLu` sublist passed through; on more than
//                            one rank the coarse solve defaults to relaxation, not KLU2).

#include <Teuchos_ParameterList.hpp>
#include <memory>

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

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace grout
