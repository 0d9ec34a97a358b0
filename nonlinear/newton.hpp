#pragma once
// Semi-smooth Newton on a NonlinearProblem, driven by NOX (docs/design.md §2): a line-search
// Newton whose convergence needs the residual tolerance AND an unchanged active set.
// NOX itself stays inside nonlinear/*.cpp; this header is NOX-free.

#include <string>
#include <vector>

#include "assembly/tpetra_types.hpp"
#include "io/solver_settings.hpp"  // NewtonOptions, read from the `Newton` and `NOX` sublists
#include "nonlinear/linear_solver.hpp"
#include "nonlinear/nonlinear_problem.hpp"

namespace grout {

struct NewtonReport {
  bool converged = false;
  /// "converged", "max iterations (25)", "non-finite residual", "residual evaluation
  /// failed", "jacobian evaluation failed", "line search failed", "linear solve failed: ..."
  std::string reason;
  int iterations = 0;
  int linear_iterations = 0;
  std::vector<double> residual_history;  ///< ‖F‖₂ per iteration, iteration 0 included
  std::vector<int> active_set_history;
  std::vector<int> active_change_history;
  /// The line search's step length that gave each iterate: 1 for the full Newton step, 0 at
  /// iteration 0.
  std::vector<double> step_length_history;
};

/// Solves F(x) = 0 from the initial guess in `x`; `x` holds the last iterate on return
/// (the solution if converged). Collective over the problem's communicator. Throws
/// InputError naming `options.where` + "/NOX" when NOX rejects its settings; an InputError
/// or ExitCodeError from the problem's evaluations passes through. Log lines:
/// `<log_prefix> newton <k>  |F| = ..  |dx| = ..  active <n> (<c> changed)  linear <its>`.
NewtonReport solve_newton(NonlinearProblem& problem, Vector& x, LinearSolver& linear,
                          const NewtonOptions& options, const std::string& log_prefix);

}  // namespace grout
