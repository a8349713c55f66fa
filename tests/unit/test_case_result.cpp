// What a study (sweep, validate, calibrate) reads of one case's run directory (studies/case_runs.hpp).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/atomic_file.hpp"
#include "io/scene_writer.hpp"
#include "run/case_loading.hpp"
#include "run/run_summary.hpp"
#include "studies/case_runs.hpp"

namespace mpmcut {
namespace {

namespace fs = std::filesystem;

// A run directory whose summary.json has `status` and steady-window means of 120 / 40 N/mm.
fs::path run_dir(const std::string& name, const std::string& status) {
  const fs::path dir = fs::temp_directory_path() / ("mpmcut_test_case_result_" + std::to_string(::getpid())) / name;
  fs::create_directories(dir);
  RunSummary s;
  s.status = status;
  s.mean_cutting_force_N_per_mm = 120.0;
  s.mean_thrust_force_N_per_mm = 40.0;
  write_summary(dir / "summary.json", s);
  return dir;
}

// An interrupted or failed run has cut only part of its length: its means must not sit in the study's table
// beside the complete runs' (sweep.csv showed an interrupted case's partial-cut forces with nothing but its
// status to tell them apart).
TEST(CaseResult, ARunThatDidNotCompleteGivesNoForces) {
  for (const std::string status : {"interrupted", "failed", "running"}) {
    const CaseResult r = read_case_result(run_dir(status, status), {}, 0);
    EXPECT_EQ(r.status, status);
    EXPECT_FALSE(r.cutting_force_N_per_mm.has_value()) << status;
    EXPECT_FALSE(r.thrust_force_N_per_mm.has_value()) << status;
    EXPECT_EQ(r.force_basis, "") << status;
    EXPECT_NE(r.message.find("forces left out: the run did not complete"), std::string::npos) << r.message;
  }
  const CaseResult done = read_case_result(run_dir("complete", "complete"), {}, 0);
  EXPECT_EQ(done.status, "complete");
  EXPECT_EQ(done.cutting_force_N_per_mm, 120.0);
  EXPECT_EQ(done.thrust_force_N_per_mm, 40.0);
  EXPECT_EQ(done.force_basis, "steady window");
  EXPECT_EQ(done.message.find("forces left out"), std::string::npos) << done.message;
  fs::remove_all(fs::temp_directory_path() / ("mpmcut_test_case_result_" + std::to_string(::getpid())));
}

// A complete run of an older model of its scene (solver/model_version.hpp) that a study stopped before it ran it
// again: its forces are not today's model's, so they do not go into the study's table. The elastic block against a
// wall with penalty contact and friction is of version 1; a summary without the version was written before it.
TEST(CaseResult, ACompleteRunOfAnOlderModelOfItsSceneIsOutdatedAndGivesNoForces) {
  const Case c = load_case(std::string(MPMCUT_TEST_DIR) + "/support/cases/elastic_block.toml",
                           {"solver.contact_detection=penalty", "rigid_body[0].friction=0.3",
                            "rigid_body[0].friction_heat_share=0"});
  for (const int recorded : {0, 1}) {
    const fs::path dir = run_dir("penalty_v" + std::to_string(recorded), "complete");
    write_file_atomically(dir / "scene.toml", [&](std::ostream& s) { write_scene(c, s); });
    RunSummary s = read_summary(dir / "summary.json");
    s.model_version = recorded;
    write_summary(dir / "summary.json", s);
    const CaseResult r = read_case_result(dir, {}, 0);
    if (recorded == 0) {
      EXPECT_EQ(r.status, "outdated");
      EXPECT_FALSE(r.cutting_force_N_per_mm.has_value());
      EXPECT_NE(r.message.find("made by model version 0 of this scene; since then: version 1"), std::string::npos)
          << r.message;
    } else {
      EXPECT_EQ(r.status, "complete");
      EXPECT_EQ(r.cutting_force_N_per_mm, 120.0);
    }
  }
  fs::remove_all(fs::temp_directory_path() / ("mpmcut_test_case_result_" + std::to_string(::getpid())));
}

}  // namespace
}  // namespace mpmcut
