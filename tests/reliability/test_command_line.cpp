// The command line itself, as a user meets it: no command lists the commands (CLI11 said only "A subcommand is
// required"), and an option's bad value names the option once (it read "--checkpoint-every: --checkpoint-every
// 'abc'").
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "cli.hpp"

namespace mpmcut::testing {
namespace {

TEST(CommandLine, NoCommandListsTheCommandsAndNamesAnOptionOnce) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("mpmcut_command_line_{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  CliResult r = run_mpmcut({}, dir / "none.txt");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  for (const char* command : {"run", "resume", "sweep", "validate", "calibrate", "analyze", "plot", "keys"})
    EXPECT_NE(r.output.find(fmt::format("  {} ", command)), std::string::npos) << command << "\n" << r.output;
  EXPECT_NE(r.output.find("error: give a command"), std::string::npos) << r.output;
  r = run_mpmcut({"run", "--checkpoint-every", "abc"}, dir / "checkpoint.txt");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--checkpoint-every: 'abc': expected a positive number"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mpmcut::testing
