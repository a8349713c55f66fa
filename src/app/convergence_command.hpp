#pragma once
// `mpmcut convergence SWEEP_DIR`: the Richardson extrapolation of a resolution sweep
// (studies/grid_convergence_report.hpp) from its sweep.csv alone, so that a committed study can be
// re-evaluated without its result directories. Writes grid_convergence.csv and grid_convergence.md
// into SWEEP_DIR and prints the Markdown.
#include <CLI/CLI.hpp>

namespace mpmcut {

void add_convergence_command(CLI::App& app);

}  // namespace mpmcut
