// Load-step times (nonlinear/step_times.hpp): every time is t_end · k / den from integers, so
// a nominal step time is the double nearest the decimal value, with and without cut-backs.
// Summing Δt = 0.1 ten times gives 0.30000000000000004 at step 3 and 0.9999999999999999 at
// step 10, the values these tests reject.

#include <gtest/gtest.h>

#include <vector>

#include "nonlinear/step_times.hpp"

namespace grout {
namespace {

TEST(StepTimes, TenStepsAreTheDecimalValues) {
  StepTimes times(1.0, 10);
  const std::vector<double> expected = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
  std::vector<double> got;
  while (!times.finished()) {
    EXPECT_EQ(times.step_size(), 0.1);
    times.advance();
    got.push_back(times.time());
  }
  EXPECT_EQ(got, expected);  // bitwise: the doubles nearest the decimals
}

TEST(StepTimes, EndTimeOtherThanOne) {
  StepTimes times(1.5, 15);
  std::vector<double> got;
  while (!times.finished()) {
    times.advance();
    got.push_back(times.time());
  }
  ASSERT_EQ(got.size(), 15u);
  EXPECT_EQ(got[2], 0.3);
  EXPECT_EQ(got[9], 1.0);
  EXPECT_EQ(got.back(), 1.5);
}

// Step 3 of 10 cut twice (0.2 -> 0.225 -> 0.25), then grown back: 0.3 is still 0.3 and
// the run ends at exactly 1.
TEST(StepTimes, CutBacksAreFinerFractions) {
  StepTimes times(1.0, 10);
  times.advance();
  times.advance();
  EXPECT_EQ(times.next_time(), 0.3);
  times.halve();
  EXPECT_EQ(times.next_time(), 0.25);
  EXPECT_EQ(times.step_size(), 0.05);
  times.halve();
  EXPECT_EQ(times.next_time(), 0.225);
  times.advance();
  EXPECT_EQ(times.time(), 0.225);
  times.advance();
  EXPECT_EQ(times.time(), 0.25);
  times.grow();
  EXPECT_EQ(times.next_time(), 0.3);
  times.advance();
  times.grow();
  times.grow();  // capped at the nominal step
  EXPECT_EQ(times.step_size(), 0.1);
  std::vector<double> rest;
  while (!times.finished()) {
    times.advance();
    rest.push_back(times.time());
  }
  EXPECT_EQ(rest, (std::vector<double>{0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0}));
}

// A step size not dividing the rest of the run: the last step stops at t_end.
TEST(StepTimes, LastStepEndsAtTheEndTime) {
  StepTimes times(1.0, 3);
  times.halve();  // 1/6
  for (int i = 0; i < 5; ++i) times.advance();
  EXPECT_EQ(times.time(), 5.0 / 6.0);
  times.grow();  // 1/3 would pass t_end
  EXPECT_EQ(times.next_time(), 1.0);
  times.advance();
  EXPECT_TRUE(times.finished());
  EXPECT_EQ(times.time(), 1.0);
}

}  // namespace
}  // namespace grout
