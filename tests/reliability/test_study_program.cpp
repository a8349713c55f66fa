// A study (sweep, validate, calibrate) runs every case with the program it was started as, even when the
// file it was started from is replaced meanwhile, as a rebuild relinks build/mpmcut under a running study
// (docs/reliability.md, "Studies"). Otherwise later cases would run another program than earlier ones.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include "cli.hpp"

namespace mpmcut::testing {
namespace {

TEST(StudyProgram, ReplacingTheBinaryDoesNotChangeWhatTheStudyRuns) {
  const fs::path dir = fs::temp_directory_path() / ("mpmcut_study_program_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path program = dir / "mpmcut_copy";
  fs::copy_file(MPMCUT_BINARY, program);
  const fs::path case_file = fs::path(MPMCUT_TEST_DIR) / ".." / "cases" / "ti64_quick.toml";
  const fs::path out = dir / "sweep";
  // Two short cuts, one after the other.
  const pid_t pid = spawn_mpmcut({"sweep", case_file.string(), "--speeds", "10,20", "--jobs", "1", "--threads", "1",
                                  "--out", out.string(), "--no-plots", "--set", "cutting.cut_length=2e-5"},
                                 {dir / "sweep.log", 0, program});
  // Once the first cut steps, the file the sweep was started from becomes a program that fails at once
  // (removed and written anew, as a linker does).
  ASSERT_TRUE(wait_until([&] { return history_rows(out / "v10mps_h0.1mm") > 3; }, 60.0)) << read_file(dir / "sweep.log");
  fs::remove(program);
  write_file(program, "#!/bin/sh\necho replaced; exit 3\n");
  ::chmod(program.c_str(), 0755);
  const int code = wait_exit_code(pid);
  const std::string log = read_file(dir / "sweep.log");
  EXPECT_EQ(code, 0) << log;
  // The second cut started after the replacement and still ran the real program to the end.
  EXPECT_EQ(summary_status(out / "v10mps_h0.1mm"), "complete") << log;
  EXPECT_EQ(summary_status(out / "v20mps_h0.1mm"), "complete") << log;
  EXPECT_EQ(read_file(out / "logs" / "v20mps_h0.1mm.log").find("replaced"), std::string::npos);
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace mpmcut::testing
