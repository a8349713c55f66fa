#pragma once
// `mpmcut validate [--quick]`: runs the cutting conditions of the published Ti-6Al-4V measurements in
// data/experiments/ (compiled into the program) and compares: validation.md, validation.csv,
// validation_runs.csv and plots (tools/plot_validation.py). docs/results.md describes the outputs.
#include <CLI/CLI.hpp>

namespace mpmcut {

void add_validate_command(CLI::App& app);

}  // namespace mpmcut
