// The conduction sub-cycle (thermal/heat_conduction.hpp): conduction runs every kSubsteps steps,
// or earlier when the next step would pass the explicit limit, over the time the steps covered;
// off, it never runs.
#include <gtest/gtest.h>

#include "thermal/heat_conduction.hpp"

using namespace mpmcut;

namespace {
MaterialParameters conductor() {
  MaterialParameters m;
  m.density = 4000.0;
  m.specific_heat = 500.0;
  m.thermal_conductivity = 10.0;
  return m;
}
}  // namespace

TEST(ConductionSubcycle, LimitIsCflTimesHSquaredOverFourAlpha) {
  const SubcycledConduction c(true, {conductor()}, 1e-5, 0.4);
  const double alpha = 10.0 / (4000.0 * 500.0);
  EXPECT_DOUBLE_EQ(c.time_step_limit(), 0.4 * 1e-10 / (4.0 * alpha));
}

TEST(ConductionSubcycle, RunsEverySixteenStepsOverTheTimeTheyCovered) {
  const SubcycledConduction c(true, {conductor()}, 1e-5, 0.4);
  const double dt = 1e-3 * c.time_step_limit();
  ConductionSubcycle s;
  for (int cycle = 0; cycle < 3; ++cycle) {
    for (int k = 1; k <= SubcycledConduction::kSubsteps; ++k) {
      const bool due = c.begin_step(s, dt);
      ASSERT_EQ(due, k == SubcycledConduction::kSubsteps) << "step " << k;
      const auto elapsed = c.end_step(s, dt, due);
      ASSERT_EQ(elapsed.has_value(), due);
      if (due) EXPECT_NEAR(*elapsed, SubcycledConduction::kSubsteps * dt, 1e-12 * dt);
    }
    EXPECT_EQ(s.steps, 0);
    EXPECT_EQ(s.elapsed, 0.0);
  }
}

TEST(ConductionSubcycle, RunsEarlyBeforeTheExplicitLimit) {
  const SubcycledConduction c(true, {conductor()}, 1e-5, 0.4);
  const double dt = 0.4 * c.time_step_limit();
  ConductionSubcycle s;
  EXPECT_FALSE(c.begin_step(s, dt));  // elapsed 0 + 2 dt = 0.8 limit: another step fits
  c.end_step(s, dt, false);
  EXPECT_TRUE(c.begin_step(s, dt));   // elapsed dt + 2 dt = 1.2 limit: conduct at the end of this one
  const auto elapsed = c.end_step(s, dt, true);
  ASSERT_TRUE(elapsed.has_value());
  EXPECT_DOUBLE_EQ(*elapsed, 2 * dt);
}

TEST(ConductionSubcycle, OffNeverRuns) {
  const SubcycledConduction c(false, {conductor()}, 1e-5, 0.4);
  ConductionSubcycle s;
  for (int k = 0; k < 40; ++k) {
    ASSERT_FALSE(c.begin_step(s, 1.0));
    ASSERT_FALSE(c.end_step(s, 1.0, false).has_value());
  }
  EXPECT_EQ(s.steps, 0);
}
