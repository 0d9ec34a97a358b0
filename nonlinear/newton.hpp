#pragma once
// Semi-smooth Newton on a NonlinearProblem, driven by NOX (docs/design.md §2): a line-search
// Newton whose convergence needs the residual tolerance AND an unchanged active set.
// NOX itself stays inside nonlinear/*.cpp; this header is NOX-free.

#include <Teuchos_ParameterList.hpp>
#include <string>
#include <vector>

#include "assembly/tpetra_types.hpp"
#include "nonlinear/linear_solver.hpp"
#include "nonlinear/nonlinear_problem.hpp"

namespace grout {

struct NewtonOptions {
  int max_iterations = 25;
  double absolute_tolerance = 1e-10;  ///< converged if ‖F‖₂ ≤ this ...
  double relative_tolerance = 1e-10;  ///< ... or ‖F‖₂ / ‖F(x₀)‖₂ < this
  double floor_factor = 10.0;  ///< ... or ‖F‖₂ ≤ this · residual_floor() (round-off; 0 = off)
  double update_tolerance = 0.0;          ///< and, if > 0, ‖Δx‖_∞ < this
  std::string line_search = "Full Step";  ///< NOX name: "Full Step", "Backtrack", "Polynomial"
  /// The line search of the retries of a step whose Newton solve failed (and of its
  /// cut-backs), when `line_search` is the default full step and the input chose none
  /// (Newton/line_search, or NOX's Line Search sublist); empty: none (load_stepping.hpp).
  std::string fallback_line_search = "Backtrack";
  bool require_unchanged_active_set = true;  ///< and no active-set change at the iterate
  bool verbose = true;                       ///< one log line per iteration on rank 0
  Teuchos::ParameterList nox;                ///< passed to NOX, merged over Grout's defaults
  std::string where = "grout/solver";        ///< "<input file>: grout/solver", for errors
};

/// Reads the optional `Newton` sublist of the `solver` sublist (keys max_iterations,
/// absolute_tolerance, relative_tolerance, floor_factor, update_tolerance, line_search,
/// require_unchanged_active_set) and the optional `NOX` sublist (passed through). Throws
/// InputError naming "<file>: grout/solver/Newton/<key>" on an unknown key or a bad value.
NewtonOptions newton_options_from(const Teuchos::ParameterList& solver_sublist,
                                  const std::string& file = "");

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
