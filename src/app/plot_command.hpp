#pragma once
// `mpmcut plot RESULT_DIR`: pictures of a result directory (chip fields, tool, forces), drawn by the
// Python/matplotlib script tools/plot_result.py. The scripts in tools/*.py and the measured data in
// data/experiments/* are compiled into the program (the "embedded plot scripts" block in CMakeLists.txt),
// so an installed binary needs no source tree; they are written to a temporary folder when needed.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "io/embedded_text.hpp"

namespace mpmcut {

// tools/*.py and data/experiments/*, with their paths relative to the source tree.
std::span<const EmbeddedText> embedded_tool_files();

// The text of one embedded file, e.g. "data/experiments/ti64_klippel2024_orthogonal_forces.csv";
// throws std::runtime_error naming the file if it was not embedded.
std::string_view embedded_tool_file(std::string_view path);

// The interpreter the plot scripts run with: $MPMCUT_PYTHON, else /usr/bin/python3.
std::string python_interpreter();

// True when the interpreter runs and imports numpy and matplotlib (and meshio when needed);
// otherwise false and `why` says what is missing and how to get it.
bool python_plotting_available(bool need_meshio, std::string& why);

// Runs tools/<script> with the interpreter and `args`, stdout/stderr passed through, and returns
// its exit status (127 if it could not be started). The scripts come from $MPMCUT_TOOLS_DIR when
// that is set (development: edit a script without rebuilding), else from the embedded copies.
int run_python_tool(const std::string& script, const std::vector<std::string>& args);

// Registers `plot` on the command line.
void add_plot_command(CLI::App& app);

}  // namespace mpmcut
