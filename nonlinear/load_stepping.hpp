#pragma once
// Quasi-static load/time stepping with automatic cut-back (docs/design.md §4).

#include <functional>

#include "io/errors.hpp"
#include "nonlinear/mechanics_problem.hpp"
#include "nonlinear/newton.hpp"
#include "nonlinear/step_size.hpp"

namespace grout {

struct SteppingOptions {
  double end_time = 1.0;
  int steps = 1;
  int max_cuts = 6;  ///< halvings of the step size before giving up
  /// Smallest step a halving may make (ConvergenceError below it); 0 = 1e-6 · end_time. A
  /// run whose steps fall to a millionth of its span needs a million more: it has stalled
  /// (a collapsing solid cut dt down to 1e-16 and then "converged" a step of dt = 0).
  double min_step_size = 0.0;
  StepSizeOptions step_size;  ///< fixed or adaptive increments (nonlinear/step_size.hpp)
  /// Each step starts from the last two converged states extrapolated to its time instead of
  /// the last one; a step that fails from there is retried from the last one (docs/input.md,
  /// `time/predictor`; quasi-static only: the reader refuses it with dynamics).
  bool extrapolate = false;
};

class DynamicProblem;

/// What a converged step hands to the output.
struct ConvergedStep {
  int step = 0;
  double time = 0.0;
  double step_size = 0.0;  ///< the increment that reached `time`
  const NewtonReport* newton = nullptr;
  const Vector* state = nullptr;             ///< (u, λ)
  const DynamicProblem* dynamics = nullptr;  ///< velocity, acceleration, energies (dynamics)
};

/// Thrown when a step fails after every cut-back: names the time and the reason.
class ConvergenceError : public ExitCodeError {
 public:
  explicit ConvergenceError(const std::string& what) : ExitCodeError(what, 3) {}
};

/// The stepping loop of every analysis: from x = 0, times from StepTimes (fixed or adaptive,
/// stepping.step_size), each step begun by begin_step(t, x) (prescribed values into x) and
/// solved by Newton; a step that fails with the default full step after at least one update
/// is first retried at the same increment with newton.fallback_line_search (kept for its
/// cut-backs; docs/input.md "Failed steps"); a failed step is retried with half the
/// increment, up to max_cuts times per step and never below stepping.min_step_size, then
/// ConvergenceError naming the step and its time; a converged one goes to
/// `accept` (its state is the converged x, which accept may evaluate and commit).
void march_steps(NonlinearProblem& problem, LinearSolver& linear, const NewtonOptions& newton,
                 const SteppingOptions& stepping,
                 const std::function<void(double t, Vector& x)>& begin_step,
                 const std::function<void(ConvergedStep&)>& accept);

/// After a converged step: a warning on stderr (rank 0) when an element of a finite-strain
/// block is folded at a corner (assembly/folded_elements.hpp). Collective.
void warn_of_folded(const MechanicsProblem& problem, const ConvergedStep& converged);

/// Steps from t = 0 to end_time in `steps` equal increments (or, adaptive, starting with
/// end_time / steps and doubling after easy steps; step_size.hpp). A step whose Newton solve
/// fails is retried with half the increment, up to max_cuts times per step (the count restarts
/// after each converged step); then ConvergenceError. Every
/// converged step goes to `on_step` at once (the caller writes and flushes it).
void solve_load_steps(MechanicsProblem& problem, LinearSolver& linear, const NewtonOptions& newton,
                      const SteppingOptions& stepping,
                      const std::function<void(const ConvergedStep&)>& on_step);

}  // namespace grout
