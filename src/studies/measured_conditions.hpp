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

#include "core/range.hpp"

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
  // An optional cell within `range`: none if blank (or the column is absent); InputError naming file, line and
  // column if it is not a number or out of the range ("must be in (-45, 45) degrees, got 50").
  std::optional<double> number_in(const Row& row, const std::string& column, const Range& range) const;
  // A misspelt optional column (widht_mm) would be ignored silently and change the comparison: a column within an
  // edit or two of a `known` one is an InputError naming it; other extra columns (notes) are left alone.
  void refuse_misspelt_columns(const std::vector<std::string>& known) const;
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
  // The tool's angles, where the file gives them (columns rake_deg, clearance_deg); none: the preset's 0° / 11°,
  // stated as assumptions in the case.
  std::optional<double> rake_deg, clearance_deg;
  // The width of cut of the tests, mm (column width_mm); none: not in the file, and a study assumes one.
  std::optional<double> width_mm;
  int n_tests = 0;
  std::string status;
  // The file holds a cut (h, speed, angles) with several edge radii: its tools differ in r_n, and every row's id
  // and tool name it.
  bool edge_radius_names_tool = false;

  // The forces per mm of width: divided by the file's width, or by `assumed_width_mm` where it gives none.
  MeasuredForces per_mm_of_width(double assumed_width_mm) const;
};

// The tool's angles where a measurement file gives them (the cutting preset's ranges), degrees.
inline constexpr Range kRakeColumn = Range::open(-45.0, 45.0, "degrees");
inline constexpr Range kClearanceColumn = Range::open(0.0, 45.0, "degrees");

// The columns a force file must have (calibration measurements: the same columns); min/max, n_tests,
// status, chip_thickness_um, rake_deg, clearance_deg and width_mm are optional (min = max = mean, n = 1, "ok", none,
// the preset's angles, an assumed width when absent).
const std::vector<std::string>& required_force_columns();
std::vector<MeasuredForces> read_measured_forces(const DataFile& file);

// A simulated cutting condition.
struct CuttingCondition {
  std::string id;           // result directory name
  std::string kind;         // "forces" | "chip"
  double speed_m_per_s = 0;
  double h_mm = 0;
  double edge_radius_um = 0;  // measured r_n for force conditions; the preset's 5 um where the source gives none
  bool edge_radius_given = false;  // a chip-type condition whose source gives r_n (a force condition's always does)
  std::optional<double> rake_deg, clearance_deg;  // from the measurements; none: the preset's (an assumption)
  std::optional<double> width_mm;  // the tests' width of cut, for the case's note (the run itself is 1 mm wide)
};

// The id (result directory name) of a force condition: forces_h<h>mm_vc<v>mpmin, with _rake<r>deg and
// _clearance<c>deg where the measurements give the tool's angles, and _rn<r>um where the file holds a cut with
// several edge radii.
std::string force_condition_id(const MeasuredForces& m);
// The simulated condition of a row of measured forces.
CuttingCondition force_condition(const MeasuredForces& m);

// Cells across t0 of chip-type conditions by default. At t0/10 the 75 m/s chip (discontinuous, observed) came out
// continuous or serrated, at t0/20 discontinuous in 6 of 6 steady samples, with and without crack friction
// (docs/results/validation_crack_friction, "The 75 m/s chip at t0/20"): the chip type of a fast cut needs its cells.
inline constexpr int kChipTypeCellsPerFeed = 20;

// How the conditions are run: resolution, material and friction.
struct ConditionRunSettings {
  std::string purpose = "validation";  // the case title's first word
  bool quick = false;       // cell = t0/4, 1 particle per cell, 4 cells of travel: a pipeline check
  int cells_per_feed = 10;  // N: cell <= t0 / N (chip-type conditions: at least chip_cells_per_feed)
  int chip_type_cells_per_feed = kChipTypeCellsPerFeed;  // cells across t0 of chip-type conditions (at least N)
  // M: cell <= r_n / M, so that the rounded edge, which at thin feeds does most of the cutting, is
  // resolved; 0 = no edge-radius limit (cell = t0 / N). Force conditions only (their r_n is measured).
  double cells_per_edge_radius = 4.0;
  // K: cell <= l_th / K, l_th = sqrt(kappa t0 / V) the thermal length, the width scale of a fast cut's shear bands
  // (cutting/cutting_resolution.hpp has the evidence); 0 = no such limit. Force and chip-type conditions alike.
  double cells_per_thermal_length = 0.0;
  std::string material = "ti64-cutting";  // a library set
  std::string material_note = "the calibrated set of the default case (materials/ti6al4v.toml)";
  // [[material]] tables (TOML text, e.g. of a user's material file) written into every case before [cutting], so
  // that `material` may name one of their sets and the case stays self-contained; empty: library sets only.
  std::string material_definitions;
  // Material keys changed from `material` (a [[material]] table with library = material in the case).
  std::vector<std::pair<std::string, double>> material_overrides;
  double friction = 0.35;   // Coulomb coefficient at the tool
  std::string friction_note = "ASSUMPTION: preset default Coulomb coefficient";
  // Share of the frictional heat that goes into the workpiece; none: the preset's (all of it), and the
  // case text stays that of the runs before the option (their records match).
  std::optional<double> friction_heat_share;
  // Heat transfer coefficient to the tool, W/(m^2 K), and its temperature, K; none: an adiabatic tool.
  std::optional<double> tool_heat_transfer_coefficient;
  std::optional<double> tool_temperature;
  // A conducting tool's conductivity, W/(m K), and volumetric heat capacity, J/(m^3 K); none: not conducting.
  std::optional<double> tool_conductivity;
  std::optional<double> tool_volumetric_heat_capacity;
  // Where tool_heat_transfer_coefficient and tool_conductivity come from when a default chose them (the case file's
  // comment); empty: the option or [runs] key of the same name.
  std::string tool_heat_transfer_note, tool_conductivity_note;
  int snapshots = 0;        // VTU snapshots of each run; 0: 2 with quick, else 20
  // solver.contact_detection of every case (a name as the case file spells it); empty: the preset's, and the
  // case text stays as it was before the option existed (committed run records still match).
  std::string contact_detection;
  // solver.volumetric_average of every case ("off" or "nodal"); empty: the preset's (off), the case text unchanged.
  std::string volumetric_average;
};

// The edge radius of a chip-type condition whose source gives none: the cutting preset's default, um.
inline constexpr double kChipConditionEdgeRadius_um = 5.0;

// Cells across t0 of chip-type conditions: the settings' chip-type count, at least the force conditions' and the chip
// analysis' resolved count (below it segments are particle roughness: at t0/5 the 5
// and 75 m/s chip types came out swapped).
int chip_cells_per_feed(const ConditionRunSettings& o);

// The resolution rule of the measured conditions: cell = min(t0 / N, r_n / M, l_th / K), m (M = 0 or K = 0: that
// limit off; l_th the thermal length, cutting/cutting_resolution.hpp).
double validation_cell_size_m(double uncut_chip_thickness_m, double edge_radius_m, int cells_per_feed,
                              double cells_per_edge_radius, double thermal_length_m = 0.0,
                              double cells_per_thermal_length = 0.0);

// The thermal diffusivity k / (rho c), m^2/s, of the workpiece material the settings name (a library set, a set of
// their material definitions, with their material overrides).
double workpiece_thermal_diffusivity_m2_per_s(const ConditionRunSettings& settings);

// Tool travel of a measured condition, m: 6 max(t0, r_n). The preset's steady window starts after
// max(40 % of the cut, 3 t0), so this leaves a window of at least 3 t0 (and 3.6 r_n where the edge is
// larger than the feed: there the deformed zone scales with r_n, not t0). It keeps thin feeds
// affordable: at t0 = 0.01 mm, r_n = 40 um it is 0.24 mm (the former max(0.4 mm, 6 t0): 0.4 mm).
double validation_cut_length_m(double uncut_chip_thickness_m, double edge_radius_m);

// Workpiece height of a measured condition, m: t0 + max(3 t0, 2 r_n), i.e. the preset's 4 t0 unless the
// edge radius is larger than 1.5 t0 (thin feeds): then the fixed base stays two edge radii below the
// machined surface, below the ploughing zone under the edge, instead of 3 t0 (30 um at t0 = 0.01 mm,
// less than one r_n).
double validation_workpiece_height_m(double uncut_chip_thickness_m, double edge_radius_m);

// The case file (TOML) of one condition. Width of cut 1 mm (forces per mm = forces in N for b = 1 mm),
// rake 0°, clearance 11° (not in the data: stated as assumptions in the file).
std::string condition_case_text(const CuttingCondition& c, const ConditionRunSettings& s);

}  // namespace mpmcut
