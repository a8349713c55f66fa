// The progress line of a study's running cases (studies/study_progress.hpp): how far a run is from its files, and
// the line itself.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "run/run_summary.hpp"
#include "io/input_error.hpp"
#include "studies/case_runs.hpp"
#include "studies/progress_interval.hpp"
#include "studies/study_progress.hpp"

namespace mpmcut {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("mpmcut_test_study_progress_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(StudyProgress, FractionDoneIsTheLastHistoryTimeOverTheEndTime) {
  const fs::path dir = fresh_dir("running");
  EXPECT_FALSE(run_fraction_done(dir));  // nothing written yet
  std::ofstream(dir / "summary.json") << R"({"status": "running", "end_time_s": 4e-05, "steps": 0})";
  EXPECT_FALSE(run_fraction_done(dir));  // no history yet
  std::ofstream(dir / "history.csv") << "time_s,step,dt_s\n";
  EXPECT_FALSE(run_fraction_done(dir));  // the header only
  {
    std::ofstream h(dir / "history.csv", std::ios::app);
    for (int i = 1; i <= 5000; ++i) h << i * 2e-9 << "," << i << ",2e-09\n";  // more than the 8 kB tail read
    h << "1.0e-05,50";                                                          // a row being written: not counted
  }
  ASSERT_TRUE(run_fraction_done(dir));
  EXPECT_NEAR(*run_fraction_done(dir), 1e-5 / 4e-5, 1e-12);
  std::ofstream(dir / "summary.json") << R"({"status": "running", "end_time_s": 0)";  // half-written
  EXPECT_FALSE(run_fraction_done(dir));
}

TEST(StudyProgress, ResultDirectoryComesFromTheOutArgument) {
  EXPECT_EQ(result_dir_of_args({"run", "case.toml", "--out", "results/a", "--keep-complete"}), fs::path("results/a"));
  EXPECT_EQ(result_dir_of_args({"run", "case.toml", "-o", "b"}), fs::path("b"));
  EXPECT_EQ(result_dir_of_args({"analyze", "dir"}), fs::path());
}

TEST(StudyProgress, LineNamesEachCaseWithItsShareTimeAndWhatIsLeft) {
  const std::string line = progress_report_line(
      {{"v20mps_h0.1mm", 2040.0, 0.62, 1260.0}, {"v50mps_h0.1mm", 45.0, std::nullopt, std::nullopt}});
  EXPECT_EQ(line, "running: v20mps_h0.1mm 62 % (34 min, ~21 min left), v50mps_h0.1mm (45 s)");
  EXPECT_EQ(progress_report_line({{"long", 7200.0, 0.5, 7200.0}}), "running: long 50 % (2.0 h, ~2.0 h left)");
}

// A stop that reaches a case after its last step ends it with 130 while its results are complete: the console line
// says complete, as its summary does (it said "interrupted").
TEST(StudyProgress, ACaseStoppedAfterItsLastStepIsReportedComplete) {
  const fs::path dir = fresh_dir("stopped_after_last_step");
  ChildRun run;
  run.args = {"run", "case.toml", "--out", dir.string()};
  run.exit_code = 130;
  RunSummary summary;
  summary.status = "complete";
  write_summary(dir / "summary.json", summary);
  EXPECT_EQ(finished_case_text(run), "complete (the stop came after its last step)");
  summary.status = "interrupted";
  write_summary(dir / "summary.json", summary);
  EXPECT_EQ(finished_case_text(run), "interrupted");
  fs::remove(dir / "summary.json");
  EXPECT_EQ(finished_case_text(run), "interrupted");  // no summary: the exit code alone
  run.exit_code = 0;
  EXPECT_EQ(finished_case_text(run), "complete");
  run.exit_code = 1;
  EXPECT_EQ(finished_case_text(run), "failed (exit status 1)");
}

// --progress-every: wall times in the units --checkpoint-every takes, a bare number in seconds, off.
TEST(StudyProgress, IntervalTakesWallTimesAndOff) {
  EXPECT_EQ(parse_progress_interval("30s"), 30.0);
  EXPECT_EQ(parse_progress_interval("0.5 min"), 30.0);
  EXPECT_EQ(parse_progress_interval("2h"), 7200.0);
  EXPECT_EQ(parse_progress_interval("45"), 45.0);
  EXPECT_EQ(parse_progress_interval("off"), 0.0);
  EXPECT_EQ(parse_progress_interval("0"), 0.0);
  for (const char* bad : {"", "-5s", "5x", "abc", "inf", "5 steps"}) {
    try {
      parse_progress_interval(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("'") + bad + "'"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("30s, 5min, 1h"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace mpmcut
