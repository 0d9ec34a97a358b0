#pragma once
// The step-size policy of the load stepping (fixed or adaptive increments), applied by
// StepTimes (nonlinear/step_times.hpp), which keeps every time an exact fraction of the end time.

namespace grout {

struct StepSizeOptions {
  /// A step is easy when it converges in at most easy_iterations Newton iterations.
  /// fixed: `steps` equal increments; after a cut-back every easy step doubles the size again,
  /// up to the nominal end / steps (a finite-strain contact step takes 5-6 iterations: with
  /// "fewer than 5" a cut step of the crossed tubes (inputs/self_contact) stayed cut).
  /// adaptive: the nominal size is only the first step; every easy step doubles the size, up
  /// to max_step_size.
  bool adaptive = false;
  int easy_iterations = 6;
  double max_step_size = 0.0;  ///< adaptive only; 0 = no bound below the end time
};

}  // namespace grout
