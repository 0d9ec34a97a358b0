// Load-step times (nonlinear/step_times.hpp) are the doubles nearest the decimals the input
// implies: step k of n to `end: 1.4` is the double nearest the decimal k·1.4/n (0.07, not
// 0.06999999999999999; 0.21, not 0.20999999999999996; 1.05, not 1.0499999999999998).
// Reference: the decimal k·D·10^e / den written out digit by digit in integer arithmetic
// (long division), read back by strtod, which rounds a decimal string correctly (C11
// 7.22.1.3, glibc). A string of 60 significant digits decides the rounding: k·D·10^e/den is a
// fraction whose denominator is not a power of two, so it is never a midpoint between two
// doubles, and these fractions are farther than 10^-40 (relative) from one.

#include <gtest/gtest.h>

#include <cstdlib>
#include <iomanip>
#include <string>
#include <vector>

#include "nonlinear/step_times.hpp"

namespace grout {
namespace {

using UInt128 = unsigned __int128;

/// The decimal p / q, 60 significant digits, as text; parsed by strtod.
double decimal_quotient(UInt128 p, UInt128 q) {
  std::string digits;
  UInt128 integer = p / q, r = p % q;
  if (integer == 0) digits = "0";
  while (integer) digits.insert(digits.begin(), char('0' + int(integer % 10))), integer /= 10;
  digits += '.';
  int significant = digits == "0." ? 0 : int(digits.size() - 1);
  while (significant < 60) {
    r *= 10;
    const int digit = int(r / q);
    r %= q;
    digits += char('0' + digit);
    if (significant > 0 || digit != 0) ++significant;
  }
  return std::strtod(digits.c_str(), nullptr);
}

/// t_k = k · (digits · 10^-decimals) / den as the double nearest the decimal.
double expected_time(long long k, long long den, unsigned long long digits, int decimals) {
  UInt128 q = UInt128(den);
  for (int i = 0; i < decimals; ++i) q *= 10;
  return decimal_quotient(UInt128(k) * digits, q);
}

struct EndTime {
  double end;
  unsigned long long digits;  ///< end = digits · 10^-decimals
  int decimals;
};

// The three of the report, and two with more digits.
const std::vector<EndTime> end_times = {
    {1.4, 14, 1}, {0.3, 3, 1}, {12.0, 12, 0}, {0.001, 1, 3}, {123.456, 123456, 3}};

TEST(StepTimesDecimal, EveryStepIsTheDoubleNearestTheDecimal) {
  for (const EndTime& e : end_times) {
    for (int n : {1, 3, 7, 10, 20, 30, 100}) {
      StepTimes times(e.end, n);
      for (long long k = 1; !times.finished(); ++k) {
        const double expected = expected_time(k, n, e.digits, e.decimals);
        EXPECT_EQ(times.next_time(), expected)
            << std::setprecision(17) << "end " << e.end << ", step " << k << " of " << n << ": got "
            << times.next_time() << ", expected " << expected;
        times.advance();
        EXPECT_EQ(times.time(), expected);
      }
      EXPECT_EQ(times.time(), e.end);
    }
  }
}

// The values of the report: end 1.4 in 20 steps.
TEST(StepTimesDecimal, EndOnePointFourInTwentySteps) {
  StepTimes times(1.4, 20);
  std::vector<double> got;
  while (!times.finished()) times.advance(), got.push_back(times.time());
  ASSERT_EQ(got.size(), 20u);
  EXPECT_EQ(got[0], 0.07);   // not 0.06999999999999999
  EXPECT_EQ(got[2], 0.21);   // not 0.20999999999999996
  EXPECT_EQ(got[14], 1.05);  // not 1.0499999999999998
  EXPECT_EQ(got.back(), 1.4);
}

// Cut-backs and growth (the step-size logic of load_stepping.cpp and of implicit dynamics,
// whose Δt is the difference of two of these times): every time reached is still the double
// nearest its decimal, and the times increase strictly.
TEST(StepTimesDecimal, CutBacksKeepDecimalTimes) {
  for (const EndTime& e : end_times) {
    StepTimes times(e.end, 20);
    long long den = 20, k = 0, size = 1;  // the same fractions, kept here independently
    double previous = 0.0;
    for (int i = 0; !times.finished(); ++i) {
      if (i % 5 == 2) {  // cut twice, as after two failed Newton solves
        for (int c = 0; c < 2; ++c) {
          times.halve();
          if (size % 2) k *= 2, den *= 2, size *= 2;
          size /= 2;
        }
      }
      const long long next = std::min(k + size, den);
      EXPECT_EQ(times.next_time(), expected_time(next, den, e.digits, e.decimals))
          << "end " << e.end << ", t = " << next << "/" << den;
      times.advance();
      k = next;
      EXPECT_GT(times.time(), previous);
      previous = times.time();
      times.grow();
      size = std::min(2 * size, den / 20);
    }
    EXPECT_EQ(times.time(), e.end);
  }
}

}  // namespace
}  // namespace grout
