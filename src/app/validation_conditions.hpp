#pragma once
// The conditions of `mpmcut validate`: the measured matrix (the built-in Klippel et al. 2024 force data and the
// chip-type statements, or a user's force file), the options that choose and resolve them, and each condition's
// run result once it is known. validate_command.cpp runs them, validation_report.cpp compares them.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "studies/case_runs.hpp"
#include "studies/chip_observations.hpp"
#include "studies/measured_conditions.hpp"
#include "studies/progress_interval.hpp"

namespace mpmcut::validation {

// The command line of `mpmcut validate` (add_validate_command gives each option's meaning).
struct Options {
  bool quick = false;
  int cells_per_feed = 10;            // N: cell <= t0 / N (the cutting preset's t0/10)
  int chip_cells_per_feed = kChipTypeCellsPerFeed;  // cells across t0 of the chip-type conditions (at least N)
  double cells_per_edge_radius = 4.0; // M: cell <= r_n / M
  double cells_per_thermal_length = 0.0;  // K: cell <= sqrt(kappa t0 / V) / K; 0 = no such limit
  std::string out_dir;
  std::string records_dir;  // --records: complete runs kept as small committed files (studies/run_records.hpp)
  int jobs = 0;
  double progress_interval_s = kDefaultProgressIntervalS;  // --progress-every (0: off)
  int threads = 1;
  bool no_plots = false;
  bool list = false;
  std::vector<double> h_mm, speeds_m_per_min;
  std::vector<std::string> condition_ids;
  // A library set or one of material_file; empty: the default (studies/validation_defaults.hpp)
  std::string material;
  std::string material_file;    // --material-file: [[material]] sets that --material may name
  std::vector<std::string> material_keys;  // --material-key KEY=VALUE: numeric keys changed from that set
  // The default set runs as it was fitted (studies/validation_defaults.hpp) where these are none: its friction and
  // a conducting tool; any other set with the preset's friction (0.35) and an adiabatic tool.
  std::optional<double> friction;
  std::optional<double> friction_heat_share;  // none: the preset's (all frictional heat into the workpiece)
  std::optional<double> tool_heat_transfer_coefficient, tool_conductivity;
  std::optional<double> tool_temperature;  // none: the workpiece's initial temperature
  std::optional<double> tool_volumetric_heat_capacity;  // none: a steady tool
  std::string contact_detection;  // empty: the preset's (penalty contact)
  std::string volumetric_average;  // empty: the preset's (off)
  // --measurements: a force file of the user's in the layout of data/experiments (then the matrix is its rows, without
  // the chip-type conditions); empty: the built-in Klippel et al. file and the chip-type conditions.
  std::string measurements;
  // --chip-observations: observed chip types in the layout of data/experiments/ti64_chip_morphology.csv, simulated
  // and compared beside the forces; empty: the built-in statements with the built-in force data, none with a user's.
  std::string chip_observations;
};

// The measurements the conditions come from: forces from the user's file or the built-in one, and chip types from
// the user's file, the built-in one, or none.
struct ForceData {
  DataFile file;
  std::string source;  // what the report's source column says
  bool builtin = true;
  std::optional<DataFile> chip_file;  // none: no chip-type conditions
  bool chips_builtin = true;
};

// One condition of the matrix: what the run is for, which measurement it is compared with, and its result.
struct Condition : CuttingCondition {
  std::optional<MeasuredForces> measured;   // force conditions; forces per mm of width (MeasuredForces::per_mm_of_width)
  std::optional<ChipObservation> chip;      // chip conditions: the observation (ti64_chip_morphology.csv layout)
  std::string case_text;
  bool selected = false;                    // run by this invocation
  // "this run" | "earlier run" (complete in --out, same scene) | "record" (complete in --records, same scene) |
  // "" (not reported)
  std::string origin;
  CaseResult result;

  bool complete() const { return !origin.empty() && result.status == "complete"; }
  double speed_m_per_min() const { return speed_m_per_s * 60.0; }
  std::optional<double> fc() const { return result.cutting_force_N_per_mm; }
  std::optional<double> ft() const { return result.thrust_force_N_per_mm; }
  std::optional<double> ratio() const {
    return fc() && ft() && *fc() != 0.0 ? std::optional<double>(*ft() / *fc()) : std::nullopt;
  }
  // Simulated chip thickness t_c = t0 / r, um.
  std::optional<double> chip_thickness_um() const { return thickness_um(result.chip_thickness_ratio); }
  // The same by area (t_A = t0 / r_A, docs/analysis.md), um.
  std::optional<double> chip_thickness_by_area_um() const { return thickness_um(result.chip_thickness_ratio_from_area); }
  std::optional<double> thickness_um(const std::optional<double>& r) const {
    return r && *r > 0.0 ? std::optional<double>(h_mm * 1e3 / *r) : std::nullopt;
  }
  // A complete force condition with both forces: the ones the errors and goals are computed over.
  bool compared() const { return kind == "forces" && complete() && fc() && ft(); }
  // Cells of the run across the thermal length sqrt(kappa t0 / V) (cutting/cutting_resolution.hpp), the width scale
  // of its shear bands; none without a cell size.
  std::optional<double> cells_per_thermal_length(double kappa) const;
};

// The thickness the report's Fc(h) ratios refer to, mm.
constexpr double kReferenceH_mm = 0.1;

// The data of the options: --measurements or the built-in force file; --chip-observations, the built-in chip file
// (with the built-in forces) or none. InputError for an unreadable file.
ForceData force_data(const Options& o);

// What every case runs with: resolution rule, material (a library set or --material-file's, with --material-key
// changes), friction, the tool's heat and the contact detection. InputError for a bad set, file or key.
ConditionRunSettings run_settings(const Options& o);

// Every condition of the force data (all rows, every status) and the chip-type rows that name a speed to simulate,
// each with its case text. InputError for two rows of one condition or a bad chip-type row.
std::vector<Condition> matrix_conditions(const ConditionRunSettings& settings, const ForceData& data);

// Marks the conditions this invocation runs (Condition::selected). Filters given together must all match; a
// filter value that matches nothing is an InputError, so that a typing error does not silently run less.
void select_conditions(std::vector<Condition>& all, const Options& o);

// The resolution rule in words, for --list and the report.
std::string resolution_text(const Options& o);

bool same_h(double a, double b);
bool same_speed(double a, double b);
// A warning when the built-in Ti-6Al-4V data are compared with a set that is not a library Ti-6Al-4V one ("" else).
std::string material_data_mismatch(const ConditionRunSettings& s, const ForceData& data);

// Conditions cut with the same tool (as far as the measurements give it: angles, and the edge radius where the
// file's tools differ in it).
bool same_tool(const Condition& a, const Condition& b);
// The tool of a condition as the measurements give it ("" where they give none): its angles, and its edge radius
// where the file's tools differ in it (unless with_edge_radius is false: a text that names r_n anyway).
std::string tool_text(const Condition& c, bool with_edge_radius = true);

std::string join(const std::vector<std::string>& parts, const std::string& sep);

}  // namespace mpmcut::validation
