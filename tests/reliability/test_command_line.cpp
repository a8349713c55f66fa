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

// validate's tool-heat options allow what the [cutting] keys allow (cutting/tool_heat_settings.hpp): an open bound
// (tool_temperature > 0 K) and NaN are refused by the option, and a combination the case reader would refuse in every
// case file (a conducting tool with an adiabatic surface) is refused before any run, naming the option.
TEST(CommandLine, ValidateRefusesToolHeatTheCaseReaderWouldRefuse) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("mpmcut_validate_tool_heat_{}", getpid());
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string out = (dir / "study").string();
  CliResult r = run_mpmcut({"validate", "--quick", "--out", out, "--tool-temperature", "0"}, dir / "temperature.txt");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("not a number in (0, 10000) K"), std::string::npos) << r.output;
  r = run_mpmcut({"validate", "--quick", "--out", out, "--friction-heat-share", "nan"}, dir / "nan.txt");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = run_mpmcut({"validate", "--quick", "--out", out, "--tool-heat-transfer-coefficient", "0", "--tool-conductivity",
                  "86"},
                 dir / "conductivity.txt");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--tool-conductivity 86: must be 0 unless tool_heat_transfer_coefficient > 0"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "study" / "cases")) << "no case may be written before the refusal";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mpmcut::testing
