#pragma once
// Observed chip types (data/experiments/ti64_chip_morphology.csv, or a user's file in its layout): which chip a
// source saw at a cutting condition, and the speed at which `mpmcut validate` simulates it to compare.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "studies/measured_conditions.hpp"

namespace mpmcut {

struct ChipObservation {
  int line = 0;                 // 1-based, in the file
  std::string id;               // unique in the file
  std::string chip_type;        // one of chip_types()
  std::optional<double> simulate_speed_m_per_s;  // none: not simulated (the note says why)
  double h_mm = 0.0;            // h_min_mm: the uncut chip thickness simulated
  std::optional<double> rake_deg, clearance_deg;  // none: the preset's (an assumption)
  std::optional<double> edge_radius_um;           // none: the preset's 5 um (an assumption)
  std::map<std::string, std::string> cells;       // the whole row: statement, source, tag, note, ...
  std::string cell(const std::string& column) const;  // "" where the file has no such column
};

// The chip types an observation may name (the chip analysis gives the first three).
const std::vector<std::string>& chip_types();

// The columns an observation file must have, and the optional ones (rake_deg, clearance_deg, edge_radius_um, source,
// tag, statement, note, the speed and h ranges of the source); a column that misspells one of them is an error.
const std::vector<std::string>& required_chip_columns();
const std::vector<std::string>& optional_chip_columns();

// Every row, checked: InputError with file, line and column for a missing or misspelt column, an unknown chip type,
// a number out of range, a simulated row without h, an id given twice, or a file without a row to simulate.
std::vector<ChipObservation> read_chip_observations(const DataFile& file);

}  // namespace mpmcut
