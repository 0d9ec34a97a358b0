// Step-size policy of the load stepping: fixed steps grow back to the nominal size after a
// cut, adaptive steps grow by the factor after easy steps up to the bound, and every failure
// halves the step.
#include <gtest/gtest.h>

#include "nonlinear/step_size.hpp"

namespace grout {
namespace {

TEST(StepSize, FailureHalves) {
  EXPECT_EQ(step_size_after_failure(0.25), 0.125);
}

TEST(StepSize, FixedGrowsBackToNominalAfterEasySteps) {
  const StepSizeOptions fixed;
  EXPECT_EQ(step_size_after_success(0.025, 0.1, 4, fixed), 0.05);
  EXPECT_EQ(step_size_after_success(0.075, 0.1, 4, fixed), 0.1);  // never above nominal
  EXPECT_EQ(step_size_after_success(0.1, 0.1, 2, fixed), 0.1);
  EXPECT_EQ(step_size_after_success(0.025, 0.1, 5, fixed), 0.025);  // not easy: kept
}

TEST(StepSize, AdaptiveGrowsAfterEasyStepsUpToTheBound) {
  StepSizeOptions adaptive;
  adaptive.adaptive = true;
  adaptive.max_step_size = 0.2;
  EXPECT_DOUBLE_EQ(step_size_after_success(0.1, 0.1, 6, adaptive), 0.15);
  EXPECT_EQ(step_size_after_success(0.15, 0.1, 3, adaptive), 0.2);  // bounded
  EXPECT_EQ(step_size_after_success(0.1, 0.1, 7, adaptive), 0.1);   // hard step: kept
  adaptive.max_step_size = 0.0;                                     // unbounded
  EXPECT_DOUBLE_EQ(step_size_after_success(0.4, 0.1, 3, adaptive), 0.6);
}

}  // namespace
}  // namespace grout
