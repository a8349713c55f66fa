#pragma once
// summary.json as a struct: the run writes it through to_json() and everything that reads a
// result directory (sweep, validate, calibrate, Python) reads it through summary_from_json(), so
// that a key has one spelling (docs/outputs.md, "summary.json"). The sections that observers add
// (the cutting process, the chip analysis, the fracture accounting, ...) are carried as JSON in
// `sections`; the headline values the studies compare have typed readers below.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/tensor.hpp"
#include "cutting/cutting_parameters.hpp"
#include "io/json_summary.hpp"

namespace mpmcut {

class Simulation;

// The energy ledger at the end, J per m of thickness (docs/cutting.md, "Energy balance").
struct EnergySummary {
  double initial = 0.0, kinetic = 0.0, elastic = 0.0, plastic_work = 0.0, heat = 0.0, damage_dissipation = 0.0,
         friction_work = 0.0, viscous_dissipation = 0.0, external_work = 0.0, transfer_dissipation = 0.0,
         contact_safeguard = 0.0, removed_energy = 0.0;
  bool operator==(const EnergySummary&) const = default;
};

struct RigidBodySummary {
  std::string name;
  Vec2 force_N_per_m = Vec2::Zero(), impulse_N_s_per_m = Vec2::Zero(), displacement_m = Vec2::Zero();
  double work_J_per_m = 0.0;
  std::optional<double> max_temperature_K;  // a conducting body's hottest cell at the end; none for the others
  bool operator==(const RigidBodySummary&) const = default;
};

struct RunSummary {
  std::string status;  // run_status: running, complete, failed, interrupted
  std::string message;  // why it failed or how to continue; empty: none
  std::string mpmcut_version, title, case_file;
  std::string source_revision;  // git revision of the program that wrote the summary (run/source_revision.hpp)
  // The model version of the run's scene (solver/model_version.hpp); 0 in summaries written before it was counted.
  int model_version = 0;
  std::uint64_t particles = 0, grid_nodes = 0;
  double cell_size_m = 0.0;
  long steps = 0;
  double simulated_time_s = 0.0, end_time_s = 0.0, wall_time_s = 0.0;
  int threads = 0;
  double particle_steps_per_s = 0.0;
  EnergySummary energy_J_per_m;
  double energy_residual_J_per_m = 0.0, energy_relative_residual = 0.0;
  double max_temperature_K = 0.0;
  std::vector<RigidBodySummary> rigid_bodies;
  std::optional<std::uint64_t> removed_particles;
  std::optional<double> removed_mass_kg_per_m;
  std::string last_checkpoint, resumed_from;  // "checkpoints/<file>"; empty: none
  // Mean tool forces over the steady window (cutting runs; none when the run ended before it).
  std::optional<double> mean_cutting_force_N_per_mm, mean_thrust_force_N_per_mm;
  // Everything else, by key: mass_scaling, cutting, chip, temperature, fracture, rake_face,
  // steady_window, thread_tuning, ... (and keys a newer version wrote).
  nlohmann::json sections = nlohmann::json::object();

  bool is_cutting_run() const { return sections.contains("cutting"); }
};

// The part of the summary the run itself knows from the simulation state (`cutting`: the process
// of a cut, cutting/case.hpp).
RunSummary summarize(const Simulation& sim, const std::optional<CuttingParameters>& cutting, const std::string& status,
                     double wall_s, const std::string& message, int threads);

// The energy balance's residual beyond which a run's numbers are suspect: the time integration's own error is
// about 0.5-1 % of the energy in (docs/cutting.md, "Energy balance"); of 252 committed runs one exceeds 5 %.
inline constexpr double kEnergyResidualWarning = 0.05;
// A warning when |relative residual| > kEnergyResidualWarning ("" otherwise): summary.json's
// energy_balance.warning and a console line at the end of the run.
std::string energy_residual_warning(double relative_residual);

nlohmann::json to_json(const RunSummary& s);
// Throws std::runtime_error naming the key when a typed key has the wrong type.
// The summary of a run whose simulation is still being set up (status running, no step yet): written as soon as its
// result directory exists, so that a stop during set-up leaves a directory that says it is not complete and that
// --force and --keep-complete may replace.
RunSummary summary_before_setup(const std::string& title, const std::string& case_file, int threads);
RunSummary summary_from_json(const nlohmann::json& j);

void write_summary(const std::filesystem::path& file, const RunSummary& s);  // atomically
RunSummary read_summary(const std::filesystem::path& file);  // throws std::runtime_error naming the path

// Headline values of the observers' sections, for the studies' tables.
struct ChipHeadline {
  std::string classification;  // empty: no chip analysis
  std::string classification_confidence;  // "clear" | "marginal" (at a threshold) | "" (not recorded)
  std::optional<double> segmentation_degree, pitch_m, segmentation_frequency_Hz, chip_thickness_ratio;
  std::optional<double> chip_thickness_ratio_from_area;  // t0 / t_A (chip thickness by area; not in older summaries)
  // "chip_over_time": Gs over the steady window's states, mean, min, max (not in older summaries)
  std::optional<double> segmentation_degree_mean, segmentation_degree_min, segmentation_degree_max;
  std::optional<double> shear_zone_max_K, tool_chip_max_K;  // "temperature" section
};
ChipHeadline chip_headline(const RunSummary& s);
std::optional<double> mass_scaling_factor(const RunSummary& s);
// tool_heat.steady_window_share_of_tool_work: the heat into the tool over the steady window / the tool's work.
std::optional<double> tool_heat_share(const RunSummary& s);
// The steady-window tool force split into the flat rake face's part (rake_face: normal and friction force)
// and the rest, carried by the edge arc and the flank, in the cutting and thrust directions; N/mm. From
// rake_face, cutting.rake_angle_deg and the mean forces, so that summaries written before edge_and_flank
// give it too. None where a part is missing.
struct ToolForceSplit {
  std::optional<double> rake_normal_N_per_mm, rake_friction_N_per_mm;
  std::optional<double> edge_flank_cutting_N_per_mm, edge_flank_thrust_N_per_mm;
  // Frictional work per unit tool travel on the rake face and on the rest of the tool (N/mm), and the
  // rake face's friction-force-weighted slip speed (m/s); none in summaries written before them.
  std::optional<double> rake_friction_work_N_per_mm, edge_flank_friction_work_N_per_mm, rake_slip_speed_m_per_s;
  // The edge arc's and the flank's thrust from the contacts' normal push and from their friction (N/mm); none
  // in summaries written before edge_and_flank had edge_arc and flank.
  std::optional<double> edge_arc_normal_thrust_N_per_mm, edge_arc_friction_thrust_N_per_mm;
  std::optional<double> flank_normal_thrust_N_per_mm, flank_friction_thrust_N_per_mm;
};
ToolForceSplit tool_force_split(const RunSummary& s);
// steady_window.drift: the second half's mean force minus the first half's, % of the mean (Fc, Ft).
std::optional<double> steady_drift_percent(const RunSummary& s, const char* force /* "cutting" | "thrust" */);

}  // namespace mpmcut
