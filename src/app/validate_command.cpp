#include "app/validate_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "analysis/chip_analysis.hpp"
#include "cutting/cutting_forces.hpp"
#include "cutting/cutting_resolution.hpp"
#include "app/plot_command.hpp"
#include "run/run_case.hpp"
#include "app/sweep_command.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/material_library.hpp"
#include "io/scene_writer.hpp"
#include "run/case_loading.hpp"
#include "run/run_summary.hpp"
#include "studies/measured_conditions.hpp"
#include "studies/run_records.hpp"
#include "studies/task_farm.hpp"
#include "studies/validation_metrics.hpp"

namespace mpmcut {

namespace {

namespace fs = std::filesystem;

constexpr const char* kForcesFile = "data/experiments/ti64_klippel2024_orthogonal_forces.csv";
constexpr const char* kChipFile = "data/experiments/ti64_chip_morphology.csv";
constexpr const char* kForcesSource =
    "Klippel et al., Int. J. Adv. Manuf. Technol. 135 (2024) 2871-2908, per-test data file [V]";

// Goals of the validation (issue 11): what the model should reach on the measured matrix without a
// parameter tuned per condition.
constexpr double kGoalRatioError = 0.15;      // Ft/Fc within +-15 % at every condition
constexpr double kGoalThicknessError = 0.10;  // Fc(h)/Fc(0.1 mm) within +-10 %
constexpr double kGoalMeanFcError = 0.15;     // mean |dFc| / Fc < 15 % (b = 1 mm assumed)
constexpr double kReferenceH_mm = 0.1;        // the thickness of the Fc(h) ratios

// --quick without a selection: a trend at one h (0.04 mm at 100 and 400.1 m/min), a thickness ratio
// (0.04 / 0.1 mm at 100 m/min) and the chip-type conditions: every part of the report, in seconds.
const std::vector<std::string>& quick_condition_ids() {
  static const std::vector<std::string> ids{"forces_h0.04mm_vc100mpmin", "forces_h0.04mm_vc400.1mpmin",
                                            "forces_h0.1mm_vc100mpmin", "chip_sutter_list_2013_low_v5mps",
                                            "chip_sutter_list_2013_high_v75mps"};
  return ids;
}

double num(const std::map<std::string, std::string>& row, const std::string& key) {
  const auto it = row.find(key);
  return it == row.end() || it->second.empty() ? NAN : std::strtod(it->second.c_str(), nullptr);
}

// One condition of the matrix: what the run is for, which measurement it is compared with, and its result.
struct Condition : CuttingCondition {
  std::optional<MeasuredForces> measured;   // force conditions; forces per mm of width (MeasuredForces::per_mm_of_width)
  std::map<std::string, std::string> chip;  // the ti64_chip_morphology.csv row for chip conditions
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
  std::optional<double> cells_per_thermal_length(double kappa) const {
    const double l_th = thermal_length_m(kappa, h_mm * 1e-3, speed_m_per_s);
    return result.cell_size_um && l_th > 0.0 ? std::optional<double>(l_th / (*result.cell_size_um * 1e-6))
                                             : std::nullopt;
  }
};

struct ValidateOptions {
  bool quick = false;
  int cells_per_feed = 10;            // N: cell <= t0 / N (the cutting preset's t0/10)
  double cells_per_edge_radius = 4.0; // M: cell <= r_n / M
  double cells_per_thermal_length = 0.0;  // K: cell <= sqrt(kappa t0 / V) / K; 0 = no such limit
  std::string out_dir;
  std::string records_dir;  // --records: complete runs kept as small committed files (studies/run_records.hpp)
  int jobs = 0;
  int threads = 1;
  bool no_plots = false;
  bool list = false;
  std::vector<double> h_mm, speeds_m_per_min;
  std::vector<std::string> condition_ids;
  std::string material;         // a library set or one of material_file; empty: the default (ti64-cutting)
  std::string material_file;    // --material-file: [[material]] sets that --material may name
  std::vector<std::string> material_keys;  // --material-key KEY=VALUE: numeric keys changed from that set
  std::optional<double> friction;  // Coulomb coefficient; none: the default (0.35)
  std::optional<double> friction_heat_share;  // none: the preset's (all frictional heat into the workpiece)
  std::optional<double> tool_heat_transfer_coefficient, tool_temperature;  // none: an adiabatic tool
  std::string contact_detection;  // empty: the preset's (node detection)
  // --measurements: a force file of the user's in the layout of data/experiments (then the matrix is its rows, without
  // the chip-type conditions); empty: the built-in Klippel et al. file and the chip-type conditions.
  std::string measurements;
};

// The force measurements the conditions come from: the user's file or the built-in one.
struct ForceData {
  DataFile file;
  std::string source;  // what the report's source column says
  bool builtin = true;
};

ForceData force_data(const ValidateOptions& o) {
  if (o.measurements.empty())
    return {read_data_file(embedded_tool_file(kForcesFile), kForcesFile), kForcesSource, true};
  std::ifstream in(o.measurements, std::ios::binary);
  if (!in) throw InputError(fmt::format("--measurements {}: cannot read the file", o.measurements));
  std::stringstream text;
  text << in.rdbuf();
  return {read_data_file(text.str(), o.measurements), o.measurements + " (--measurements)", false};
}

std::string join(const std::vector<std::string>& parts, const std::string& sep) {
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : sep) + p;
  return out;
}

// The material of the runs: a library set, or a set of --material-file (read and checked here, so that a broken
// file stops the study before any run, with its file, line and key).
void choose_material(const ValidateOptions& o, ConditionRunSettings& s) {
  if (o.material_file.empty()) {
    if (o.material.empty()) return;
    if (!builtin_material_library().find(o.material))
      throw InputError(fmt::format("--material {}: no such set; the library has: {}", o.material,
                                   join(builtin_material_library().names(), ", ")));
    s.material = o.material;
    s.material_note = "chosen with --material; docs/materials.md";
    return;
  }
  std::ifstream in(o.material_file, std::ios::binary);
  if (!in) throw InputError(fmt::format("--material-file {}: cannot read the file", o.material_file));
  std::ostringstream text;
  text << in.rdbuf();
  MaterialLibrary with_builtin = builtin_material_library();
  const std::size_t before = with_builtin.sets().size();
  with_builtin.add_file(text.str(), o.material_file);  // InputError at the file's line and key
  if (with_builtin.sets().size() == before)
    throw InputError(fmt::format("--material-file {}: no [[material]] set in the file", o.material_file));
  std::vector<std::string> names;
  for (std::size_t i = before; i < with_builtin.sets().size(); ++i) names.push_back(with_builtin.sets()[i].name);
  std::string name = o.material;
  if (name.empty() && names.size() == 1) name = names.front();
  if (name.empty())
    throw InputError(fmt::format("--material-file {} has {} sets ({}): name one with --material", o.material_file,
                                 names.size(), join(names, ", ")));
  if (!with_builtin.find(name))
    throw InputError(fmt::format("--material {}: no such set in {} ({}) or the library ({})", name, o.material_file,
                                 join(names, ", "), join(builtin_material_library().names(), ", ")));
  s.material = name;
  s.material_definitions = text.str();
  s.material_note = fmt::format("from --material-file {}", o.material_file);
}

ConditionRunSettings run_settings(const ValidateOptions& o) {
  ConditionRunSettings s;
  s.quick = o.quick;
  s.cells_per_feed = o.cells_per_feed;
  s.cells_per_edge_radius = o.cells_per_edge_radius;
  s.cells_per_thermal_length = o.cells_per_thermal_length;
  choose_material(o, s);
  for (const std::string& assignment : o.material_keys) {
    const auto eq = assignment.find('=');
    const std::string key = eq == std::string::npos ? std::string() : assignment.substr(0, eq);
    const std::string text = eq == std::string::npos ? std::string() : assignment.substr(eq + 1);
    char* end = nullptr;
    const double value = text.empty() ? NAN : std::strtod(text.c_str(), &end);
    if (key.empty() || !std::isfinite(value) || end == nullptr || *end != '\0')
      throw InputError(fmt::format("--material-key '{}': expected KEY=VALUE with a finite number, e.g. jc_C=0.035",
                                   assignment));
    s.material_overrides.emplace_back(key, value);
  }
  if (o.friction) {
    s.friction = *o.friction;
    s.friction_note = "chosen with --friction";
  }
  s.friction_heat_share = o.friction_heat_share;
  s.tool_heat_transfer_coefficient = o.tool_heat_transfer_coefficient;
  s.tool_temperature = o.tool_temperature;
  s.contact_detection = o.contact_detection;
  return s;
}

// "jc_C = 0.035, damage_d1 = 0.1": the keys --material-key changed.
std::string changed_keys_text(const ConditionRunSettings& s) {
  std::string out;
  for (const auto& [key, value] : s.material_overrides) out += (out.empty() ? "" : ", ") + fmt::format("{} = {:g}", key, value);
  return out;
}

std::string pct(std::optional<double> relative) {
  return relative ? fmt::format("{:+.1f}", 100.0 * *relative) : std::string();
}

std::string within(std::optional<double> sim, double lo, double hi) {
  if (!sim) return "";
  return (*sim >= lo && *sim <= hi) ? "yes" : (*sim < lo ? "below" : "above");
}

std::string g4(double x) { return std::isfinite(x) ? fmt::format("{:.4g}", x) : std::string(); }

std::optional<double> melting_temperature(const fs::path& dir) {
  try {
    const toml::table t = toml::parse_file((dir / "scene.toml").string());
    if (auto v = t["material"][0]["melting_temperature"].value<double>()) return *v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

// Every condition of data/experiments: all rows of the force file (every status) and the chip-type rows
// that name a speed to simulate; with a user's force file, its rows only.
std::vector<Condition> matrix_conditions(const ConditionRunSettings& settings, const ForceData& data) {
  std::vector<Condition> conditions;
  std::map<std::string, int> line_of_id;
  for (const MeasuredForces& m : read_measured_forces(data.file)) {
    Condition c;
    static_cast<CuttingCondition&>(c) = force_condition(m);
    // Forces per mm of width from here on: the file's width, or b = 1 mm ASSUMED (the simulated cut is 1 mm wide).
    c.measured = m.per_mm_of_width(1.0);
    if (const auto [it, added] = line_of_id.emplace(c.id, m.line); !added)
      throw InputError(fmt::format("{}:{}: the condition {} is on line {} already (one row per h, speed and tool "
                                   "angles: rows of repeated tests are averaged into one, as in the data files)",
                                   data.file.source, m.line, c.id, it->second));
    conditions.push_back(c);
  }
  for (const DataFile::Row& row : data.builtin ? read_data_file(embedded_tool_file(kChipFile), kChipFile).rows
                                               : std::vector<DataFile::Row>{}) {
    const auto& r = row.cells;
    const double v = num(r, "simulate_speed_m_per_s");
    if (!std::isfinite(v)) continue;
    Condition c;
    c.id = fmt::format("chip_{}_v{:g}mps", r.at("id"), v);
    c.kind = "chip";
    c.speed_m_per_s = v;
    c.h_mm = 0.1;  // the lower end of the source's h range, as in the force data
    c.edge_radius_um = 5.0;
    c.chip = r;
    conditions.push_back(c);
  }
  for (Condition& c : conditions) c.case_text = condition_case_text(c, settings);
  return conditions;
}

bool same_h(double a, double b) { return std::abs(a - b) <= 1e-9; }
bool same_speed(double a, double b) { return std::abs(a - b) <= 1e-6 * std::max(1.0, std::abs(b)); }

// Marks the conditions this invocation runs. Filters given together must all match (--h 0.1 --speeds-m-per-min
// 100 is one condition); a filter value that matches nothing in the matrix is an error, so that a typing error
// does not silently run less.
void select_conditions(std::vector<Condition>& all, const ValidateOptions& o) {
  const bool filtered = !o.h_mm.empty() || !o.speeds_m_per_min.empty() || !o.condition_ids.empty();
  const auto available = [&](auto value_of) {
    std::set<std::string> seen;
    std::vector<std::string> list;
    for (const Condition& c : all)
      if (seen.insert(value_of(c)).second) list.push_back(value_of(c));
    return join(list, ", ");
  };
  for (double h : o.h_mm)
    if (std::none_of(all.begin(), all.end(), [&](const Condition& c) { return same_h(c.h_mm, h); }))
      throw InputError(fmt::format("--h {:g}: no condition of the matrix has h = {:g} mm (it has h = {} mm)", h, h,
                                   available([](const Condition& c) { return fmt::format("{:g}", c.h_mm); })));
  for (double v : o.speeds_m_per_min)
    if (std::none_of(all.begin(), all.end(), [&](const Condition& c) { return same_speed(c.speed_m_per_min(), v); }))
      throw InputError(fmt::format("--speeds-m-per-min {:g}: no condition of the matrix has vc = {:g} m/min (it has {} "
                                   "m/min)",
                                   v, v, available([](const Condition& c) { return fmt::format("{:g}", c.speed_m_per_min()); })));
  for (const std::string& id : o.condition_ids)
    if (std::none_of(all.begin(), all.end(), [&](const Condition& c) { return c.id == id; }))
      throw InputError(fmt::format("--conditions {}: no such condition (`mpmcut validate --list` names them)", id));
  for (Condition& c : all) {
    if (!filtered) {
      const auto& quick = quick_condition_ids();
      c.selected = !o.quick || !o.measurements.empty() || std::find(quick.begin(), quick.end(), c.id) != quick.end();
      continue;
    }
    c.selected =
        (o.h_mm.empty() || std::any_of(o.h_mm.begin(), o.h_mm.end(), [&](double h) { return same_h(c.h_mm, h); })) &&
        (o.speeds_m_per_min.empty() || std::any_of(o.speeds_m_per_min.begin(), o.speeds_m_per_min.end(),
                                                   [&](double v) { return same_speed(c.speed_m_per_min(), v); })) &&
        (o.condition_ids.empty() || std::find(o.condition_ids.begin(), o.condition_ids.end(), c.id) != o.condition_ids.end());
  }
  if (std::none_of(all.begin(), all.end(), [](const Condition& c) { return c.selected; }))
    throw InputError("the selection (--h, --speeds-m-per-min, --conditions together) matches no condition of the matrix");
}

Case condition_case(const Condition& c, const fs::path& case_file) { return parse_case(c.case_text, case_file.string()); }

std::string resolution_text(const ValidateOptions& o) {
  if (o.quick) return "--quick: cell = t0/4, 1 particle per cell, 4 cells of tool travel (a pipeline check)";
  const std::string thermal =
      o.cells_per_thermal_length > 0.0
          ? fmt::format(" and at most l_th/K with K = {:g} cells across the thermal length l_th = sqrt(κ t0/V) "
                        "(--cells-per-thermal-length; κ the workpiece's thermal diffusivity, V the cutting speed; "
                        "every condition)",
                        o.cells_per_thermal_length)
          : std::string();
  return fmt::format(
      "cell = min(t0/N, r_n/M) with N = {} cells across the uncut chip thickness t0 (--cells-per-feed) and M = {:g} "
      "cells across the measured edge radius r_n (--cells-per-edge-radius; force conditions){}, 2×2 particles per "
      "cell{}. Tool travel 6·max(t0, r_n) (the steady window, after "
      "max(40 % of the cut, 3 t0), is then at least 3 t0 long); workpiece height t0 + max(3 t0, 2 r_n), rounded up "
      "by the preset so that the machined surface lies on a row of grid nodes (docs/cutting.md, \"Grid phase of the "
      "tool tip\")",
      o.cells_per_feed, o.cells_per_edge_radius, thermal,
      o.measurements.empty()  // with a user's file there are no chip-type conditions
          ? fmt::format("; chip-type conditions at t0/{} (the least the chip analysis needs to resolve segments; their "
                        "5 µm edge is the preset's, not measured, and sets no limit)",
                        chip_cells_per_feed(o.cells_per_feed))
          : std::string());
}

// --list: the selected conditions with their resolution and estimated cost; writes their case files.
int list_conditions(const std::vector<Condition>& conditions, const fs::path& out, const ValidateOptions& o) {
  fs::create_directories(out / "cases");
  std::cout << fmt::format("Resolution: {}.\n", resolution_text(o));
  std::cout << fmt::format("{:<36} {:>6} {:>6} {:>8} {:>6} {:>10} {:>7} {:>7} {:>7} {:>6} {:>9} {:>10} {:>9} {:>9}  {}\n",
                           "condition", "kind", "h_mm", "vc_m/min", "r_n_um", "status", "cell_um", "cut_mm", "cells/t0",
                           "f_mass", "particles", "steps", "Gpart·st", "core_h", "in OUT");
  double total_particle_steps = 0, total_to_run = 0;
  int n = 0, complete = 0;
  std::vector<RunCostObservation> observed;  // what the complete ones took against their estimate
  for (const Condition& c : conditions) {
    if (!c.selected) continue;
    const fs::path case_file = out / "cases" / (c.id + ".toml");
    write_file_atomically(case_file, [&](std::ostream& s) { s << c.case_text; });
    const Case condition = condition_case(c, case_file);
    const RunCost cost = estimate_run_cost(condition.scene);
    ExistingRun existing = existing_run(out / c.id, condition);
    const bool recorded = existing != ExistingRun::Complete && !o.records_dir.empty() &&
                          existing_run(fs::path(o.records_dir) / c.id, condition) == ExistingRun::Complete;
    if (recorded) existing = ExistingRun::Complete;
    const char* state = recorded ? "record" : existing == ExistingRun::Complete ? "complete"
                        : existing == ExistingRun::Resumable ? "resumable" : "-";
    const double ps = cost.particle_steps();
    total_particle_steps += ps;
    if (existing != ExistingRun::Complete) total_to_run += ps;
    complete += existing == ExistingRun::Complete;
    if (existing == ExistingRun::Complete) {
      const CaseResult done = read_case_result(recorded ? fs::path(o.records_dir) / c.id : out / c.id, {}, 0);
      if (done.steps && done.core_seconds_per_particle_step)
        observed.push_back({cost.steps, *done.steps, *done.core_seconds_per_particle_step});
    }
    ++n;
    const auto& cut = *condition.cutting;
    std::cout << fmt::format("{:<36} {:>6} {:>6g} {:>8g} {:>6g} {:>10} {:>7.3g} {:>7.3g} {:>7.3g} {:>6.3g} {:>9} {:>10.3g} "
                             "{:>9.3g} {:>9.3g}  {}\n",
                             c.id, c.kind, c.h_mm, c.speed_m_per_min(), c.edge_radius_um,
                             c.measured ? c.measured->status : std::string("-"), cut.cell_size * 1e6, cut.cut_length * 1e3,
                             cut.uncut_chip_thickness / cut.cell_size, cost.mass_scaling_factor, cost.particles, cost.steps,
                             ps * 1e-9, ps * kCoreSecondsPerParticleStep / 3600.0, state);
  }
  std::cout << fmt::format(
      "{} conditions, {} already complete in {}{}; {:.3g} G particle-steps, about {:.3g} core-hours in all, {:.3g} "
      "core-hours still to run (estimate: {:.2g} core-s per particle-step, steps at the first step's stable time step; "
      "case files in {})\n",
      n, complete, out.string(), o.records_dir.empty() ? "" : " or --records " + o.records_dir, total_particle_steps * 1e-9, total_particle_steps * kCoreSecondsPerParticleStep / 3600.0,
      total_to_run * kCoreSecondsPerParticleStep / 3600.0, kCoreSecondsPerParticleStep, (out / "cases").string());
  if (const auto fix = observed_cost_correction(observed))
    std::cout << fmt::format(
        "Corrected by the {} complete run(s) listed (steps x {:.2f} of the estimate, median; {:.2f}-{:.2f}; {:.2g} "
        "core-s per particle-step, median, on the machine and load they ran with): about {:.3g} core-hours still "
        "to run\n",
        fix->runs, fix->step_ratio, fix->step_ratio_min, fix->step_ratio_max, fix->core_seconds_per_particle_step,
        fix->core_hours(total_to_run));
  return 0;
}

// The tool's angles of a force condition as the measurements give them ("" where they give none).
std::string tool_text(const Condition& c) {
  std::string t = c.rake_deg ? fmt::format("rake {:g}°", *c.rake_deg) : "";
  if (c.clearance_deg) t += (t.empty() ? "" : ", ") + fmt::format("clearance {:g}°", *c.clearance_deg);
  return t;
}

// Conditions cut with the same tool angles (as far as the measurements give them).
bool same_tool(const Condition& a, const Condition& b) { return a.rake_deg == b.rake_deg && a.clearance_deg == b.clearance_deg; }

std::string condition_label(const Condition& c) {
  const MeasuredForces& m = *c.measured;
  const std::string tool = tool_text(c);
  return fmt::format("h = {:g} mm, vc = {:g} m/min ({:.3g} m/s), r_n = {:g} µm{}, n = {}{}", m.h_mm, m.vc_m_per_min,
                     c.speed_m_per_s, m.edge_radius_um, tool.empty() ? "" : ", " + tool, m.n_tests,
                     m.status == "ok" ? "" : ", status " + m.status);
}


// A run whose forces did not drift along the steady window by more than the run's own warning limit
// (summary.json steady_window.drift); a run without the drift (no steady window) is not steady.
bool steady(const Condition& c) {
  const auto& fc = c.result.cutting_force_drift_percent;
  const auto& ft = c.result.thrust_force_drift_percent;
  return fc && ft && std::abs(*fc) <= kSteadyDriftWarningPercent && std::abs(*ft) <= kSteadyDriftWarningPercent;
}

// One row per compared force condition: measured mean / simulated and the error of Fc, Ft, Ft/Fc and t_c.
TextTable by_condition_table(const std::vector<const Condition*>& compared) {
  TextTable t;
  t.headings = {"h (mm)", "vc (m/min)", "r_n (µm)", "Fc meas. / sim. (N/mm)", "error", "Ft meas. / sim. (N/mm)",
                "error", "Ft/Fc meas. / sim.", "error", "t_c meas. / sim. (µm)", "error", "steady"};
  // Measurements with the tool's angles: a column for them.
  const bool tools = std::any_of(compared.begin(), compared.end(), [](const Condition* c) { return !tool_text(*c).empty(); });
  if (tools) t.headings.insert(t.headings.begin() + 3, "tool");
  t.columns = t.headings;
  const auto pair = [](double measured, std::optional<double> simulated, const char* format) {
    return fmt::format(fmt::runtime(format), measured) + " / " +
           (simulated ? fmt::format(fmt::runtime(format), *simulated) : std::string("–"));
  };
  const auto err = [](double measured, std::optional<double> simulated) {
    const auto e = relative_error(simulated, measured);
    return e ? fmt::format("{:+.0f} %", 100.0 * *e) : std::string();
  };
  for (const Condition* c : compared) {
    const MeasuredForces& m = *c->measured;
    const double ratio = m.ff_N / m.fc_N, tc = m.chip_thickness_um.value_or(NAN);
    t.rows.push_back({fmt::format("{:g}", c->h_mm), fmt::format("{:g}", c->speed_m_per_min()),
                      fmt::format("{:g}", c->edge_radius_um), pair(m.fc_N, c->fc(), "{:.0f}"), err(m.fc_N, c->fc()),
                      pair(m.ff_N, c->ft(), "{:.0f}"), err(m.ff_N, c->ft()), pair(ratio, c->ratio(), "{:.2f}"),
                      err(ratio, c->ratio()), std::isfinite(tc) ? pair(tc, c->chip_thickness_um(), "{:.0f}") : "",
                      std::isfinite(tc) ? err(tc, c->chip_thickness_um()) : "", steady(*c) ? "yes" : "no"});
    if (tools) t.rows.back().insert(t.rows.back().begin() + 3, tool_text(*c));
  }
  return t;
}

// Keeps the run of condition `id` in --records if it is complete; warns where a record of another scene is there.
void record_run(const ValidateOptions& o, const fs::path& out, const std::string& id) {
  try {
    if (read_summary(out / id / "summary.json").status != "complete") return;
    if (!save_run_record(out / id, fs::path(o.records_dir) / id))
      std::cerr << fmt::format("warning: {}: the record in {} is of another scene (resolution, material or "
                               "settings); kept, not replaced by this run. Use another --records directory\n",
                               id, o.records_dir);
  } catch (const std::exception& e) {
    std::cerr << fmt::format("warning: {}: no record kept: {}\n", id, e.what());
  }
}

// Which program made the reported runs: runs kept from earlier parts or records may come from another revision.
std::string revisions_text(const std::vector<Condition>& conditions) {
  std::map<std::string, int> count;
  for (const Condition& c : conditions)
    if (c.complete()) ++count[c.result.source_revision];
  std::vector<std::string> parts;
  for (const auto& [revision, n] : count) parts.push_back(fmt::format("`{}` ({} runs)", revision, n));
  std::string text = "Source revision of the program that made the complete runs (summary.json `source_revision`): " +
                     (parts.empty() ? std::string("none") : join(parts, ", ")) + ".";
  if (count.size() > 1)
    text += " The runs come from more than one revision: where the physics changed between them, the conditions are "
            "not comparable (rerun them into a fresh --out and --records).";
  return text;
}

int run_validation(const ValidateOptions& o) {
  const fs::path out = o.out_dir.empty() ? fs::path(o.quick ? "results/validation_quick" : "results/validation")
                                         : fs::path(o.out_dir);
  const ConditionRunSettings settings = run_settings(o);
  const ForceData data = force_data(o);
  std::vector<Condition> conditions = matrix_conditions(settings, data);
  // How the measured forces became N/mm: the rows' own width of cut, or the assumed b = 1 mm.
  const auto forces = std::count_if(conditions.begin(), conditions.end(), [](const Condition& c) { return c.measured.has_value(); });
  const auto with_width = std::count_if(conditions.begin(), conditions.end(),
                                        [](const Condition& c) { return c.measured && c.measured->width_mm; });
  const std::string b_basis = with_width == 0         ? "b = 1 mm assumed"
                              : with_width == forces ? "b of the data file"
                                                     : "b of the data file, 1 mm assumed where it gives none";
  select_conditions(conditions, o);
  // A changed material key that the material rejects (unknown, out of range) stops the study before any run.
  if (!settings.material_overrides.empty()) {
    const auto first = std::find_if(conditions.begin(), conditions.end(), [](const Condition& c) { return c.selected; });
    (void)parse_case(first->case_text, "the case of " + first->id + " (--material-key)");
  }
  if (o.list) return list_conditions(conditions, out, o);
  fs::create_directories(out / "cases");
  fs::create_directories(out / "logs");

  // Complete runs of the same scene kept in --records come back into `out` and are not run again.
  if (!o.records_dir.empty()) {
    for (Condition& c : conditions) {
      const fs::path case_file = out / "cases" / (c.id + ".toml");
      if (!restore_run_record(fs::path(o.records_dir) / c.id, out / c.id, condition_case(c, case_file))) continue;
      c.selected = false;
      c.origin = "record";
    }
  }

  // The runs of this invocation; each child keeps a complete run of the same scene (--keep-complete), so a
  // rerun over a superset runs only what is new.
  std::vector<ChildRun> runs;
  std::vector<Condition*> run_of;
  for (Condition& c : conditions) {
    if (!c.selected) continue;
    const fs::path case_file = out / "cases" / (c.id + ".toml");
    write_file_atomically(case_file, [&](std::ostream& s) { s << c.case_text; });
    // Complete in `out` with the same scene: reported as an earlier run, not launched (nor counted) again.
    try {
      if (existing_run(out / c.id, condition_case(c, case_file)) == ExistingRun::Complete) {
        c.selected = false;
        c.origin = "earlier run";
        continue;
      }
    } catch (const std::exception&) {
      // An unreadable earlier result is the child's to report; it runs.
    }
    ChildRun r;
    r.name = c.id;
    r.args = {"run", case_file.string(), "--out", (out / c.id).string(), "--keep-complete", "--no-progress", "--threads",
              std::to_string(o.threads)};
    // A quick run's pictures take longer than the run and show an unconverged chip.
    if (o.quick) r.args.push_back("--no-plots");
    r.log_file = out / "logs" / (c.id + ".log");
    // A complete run is recorded as soon as it ends, so that an interrupted study keeps it.
    if (!o.records_dir.empty())
      r.on_finished = [&o, &out, id = c.id](const ChildRun& finished) {
        if (finished.exit_code == 0) record_run(o, out, id);
      };
    runs.push_back(r);
    run_of.push_back(&c);
  }
  const int jobs = o.jobs > 0 ? o.jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / o.threads);
  std::cout << fmt::format("mpmcut validate{}: {} of the {} conditions of the matrix, {}, each with --threads {}; "
                           "results in {}\n",
                           o.quick ? " --quick (coarse: 4 cells/t0, 1 particle per cell, 4 cells of travel; checks "
                                     "the pipeline, the numbers are not converged)"
                                   : "",
                           runs.size(), conditions.size(), concurrency_text(jobs), o.threads, out.string())
            << std::flush;
  const bool completed = run_cases(runs, jobs, true);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    run_of[i]->result = read_case_result(out / run_of[i]->id, runs[i].log_file, runs[i].exit_code);
    run_of[i]->origin = "this run";
  }
  // Conditions not selected now but complete in `out` from an earlier part with the same scene (the same
  // resolution rule and settings), or restored from a record, are reported too, so that a matrix run in parts
  // ends in one report.
  for (Condition& c : conditions) {
    if (c.selected) continue;
    if (c.origin.empty()) {  // neither a record nor found complete before the launch: look now
      try {
        if (existing_run(out / c.id, condition_case(c, out / "cases" / (c.id + ".toml"))) != ExistingRun::Complete)
          continue;
      } catch (const std::exception&) {
        continue;
      }
      c.origin = "earlier run";
    }
    c.result = read_case_result(out / c.id, out / "logs" / (c.id + ".log"), 0);
  }
  // Every complete run goes into --records (those of earlier parts too), so that the next part (or session) keeps it.
  if (!o.records_dir.empty())
    for (const Condition& c : conditions)
      if (c.complete() && c.origin == "earlier run") record_run(o, out, c.id);
  int reported = 0, complete = 0, failed = 0;
  for (const Condition& c : conditions) {
    reported += !c.origin.empty();
    complete += c.complete();
    failed += c.selected && !c.complete();
  }

  // The workpiece's thermal diffusivity, for the cells across each run's thermal length.
  const double kappa = workpiece_thermal_diffusivity_m2_per_s(settings);
  std::vector<std::string> unresolved_bands;  // force conditions with fewer than kResolvedCellsPerThermalLength
  for (const Condition& c : conditions)
    if (const auto n = c.cells_per_thermal_length(kappa); c.compared() && n && *n < kResolvedCellsPerThermalLength)
      unresolved_bands.push_back(fmt::format("h = {:g} mm at {:g} m/min ({:.3g})", c.h_mm, c.speed_m_per_min(), *n));

  // Per-run results, for the plots and for anyone who wants the numbers.
  TextTable runs_table;
  runs_table.columns = {"condition", "kind", "speed_m_per_s", "speed_m_per_min", "h_mm", "edge_radius_um",
                        "measured_status", "origin", "status", "cutting_force_N_per_mm", "thrust_force_N_per_mm",
                        "force_window", "Fc_drift_in_window_percent", "Ft_drift_in_window_percent",
                        "rake_normal_force_N_per_mm", "rake_friction_force_N_per_mm", "edge_flank_cutting_force_N_per_mm",
                        "edge_flank_thrust_force_N_per_mm", "rake_friction_work_per_travel_N_per_mm",
                        "edge_flank_friction_work_per_travel_N_per_mm", "rake_mean_slip_speed_m_per_s", "chip_thickness_ratio", "chip_thickness_um",
                        "chip_thickness_by_area_um", "cell_size_um", "cells_per_thermal_length", "mass_scaling_factor",
                        "max_temperature_K", "chip_classification", "segmentation_degree", "segmentation_degree_mean",
                        "segmentation_degree_min", "segmentation_degree_max", "wall_time_s", "source_revision", "result_dir", "message"};
  for (const Condition& c : conditions) {
    if (c.origin.empty()) continue;
    runs_table.rows.push_back({c.id, c.kind, fmt::format("{:g}", c.speed_m_per_s), fmt::format("{:g}", c.speed_m_per_min()),
                               fmt::format("{:g}", c.h_mm), fmt::format("{:g}", c.edge_radius_um),
                               c.measured ? c.measured->status : "", c.origin, c.result.status,
                               format_number(c.fc()), format_number(c.ft()), c.result.force_basis,
                               format_number(c.result.cutting_force_drift_percent, 2),
                               format_number(c.result.thrust_force_drift_percent, 2),
                               format_number(c.result.tool_force_split.rake_normal_N_per_mm),
                               format_number(c.result.tool_force_split.rake_friction_N_per_mm),
                               format_number(c.result.tool_force_split.edge_flank_cutting_N_per_mm),
                               format_number(c.result.tool_force_split.edge_flank_thrust_N_per_mm),
                               format_number(c.result.tool_force_split.rake_friction_work_N_per_mm),
                               format_number(c.result.tool_force_split.edge_flank_friction_work_N_per_mm),
                               format_number(c.result.tool_force_split.rake_slip_speed_m_per_s),
                               format_number(c.result.chip_thickness_ratio), format_number(c.chip_thickness_um()),
                               format_number(c.chip_thickness_by_area_um()),
                               format_number(c.result.cell_size_um), format_number(c.cells_per_thermal_length(kappa), 3),
                               format_number(c.result.mass_scaling_factor),
                               format_number(c.result.max_temperature_K), c.result.chip_classification,
                               format_number(c.result.segmentation_degree, 3),
                               format_number(c.result.segmentation_degree_mean, 3),
                               format_number(c.result.segmentation_degree_min, 3),
                               format_number(c.result.segmentation_degree_max, 3),
                               format_number(c.result.wall_time_s), c.result.source_revision, (out / c.id).string(),
                               c.result.message});
  }
  runs_table.write_csv(out / "validation_runs.csv");

  // The measurements as this report read them (forces per mm of width: the row's width_mm, blank = 1 mm assumed;
  // ranges filled in, tool angles as text), one row per force condition:
  // what the plots draw, so that they need not read the data file again.
  TextTable measured_table;
  measured_table.columns = {"condition",       "h_mm",           "vc_m_per_min",   "tool",
                            "edge_radius_um",  "width_mm",       "Fc_mean_N_per_mm", "Fc_min_N_per_mm",
                            "Fc_max_N_per_mm", "Ff_mean_N_per_mm", "Ff_min_N_per_mm", "Ff_max_N_per_mm",
                            "chip_thickness_um", "status",       "source"};
  measured_table.headings = measured_table.columns;
  for (const Condition& c : conditions) {
    if (c.kind != "forces") continue;
    const MeasuredForces& m = *c.measured;
    measured_table.rows.push_back({c.id, fmt::format("{:g}", m.h_mm), fmt::format("{:g}", m.vc_m_per_min), tool_text(c),
                                   fmt::format("{:g}", m.edge_radius_um), format_number(m.width_mm, 6),
                                   fmt::format("{:g}", m.fc_N),
                                   fmt::format("{:g}", m.fc_min_N), fmt::format("{:g}", m.fc_max_N),
                                   fmt::format("{:g}", m.ff_N), fmt::format("{:g}", m.ff_min_N),
                                   fmt::format("{:g}", m.ff_max_N), format_number(m.chip_thickness_um, 6), m.status,
                                   data.builtin ? "Klippel et al. 2024" : o.measurements});
  }
  measured_table.write_csv(out / "validation_measured.csv");

  // The comparison table: one row per compared quantity of every reported force condition.
  TextTable table;
  table.columns = {"condition", "quantity", "unit", "measured_mean", "measured_min", "measured_max", "simulated",
                   "error_percent", "in_measured_range", "basis", "source"};
  table.headings = {"condition", "quantity", "unit", "measured (mean)", "measured min", "measured max", "simulated",
                    "error %", "in range", "basis / assumption", "source"};
  const auto reference_of = [&](const Condition& c) -> const Condition* {
    for (const Condition& b : conditions)
      if (b.kind == "forces" && same_h(b.h_mm, kReferenceH_mm) && same_speed(b.speed_m_per_s, c.speed_m_per_s) &&
          same_tool(b, c))
        return &b;
    return nullptr;
  };
  // Errors over the compared conditions (complete force runs), in matrix order.
  std::vector<const Condition*> compared;
  std::vector<std::optional<double>> err_fc, err_ft, err_ratio, err_tc;
  // The same over the runs that reached a steady state (both forces' drift within the run's warning limit);
  // none for the others, so that the indices stay those of `compared`.
  std::vector<std::optional<double>> steady_fc, steady_ft, steady_ratio;
  std::vector<std::string> drifting;
  struct ThicknessRatio {
    const Condition* c;
    double measured, simulated;
  };
  std::vector<ThicknessRatio> thickness_ratios;
  for (const Condition& c : conditions) {
    if (c.kind != "forces" || c.origin.empty()) continue;
    const MeasuredForces& m = *c.measured;
    const std::string cond = condition_label(c);
    const bool ok = c.compared();
    const auto fc = ok ? c.fc() : std::nullopt, ft = ok ? c.ft() : std::nullopt, ratio = ok ? c.ratio() : std::nullopt;
    const auto tc = ok ? c.chip_thickness_um() : std::nullopt;
    const double measured_tc = m.chip_thickness_um.value_or(NAN);
    const std::string b_assumed = m.width_mm ? fmt::format("N/mm vs N / b, b = {:g} mm of the data file", *m.width_mm)
                                             : "N/mm vs N with b = 1 mm ASSUMED (b not in the data file)";
    table.rows.push_back({cond, "Fc", "N/mm", g4(m.fc_N), g4(m.fc_min_N), g4(m.fc_max_N), format_number(fc),
                          pct(relative_error(fc, m.fc_N)), within(fc, m.fc_min_N, m.fc_max_N), b_assumed, data.source});
    table.rows.push_back({cond, "Ft", "N/mm", g4(m.ff_N), g4(m.ff_min_N), g4(m.ff_max_N), format_number(ft),
                          pct(relative_error(ft, m.ff_N)), within(ft, m.ff_min_N, m.ff_max_N), b_assumed, data.source});
    const double r_lo = m.ff_min_N / m.fc_max_N, r_hi = m.ff_max_N / m.fc_min_N;
    table.rows.push_back({cond, "Ft/Fc", "-", g4(m.ff_N / m.fc_N), g4(r_lo), g4(r_hi), format_number(ratio, 3),
                          pct(relative_error(ratio, m.ff_N / m.fc_N)), within(ratio, r_lo, r_hi),
                          "independent of b (range: extreme combinations of the test ranges)", data.source});
    table.rows.push_back({cond, "t_c", "µm", g4(measured_tc), "", "", format_number(tc, 3),
                          pct(relative_error(tc, measured_tc)), "",
                          "simulated t0 / chip thickness ratio (chip analysis) vs measured h_avg", data.source});
    if (const Condition* ref = reference_of(c); ref && ref != &c && ref->compared() && ok) {
      const MeasuredForces& mr = *ref->measured;
      const double meas = m.fc_N / mr.fc_N, sim = *fc / *ref->fc();
      table.rows.push_back({cond, "Fc / Fc(h = 0.1 mm)", "-", g4(meas), g4(m.fc_min_N / mr.fc_max_N),
                            g4(m.fc_max_N / mr.fc_min_N), format_number(sim, 3), pct(relative_error(sim, meas)),
                            within(sim, m.fc_min_N / mr.fc_max_N, m.fc_max_N / mr.fc_min_N),
                            fmt::format("independent of b; same speed, h = 0.1 mm run with r_n = {:g} µm", mr.edge_radius_um),
                            data.source});
      thickness_ratios.push_back({&c, meas, sim});
    }
    if (!ok) continue;
    compared.push_back(&c);
    err_fc.push_back(relative_error(fc, m.fc_N));
    err_ft.push_back(relative_error(ft, m.ff_N));
    err_ratio.push_back(relative_error(ratio, m.ff_N / m.fc_N));
    err_tc.push_back(relative_error(tc, measured_tc));
    const bool is_steady = steady(c);
    steady_fc.push_back(is_steady ? relative_error(fc, m.fc_N) : std::nullopt);
    steady_ft.push_back(is_steady ? relative_error(ft, m.ff_N) : std::nullopt);
    steady_ratio.push_back(is_steady ? relative_error(ratio, m.ff_N / m.fc_N) : std::nullopt);
    if (!is_steady) drifting.push_back(fmt::format("`{}` (Fc {:+.0f} %, Ft {:+.0f} %)", c.id,
                                                   c.result.cutting_force_drift_percent.value_or(NAN),
                                                   c.result.thrust_force_drift_percent.value_or(NAN)));
  }
  for (const Condition& c : conditions) {
    if (c.kind != "chip" || c.origin.empty()) continue;
    const std::string sim = c.result.status != "complete" ? c.result.status
                            : c.result.chip_classification.empty() ? "n/a (no chip analysis in summary.json)"
                                                                   : c.result.chip_classification;
    table.rows.push_back({fmt::format("h = 0.1 mm, V = {:g} m/s ({:g} m/min), rake 0° (assumed)", c.speed_m_per_s,
                                      c.speed_m_per_min()),
                          "chip type", "-", c.chip.at("chip_type"), "", "", sim, "", "",
                          c.chip.at("statement") + " (" + c.chip.at("note") + ")",
                          c.chip.at("source") + " [" + c.chip.at("tag") + "]"});
  }
  table.write_csv(out / "validation.csv");

  // Mean and worst absolute errors.
  TextTable errors;
  errors.columns = {"quantity", "unit", "conditions", "mean_abs_error_percent", "worst_abs_error_percent", "worst_condition"};
  errors.headings = {"quantity", "unit", "conditions with a value", "mean abs. error %", "worst abs. error %", "worst at"};
  const auto error_row = [&](const std::string& q, const std::string& unit, const std::vector<std::optional<double>>& e) {
    const ErrorSummary s = summarize_errors(e);
    errors.rows.push_back({q, unit, std::to_string(s.count), s.count ? fmt::format("{:.1f}", 100 * s.mean_abs) : "",
                           s.count ? fmt::format("{:.1f}", 100 * s.worst_abs) : "",
                           s.count ? compared[s.worst_index]->id : ""});
    return s;
  };
  const ErrorSummary s_fc = error_row("Fc", "N/mm (" + b_basis + ")", err_fc);
  error_row("Ft", "N/mm (" + b_basis + ")", err_ft);
  const ErrorSummary s_ratio = error_row("Ft/Fc", "-", err_ratio);
  error_row("t_c", "µm", err_tc);
  error_row("Fc, steady runs", "N/mm (" + b_basis + ")", steady_fc);
  error_row("Ft, steady runs", "N/mm (" + b_basis + ")", steady_ft);
  error_row("Ft/Fc, steady runs", "-", steady_ratio);
  std::vector<std::optional<double>> err_thickness;
  for (const auto& t : thickness_ratios) err_thickness.push_back(relative_error(t.simulated, t.measured));
  const ErrorSummary s_thick = summarize_errors(err_thickness);
  errors.rows.push_back({"Fc / Fc(h = 0.1 mm)", "-", std::to_string(s_thick.count),
                         s_thick.count ? fmt::format("{:.1f}", 100 * s_thick.mean_abs) : "",
                         s_thick.count ? fmt::format("{:.1f}", 100 * s_thick.worst_abs) : "",
                         s_thick.count ? thickness_ratios[s_thick.worst_index].c->id : ""});
  errors.write_csv(out / "validation_errors.csv");

  // Speed trends: the least-squares slope of Fc over ln v at each h with two or more compared speeds; the
  // measured slope over the same speeds, so that the two see the same conditions. Also in % of the mean Fc
  // per e-fold (a slope of 1 N/mm is flat at h = 0.1 mm, not at 0.01 mm). Where tests of status "short" are
  // among them (their cut may not have been steady: data file, caveat 4), the same over the "ok" tests only;
  // the goal counts the rows over all tests.
  TextTable trends;
  trends.columns = {"h_mm", "tests", "speeds_m_per_min", "measured_slope_N_per_mm", "simulated_slope_N_per_mm",
                    "measured_slope_percent", "simulated_slope_percent", "sign_right"};
  trends.headings = {"h (mm)", "tests", "speeds (m/min)", "measured dFc/d ln v (N/mm, " + b_basis + ")",
                     "simulated dFc/d ln v (N/mm)", "measured (% of mean Fc)", "simulated (% of mean Fc)", "sign right"};
  int trends_total = 0, trends_right = 0;
  // One series per h and tool (measurements with the tool's angles may hold several tools at one h).
  std::vector<const Condition*> series;
  for (const Condition* c : compared)
    if (std::none_of(series.begin(), series.end(),
                     [&](const Condition* s) { return same_h(s->h_mm, c->h_mm) && same_tool(*s, *c); }))
      series.push_back(c);
  std::stable_sort(series.begin(), series.end(), [](const Condition* a, const Condition* b) { return a->h_mm < b->h_mm; });
  const bool tools = std::any_of(series.begin(), series.end(), [](const Condition* c) { return !tool_text(*c).empty(); });
  if (tools) {
    trends.columns.push_back("tool");
    trends.headings.push_back("tool");
  }
  const auto mean_of = [](const std::vector<double>& x) {
    double sum = 0.0;
    for (double v : x) sum += v;
    return sum / static_cast<double>(x.size());
  };
  for (const Condition* first : series) {
    const double h = first->h_mm;
    for (const bool ok_only : {false, true}) {
      std::vector<double> v, fm, fs;
      std::vector<std::string> vs;
      bool any_short = false;
      for (const Condition* c : compared) {
        if (!same_h(c->h_mm, h) || !same_tool(*c, *first)) continue;
        any_short = any_short || c->measured->status != "ok";
        if (ok_only && c->measured->status != "ok") continue;
        v.push_back(c->speed_m_per_min());
        fm.push_back(c->measured->fc_N);
        fs.push_back(*c->fc());
        vs.push_back(fmt::format("{:g}", c->speed_m_per_min()));
      }
      if (ok_only && !any_short) continue;
      const auto sm = speed_trend_slope(v, fm), ss = speed_trend_slope(v, fs);
      if (!sm || !ss) continue;
      const bool right = (*sm > 0) == (*ss > 0);
      if (!ok_only) {
        ++trends_total;
        trends_right += right;
      }
      trends.rows.push_back({fmt::format("{:g}", h), ok_only ? "status ok only" : "all", join(vs, " "),
                             fmt::format("{:.3g}", *sm), fmt::format("{:.3g}", *ss),
                             fmt::format("{:.2f}", 100.0 * *sm / mean_of(fm)),
                             fmt::format("{:.2f}", 100.0 * *ss / mean_of(fs)), right ? "yes" : "no"});
      if (tools) trends.rows.back().push_back(tool_text(*first));
    }
  }
  trends.write_csv(out / "validation_trends.csv");

  // The goals.
  TextTable goals;
  goals.columns = {"goal", "value", "conditions", "met"};
  goals.headings = {"goal", "value", "conditions", "met?"};
  const auto met = [](int n, bool ok) { return n == 0 ? std::string("n/a (no compared condition)") : ok ? "yes" : "no"; };
  goals.rows.push_back({"Ft/Fc within ±15 % at every condition",
                        s_ratio.count ? fmt::format("worst {:.1f} %", 100 * s_ratio.worst_abs) : "",
                        std::to_string(s_ratio.count), met(s_ratio.count, s_ratio.worst_abs <= kGoalRatioError)});
  goals.rows.push_back({"Fc(h)/Fc(0.1 mm) within ±10 % at each speed with h = 0.1 mm",
                        s_thick.count ? fmt::format("worst {:.1f} %", 100 * s_thick.worst_abs) : "",
                        std::to_string(s_thick.count), met(s_thick.count, s_thick.worst_abs <= kGoalThicknessError)});
  goals.rows.push_back({"sign of the speed trend of Fc (dFc/d ln v) right at each h with ≥ 2 speeds",
                        trends_total ? fmt::format("{} of {} right", trends_right, trends_total) : "",
                        std::to_string(trends_total), met(trends_total, trends_right == trends_total)});
  goals.rows.push_back({"mean absolute error of Fc < 15 % (" + b_basis + ")",
                        s_fc.count ? fmt::format("mean {:.1f} %", 100 * s_fc.mean_abs) : "", std::to_string(s_fc.count),
                        met(s_fc.count, s_fc.mean_abs < kGoalMeanFcError)});
  goals.write_csv(out / "validation_goals.csv");

  // The report.
  std::vector<std::string> hot;
  for (const Condition& c : conditions) {
    if (c.origin.empty()) continue;
    const auto tm = melting_temperature(out / c.id);
    if (tm && c.result.max_temperature_K && *c.result.max_temperature_K > *tm)
      hot.push_back(fmt::format("{} ({:.0f} K)", c.id, *c.result.max_temperature_K));
  }
  std::vector<std::string> incomplete, not_run;
  for (const Condition& c : conditions) {
    if (c.origin.empty())
      not_run.push_back("`" + c.id + "`");
    else if (!c.complete())
      incomplete.push_back(fmt::format("| `{}` | {} | {} |", c.id, c.result.status, c.result.message));
  }
  write_file_atomically(out / "validation.md", [&](std::ostream& s) {
    s << (data.builtin ? std::string("# Validation against published Ti-6Al-4V orthogonal-cutting measurements\n\n")
                       : "# Validation against the measurements of " + o.measurements + "\n\n");
    if (o.quick)
      s << "**--quick: coarse resolution (cell = t0/4, 1 particle per cell, 4 cells of tool travel). This checks "
           "that the pipeline runs; the simulated numbers are not converged and must not be read as a "
           "validation.**\n\n";
    s << fmt::format("**{} of the {} conditions of the matrix are complete** ({} of {} force conditions and {} of {} "
                     "chip-type conditions); {} reported ({} run by this invocation{}, {} complete from an earlier run "
                     "in this directory, {} from the run records{}), {} not run yet{}. Errors and goals are over the {} complete force "
                     "conditions.\n\n",
                     complete, conditions.size(),
                     std::count_if(conditions.begin(), conditions.end(), [](const Condition& c) { return c.kind == "forces" && c.complete(); }),
                     std::count_if(conditions.begin(), conditions.end(), [](const Condition& c) { return c.kind == "forces"; }),
                     std::count_if(conditions.begin(), conditions.end(), [](const Condition& c) { return c.kind == "chip" && c.complete(); }),
                     std::count_if(conditions.begin(), conditions.end(), [](const Condition& c) { return c.kind == "chip"; }),
                     reported, runs.size(), completed ? "" : ", interrupted",
                     std::count_if(conditions.begin(), conditions.end(), [](const Condition& c) { return c.origin == "earlier run"; }),
                     std::count_if(conditions.begin(), conditions.end(), [](const Condition& c) { return c.origin == "record"; }),
                     o.records_dir.empty() ? "" : " in " + o.records_dir, not_run.size(), not_run.empty() ? "" : " (listed at the end)", compared.size());
    s << "Resolution: " << resolution_text(o) << ".\n\n";
    if (!unresolved_bands.empty())
      s << fmt::format("**Shear bands not resolved at {} of {} compared conditions**: fewer than {:g} cells across "
                       "the thermal length √(κ t0/V), the width scale of a fast cut's adiabatic shear bands; there the "
                       "forces still move with the cell (at h = 0.1 mm, 381.3 m/min: Fc −8 % from 1.1 to 1.6 cells; "
                       "docs/results.md \"Resolution rule\", `--cells-per-thermal-length`): {} (cells across l_th in "
                       "brackets; validation_runs.csv `cells_per_thermal_length`).\n\n",
                       unresolved_bands.size(), compared.size(), kResolvedCellsPerThermalLength,
                       join(unresolved_bands, ", "));
    s << revisions_text(conditions) << "\n\n";
    s << "## Goals\n\n" << goals.markdown() << "\n";
    s << (with_width == forces ? std::string("No") : "Under the stated assumption b = 1 mm" +
                                                          std::string(with_width > 0 ? " where the data give no width" : "") +
                                                          "; no")
      << " parameter was tuned per condition (one material set, one friction coefficient for the whole matrix).\n\n";
    s << "## Errors over the complete force conditions\n\n" << errors.markdown() << "\n";
    s << fmt::format("\"steady runs\": the {} of {} runs whose mean Fc and Ft change by at most {:g} % between the halves "
                     "of the steady window (summary.json steady_window.drift).{}\n\n",
                     compared.size() - drifting.size(), compared.size(), kSteadyDriftWarningPercent,
                     drifting.empty() ? std::string()
                                      : " Not steady (the cut is shorter than its transient; a longer cut_length "
                                        "would move their mean): " + join(drifting, ", ") + ".");
    s << "Error = (simulated − measured mean) / measured mean, per condition; mean and worst of its absolute value over the conditions with "
         "a value. t_c: simulated t0 / (chip thickness ratio of the chip analysis) against the measured mean chip "
         "thickness h_avg (mostly one measurement per condition).\n\n";
    s << "## Speed trends\n\n";
    if (trends.rows.empty())
      s << "No thickness has two or more complete speeds.\n\n";
    else
      s << trends.markdown() << "\nLeast-squares slope of Fc over ln(v) (N/mm per e-fold of speed, and in % of the "
                                "mean Fc over the same speeds) over the complete speeds at each h; the measured slope "
                                "over the same speeds. \"status ok only\": the same without the tests of status "
                                "\"short\" (a short cut, maybe not steady: data file, caveat 4); the goal counts the "
                                "rows over all tests.\n\n";
    s << "## Assumptions\n\n"
      << (data.builtin
              ? "- **Width of cut b = 1 mm (assumed).** The Klippel et al. data give forces in N for the whole width; b "
                "is in the paper's section 2, which was not read. Absolute Fc, Ft in N/mm are compared under this "
                "assumption; Ft/Fc and the ratios between conditions do not depend on it and are the primary "
                "comparison.\n"
                "- Rake 0°, clearance 11° (preset defaults): the tool angles are not in the data file. The edge radius "
                "of each force run is the measured mean r_n of its tests. Coulomb friction "
              : (with_width == forces
                     ? "- **Width of cut**: the measured forces of " + o.measurements +
                           " are divided by each row's width_mm and compared as N/mm.\n"
                     : "- **Width of cut b = 1 mm (assumed)** for the " + std::to_string(forces - with_width) + " of " +
                           std::to_string(forces) + " rows of " + o.measurements +
                           " without a width_mm: their forces in N are compared as N/mm of a cut 1 mm wide; the rows "
                           "with a width are divided by it. Ft/Fc and the ratios between conditions do not depend on "
                           "it.\n") +
                    "- Tool angles: the file's rake_deg and clearance_deg where its rows give them, else rake 0° and "
                    "clearance 11° (the preset's, assumed; each case file says which). The edge radius of each run is "
                    "the file's edge_radius_um. Coulomb friction ")
      << fmt::format("{:g} ({})", settings.friction, settings.friction_note)
      << (settings.friction_heat_share
              ? fmt::format("; a share {:g} of the frictional heat goes into the workpiece, the rest into the tool "
                            "(--friction-heat-share)",
                            *settings.friction_heat_share)
              : std::string("; all frictional heat goes into the workpiece"))
      << (settings.tool_heat_transfer_coefficient
              ? fmt::format("; the tool is a heat sink at {} with a heat transfer coefficient of {:g} W/(m² K)",
                            settings.tool_temperature ? fmt::format("{:g} K", *settings.tool_temperature)
                                                      : std::string("the initial temperature"),
                            *settings.tool_heat_transfer_coefficient)
              : std::string("; the tool surface is adiabatic"))
      << "; contact detection: "
      << (settings.contact_detection.empty() ? std::string("node (the preset's)")
                                             : settings.contact_detection + " (--contact-detection)")
      << ".\n"
      << "- Material: the `" << settings.material << "` set"
      << (settings.material_definitions.empty() ? " of the material library" : "") << " ("
      << settings.material_note << ")"
      << (settings.material_overrides.empty() ? std::string() : " with " + changed_keys_text(settings) +
                                                                     " (--material-key: the cases' set \"trial\")")
      << (settings.material_overrides.empty() && settings.material == "ti64-cutting"
              ? ": Johnson 1985 JC flow and JC damage initiation, G_f = 15 kJ/m² falling to 5 kJ/m² above a plastic "
                "strain rate of ~2e6 1/s (docs/materials.md)"
              : "")
      << ".\n"
         "- Simulated forces are means over the steady window of each run; where a run ended before it (short "
         "cuts), the mean raw force over the last half of the cut (column force_window of validation_runs.csv). "
         "Columns Fc_ and Ft_drift_in_window_percent there give the second half's mean minus the first half's, in % "
         "of the mean: beyond ±10 % the cut had not reached a steady state.\n"
      << (data.builtin ? "- The measured speeds (≤ 6.4 m/s) are below the ultra-high-speed range of the target paper; "
                         "chip-type data at 5–75 m/s exist only as abstract statements without the transition speed.\n"
                       : "")
      << "\n";

    s << "## By condition\n\n" << by_condition_table(compared).markdown()
      << "\nMeasured mean / simulated; error = (simulated − measured) / measured. N/mm (" << b_basis << "). "
         "\"steady\": both forces drift by at most "
      << fmt::format("{:g}", kSteadyDriftWarningPercent) << " % between the halves of the steady window.\n\n";
    s << "## Comparison\n\n" << table.markdown() << "\n";
    s << "Error % = (simulated − measured mean) / measured mean. \"in range\": the simulated value lies within the "
         "min–max of the repeated tests (for ratios: the extreme combinations of the ranges).\n\n";
    if (!incomplete.empty())
      s << "## Not complete\n\n| condition | status | message |\n|---|---|---|\n" << join(incomplete, "\n") << "\n\n";
    if (!not_run.empty())
      s << "## Not run yet\n\n" << not_run.size() << " conditions of the matrix have no complete run of this "
        << "resolution in this directory: " << join(not_run, ", ")
        << ". `mpmcut validate --out " << out.string() << "` with a selection (--h, --speeds-m-per-min, --conditions) "
        << "runs them; complete ones are kept.\n\n";
    if (data.builtin)
      s << "## Where the data disagree or are thin\n\n"
           "- At h = 0.1 mm and nearly equal speeds the Klippel condition means differ by more than the scatter "
           "within a condition: 222.8 N at 10 m/min (r_n 40.8 µm) vs 209.2 N at 10.5 m/min (r_n 29.4 µm); tests marked "
           "`short` (74.3, 88.9, 159–381 m/min) lie 5–10 % below neighbouring `ok` tests. The edge radius and the "
           "unexplained status explain part of it; validation_forces.png shows every condition with its range "
           "rather than a single curve.\n"
           "- Ff/Fc: Klippel et al. give 0.6–0.7 at h = 0.1 mm and Ff > Fc at h ≤ 0.04 mm (r_n ≈ 37 µm ≥ h: "
           "ploughing); Ducobu, Pantalé & Lauwers (CIRP JMST, [V]) report Ff ≈ 46 % of Fc at h = 40 µm, 10 m/min, with "
           "a 15° rake, r_β = 20 µm tool in oblique cutting (λs = 6°). The two do not contradict each other — tool "
           "geometry differs — but they show how strongly Ft/Fc depends on rake and edge radius, which this "
           "comparison had to assume.\n"
           "- Chip type: Sutter & List (2013) [A] state serrated chips at the lower speeds of 5–75 m/s and "
           "discontinuous chips at very high speed without the transition speed in the abstract; Ducobu et al. [V] "
           "saw only continuous chips at 5–40 m/min with a 15° rake (not simulated: below 1 m/s the explicit run is "
           "too long, and the tool differs).\n\n";
    if (!hot.empty())
      s << "## Physically odd\n\nMaximum particle temperature above the material's melting temperature in: "
        << join(hot, ", ") << ". Single particles at the tool–chip contact usually; see the chip pictures (mpmcut plot DIR).\n\n";
    s << "## Files\n\nvalidation.csv (the comparison table), validation_goals.csv, validation_errors.csv, "
         "validation_trends.csv, validation_runs.csv (one row per reported run), validation_measured.csv (the "
         "measurements as read, one row per force condition), validation_parity.png, "
         "validation_speed.png, validation_thickness.png, validation_forces.png, validation_ratio.png, cases/*.toml (the "
         "run inputs), <condition>/ (result directories), logs/.\n\n"
      << (data.builtin ? "Data: data/experiments/ti64_klippel2024_orthogonal_forces.csv and ti64_chip_morphology.csv "
                         "(sources and caveats in their headers).\n"
                       : "Data: " + o.measurements + " (--measurements).\n");
  });
  std::cout << "wrote " << (out / "validation.md").string()
            << ", validation.csv, validation_goals.csv, validation_errors.csv, validation_trends.csv, validation_runs.csv\n";

  if (!o.no_plots && completed) {  // an interrupted validation stops here: no plots of partial results
    std::string why;
    if (!python_plotting_available(false, why))
      std::cerr << "warning: no validation plots: " << why << "\n";
    else if (int code = run_python_tool("plot_validation.py", o.quick ? std::vector<std::string>{out.string(), "--quick"}
                                                                                : std::vector<std::string>{out.string()}); code != 0)
      std::cerr << "warning: plot_validation.py failed (exit status " << code << ")\n";
  }
  if (!completed) return 130;
  if (failed) {
    std::cerr << fmt::format("mpmcut validate: {} of {} runs did not complete (see validation.md and logs/)\n", failed,
                             runs.size());
    return 1;
  }
  return 0;
}

}  // namespace

void add_validate_command(CLI::App& app) {
  auto o = std::make_shared<ValidateOptions>();
  CLI::App* v = app.add_subcommand(
      "validate",
      "Run the measured conditions of data/experiments (every speed and thickness of the Klippel et al. 2024 force "
      "data with its measured edge radius, and the chip-type conditions) and compare: validation.md (goals, errors, "
      "trends), CSV tables, parity and trend plots. Resumable: a rerun into the same --out keeps the complete "
      "conditions, so the matrix can be run in parts (select with --h, --speeds-m-per-min, --conditions; --list "
      "shows the conditions and their cost); the report covers every complete condition in --out");
  v->add_flag("--quick", o->quick,
              "Coarse and short runs (seconds) of 5 conditions (h 0.04 mm at 100 and 400.1 m/min, 0.1 mm at 100 m/min, "
              "the two chip-type conditions) unless a selection is given: checks the pipeline, numbers not converged");
  v->add_option("--cells-per-feed", o->cells_per_feed,
                "N: cell <= t0/N, cells across the uncut chip thickness (default 10; cost grows as N^3); chip-type "
                "conditions use at least 8")
      ->check(CLI::Range(2, 100));
  v->add_option("--cells-per-edge-radius", o->cells_per_edge_radius,
                "M: cell <= r_n/M, cells across the measured edge radius of the force conditions (default 4: the "
                "edge's quarter arc then spans ~6 cells; 0 = no limit). cell = min(t0/N, r_n/M)")
      ->check(CLI::Range(0.0, 100.0));
  v->add_option("--cells-per-thermal-length", o->cells_per_thermal_length,
                "K: cell <= l_th/K, cells across the thermal length l_th = sqrt(kappa t0/V), the width scale of an "
                "adiabatic shear band (6.8 um at h = 0.1 mm, 381.3 m/min in Ti-6Al-4V; default 0 = no limit; 1.6 "
                "resolves the fast cuts' shear bands to within ~4 % in Fc: docs/results.md)")
      ->check(CLI::Range(0.0, 100.0));
  v->add_option("--h", o->h_mm, "Run only these uncut chip thicknesses, mm (comma-separated, e.g. 0.1,0.04)")
      ->delimiter(',');
  v->add_option("--speeds-m-per-min", o->speeds_m_per_min,
                "Run only these cutting speeds, m/min (comma-separated, e.g. 100,400.1)")
      ->delimiter(',');
  v->add_option("--conditions", o->condition_ids, "Run only these conditions (ids as --list prints them, comma-separated)")
      ->delimiter(',');
  v->add_flag("--list", o->list,
              "Print the selected conditions with cell size, cut length and estimated cost (particles x steps, "
              "core-hours) and whether --out holds them complete; writes their case files, runs nothing");
  v->add_option("-o,--out", o->out_dir, "Output directory (default: results/validation or results/validation_quick)");
  v->add_option("--records", o->records_dir,
                "Directory of run records (scene.toml, forces.csv, summary.json of each complete condition; small, "
                "meant to be committed): conditions complete there with the same scene are reported without running, "
                "and every complete condition is added to it, so that a matrix run over several sessions or machines "
                "keeps its parts when the result directories are gone");
  v->add_option("-j,--jobs", o->jobs, "Runs at the same time (default: cores / threads)")->check(CLI::Range(1, 1024));
  v->add_option("-t,--threads", o->threads, "OpenMP threads of each run (default: 1)")->check(CLI::Range(1, 1024));
  v->add_flag("--no-plots", o->no_plots, "Only the tables");
  v->add_option("--material", o->material,
                "Material set to run: a set of the library (default ti64-cutting; docs/materials.md) or of "
                "--material-file");
  v->add_option("--measurements", o->measurements,
                "Validate against your own force measurements instead of the built-in Klippel et al. 2024 data: a CSV "
                "in the layout of data/experiments/ti64_klippel2024_orthogonal_forces.csv (columns h_mm, vc_m_per_min, "
                "Fc_mean_N, Ff_mean_N, edge_radius_um; optional Fc_/Ff_min_N, _max_N, n_tests, chip_thickness_um, "
                "status, rake_deg, clearance_deg, width_mm: forces in N are divided by it, else b = 1 mm is assumed); the "
                "conditions are then its rows "
                "(docs/results.md)");
  v->add_option("--material-file", o->material_file,
                "A TOML file of [[material]] sets (as materials/*.toml, or the best_material.toml of `mpmcut "
                "calibrate`): --material may name one of them (a file of one set needs no --material); every case "
                "file then carries the file's sets");
  v->add_option("--material-key", o->material_keys,
                "Change a numeric key of the chosen set, KEY=VALUE (repeatable, e.g. --material-key jc_C=0.035): "
                "every case then runs a set \"trial\" that starts from it (library = the set) with these keys; "
                "docs/materials.md lists the keys");
  v->add_option("--friction", o->friction, "Coulomb coefficient at the tool (default 0.35; e.g. a calibrated one)")
      ->check(CLI::Range(0.0, 2.0));
  v->add_option("--contact-detection", o->contact_detection,
                "How the tool contact finds the material (solver.contact_detection; default node; penalty: a "
                "spring per particle, smooth in the tool's position on the grid, docs/cutting.md)")
      ->check(CLI::IsMember(contact_detection_names()));
  // The tool's thermal options: bounded numbers that, when given, go into every case file.
  struct ThermalOption {
    const char* name;
    std::optional<double>* value;
    const char* help;
    double lo, hi;
  };
  for (const ThermalOption& t : {
           ThermalOption{"--friction-heat-share", &o->friction_heat_share,
                         "Share of the frictional heat that goes into the workpiece, the rest into the tool (default 1: "
                         "all of it; [cutting] friction_heat_share)",
                         0.0, 1.0},
           ThermalOption{"--tool-heat-transfer-coefficient", &o->tool_heat_transfer_coefficient,
                         "Heat transfer coefficient between the workpiece and the tool, W/(m^2 K) (default 0: an "
                         "adiabatic tool; [cutting] tool_heat_transfer_coefficient)",
                         0.0, 1e9},
           ThermalOption{"--tool-temperature", &o->tool_temperature,
                         "The tool's constant temperature, K, where it exchanges heat (default: the workpiece's "
                         "initial temperature)",
                         1.0, 1e4}})
    v->add_option(t.name, *t.value, t.help)->check(CLI::Range(t.lo, t.hi));
  v->callback([o]() {
    int code = 0;
    try {
      code = run_study([&] { return run_validation(*o); });
    } catch (const InputError& e) {
      std::cerr << "error: " << e.what() << "\n";
      code = kExitInputError;
    } catch (const std::exception& e) {
      std::cerr << "error: " << e.what() << "\n";
      code = 4;
    }
    throw CLI::RuntimeError(code);
  });
}

}  // namespace mpmcut
