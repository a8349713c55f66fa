// Mass scaling as a user states it: [solver] mass_scaling_factor / mass_scaling_target_time_step,
// and the [cutting] preset's mass_scaling = "auto" | "off" | factor (docs/mass_scaling.md).
#include <gtest/gtest.h>

#include <cmath>

#include "../support/parse_errors.hpp"
#include "../support/ti64_parameters.hpp"
#include "cutting/mass_scaling.hpp"
#include "io/input_error.hpp"
#include "run/case_loading.hpp"

using namespace mpmcut;

namespace {

const std::string kCut = R"(title = "cut"
[cutting]
material = "ti64-johnson-1985"
cutting_speed = 1.0
uncut_chip_thickness = 0.1e-3
cut_length = 0.1e-3
cell_size = 20e-6
)";

std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return mpmcut::testing::parse_error_of(text, overrides);
}

}  // namespace

// rho f V^2 / A = target: for Ti-6Al-4V (rho 4430 kg/m^3, A 862 MPa) at 1 m/s and 2e-3 that is
// f = 2e-3 * 862e6 / 4430 = 389.2; at 30 m/s the unscaled number 0.0462 is above the target: f = 1.
TEST(MassScalingInput, AutomaticFactorReachesTheTargetInertiaNumber) {
  const MaterialParameters m = mpmcut::testing::ti64_johnson_1985();
  CuttingParameters c;
  c.cutting_speed = 1.0;
  EXPECT_NEAR(cutting_mass_scaling_factor(c, m), 2e-3 * 862e6 / 4430.0, 1e-9);
  EXPECT_NEAR(inertia_number(m, cutting_mass_scaling_factor(c, m), c.cutting_speed), 2e-3, 1e-12);
  c.cutting_speed = 30.0;
  EXPECT_EQ(cutting_mass_scaling_factor(c, m), 1.0);
  c.cutting_speed = 1.0;
  c.mass_scaling = 1.0;  // "off"
  EXPECT_EQ(cutting_mass_scaling_factor(c, m), 1.0);
  c.mass_scaling = 25.0;
  EXPECT_EQ(cutting_mass_scaling_factor(c, m), 25.0);
}

TEST(MassScalingInput, CuttingPresetWritesTheFactorIntoTheSolver) {
  const Scene automatic = parse_case(kCut, "case.toml").scene;
  EXPECT_NEAR(automatic.solver.mass_scaling_factor, 2e-3 * 862e6 / 4430.0, 1e-6);
  EXPECT_EQ(parse_case(kCut, "case.toml", {"cutting.mass_scaling=\"off\""}).scene.solver.mass_scaling_factor, 1.0);
  EXPECT_EQ(parse_case(kCut, "case.toml", {"cutting.mass_scaling=40"}).scene.solver.mass_scaling_factor, 40.0);
  // [solver] has the last word.
  EXPECT_EQ(parse_case(kCut + "[solver]\nmass_scaling_factor = 7\n", "case.toml").scene.solver.mass_scaling_factor, 7.0);
}

TEST(MassScalingInput, BadValuesNameTheKeyAndTheRange) {
  std::string e = error_of(kCut, {"cutting.mass_scaling=\"sometimes\""});
  EXPECT_NE(e.find("cutting.mass_scaling"), std::string::npos) << e;
  EXPECT_NE(e.find("\"auto\", \"off\""), std::string::npos) << e;
  e = error_of(kCut, {"cutting.mass_scaling=0.5"});
  EXPECT_NE(e.find("cutting.mass_scaling"), std::string::npos) << e;
  e = error_of(kCut, {"cutting.mass_scaling=nan"});
  EXPECT_NE(e.find("cutting.mass_scaling"), std::string::npos) << e;
  e = error_of(kCut, {"cutting.mass_scaling_inertia_number=0"});
  EXPECT_NE(e.find("mass_scaling_inertia_number"), std::string::npos) << e;
  e = error_of(kCut + "[solver]\nmass_scaling_factor = 0.9\n");
  EXPECT_NE(e.find("solver.mass_scaling_factor"), std::string::npos) << e;
  EXPECT_NE(e.find("[1, 1e+06]"), std::string::npos) << e;
  e = error_of(kCut + "[solver]\nmass_scaling_factor = inf\n");
  EXPECT_NE(e.find("solver.mass_scaling_factor"), std::string::npos) << e;
  e = error_of(kCut + "[solver]\nmass_scaling_factor = 4\nmass_scaling_target_time_step = 1e-8\n");
  EXPECT_NE(e.find("not both"), std::string::npos) << e;
  e = error_of(kCut + "[solver]\nmass_scaling_target_time_step = -1e-9\n");
  EXPECT_NE(e.find("solver.mass_scaling_target_time_step"), std::string::npos) << e;
}
