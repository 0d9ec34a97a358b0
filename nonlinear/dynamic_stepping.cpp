#include "nonlinear/dynamic_stepping.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace grout {

void solve_time_steps(DynamicProblem& problem, LinearSolver& linear, LinearSolver& mass_solver,
                      const NewtonOptions& newton, const SteppingOptions& stepping,
                      const std::function<void(const ConvergedStep&)>& on_step) {
  const bool root = problem.map()->getComm()->getRank() == 0;
  Vector x(problem.map());  // the initial state: u = 0, λ = 0
  problem.start(x, mass_solver);
  const double E0 = problem.balance().total;
  double E_scale = problem.balance().kinetic + problem.balance().strain, drift_max = 0.0;

  Vector F(problem.map());
  march_steps(
      problem, linear, newton, stepping, [&](double t, Vector& y) { problem.begin_step(t, y); },
      [&](ConvergedStep& converged) {
        const Vector& y = *converged.state;
        problem.residual(y, F);  // reactions and contact results at the converged state
        problem.quasi_static().commit_step();
        problem.commit_step(y);
        warn_of_folded(problem.quasi_static(), converged);
        const EnergyBalance& b = problem.balance();
        E_scale = std::max(E_scale, b.kinetic + b.strain);
        drift_max = std::max(drift_max, std::abs(b.total - E0));
        if (root) {
          std::printf(
              "  step %d t = %.10g: kinetic %.6e strain %.6e external work %.6e contact work "
              "%.6e total %.6e\n",
              converged.step, converged.time, b.kinetic, b.strain, b.external_work, b.contact_work,
              b.total);
          std::fflush(stdout);
        }
        converged.dynamics = &problem;
        on_step(converged);
      });
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
