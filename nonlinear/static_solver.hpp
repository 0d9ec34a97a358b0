#pragma once
// Quasi-static load stepping with Newton's method on the solid (DESIGN.md §4).

#include <functional>
#include <string>
#include <vector>

#include "assembly/solid_problem.hpp"
#include "nonlinear/linear_solver.hpp"

namespace grout {

struct NewtonSettings {
  int max_iterations = 20;
  double relative_tolerance = 1e-10;  ///< on ‖r_free‖ relative to max(‖f_int‖, ‖f_ext‖)
  double absolute_tolerance = 1e-14;
};

/// What a converged step reports to the output.
struct StepResult {
  int step = 0;
  double time = 0.0;
  int newton_iterations = 0;
  int linear_iterations = 0;
  double residual = 0.0;  ///< ‖r_free‖₂ at convergence
  const Vector* displacement = nullptr;
  const Vector* reaction = nullptr;  ///< f_int − f_ext on prescribed dofs, 0 elsewhere
};

/// Thrown when a step does not converge: names the step, time and residual.
class ConvergenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Run `steps` load steps to `end_time`; `on_step` is called after every converged step
/// (the caller writes and flushes it at once). Prints one progress line per iteration on
/// rank 0.
void solve_static(const SolidProblem& problem, LinearSolver& linear, const NewtonSettings& newton,
                  double end_time, int steps,
                  const std::function<void(const StepResult&)>& on_step);

}  // namespace grout
