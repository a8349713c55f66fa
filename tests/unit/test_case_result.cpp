// What a study (sweep, validate, calibrate) reads of one case's run directory (studies/case_runs.hpp).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

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

}  // namespace
}  // namespace mpmcut
