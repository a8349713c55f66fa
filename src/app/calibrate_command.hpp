#pragma once
// `mpmcut calibrate CONFIG.toml`: material parameters fitted to measured cutting forces with NLopt
// (studies/calibration.hpp), then plots (tools/plot_calibration.py). docs/calibration.md.
#include <CLI/CLI.hpp>

namespace mpmcut {

void add_calibrate_command(CLI::App& app);

}  // namespace mpmcut
