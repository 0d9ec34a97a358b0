#pragma once
// The step-size policy of the load stepping: how the increment changes after a failed and
// after a converged step. Plain functions of the current size, so that the stepping loop
// (nonlinear/load_stepping.cpp) owns only the time and the cut-back budget.

namespace grout {

struct StepSizeOptions {
  /// fixed: `steps` equal increments; a cut step grows back (x2, up to the nominal size) after
  /// steps that converge in fewer than 5 Newton iterations.
  /// adaptive: the nominal size is only the first step; every easy step (at most
  /// easy_iterations Newton iterations) grows the size by `growth`, up to max_step_size.
  bool adaptive = false;
  double growth = 1.5;
  int easy_iterations = 6;
  double max_step_size = 0.0;  ///< adaptive only; 0 = no bound below the end time
};

/// Size after a failed step: half the size (the step is retried from the same time).
inline double step_size_after_failure(double size) {
  return 0.5 * size;
}

/// Size after a converged step that took `newton_iterations`; `nominal` = end time / steps.
inline double step_size_after_success(double size, double nominal, int newton_iterations,
                                      const StepSizeOptions& options) {
  if (!options.adaptive)
    return newton_iterations < 5 ? (2.0 * size < nominal ? 2.0 * size : nominal) : size;
  if (newton_iterations > options.easy_iterations) return size;
  const double grown = options.growth * size;
  return options.max_step_size > 0.0 && grown > options.max_step_size ? options.max_step_size
                                                                      : grown;
}

}  // namespace grout
