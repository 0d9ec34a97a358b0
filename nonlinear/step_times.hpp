#pragma once
// Load-step times kept as integer fractions of the end time.

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "nonlinear/step_size.hpp"

namespace grout {

/// \brief The times of a load-stepping run: t = t_end · k / den with integers k ≤ den, never
/// a sum of increments. The run starts with den = n (the number of steps) and step size 1, so
/// step i of an uncut run ends at t_end · i / n, evaluated as t_end · p / q with p/q = i/n in
/// lowest terms: t = 0.3 of t_end = 1, n = 10 is the double nearest 0.3, and the last step is
/// t_end itself. Halving a step of odd size doubles k, den and the size first, so cut-back
/// times are finer fractions of the same kind (0.25 + 0.05 = 0.3 stays 0.3).
class StepTimes {
 public:
  StepTimes(double end_time, int steps) : end_(end_time), den_(steps), nominal_(1) {
    if (steps < 1) throw std::invalid_argument("StepTimes: steps must be >= 1");
  }

  bool finished() const { return k_ >= den_; }
  /// Time at the end of the current (trial) step.
  double next_time() const { return time_at(std::min(k_ + size_, den_)); }
  /// Time reached so far.
  double time() const { return time_at(k_); }
  /// Length of the current step.
  double step_size() const { return end_ * double(size_) / double(den_); }

  /// The trial step converged: move to its end.
  void advance() { k_ = std::min(k_ + size_, den_); }
  /// Halve the step. Throws std::overflow_error when the fraction no longer fits (after
  /// some 50 halvings; the cut-back budget stops long before).
  void halve() {
    if (size_ % 2 != 0) {
      if (den_ > (1LL << 61)) throw std::overflow_error("StepTimes: step size below 2^-61");
      k_ *= 2, den_ *= 2, size_ *= 2, nominal_ *= 2;
    }
    size_ /= 2;
  }
  /// Double the step, up to the nominal size t_end / n.
  void grow() { size_ = std::min(2 * size_, nominal_); }
  /// Double the step up to max_size (a time, rounded down to a whole number of t_end / den;
  /// at least one unit); 0 = up to the end time.
  void grow_to(double max_size) {
    long long limit = den_;
    if (max_size > 0.0 && max_size < end_)
      limit = std::max(1LL, static_cast<long long>(max_size / end_ * double(den_)));
    size_ = std::min(2 * size_, limit);
  }
  /// The step-size policy after a converged step of `newton_iterations` (step_size.hpp).
  void after_success(int newton_iterations, const StepSizeOptions& options) {
    if (!options.adaptive) {
      if (newton_iterations < 5) grow();
    } else if (newton_iterations <= options.easy_iterations) {
      grow_to(options.max_step_size);
    }
  }

 private:
  double time_at(long long k) const {
    const long long g = std::gcd(k, den_);
    return k == den_ ? end_ : end_ * double(k / g) / double(den_ / g);
  }

  double end_;
  long long den_;       ///< denominator: n · 2^(halvings of an odd size so far)
  long long nominal_;   ///< nominal step size t_end / n in units of t_end / den
  long long k_ = 0;     ///< position: t = t_end · k / den
  long long size_ = 1;  ///< current step size in units of t_end / den
};

}  // namespace grout
