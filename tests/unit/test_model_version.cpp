// The model version of a scene (solver/model_version.hpp): which changes to the physics apply to it.
#include <gtest/gtest.h>

#include <string>

#include "run/case_loading.hpp"
#include "solver/model_version.hpp"

namespace mpmcut::testing {
namespace {

// The elastic block against a rigid wall, with the wall's contact detection and friction set (the block has no
// heat capacity: the friction heats the wall).
Scene block_against_wall(const std::string& detection, double friction) {
  return load_case(std::string(MPMCUT_TEST_DIR) + "/support/cases/elastic_block.toml",
                   {"solver.contact_detection=" + detection, "rigid_body[0].friction=" + std::to_string(friction),
                    "rigid_body[0].friction_heat_share=0"})
      .scene;
}

TEST(ModelVersion, TheGridSlipChangeAppliesToPenaltyContactWithFrictionOnly) {
  EXPECT_EQ(model_version(block_against_wall("penalty", 0.35)), 1);
  EXPECT_EQ(model_version(block_against_wall("penalty", 0.0)), 0);  // no friction spring: the change alters nothing
  EXPECT_EQ(model_version(block_against_wall("node", 0.35)), 0);
  EXPECT_EQ(model_version(block_against_wall("gap", 0.35)), 0);
  EXPECT_NE(model_changes_since(0, block_against_wall("penalty", 0.35)).find("version 1 (08f9ca5): penalty contact"),
            std::string::npos);
  EXPECT_EQ(model_changes_since(1, block_against_wall("penalty", 0.35)), "");
  EXPECT_EQ(model_changes_since(0, block_against_wall("node", 0.35)), "");
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
