#include "nonlinear/load_stepping.hpp"

#include <cstdio>
#include <sstream>

#include "assembly/folded_elements.hpp"
#include "nonlinear/step_times.hpp"

namespace grout {

void march_steps(NonlinearProblem& problem, LinearSolver& linear, const NewtonOptions& newton,
                 const SteppingOptions& stepping,
                 const std::function<void(double t, Vector& x)>& begin_step,
                 const std::function<void(ConvergedStep&)>& accept) {
  const bool root = problem.map()->getComm()->getRank() == 0;
  Vector x(problem.map()), trial(problem.map()), x_before(problem.map());  // x_n, x_{n−1}
  StepTimes times(stepping.end_time, stepping.steps);  // t = t_end·k/den, never a sum of Δt
  // A step whose full-step Newton solve fails (the active set, or stick and slip, cycling
  // where many nodes change at once: a frictional landing from an open gap) is retried at the
  // same increment with newton.fallback_line_search, which its cut-backs keep; the next step
  // starts with the full step again. Where the full step converges nothing changes.
  NewtonOptions fallback = newton;
  const bool can_fall_back =
      newton.line_search == "Full Step" && !newton.fallback_line_search.empty();
  if (can_fall_back) fallback.line_search = newton.fallback_line_search;
  const double min_step_size =
      stepping.min_step_size > 0.0 ? stepping.min_step_size : 1e-6 * stepping.end_time;
  int step = 0, cuts = 0;
  bool fell_back = false, plain = false;
  double t_before = 0.0;  // the time of x_before (x_{−1} = 0 at t = 0)
  while (!times.finished()) {
    const double t_next = times.next_time();
    trial.assign(x);
    // Secant predictor (stepping.extrapolate): x_n + (t − t_n)/(t_n − t_{n−1}) (x_n − x_{n−1}),
    // displacements and multipliers alike, begin_step then setting the prescribed values
    // (linear extrapolation along the path, the usual predictor of incremental
    // path-following). From x_n alone only the prescribed nodes move, and the first solve
    // carries the whole increment through the contact state of t_n. A step that fails from
    // the predicted start is retried from x_n (then as without the predictor); a cut step
    // begins the same sequence again, from the predicted start with the full step.
    const bool extrapolated = stepping.extrapolate && step > 0 && !plain && !fell_back;
    if (extrapolated) {
      const double r = (t_next - times.time()) / (times.time() - t_before);
      trial.update(-r, x_before, 1.0 + r);
    }
    begin_step(t_next, trial);
    std::ostringstream prefix;
    prefix << "  step " << step + 1 << " t = " << t_next;
    const NewtonReport report =
        solve_newton(problem, trial, linear, fell_back ? fallback : newton, prefix.str());
    if (!report.converged) {
      if (extrapolated) {
        plain = true;
        if (root) {
          std::printf("  step %d t = %g: %s; retrying from the last converged state\n", step + 1,
                      t_next, report.reason.c_str());
          std::fflush(stdout);
        }
        continue;
      }
      // Only after an iterate: a failure at the start point (its residual, or the first
      // Jacobian's solve) would repeat itself, as the line search acts after the first solve.
      if (can_fall_back && !fell_back && report.residual_history.size() > 1) {
        fell_back = true;
        if (root) {
          std::printf("  step %d t = %g: %s; retrying with line search %s\n", step + 1, t_next,
                      report.reason.c_str(), fallback.line_search.c_str());
          std::fflush(stdout);
        }
        continue;
      }
      const bool below_minimum = times.step_size() / 2 < min_step_size;
      if (cuts == stepping.max_cuts || below_minimum) {
        std::ostringstream what;
        what << "step " << step + 1 << " (t = " << t_next << ") did not converge: " << report.reason
             << ", after " << cuts << " cut-backs of the step size";
        if (fell_back) what << " (with line search " << fallback.line_search << ")";
        if (below_minimum)
          what << "; a further cut-back to dt = " << times.step_size() / 2
               << " would go below the minimum step size " << min_step_size
               << " (grout/time/min_step_size)";
        throw ConvergenceError(what.str());
      }
      ++cuts;
      times.halve();
      plain = false;
      if (stepping.extrapolate) fell_back = false;  // the cut step: predicted, full step first
      if (root) {
        std::printf("  step %d t = %g: %s; cutting the step to dt = %g (%d/%d)\n", step + 1, t_next,
                    report.reason.c_str(), times.step_size(), cuts, stepping.max_cuts);
        std::fflush(stdout);
      }
      continue;
    }
    x_before.assign(x);
    t_before = times.time();
    x.assign(trial);
    const double previous_time = times.time();
    times.advance();
    ++step;
    ConvergedStep converged;
    converged.step = step;
    converged.time = times.time();
    converged.step_size = converged.time - previous_time;
    if (!(converged.step_size > 0.0)) {  // a repeated time: never written as a step
      std::ostringstream what;
      what << "step " << step << " (t = " << converged.time << ") has a step size of "
           << converged.step_size << " (below the resolution of the time)";
      throw ConvergenceError(what.str());
    }
    converged.newton = &report;
    converged.state = &x;
    accept(converged);
    times.after_success(report.iterations, stepping.step_size);
    cuts = 0;  // the budget of halvings is per step
    fell_back = plain = false;
  }
}

void warn_of_folded(const MechanicsProblem& problem, const ConvergedStep& converged) {
  Vector u(problem.solid().owned_map());
  problem.displacement(*converged.state, u);
  warn_of_folded_elements(problem.solid(), u, converged.step, converged.time);
}

void solve_load_steps(MechanicsProblem& problem, LinearSolver& linear, const NewtonOptions& newton,
                      const SteppingOptions& stepping,
                      const std::function<void(const ConvergedStep&)>& on_step) {
  Vector F(problem.map());
  march_steps(
      problem, linear, newton, stepping, [&](double t, Vector& x) { problem.begin_step(t, x); },
      [&](ConvergedStep& converged) {
        problem.residual(*converged.state, F);  // reactions and contact results there
        problem.commit_step();
        warn_of_folded(problem, converged);
        on_step(converged);
      });
}

}  // namespace grout
