// The pure arithmetic of `mpmcut validate`: the resolution rule of the measured conditions, the tool travel
// and workpiece height rules, the speed-trend slope, the error summary and the cost estimate's correction.
#include <cmath>

#include <gtest/gtest.h>

#include "cutting/cutting_resolution.hpp"
#include "run/case_loading.hpp"
#include "studies/measured_conditions.hpp"
#include "studies/validation_metrics.hpp"

namespace mpmcut {
namespace {

// cell = min(t0/N, r_n/M): the feed limits thin feeds, the edge radius thick ones.
TEST(ValidationResolution, CellIsTheSmallerOfFeedAndEdgeRadiusLimits) {
  EXPECT_NEAR(validation_cell_size_m(0.01e-3, 40e-6, 10, 4.0), 1e-6, 1e-15);    // t0/10 = 1 um < r_n/4 = 10 um
  EXPECT_NEAR(validation_cell_size_m(0.2e-3, 38.8e-6, 10, 4.0), 9.7e-6, 1e-15); // r_n/4 = 9.7 um < t0/10 = 20 um
  EXPECT_NEAR(validation_cell_size_m(0.2e-3, 38.8e-6, 10, 0.0), 20e-6, 1e-15);  // M = 0: no edge-radius limit
}

TEST(ValidationResolution, CutAndWorkpieceScaleWithTheLargerOfFeedAndEdgeRadius) {
  EXPECT_NEAR(validation_cut_length_m(0.01e-3, 40e-6), 240e-6, 1e-15);  // thin feed: the edge sets it
  EXPECT_NEAR(validation_cut_length_m(0.1e-3, 37e-6), 0.6e-3, 1e-15);   // thick feed: 6 t0
  EXPECT_NEAR(validation_workpiece_height_m(0.01e-3, 40e-6), 90e-6, 1e-15);  // t0 + 2 r_n, not 4 t0 = 40 um
  EXPECT_NEAR(validation_workpiece_height_m(0.1e-3, 37e-6), 0.4e-3, 1e-15);  // the preset's 4 t0
}

// The case file carries the rule: the thin feed with a large edge gets t0/N, the thick one r_n/M, the chip-type
// condition (preset 5 um edge, not measured) no edge limit but its own cells across t0 (kChipTypeCellsPerFeed, or
// the settings', never fewer than the force conditions'); and the case reads back with those cells.
TEST(ValidationResolution, CaseFileCellSizeFollowsTheRule) {
  ConditionRunSettings s;
  s.cells_per_feed = 10;
  s.cells_per_edge_radius = 4.0;
  const auto cell_of = [&](const char* kind, double h_mm, double r_um) {
    CuttingCondition c;
    c.id = "test";
    c.kind = kind;
    c.speed_m_per_s = 5.0;
    c.h_mm = h_mm;
    c.edge_radius_um = r_um;
    return parse_case(condition_case_text(c, s), "test.toml").cutting->cell_size;
  };
  EXPECT_NEAR(cell_of("forces", 0.01, 39.8), 1e-6, 1e-12);
  EXPECT_NEAR(cell_of("forces", 0.2, 38.8), 9.7e-6, 1e-12);
  EXPECT_NEAR(cell_of("chip", 0.1, 5.0), 5e-6, 1e-12);  // kChipTypeCellsPerFeed = 20
  s.chip_type_cells_per_feed = 10;                        // the matrices before 2026-12-07
  EXPECT_NEAR(cell_of("chip", 0.1, 5.0), 10e-6, 1e-12);
  s.cells_per_feed = 24;  // never coarser than the force conditions
  EXPECT_NEAR(cell_of("chip", 0.1, 5.0), 0.1e-3 / 24, 1e-12);
}

// l_th = sqrt(kappa t0 / V) with kappa = k / (rho c) of the workpiece set; cell <= l_th / K where that is the smallest.
// By hand for ti64-sima-ozel-2010 (k 6.8 W/(m K), rho 4430 kg/m^3, c 526.3 J/(kg K): kappa = 2.9166e-6 m^2/s) at
// h = 0.1 mm: 381.3 m/min l_th = 6.774 um, 12.6 m/min 37.27 um.
TEST(ValidationResolution, ThermalLengthLimitsTheCellOfFastCuts) {
  ConditionRunSettings s;
  s.material = "ti64-sima-ozel-2010";
  const double kappa = 6.8 / (4430.0 * 526.3);
  EXPECT_NEAR(workpiece_thermal_diffusivity_m2_per_s(s), kappa, 1e-12 * kappa);
  EXPECT_NEAR(thermal_length_m(kappa, 0.1e-3, 381.3 / 60.0), 6.774e-6, 0.001e-6);
  EXPECT_NEAR(thermal_length_m(kappa, 0.1e-3, 12.6 / 60.0), 37.27e-6, 0.01e-6);
  // K = 1.6 at 381.3 m/min: 4.234 um (finer than t0/10 = 10 um and r_n/4 = 8.25 um); at 12.6 m/min l_th/K = 23 um
  // does not limit (r_n/4 = 7.875 um does).
  EXPECT_NEAR(validation_cell_size_m(0.1e-3, 33e-6, 10, 4.0, 6.774e-6, 1.6), 6.774e-6 / 1.6, 1e-15);
  EXPECT_NEAR(validation_cell_size_m(0.1e-3, 31.5e-6, 10, 4.0, 37.27e-6, 1.6), 7.875e-6, 1e-15);
  EXPECT_NEAR(validation_cell_size_m(0.1e-3, 33e-6, 10, 4.0, 6.774e-6, 0.0), 8.25e-6, 1e-15);  // K = 0: off

  // The case file: the same cell, and a set whose conductivity is four times larger has l_th twice as long.
  s.cells_per_thermal_length = 1.6;
  const CuttingCondition fast{"fast", "forces", 381.3 / 60.0, 0.1, 33.0};
  EXPECT_NEAR(parse_case(condition_case_text(fast, s), "test.toml").cutting->cell_size, 6.774e-6 / 1.6, 0.001e-6);
  s.material_overrides = {{"thermal_conductivity", 4 * 6.8}};
  EXPECT_NEAR(workpiece_thermal_diffusivity_m2_per_s(s), 4 * kappa, 1e-12 * kappa);
  EXPECT_NEAR(parse_case(condition_case_text(fast, s), "test.toml").cutting->cell_size, 8.25e-6, 1e-12);  // r_n/4
  // A material file's own set.
  s.material_overrides.clear();
  s.material_definitions = "[[material]]\nname = \"slow-heat\"\nlibrary = \"ti64-sima-ozel-2010\"\nthermal_conductivity = 0.68\n";
  s.material = "slow-heat";
  EXPECT_NEAR(workpiece_thermal_diffusivity_m2_per_s(s), 0.1 * kappa, 1e-12 * kappa);
  EXPECT_NEAR(parse_case(condition_case_text(fast, s), "test.toml").cutting->cell_size,
              std::sqrt(0.1) * 6.774e-6 / 1.6, 0.001e-6);
}

// A force condition at h = 0.1 mm, 1 m/s, r_n = 30 um.
CuttingCondition force_condition() {
  CuttingCondition c;
  c.id = "test";
  c.kind = "forces";
  c.speed_m_per_s = 1.0;
  c.h_mm = 0.1;
  c.edge_radius_um = 30.0;
  return c;
}

// --contact-detection reaches the run's scene; without it the case text has no [solver] table, so the cases (and
// the committed run records made from them) are what they were before the option existed.
TEST(ValidationCases, ContactDetectionReachesTheScene) {
  const CuttingCondition c = force_condition();
  ConditionRunSettings s;
  EXPECT_EQ(condition_case_text(c, s).find("[solver]"), std::string::npos);
  // Without the option: the cutting preset's penalty contact.
  EXPECT_EQ(parse_case(condition_case_text(c, s), "test.toml").scene.solver.contact_detection,
            ContactDetection::Penalty);
  s.contact_detection = "node";
  EXPECT_EQ(parse_case(condition_case_text(c, s), "test.toml").scene.solver.contact_detection, ContactDetection::Node);
  s.contact_detection = "penalty";
  // --volumetric-average likewise, into the same [solver] table.
  EXPECT_EQ(parse_case(condition_case_text(c, s), "test.toml").scene.solver.volumetric_average, VolumetricAverage::Off);
  s.volumetric_average = "nodal";
  const Scene both = parse_case(condition_case_text(c, s), "test.toml").scene;
  EXPECT_EQ(both.solver.volumetric_average, VolumetricAverage::Nodal);
  EXPECT_EQ(both.solver.contact_detection, ContactDetection::Penalty);
}

// --tool-heat-transfer-coefficient, --tool-temperature and --tool-conductivity reach the run's tool: a steady
// conducting tool held at the given temperature (its volumetric heat capacity makes it transient).
TEST(ValidationCases, ConductingToolReachesTheScene) {
  const CuttingCondition c = force_condition();
  ConditionRunSettings s;
  EXPECT_EQ(parse_case(condition_case_text(c, s), "test.toml").scene.rigid_bodies.at(0).conductivity, 0.0);
  s.tool_heat_transfer_coefficient = 1e6;
  s.tool_temperature = 350.0;
  s.tool_conductivity = 86.0;
  const RigidBodySpec steady = parse_case(condition_case_text(c, s), "test.toml").scene.rigid_bodies.at(0);
  EXPECT_EQ(steady.conductivity, 86.0);
  EXPECT_EQ(steady.heat_transfer_coefficient, 1e6);
  EXPECT_EQ(steady.temperature, 350.0);
  EXPECT_EQ(steady.volumetric_heat_capacity, 0.0);
  EXPECT_GT(steady.heat_averaging_time, 0.0);
  s.tool_volumetric_heat_capacity = 3e6;
  EXPECT_EQ(parse_case(condition_case_text(c, s), "test.toml").scene.rigid_bodies.at(0).volumetric_heat_capacity, 3e6);
}

// Fc = a + b ln v is recovered exactly; a falling force has a negative slope.
TEST(ValidationTrend, SlopeOverLogSpeed) {
  const std::vector<double> v{10, 100, 400};
  std::vector<double> f;
  for (double x : v) f.push_back(200.0 - 7.5 * std::log(x));
  ASSERT_TRUE(speed_trend_slope(v, f).has_value());
  EXPECT_NEAR(*speed_trend_slope(v, f), -7.5, 1e-12);
  // Least squares, not end points: (1,0), (2,2), (3,1) has slope 0.5.
  EXPECT_NEAR(*least_squares_slope({1, 2, 3}, {0, 2, 1}), 0.5, 1e-12);
  EXPECT_FALSE(speed_trend_slope({100}, {1}).has_value());
  EXPECT_FALSE(speed_trend_slope({100, 100}, {1, 2}).has_value());  // one distinct speed
}

TEST(ValidationErrors, MeanAndWorstOfAbsoluteRelativeErrors) {
  EXPECT_NEAR(*relative_error(90.0, 100.0), -0.1, 1e-15);
  EXPECT_FALSE(relative_error(std::nullopt, 100.0).has_value());
  const ErrorSummary s = summarize_errors({-0.1, std::nullopt, 0.3, -0.2});
  EXPECT_EQ(s.count, 3);
  EXPECT_NEAR(s.mean_abs, 0.2, 1e-15);
  EXPECT_NEAR(s.worst_abs, 0.3, 1e-15);
  EXPECT_EQ(s.worst_index, 2);
  EXPECT_EQ(summarize_errors({}).count, 0);
}

// The corrected estimate takes the medians of what complete runs took (steps against the estimate, core-s per
// particle-step), so one odd run does not move it; unusable observations are left out.
TEST(ValidationCost, CorrectionFromCompleteRunsIsTheMedian) {
  EXPECT_FALSE(observed_cost_correction({}).has_value());
  EXPECT_FALSE(observed_cost_correction({{0.0, 100.0, 1e-6}, {100.0, NAN, 1e-6}}).has_value());
  // Ratios 1.1, 1.35, 3.0 (odd one); costs 0.4, 0.5, 0.53 us; one unusable run (no rate).
  const auto c = observed_cost_correction(
      {{1000.0, 1100.0, 0.4e-6}, {1000.0, 1350.0, 0.53e-6}, {1000.0, 3000.0, 0.5e-6}, {1000.0, 1200.0, 0.0}});
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->runs, 3);
  EXPECT_NEAR(c->step_ratio, 1.35, 1e-12);
  EXPECT_NEAR(c->step_ratio_min, 1.1, 1e-12);
  EXPECT_NEAR(c->step_ratio_max, 3.0, 1e-12);
  EXPECT_NEAR(c->core_seconds_per_particle_step, 0.5e-6, 1e-18);
  // 1e10 estimated particle-steps: 1.35e10 actual at 0.5 us = 6750 core-s = 1.875 core-h.
  EXPECT_NEAR(c->core_hours(1e10), 1.875, 1e-9);
  // An even count takes the mean of the middle two.
  const auto even = observed_cost_correction({{1000.0, 1000.0, 0.2e-6}, {1000.0, 2000.0, 0.4e-6}});
  ASSERT_TRUE(even.has_value());
  EXPECT_NEAR(even->step_ratio, 1.5, 1e-12);
  EXPECT_NEAR(even->core_seconds_per_particle_step, 0.3e-6, 1e-18);
}

}  // namespace
}  // namespace mpmcut
