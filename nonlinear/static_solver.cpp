#include "nonlinear/static_solver.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "nonlinear/dirichlet.hpp"

namespace grout {

namespace {

// ‖r‖₂ over free (fp = false) or prescribed (fp = true) dofs.
double restricted_norm(const Vector& r, const std::vector<double>& prescribed, bool on_prescribed) {
  const auto& map = *r.getMap();
  const auto v = r.getLocalViewHost(Tpetra::Access::ReadOnly);
  double local = 0.0;
  for (LO i = 0; i < LO(map.getNodeNumElements()); ++i) {
    if (std::isnan(prescribed[map.getGlobalElement(i)]) != on_prescribed) local += v(i, 0) * v(i, 0);
  }
  double global = 0.0;
  Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return std::sqrt(global);
}

}  // namespace

void solve_static(const SolidProblem& problem, LinearSolver& linear, const NewtonSettings& newton,
                  double end_time, int steps,
                  const std::function<void(const StepResult&)>& on_step) {
  const bool root = problem.comm()->getRank() == 0;
  auto u = problem.create_vector();
  auto du = problem.create_vector();
  auto f_int = problem.create_vector();
  auto f_ext = problem.create_vector();
  auto r = problem.create_vector();
  auto rhs = problem.create_vector();
  auto reaction = problem.create_vector();
  auto K = problem.create_matrix();
  const auto& map = *problem.owned_map();
  const auto& column_map = *problem.column_map();
  auto u_column = Teuchos::rcp(new Vector(problem.column_map()));

  for (int step = 1; step <= steps; ++step) {
    const double t = end_time * step / steps;
    const std::vector<double> prescribed = problem.prescribed_displacements(t);
    problem.external_force(t, *f_ext);
    StepResult result;
    result.step = step;
    result.time = t;
    bool converged = false;
    for (int it = 0; it <= newton.max_iterations; ++it) {
      problem.assemble(*u, *f_int, K.get());
      r->update(1.0, *f_int, -1.0, *f_ext, 0.0);  // r = f_int − f_ext

      // Remaining increments of the prescribed dofs, on the column map (apply_dirichlet
      // eliminates columns too).
      problem.import_to_column(*u, *u_column);
      std::vector<double> delta(column_map.getNodeNumElements());
      double delta_max = 0.0;
      {
        const auto uc = u_column->getLocalViewHost(Tpetra::Access::ReadOnly);
        for (std::size_t c = 0; c < delta.size(); ++c) {
          const double value = prescribed[column_map.getGlobalElement(LO(c))];
          delta[c] = value - uc(c, 0);  // NaN where free
          if (!std::isnan(value)) delta_max = std::max(delta_max, std::abs(delta[c]));
        }
        double global = 0.0;
        Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_MAX, delta_max, Teuchos::outArg(global));
        delta_max = global;
      }
      const double r_free = restricted_norm(*r, prescribed, false);
      const double scale = std::max(f_int->norm2(), f_ext->norm2());
      if (root) {
        std::printf("  step %d  t = %-10.4g newton %2d  |r| = %.3e  (scale %.3e)  |du_D| = %.3e\n",
                    step, t, it, r_free, scale, delta_max);
        std::fflush(stdout);
      }
      if (it > 0 && delta_max == 0.0 &&
          r_free <= std::max(newton.absolute_tolerance, newton.relative_tolerance * scale)) {
        result.newton_iterations = it;
        result.residual = r_free;
        converged = true;
        break;
      }
      if (it == newton.max_iterations) break;
      rhs->update(-1.0, *r, 0.0);
      apply_dirichlet(*K, *rhs, delta);
      result.linear_iterations += linear.solve(K, *rhs, *du);
      const double du_norm = du->norm2();
      if (!std::isfinite(du_norm)) {
        throw ConvergenceError("NaN in the solution at step " + std::to_string(step) +
                               " (t = " + std::to_string(t) + "), Newton iteration " +
                               std::to_string(it + 1));
      }
      u->update(1.0, *du, 1.0);
      // Prescribed dofs take their values exactly (the solve gives them to round-off).
      auto uv = u->getLocalViewHost(Tpetra::Access::ReadWrite);
      for (LO i = 0; i < LO(map.getNodeNumElements()); ++i) {
        const double value = prescribed[map.getGlobalElement(i)];
        if (!std::isnan(value)) uv(i, 0) = value;
      }
    }
    if (!converged) {
      throw ConvergenceError("step " + std::to_string(step) + " (t = " + std::to_string(t) +
                             ") did not converge in " + std::to_string(newton.max_iterations) +
                             " Newton iterations");
    }
    // Reactions: the residual on the prescribed dofs.
    {
      reaction->putScalar(0.0);
      auto rv = reaction->getLocalViewHost(Tpetra::Access::ReadWrite);
      const auto res = r->getLocalViewHost(Tpetra::Access::ReadOnly);
      for (LO i = 0; i < LO(map.getNodeNumElements()); ++i)
        if (!std::isnan(prescribed[map.getGlobalElement(i)])) rv(i, 0) = res(i, 0);
    }
    result.displacement = u.get();
    result.reaction = reaction.get();
    on_step(result);
  }
}

}  // namespace grout
