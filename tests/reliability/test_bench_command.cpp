// `mpmcut bench` as a user runs it: a timed stretch too short to mean anything is flagged as noise (5 steps of
// 100 particles "sped up" 33x on 2 cores), a long enough one is not, and a thread count out of range is refused.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "cli.hpp"

namespace mpmcut::testing {
namespace {

TEST(BenchCommand, ATimingTooShortToMeanAnythingIsFlaggedAsNoise) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("mpmcut_bench_{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  CliResult r = run_mpmcut({"bench", "--case", "elastic", "--particles", "100", "--steps", "5", "--threads", "1"},
                           dir / "short.txt");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("threads  1:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("noise, not a speed; raise --steps or --particles"), std::string::npos) << r.output;
  // About 40 000 particles x 60 steps: well over 0.2 s on any machine this runs on (a few 1e6 particle-steps/s).
  r = run_mpmcut({"bench", "--case", "elastic", "--particles", "40000", "--steps", "60", "--threads", "1"},
                 dir / "long.txt");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("noise"), std::string::npos) << r.output;
  r = run_mpmcut({"bench", "--threads", "0"}, dir / "zero.txt");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mpmcut::testing
