#pragma once
// `mpmcut analyze RESULT_DIR [--snapshot N|last]`: the chip analysis (analysis/chip_analysis.hpp)
// of one snapshot of a finished (or stopped) cutting run. Prints a short summary and merges the
// results into the directory's summary.json under "chip" and "temperature", keeping every other key.
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

namespace mpmcut {

// Registers the subcommand; its callback runs the analysis and ends the program by throwing
// CLI::RuntimeError(exit code) (0 on success), which CLI11_PARSE turns into main's return value.
void add_analyze_command(CLI::App& app);

// The work behind the subcommand, for tests: returns the exit code (0, or 2 with a message on
// stderr for a missing or non-result directory, a non-cutting scene or a bad snapshot choice).
int analyze_result_directory(const std::filesystem::path& dir, const std::string& snapshot);

}  // namespace mpmcut
