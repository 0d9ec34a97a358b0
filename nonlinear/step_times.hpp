#pragma once
// Load-step times kept as integer fractions of the end time, rounded once from their decimal.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <string>

#include "nonlinear/step_size.hpp"

namespace grout {

namespace detail {

using UInt128 = unsigned __int128;

/// \brief The double nearest p / q (ties to even) for integers p ≥ 0, 0 < q < 2^127, rounded
/// once: binary long division gives the quotient to 55 significant bits Q = ⌊p · 2^s / q⌋ and
/// a sticky bit (any remainder); rounding Q to 53 bits on its two low bits and the sticky bit
/// is IEEE 754 roundTiesToEven of the exact quotient (the kept bits, the first dropped bit and
/// whether anything below it is non-zero decide it), and the scaling by 2^-s is exact (ldexp,
/// normal range).
inline double nearest_double_of_fraction(UInt128 p, UInt128 q) {
  if (p == 0) return 0.0;
  const UInt128 low = UInt128(1) << 54, high = UInt128(1) << 55;
  UInt128 Q = p / q, r = p % q;
  int s = 0;
  bool sticky = false;
  while (Q < low) {  // one more quotient bit; r < q < 2^127, so 2r does not overflow
    r <<= 1, Q <<= 1, ++s;
    if (r >= q) r -= q, Q |= 1;
  }
  while (Q >= high) sticky |= (Q & 1) != 0, Q >>= 1, --s;
  sticky |= r != 0;
  std::uint64_t m = std::uint64_t(Q >> 2);  // 53 bits
  const bool half = (Q & 2) != 0, above_half = (Q & 1) != 0 || sticky;
  if (half && (above_half || (m & 1) != 0)) ++m;  // 2^53 after a carry is still exact
  return std::ldexp(double(m), 2 - s);
}

/// \brief The shortest decimal that reads back as x > 0: x ≈ digits · 10^exponent with
/// `digits` < 10^17 (std::to_chars, the shortest round-trip form).
inline bool shortest_decimal(double x, std::uint64_t& digits, int& exponent) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof(buffer), x, std::chars_format::scientific);
  if (r.ec != std::errc()) return false;
  const std::string text(buffer, r.ptr);  // d[.ddd]e±XX
  const auto e = text.find('e');
  std::string mantissa = text.substr(0, e);
  const auto point = mantissa.find('.');
  int decimals = 0;
  if (point != std::string::npos) {
    decimals = int(mantissa.size() - point - 1);
    mantissa.erase(point, 1);
  }
  digits = std::strtoull(mantissa.c_str(), nullptr, 10);
  exponent = std::atoi(text.c_str() + e + 1) - decimals;
  return true;
}

}  // namespace detail

/// \brief The times of a load-stepping run: t = t_end · k / den with integers k ≤ den, never
/// a sum of increments. The run starts with den = n (the number of steps) and step size 1, so
/// step i of an uncut run ends at t_end · i / n. Halving a step of odd size doubles k, den and
/// the size first, so cut-back times are finer fractions of the same kind.
///
/// Each time is the double nearest the decimal value the input implies: t_end is read as the
/// shortest decimal that gives its double, D · 10^e (1.4 → 14 · 10^-1), and t = k·D·10^e / den
/// is an exact fraction p/q of integers, rounded once (detail::nearest_double_of_fraction).
/// Rounding twice, t_end · k then / den, or even once from the double t_end (which is not 1.4
/// but 1.399999999999999911…), gives 0.06999999999999999 for step 1 of 20 to 1.4. The
/// integers fit in 128 bits: k ≤ den ≤ 2^62 and D < 10^17 < 2^57, so k·D < 2^119, and
/// den · 10^|e| < 2^127 for |e| ≤ 19; past that (an end time of many digits far from 1) the
/// time falls back to t_end · k / den, two roundings.
class StepTimes {
 public:
  StepTimes(double end_time, int steps) : end_(end_time), den_(steps), nominal_(1) {
    if (steps < 1) throw std::invalid_argument("StepTimes: steps must be >= 1");
    decimal_ = end_ > 0.0 && std::isfinite(end_) &&
               detail::shortest_decimal(end_, end_digits_, end_exponent_);
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
    if (newton_iterations > options.easy_iterations) return;
    if (options.adaptive)
      grow_to(options.max_step_size);
    else
      grow();
  }

 private:
  /// t_end · k / den: the double nearest k·D·10^e / den (class comment), t_end itself at the end.
  double time_at(long long k) const {
    if (k == den_) return end_;
    if (decimal_) {
      detail::UInt128 p = detail::UInt128(k) * end_digits_, q = detail::UInt128(den_);
      detail::UInt128& scaled = end_exponent_ > 0 ? p : q;  // by 10^|e|
      bool fits = true;
      for (int i = 0; i < std::abs(end_exponent_) && fits; ++i)
        fits = !__builtin_mul_overflow(scaled, detail::UInt128(10), &scaled);
      if (fits && q < (detail::UInt128(1) << 127)) return detail::nearest_double_of_fraction(p, q);
    }
    const long long g = std::gcd(k, den_);
    return end_ * double(k / g) / double(den_ / g);
  }

  double end_;
  long long den_;         ///< denominator: n · 2^(halvings of an odd size so far)
  long long nominal_;     ///< nominal step size t_end / n in units of t_end / den
  long long k_ = 0;       ///< position: t = t_end · k / den
  long long size_ = 1;    ///< current step size in units of t_end / den
  bool decimal_ = false;  ///< t_end = end_digits_ · 10^end_exponent_ (shortest)
  std::uint64_t end_digits_ = 0;
  int end_exponent_ = 0;
};

}  // namespace grout
