#include "nonlinear/dynamic_stepping.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "nonlinear/step_times.hpp"

namespace grout {

void solve_time_steps(DynamicProblem& problem, LinearSolver& linear, LinearSolver& mass_solver,
                      const NewtonOptions& newton, const SteppingOptions& stepping,
                      const std::function<void(const ConvergedStep&)>& on_step) {
  const bool root = problem.map()->getComm()->getRank() == 0;
  Vector x(problem.map()), trial(problem.map()), F(problem.map());
  problem.start(x, mass_solver);
  const double E0 = problem.balance().total;
  double E_scale = problem.balance().kinetic + problem.balance().strain, drift_max = 0.0;

  StepTimes times(stepping.end_time, stepping.steps);  // t = t_end·k/den, never a sum of Δt
  int step = 0, cuts = 0;
  while (!times.finished()) {
    const double t_next = times.next_time();
    trial.assign(x);
    problem.begin_step(t_next, trial);
    std::ostringstream prefix;
    prefix << "  step " << step + 1 << " t = " << t_next;
    const NewtonReport report = solve_newton(problem, trial, linear, newton, prefix.str());
    if (!report.converged) {
      if (cuts == stepping.max_cuts) {
        std::ostringstream what;
        what << "step " << step + 1 << " (t = " << t_next << ") did not converge: " << report.reason
             << ", after " << cuts << " cut-backs of the time step";
        throw ConvergenceError(what.str());
      }
      ++cuts;
      times.halve();
      if (root) {
        std::printf("  step %d t = %g: %s; cutting the time step to dt = %g (%d/%d)\n", step + 1,
                    t_next, report.reason.c_str(), times.step_size(), cuts, stepping.max_cuts);
        std::fflush(stdout);
      }
      continue;
    }
    x.assign(trial);
    times.advance();
    ++step;
    cuts = 0;
    if (report.iterations < 5) times.grow();  // back towards t_end / n
    problem.residual(x, F);  // reactions and contact results at the converged state
    problem.quasi_static().commit_step();
    problem.commit_step(x);
    const EnergyBalance& b = problem.balance();
    E_scale = std::max(E_scale, b.kinetic + b.strain);
    drift_max = std::max(drift_max, std::abs(b.total - E0));
    if (root) {
      std::printf(
          "  step %d t = %.10g: kinetic %.6e strain %.6e external work %.6e contact work "
          "%.6e total %.6e\n",
          step, t_next, b.kinetic, b.strain, b.external_work, b.contact_work, b.total);
      std::fflush(stdout);
    }
    ConvergedStep converged;
    converged.step = step;
    converged.time = t_next;
    converged.newton = &report;
    converged.state = &x;
    converged.dynamics = &problem;
    on_step(converged);
  }
  if (root) {
    const double scale = E_scale > 0.0 ? E_scale : 1.0;
    std::printf(
        "grout: energy drift: total energy %.6e -> %.6e, final %.3e, max %.3e of the "
        "largest kinetic + strain energy %.6e\n",
        E0, problem.balance().total, (problem.balance().total - E0) / scale, drift_max / scale,
        E_scale);
    std::fflush(stdout);
  }
}

}  // namespace grout
