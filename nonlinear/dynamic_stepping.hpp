#pragma once
// Implicit dynamics: time steps of a DynamicProblem from t = 0 to the end time.

#include <functional>

#include "nonlinear/dynamic_problem.hpp"
#include "nonlinear/load_stepping.hpp"

namespace grout {

/// Starts from x = 0 (the initial velocity is in `problem`) and marches through the time steps
/// of march_steps (load_stepping.hpp: exact fractions of the end time, cut-backs per step).
/// Every converged step goes to `on_step` at once; `mass_solver` solves for the initial
/// acceleration. Prints one line per step and, at the end, the drift of the total energy
/// (rank 0).
void solve_time_steps(DynamicProblem& problem, LinearSolver& linear, LinearSolver& mass_solver,
                      const NewtonOptions& newton, const SteppingOptions& stepping,
                      const std::function<void(const ConvergedStep&)>& on_step);

}  // namespace grout
