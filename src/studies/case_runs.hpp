#pragma once
// The runs of a study (sweep, validate, calibrate): each one a separate process of this same program,
// `mpmcut run CASE --out DIR ...`, so that a crashing case cannot take the study down and a case runs
// exactly as it would on its own. Here: the local process pool and the reading of a run's results;
// studies/task_farm.hpp hands the same runs to MPI ranks instead when started under mpirun/srun.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "run/run_summary.hpp"
#include "studies/progress_interval.hpp"

namespace mpmcut {

// One child run: `mpmcut <args...>`, stdout and stderr into log_file.
struct ChildRun {
  std::string name;                 // for progress lines, e.g. "v20mps_h0.1mm"
  std::vector<std::string> args;    // after the program name, e.g. {"run", "case.toml", "--out", ...}
  std::filesystem::path log_file;
  int exit_code = -1;               // -1: not run (interrupted before it started)
  double wall_time_s = 0.0;
  // Called once the child has ended (exit_code set), in the study's process: e.g. to keep a record of a
  // complete run at once rather than at the end of a study that may be interrupted.
  std::function<void(const ChildRun&)> on_finished;
};

// What the console says of a finished case: "complete", "interrupted", "failed (exit status 1)"... A stop that
// reached a case after its last step (exit 130) leaves its results complete (docs/reliability.md, "Signals"):
// then "complete (the stop came after its last step)", as its summary and the study's table say.
std::string finished_case_text(const ChildRun& run);

// Runs the children, at most `jobs` at a time, each as /proc/self/exe in its own process group: the
// program the study was started as, even if its file is replaced (rebuilt) while the study runs.
// SIGINT/SIGTERM to this process are passed on once to the running children (which checkpoint and stop);
// a second one kills them. Returns false if interrupted (children not started keep exit_code -1).
bool run_children(std::vector<ChildRun>& runs, int jobs, bool print_progress,
                  double progress_interval_s = kDefaultProgressIntervalS);

// The headline results of one run directory, as far as summary.json (and forces.csv) give them.
struct CaseResult {
  std::string status;               // summary.json status, or "failed" / "not run"
  std::string message;              // why it failed (summary message or the end of the log)
  std::string source_revision;      // of the program that wrote summary.json; "unrecorded" before it was recorded
  std::optional<double> cutting_force_N_per_mm, thrust_force_N_per_mm;
  std::string force_basis;          // "steady window" | "last half of the cut (no steady window)" | ""
  // Second half of the steady window's mean minus the first half's, % of the mean (a drifting cut).
  std::optional<double> cutting_force_drift_percent, thrust_force_drift_percent;
  std::optional<double> max_temperature_K;
  std::optional<double> tool_heat_share;  // summary.json tool_heat: heat into the tool / tool's work, steady window
  std::optional<double> shear_zone_max_K, tool_chip_max_K;  // summary.json "temperature" (mpmcut analyze)
  std::string chip_classification;  // from summary.json "chip" (mpmcut analyze); blank if absent
  std::string chip_classification_confidence;  // "clear" | "marginal" (at a threshold) | blank
  std::optional<double> segmentation_degree, pitch_um, frequency_kHz;
  std::optional<double> chip_thickness_ratio;  // r = t0 / t_c from the chip analysis
  std::optional<double> chip_thickness_ratio_from_area;  // t0 / t_A, the chip's thickness by area (docs/analysis.md)
  std::optional<double> segmentation_degree_mean, segmentation_degree_min, segmentation_degree_max;  // over time
  std::optional<double> wall_time_s;
  std::optional<double> steps;                           // explicit steps the run took
  std::optional<double> core_seconds_per_particle_step;  // threads / particle_steps_per_s (whole wall time)
  std::optional<double> cell_size_um, mass_scaling_factor;
  ToolForceSplit tool_force_split;  // rake face (normal, friction) and the rest, edge arc + flank (N/mm)
  // Energy ledger at the end (summary.json energy_J_per_m): the tool's work and where it went; the
  // numerical part is the rest: FLIP/PIC transfer dissipation, removed particles, the contact safeguard, the residual.
  std::optional<double> tool_work_J_per_m, plastic_work_J_per_m, damage_J_per_m, friction_J_per_m,
      kinetic_elastic_J_per_m, numerical_J_per_m;
};

// Reads summary.json of `dir` (and forces.csv for the fallback mean: when the run ended before its steady
// window, the mean of the raw forces over the last half of the tool travel). `log_file` and `exit_code`
// explain a missing or failed summary. A run that did not complete gets no forces (a partial cut's means
// would read as results); its message says so.
CaseResult read_case_result(const std::filesystem::path& dir, const std::filesystem::path& log_file, int exit_code);

// A table of text cells written as CSV (cells with commas or quotes quoted) and as Markdown.
struct TextTable {
  std::vector<std::string> columns;               // CSV header: machine names with units (write_csv)
  std::vector<std::string> headings;              // Markdown header: for people (markdown; empty: the columns)
  std::vector<std::vector<std::string>> rows;
  void write_csv(const std::filesystem::path& file) const;
  std::string markdown() const;
};

// Short number text for tables: "" for none, else up to `digits` significant digits.
std::string format_number(const std::optional<double>& x, int digits = 4);

}  // namespace mpmcut
