// Stepping onto target times (src/solver/time_step_to_target.hpp): every output time is hit exactly
// and no step is a sliver; a sliver carried a contact velocity correction over a tiny dt, a spike of
// 100x the mean in forces.csv's step-force columns (seen at 60 m/min in the validation matrix).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/time_step_to_target.hpp"

namespace mpmcut {
namespace {

TEST(TimeStepToTarget, TheLastTwoStepsShareARemainderBetweenOneAndTwoStableSteps) {
  EXPECT_DOUBLE_EQ(time_step_to_target(1.3, 1.0), 0.65);
  EXPECT_DOUBLE_EQ(time_step_to_target(0.65, 1.0), 0.65);  // the second half lands on the target
  EXPECT_DOUBLE_EQ(time_step_to_target(5.0, 1.0), 1.0);    // far away: the stable step
  EXPECT_DOUBLE_EQ(time_step_to_target(0.4, 1.0), 0.4);    // within one step: land on it
  EXPECT_DOUBLE_EQ(time_step_to_target(std::numeric_limits<double>::infinity(), 1.0), 1.0);
}

// Outputs every 10.3 and every 7.9 stable steps (history and snapshots): every output time is hit
// exactly, and no step is shorter than half the stable one unless two output times lie closer.
TEST(TimeStepToTarget, OutputsAreHitExactlyWithoutSliverSteps) {
  const double stable = 1.0, every_a = 10.3, every_b = 7.9, end = 200.0;
  double t = 0.0, next_a = every_a, next_b = every_b, shortest = stable;
  int outputs = 0;
  while (t < end - 1e-12) {
    const double target = std::min({next_a, next_b, end});
    const double previous_output = std::max(next_a - every_a, next_b - every_b);
    const double dt = time_step_to_target(target - t, stable);
    if (target - previous_output >= 0.5 * stable) shortest = std::min(shortest, dt);
    t += dt;
    ASSERT_LE(t, target + 1e-9) << "a step went past an output time";
    if (std::abs(t - target) < 1e-9) {
      t = target;
      ++outputs;
      if (std::abs(next_a - target) < 1e-9) next_a += every_a;
      if (std::abs(next_b - target) < 1e-9) next_b += every_b;
    }
  }
  EXPECT_GT(outputs, 40);
  EXPECT_GE(shortest, 0.5 * stable);  // cutting the last step short gives 0.3 here
}

}  // namespace
}  // namespace mpmcut
