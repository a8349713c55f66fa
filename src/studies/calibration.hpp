#pragma once
// `mpmcut calibrate CONFIG.toml`: fits free material parameters (and the tool friction) to measured
// cutting forces and chip thicknesses with NLopt, each evaluation a set of cutting runs of the measured
// conditions (studies/measured_conditions.hpp, the path `mpmcut validate` uses). docs/calibration.md
// describes the configuration and the outputs.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "studies/measured_conditions.hpp"
#include "studies/progress_interval.hpp"

namespace mpmcut {

struct CalibrationParameter {
  std::string name;         // a numeric [[material]] key, or "friction" (the [cutting] Coulomb coefficient)
  double min = 0, max = 0;  // bounds, in the key's unit
  double start = 0;         // the base set's value unless given
  bool log_scale = false;   // searched uniformly in log(value) (bounds > 0)
  std::string location;     // "config.toml:12:1" for messages
  std::string unit;         // the key's unit, e.g. "Pa" (io/material_keys.hpp); empty for a ratio and for friction
};

// A parameter's value at the optimizer's variable u in [0, 1] (uniform, or uniform in log for log_scale), and back.
// At the u of its start value the value is the start value exactly: the log-scale round trip changes the last bit
// (0.035 came back as 0.034999999999999996), and a serrated cut turns such a difference into a different force.
double parameter_value(const CalibrationParameter& p, double u);
double parameter_unit(const CalibrationParameter& p, double value);

struct CalibrationConfig {
  std::filesystem::path file;
  std::string set_name;          // name of the resulting [[material]] set
  std::string base_material;     // library set the other keys come from
  std::vector<CalibrationParameter> parameters;

  std::string measurements_source;  // the data file as named in the config (or the built-in path)
  std::vector<MeasuredForces> training, held_back;

  double weight_fc = 1.0, weight_ft = 1.0, weight_chip_thickness = 0.0;
  double width_of_cut_mm = 1.0;  // ASSUMED width of cut: measured N -> N/mm

  std::string global_algorithm = "GN_CRS2_LM";  // NLopt name without "NLOPT_", or "none"
  std::string local_algorithm = "LN_BOBYQA";    // NLopt name, or "none"
  int evaluations = 40;          // total budget (both stages)
  int global_evaluations = 20;   // of which the global stage
  unsigned seed = 1;             // NLopt's random seed (CRS2, ISRES, MLSL)

  ConditionRunSettings runs;     // resolution (quick / cells_per_feed), base material, friction
  // A condition's own cells across t0 (its `cells_per_feed` in the training or held-back list), by its line in the
  // measurement file; the others run at runs.cells_per_feed. A fast cut resolves its shear bands only at finer
  // cells than a slow one (docs/results/low_speed_chip), so one value for all would be either wasteful or coarse.
  std::map<int, int> cells_per_feed_by_line;
  int threads = 1;               // OpenMP threads of each run
};

// Reads and checks the configuration: every error (unknown parameter, bounds that exclude the start value,
// bounds outside the material's valid range, an empty training set, a measurement file with missing columns
// or a condition not in it) is an InputError naming the file, line and key, before anything runs.
// `builtin_forces_csv` is the text of data/experiments/ti64_klippel2024_orthogonal_forces.csv, used when
// the config names no measurement file of its own.
CalibrationConfig read_calibration_config(const std::filesystem::path& file, std::string_view builtin_forces_csv);

// The path of the built-in measurements, as a config names it.
constexpr const char* kBuiltinForcesFile = "data/experiments/ti64_klippel2024_orthogonal_forces.csv";

// The run settings of one condition: `runs` with the condition's own cells_per_feed where it has one.
ConditionRunSettings condition_run_settings(const CalibrationConfig& config, const MeasuredForces& condition);

// Runs (or resumes) the calibration into `out`: evaluations.csv, best_material.toml, calibration.md,
// calibration_best.csv, cache.jsonl, evaluations/. Returns 0, 1 (the best set's held-back runs failed),
// or 130 (interrupted: run the same command again to resume). progress_interval_s: how often a line on the running
// runs' progress is printed (0: only as each run ends).
int run_calibration(const CalibrationConfig& config, const std::filesystem::path& out, int jobs,
                    double progress_interval_s = kDefaultProgressIntervalS);

}  // namespace mpmcut
