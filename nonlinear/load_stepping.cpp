#include "nonlinear/load_stepping.hpp"

#include <cstdio>
#include <sstream>

#include "nonlinear/step_times.hpp"

namespace grout {

void march_steps(NonlinearProblem& problem, LinearSolver& linear, const NewtonOptions& newton,
                 const SteppingOptions& stepping,
                 const std::function<void(double t, Vector& x)>& begin_step,
                 const std::function<void(ConvergedStep&)>& accept) {
  const bool root = problem.map()->getComm()->getRank() == 0;
  Vector x(problem.map()), trial(problem.map());
  StepTimes times(stepping.end_time, stepping.steps);  // t = t_end·k/den, never a sum of Δt
  int step = 0, cuts = 0;
  while (!times.finished()) {
    const double t_next = times.next_time();
    trial.assign(x);
    begin_step(t_next, trial);
    std::ostringstream prefix;
    prefix << "  step " << step + 1 << " t = " << t_next;
    const NewtonReport report = solve_newton(problem, trial, linear, newton, prefix.str());
    if (!report.converged) {
      if (cuts == stepping.max_cuts) {
        std::ostringstream what;
        what << "step " << step + 1 << " (t = " << t_next << ") did not converge: " << report.reason
             << ", after " << cuts << " cut-backs of the step size";
        throw ConvergenceError(what.str());
      }
      ++cuts;
      times.halve();
      if (root) {
        std::printf("  step %d t = %g: %s; cutting the step to dt = %g (%d/%d)\n", step + 1, t_next,
                    report.reason.c_str(), times.step_size(), cuts, stepping.max_cuts);
        std::fflush(stdout);
      }
      continue;
    }
    x.assign(trial);
    const double previous_time = times.time();
    times.advance();
    ++step;
    ConvergedStep converged;
    converged.step = step;
    converged.time = times.time();
    converged.step_size = converged.time - previous_time;
    converged.newton = &report;
    converged.state = &x;
    accept(converged);
    times.after_success(report.iterations, stepping.step_size);
    cuts = 0;  // the budget of halvings is per step
  }
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
        on_step(converged);
      });
}

}  // namespace grout
