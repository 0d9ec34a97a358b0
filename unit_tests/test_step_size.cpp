// Step-size policy of the load stepping (StepTimes::after_success): fixed steps double back
// to the nominal size after a cut, adaptive steps double after easy steps up to the bound, and
// the times stay exact fractions of the end time.
#include <gtest/gtest.h>

#include "nonlinear/step_times.hpp"

namespace grout {
namespace {

TEST(StepSize, FixedGrowsBackToNominalAfterEasySteps) {
  StepTimes times(1.0, 10);
  const StepSizeOptions fixed;
  times.halve();
  times.halve();
  EXPECT_DOUBLE_EQ(times.step_size(), 0.025);
  times.after_success(7, fixed);  // not easy: kept
  EXPECT_DOUBLE_EQ(times.step_size(), 0.025);
  times.after_success(6, fixed);  // a finite-strain contact step's count is easy
  EXPECT_DOUBLE_EQ(times.step_size(), 0.05);
  times.after_success(2, fixed);
  times.after_success(2, fixed);  // never above nominal
  EXPECT_DOUBLE_EQ(times.step_size(), 0.1);
}

TEST(StepSize, AdaptiveDoublesAfterEasyStepsUpToTheBound) {
  StepTimes times(1.0, 10);
  StepSizeOptions adaptive;
  adaptive.adaptive = true;
  adaptive.max_step_size = 0.25;
  times.after_success(6, adaptive);
  EXPECT_DOUBLE_EQ(times.step_size(), 0.2);
  times.after_success(3, adaptive);  // bounded: 2 units of 0.1
  EXPECT_DOUBLE_EQ(times.step_size(), 0.2);
  times.after_success(7, adaptive);  // hard step: kept
  EXPECT_DOUBLE_EQ(times.step_size(), 0.2);
  adaptive.max_step_size = 0.0;  // unbounded
  times.after_success(3, adaptive);
  EXPECT_DOUBLE_EQ(times.step_size(), 0.4);
  times.advance();
  EXPECT_EQ(times.time(), 0.4);  // an exact fraction
}

}  // namespace
}  // namespace grout
