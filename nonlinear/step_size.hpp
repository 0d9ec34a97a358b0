#pragma once
// The step-size policy of the load stepping (fixed or adaptive increments), applied by
// StepTimes (nonlinear/step_times.hpp), which keeps every time an exact fraction of the end time.

namespace grout {

struct StepSizeOptions {
  /// fixed: `steps` equal increments; a cut step doubles back (up to the nominal size) after
  /// steps that converge in fewer than 5 Newton iterations.
  /// adaptive: the nominal size is only the first step; every easy step (at most
  /// easy_iterations Newton iterations) doubles the size, up to max_step_size.
  bool adaptive = false;
  int easy_iterations = 6;
  double max_step_size = 0.0;  ///< adaptive only; 0 = no bound below the end time
};

}  // namespace grout
