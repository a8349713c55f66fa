// The model version of a scene (solver/model_version.hpp): which changes to the physics apply to it.
#include <gtest/gtest.h>

#include <string>

#include "run/case_loading.hpp"
#include "solver/model_version.hpp"

namespace mpmcut::testing {
namespace {

Scene punch(const std::string& detection, double friction) {
  const std::string text = R"toml(
[grid]
cell_size = 40.0e-6
min = [0.0, 0.0]
max = [2.0e-3, 1.0e-3]
[solver]
end_time = 1.0e-6
contact_detection = ")toml" + detection + R"toml("
[[material]]
name = "ti64"
library = "ti64-johnson-1985"
[[body]]
name = "workpiece"
material = "ti64"
rectangle = { min = [0.0, 0.0], max = [1.5e-3, 0.5e-3] }
[[rigid_body]]
name = "punch"
polygon = [[0.6e-3, 0.5e-3], [1.0e-3, 0.5e-3], [1.0e-3, 0.9e-3], [0.6e-3, 0.9e-3]]
velocity = [0.0, -100.0]
friction = )toml" + std::to_string(friction) + "\n";
  return parse_case(text, "punch.toml").scene;
}

TEST(ModelVersion, TheGridSlipChangeAppliesToPenaltyContactWithFrictionOnly) {
  EXPECT_EQ(model_version(punch("penalty", 0.35)), 1);
  EXPECT_EQ(model_version(punch("penalty", 0.0)), 0);  // no friction spring: the change alters nothing
  EXPECT_EQ(model_version(punch("node", 0.35)), 0);
  EXPECT_EQ(model_version(punch("gap", 0.35)), 0);
  EXPECT_NE(model_changes_since(0, punch("penalty", 0.35)).find("version 1 (08f9ca5): penalty contact"),
            std::string::npos);
  EXPECT_EQ(model_changes_since(1, punch("penalty", 0.35)), "");
  EXPECT_EQ(model_changes_since(0, punch("node", 0.35)), "");
}

TEST(ModelVersion, VersionsCountUpFromOneWithTheirCommitAndWhatChanged) {
  int expected = 1;
  for (const ModelChange& c : model_changes()) {
    EXPECT_EQ(c.version, expected++);
    EXPECT_FALSE(std::string(c.revision).empty());
    EXPECT_FALSE(std::string(c.what).empty());
    EXPECT_NE(c.applies, nullptr);
  }
}

}  // namespace
}  // namespace mpmcut::testing
