#pragma once
// Measured cutting conditions and how each becomes a cutting case: the one path that `mpmcut validate`
// and `mpmcut calibrate` share, so that a change of the cutting preset reaches both.
//
// The measurements are CSV files in the layout of data/experiments/ (lines starting with '#' are
// comments, the first other line names the columns, no quoted cells).
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mpmcut {

// A data file's rows with their line numbers, for error messages "file:line: column 'x': ...".
struct DataFile {
  std::string source;               // the file name as the user gave it (or the embedded path)
  std::vector<std::string> columns;
  int header_line = 0;              // 1-based; 0 if the file has no header line
  struct Row {
    int line = 0;                   // 1-based
    std::map<std::string, std::string> cells;
  };
  std::vector<Row> rows;

  // Throws InputError "source:line: missing column(s) 'a', 'b' (the columns are: ...)" if any is absent.
  void require_columns(const std::vector<std::string>& names) const;
  // The cell as a number: NaN if blank; InputError naming file, line and column if it is not a number.
  double number(const Row& row, const std::string& column) const;
};

DataFile read_data_file(std::string_view text, const std::string& source);

// One condition of measured forces (data/experiments/ti64_klippel2024_orthogonal_forces.csv columns).
// Forces are in N for the whole width of cut, which the file does not state.
struct MeasuredForces {
  int line = 0;
  double h_mm = 0, vc_m_per_min = 0;
  double fc_N = 0, fc_min_N = 0, fc_max_N = 0;  // cutting force: mean, min, max over the tests
  double ff_N = 0, ff_min_N = 0, ff_max_N = 0;  // feed (thrust) force
  double edge_radius_um = 0;
  std::optional<double> chip_thickness_um;      // measured chip thickness, where given
  int n_tests = 0;
  std::string status;
};

// The columns a force file must have (calibration measurements: the same columns); min/max, n_tests,
// status and chip_thickness_um are optional (min = max = mean, n = 1, "ok", none when absent).
const std::vector<std::string>& required_force_columns();
std::vector<MeasuredForces> read_measured_forces(const DataFile& file);

// A simulated cutting condition.
struct CuttingCondition {
  std::string id;           // result directory name
  std::string kind;         // "forces" | "chip"
  double speed_m_per_s = 0;
  double h_mm = 0;
  double edge_radius_um = 0;  // measured r_n for force conditions; the preset's 5 um where the source gives none
};

// How the conditions are run: resolution, material and friction.
struct ConditionRunSettings {
  std::string purpose = "validation";  // the case title's first word
  bool quick = false;       // cell = t0/4, 1 particle per cell, 4 cells of travel: a pipeline check
  int cells_per_feed = 10;  // cell = t0 / cells_per_feed (chip-type conditions: at least chip_cells_per_feed)
  std::string material = "ti64-cutting";  // a library set
  std::string material_note = "the calibrated set of the default case (materials/ti6al4v.toml)";
  // Material keys changed from `material` (a [[material]] table with library = material in the case).
  std::vector<std::pair<std::string, double>> material_overrides;
  double friction = 0.35;   // Coulomb coefficient at the tool
  std::string friction_note = "ASSUMPTION: preset default Coulomb coefficient";
  int snapshots = 0;        // VTU snapshots of each run; 0: 2 with quick, else 20
};

// Cells across t0 of chip-type conditions: at least the chip analysis' resolved count (below it
// segments are particle roughness: at t0/5 the 5 and 75 m/s chip types came out swapped).
int chip_cells_per_feed(int cells_per_feed);

// The case file (TOML) of one condition. Width of cut 1 mm (forces per mm = forces in N for b = 1 mm),
// rake 0°, clearance 11° (not in the data: stated as assumptions in the file).
std::string condition_case_text(const CuttingCondition& c, const ConditionRunSettings& s);

}  // namespace mpmcut
