#pragma once
// The grid-convergence table of a sweep over resolutions (sweep.csv with cells_per_feed):
// for each condition (speed, feed) with three or more complete resolutions, the three finest give each
// headline quantity's observed order, its extrapolated (h -> 0) value and the GCI of the finest run
// (analysis/grid_convergence.hpp). Written by `mpmcut sweep` and by `mpmcut convergence DIR`.
#include <filesystem>
#include <string>

#include "studies/case_runs.hpp"

namespace mpmcut {

struct GridConvergenceReport {
  TextTable table;        // one row per condition and quantity
  int conditions = 0;     // conditions with three or more complete resolutions
  std::string markdown;   // a section for sweep.md / grid_convergence.md: what it is, the table, the reference
};

// Reads `sweep_csv` (InputError naming the file, line and column if a needed column is absent or not a
// number).
GridConvergenceReport grid_convergence_report(const std::filesystem::path& sweep_csv);

}  // namespace mpmcut
