#include "nonlinear/load_stepping.hpp"

#include <cstdio>
#include <sstream>

#include "nonlinear/step_size.hpp"

namespace grout {

void solve_load_steps(MechanicsProblem& problem, LinearSolver& linear, const NewtonOptions& newton,
                      const SteppingOptions& stepping,
                      const std::function<void(const ConvergedStep&)>& on_step) {
  const bool root = problem.map()->getComm()->getRank() == 0;
  Vector x(problem.map()), trial(problem.map()), F(problem.map());
  const double nominal = stepping.end_time / stepping.steps;
  const double eps = 1e-12 * stepping.end_time;
  double t = 0.0, dt = nominal;
  int step = 0, cuts = 0;
  while (t < stepping.end_time - eps) {
    const double t_next = std::min(t + dt, stepping.end_time);
    trial.assign(x);
    problem.begin_step(t_next, trial);
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
      dt = step_size_after_failure(dt);
      if (root) {
        std::printf("  step %d t = %g: %s; cutting the step to dt = %g (%d/%d)\n", step + 1, t_next,
                    report.reason.c_str(), dt, cuts, stepping.max_cuts);
        std::fflush(stdout);
      }
      continue;
    }
    x.assign(trial);
    const double converged_dt = t_next - t;
    t = t_next;
    ++step;
    problem.residual(x, F);  // reactions and contact results at the converged state
    problem.commit_step();
    ConvergedStep converged;
    converged.step = step;
    converged.time = t;
    converged.step_size = converged_dt;
    converged.newton = &report;
    converged.state = &x;
    on_step(converged);
    if (stepping.step_size.adaptive || cuts > 0)
      dt = step_size_after_success(dt, nominal, report.iterations, stepping.step_size);
  }
}

}  // namespace grout
