#include "app/validation_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <utility>

#include <fmt/format.h>

#include "app/plot_command.hpp"
#include "cutting/cutting_resolution.hpp"
#include "cutting/tool_heat_settings.hpp"
#include "io/input_error.hpp"
#include "io/material_library.hpp"
#include "io/whole_file.hpp"
#include "studies/validation_defaults.hpp"

namespace mpmcut::validation {

namespace {

constexpr const char* kForcesFile = "data/experiments/ti64_klippel2024_orthogonal_forces.csv";
constexpr const char* kChipFile = "data/experiments/ti64_chip_morphology.csv";
constexpr const char* kForcesSource =
    "Klippel et al., Int. J. Adv. Manuf. Technol. 135 (2024) 2871-2908, per-test data file [V]";

// --quick without a selection: a trend at one h (0.04 mm at 100 and 400.1 m/min), a thickness ratio
// (0.04 / 0.1 mm at 100 m/min) and the chip-type conditions: every part of the report, in seconds.
const std::vector<std::string>& quick_condition_ids() {
  static const std::vector<std::string> ids{"forces_h0.04mm_vc100mpmin", "forces_h0.04mm_vc400.1mpmin",
                                            "forces_h0.1mm_vc100mpmin", "chip_sutter_list_2013_low_v5mps",
                                            "chip_sutter_list_2013_high_v75mps"};
  return ids;
}

// The material of the runs: a library set, or a set of --material-file (read and checked here, so that a broken
// file stops the study before any run, with its file, line and key).
void choose_material(const Options& o, ConditionRunSettings& s) {
  if (o.material_file.empty()) {
    if (o.material.empty()) {
      s.material = kValidationMaterial;
      s.material_note = "the default: fitted to Klippel et al. 2024 forces with crack friction and a conducting tool, "
                        "docs/results/calibration_crack_friction";
      return;
    }
    if (!builtin_material_library().find(o.material))
      throw InputError(fmt::format("--material {}: no such set; the library has: {}", o.material,
                                   join(builtin_material_library().names(), ", ")));
    s.material = o.material;
    s.material_note = "chosen with --material; docs/materials.md";
    return;
  }
  const std::optional<std::string> text = read_whole_file(o.material_file);
  if (!text)
    throw InputError(fmt::format("--material-file {}: cannot read the file: {}", o.material_file,
                                 unreadable_reason(o.material_file)));
  MaterialLibrary with_builtin = builtin_material_library();
  const std::size_t before = with_builtin.sets().size();
  with_builtin.add_file(*text, o.material_file);  // InputError at the file's line and key
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
  s.material_definitions = *text;
  s.material_note = fmt::format("from --material-file {}", o.material_file);
}

}  // namespace

std::optional<double> Condition::cells_per_thermal_length(double kappa) const {
  const double l_th = thermal_length_m(kappa, h_mm * 1e-3, speed_m_per_s);
  return result.cell_size_um && l_th > 0.0 ? std::optional<double>(l_th / (*result.cell_size_um * 1e-6)) : std::nullopt;
}

namespace {

DataFile read_user_file(const std::string& option, const std::string& path) {
  const std::optional<std::string> text = read_whole_file(path);
  if (!text) throw InputError(fmt::format("{} {}: cannot read the file: {}", option, path, unreadable_reason(path)));
  return read_data_file(*text, path);
}

}  // namespace

ForceData force_data(const Options& o) {
  ForceData data;
  if (o.measurements.empty()) {
    data.file = read_data_file(embedded_tool_file(kForcesFile), kForcesFile);
    data.source = kForcesSource;
  } else {
    data.file = read_user_file("--measurements", o.measurements);
    data.source = o.measurements + " (--measurements)";
    data.builtin = false;
  }
  if (!o.chip_observations.empty()) {
    data.chip_file = read_user_file("--chip-observations", o.chip_observations);
    data.chips_builtin = false;
  } else if (o.measurements.empty()) {
    data.chip_file = read_data_file(embedded_tool_file(kChipFile), kChipFile);
  }
  return data;
}

std::string join(const std::vector<std::string>& parts, const std::string& sep) {
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : sep) + p;
  return out;
}

// The resolution part of the run settings (resolution_text needs no more; run_settings starts from it).
static ConditionRunSettings run_settings_resolution(const Options& o) {
  ConditionRunSettings s;
  s.cells_per_feed = o.cells_per_feed;
  s.chip_type_cells_per_feed = o.chip_cells_per_feed;
  return s;
}

ConditionRunSettings run_settings(const Options& o) {
  // CLI11's range checks let NaN through (every comparison with it is false).
  for (const auto& [option, value] :
       {std::pair<const char*, std::optional<double>>{"--cells-per-edge-radius", o.cells_per_edge_radius},
        {"--cells-per-thermal-length", o.cells_per_thermal_length}, {"--friction", o.friction},
        {"--friction-heat-share", o.friction_heat_share},
        {"--tool-heat-transfer-coefficient", o.tool_heat_transfer_coefficient},
        {"--tool-temperature", o.tool_temperature}, {"--tool-conductivity", o.tool_conductivity},
        {"--tool-volumetric-heat-capacity", o.tool_volumetric_heat_capacity}})
    if (value && !std::isfinite(*value)) throw InputError(fmt::format("{} {}: a finite number is needed", option, *value));
  ConditionRunSettings s = run_settings_resolution(o);
  s.quick = o.quick;
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
    for (const auto& [given, given_value] : s.material_overrides)
      if (given == key)
        throw InputError(fmt::format("--material-key {} is given twice ({:g} and {:g}): give each key once", key,
                                     given_value, value));
    s.material_overrides.emplace_back(key, value);
  }
  if (o.friction) {
    s.friction = *o.friction;
    s.friction_note = "chosen with --friction";
  }
  // The default set runs as it was fitted (studies/validation_defaults.hpp): its friction and a conducting tool,
  // where no option says otherwise; any other set with the cutting preset's friction and an adiabatic tool.
  const bool as_fitted = s.material == kValidationMaterial && s.material_definitions.empty();
  if (as_fitted && !o.friction) {
    s.friction = kValidationMaterialFriction;
    s.friction_note = "fitted with the material set, docs/results/calibration_crack_friction";
  }
  // A heat transfer coefficient of 0 makes the tool adiabatic, and then it conducts nothing.
  const double heat_transfer =
      o.tool_heat_transfer_coefficient.value_or(as_fitted ? kValidationToolHeatTransferCoefficient : 0.0);
  const double conductivity =
      o.tool_conductivity.value_or(as_fitted && heat_transfer > 0.0 ? kValidationToolConductivity : 0.0);
  // The conditions between the tool's heat options, as the case reader puts them on its keys: refused here, before
  // any run, rather than in every case file.
  if (const auto conflict = tool_heat_conflict({o.friction_heat_share.value_or(1.0), heat_transfer, conductivity,
                                                o.tool_volumetric_heat_capacity.value_or(0.0)})) {
    std::string option = "--" + std::string(conflict->key);
    std::replace(option.begin(), option.end(), '_', '-');
    throw InputError(fmt::format("{} {:g}: must be {}", option, conflict->value, conflict->allowed));
  }
  s.friction_heat_share = o.friction_heat_share;
  // A value of 0 is the key's default: left out of the case files, which stay those of the runs made before the
  // conducting default (their records match).
  const auto unless_zero = [](double v) { return v > 0.0 ? std::optional<double>(v) : std::nullopt; };
  s.tool_heat_transfer_coefficient = unless_zero(heat_transfer);
  s.tool_conductivity = unless_zero(conductivity);
  const char* kFittedTool = "the conducting carbide tool the set was fitted with (ASSUMPTION; "
                            "--tool-heat-transfer-coefficient 0: adiabatic)";
  if (as_fitted && !o.tool_heat_transfer_coefficient) s.tool_heat_transfer_note = kFittedTool;
  if (as_fitted && !o.tool_conductivity) s.tool_conductivity_note = kFittedTool;
  s.tool_temperature = o.tool_temperature;
  s.tool_volumetric_heat_capacity = o.tool_volumetric_heat_capacity;
  s.contact_detection = o.contact_detection;
  s.volumetric_average = o.volumetric_average;
  return s;
}

// Every condition of data/experiments: all rows of the force file (every status) and the chip-type rows
// that name a speed to simulate; with a user's force file, its rows only.
std::vector<Condition> matrix_conditions(const ConditionRunSettings& settings, const ForceData& data) {
  std::vector<Condition> conditions;
  const std::vector<MeasuredForces> rows = read_measured_forces(data.file);
  std::map<std::string, int> line_of_id;
  for (const MeasuredForces& m : rows) {
    Condition c;
    static_cast<CuttingCondition&>(c) = force_condition(m);
    // Forces per mm of width from here on: the file's width, or b = 1 mm ASSUMED (the simulated cut is 1 mm wide).
    c.measured = m.per_mm_of_width(1.0);
    // The reader refuses a cut given twice; ids print 6 digits, so cuts closer than that would share a directory.
    if (const auto [it, added] = line_of_id.emplace(c.id, m.line); !added)
      throw InputError(fmt::format("{}:{}: the condition {} is on line {} already: h, speed, edge radius or angles "
                                   "closer than the 6 digits of the result directory's name",
                                   data.file.source, m.line, c.id, it->second));
    conditions.push_back(c);
  }
  for (const ChipObservation& o : data.chip_file ? read_chip_observations(*data.chip_file)
                                                 : std::vector<ChipObservation>{}) {
    if (!o.simulate_speed_m_per_s) continue;
    Condition c;
    c.id = fmt::format("chip_{}_v{:g}mps", o.id, *o.simulate_speed_m_per_s);
    c.kind = "chip";
    c.speed_m_per_s = *o.simulate_speed_m_per_s;
    c.h_mm = o.h_mm;  // the lower end of the source's h range
    c.edge_radius_um = o.edge_radius_um.value_or(kChipConditionEdgeRadius_um);
    c.edge_radius_given = o.edge_radius_um.has_value();
    c.rake_deg = o.rake_deg;
    c.clearance_deg = o.clearance_deg;
    c.chip = o;
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
// A speed given on the command line: within round-off of the condition's, or as --list and the report print it (6
// significant digits: a chip observation's 5.123456789 m/s shows as 307.407 m/min, 1.3e-6 away).
bool speed_selected(const Condition& c, double v_m_per_min) {
  return same_speed(c.speed_m_per_min(), v_m_per_min) ||
         fmt::format("{:g}", c.speed_m_per_min()) == fmt::format("{:g}", v_m_per_min);
}

void select_conditions(std::vector<Condition>& all, const Options& o) {
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
    if (std::none_of(all.begin(), all.end(), [&](const Condition& c) { return speed_selected(c, v); }))
      throw InputError(fmt::format("--speeds-m-per-min {:g}: no condition of the matrix has vc = {:g} m/min (it has {} "
                                   "m/min)",
                                   v, v, available([](const Condition& c) { return fmt::format("{:g}", c.speed_m_per_min()); })));
  for (const std::string& id : o.condition_ids)
    if (std::none_of(all.begin(), all.end(), [&](const Condition& c) { return c.id == id; }))
      throw InputError(fmt::format("--conditions {}: no such condition (`mpmcut validate --list` names them)", id));
  for (Condition& c : all) {
    if (!filtered) {
      const auto& quick = quick_condition_ids();
      // --quick: the quick subset of the built-in matrix; every condition of a user's file (forces or chips).
      const bool users = c.kind == "forces" ? !o.measurements.empty() : !o.chip_observations.empty();
      c.selected = !o.quick || users || std::find(quick.begin(), quick.end(), c.id) != quick.end();
      continue;
    }
    c.selected =
        (o.h_mm.empty() || std::any_of(o.h_mm.begin(), o.h_mm.end(), [&](double h) { return same_h(c.h_mm, h); })) &&
        (o.speeds_m_per_min.empty() || std::any_of(o.speeds_m_per_min.begin(), o.speeds_m_per_min.end(),
                                                   [&](double v) { return speed_selected(c, v); })) &&
        (o.condition_ids.empty() || std::find(o.condition_ids.begin(), o.condition_ids.end(), c.id) != o.condition_ids.end());
  }
  if (std::none_of(all.begin(), all.end(), [](const Condition& c) { return c.selected; }))
    throw InputError("the selection (--h, --speeds-m-per-min, --conditions together) matches no condition of the matrix");
}

std::string resolution_text(const Options& o) {
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
      o.measurements.empty() || !o.chip_observations.empty()  // with a user's force file alone there are none
          ? fmt::format("; chip-type conditions at t0/{} (--chip-cells-per-feed: at t0/10 the 75 m/s chip's type was "
                        "not decided, at t0/20 it was the observed one; an edge radius the observations give is "
                        "resolved as a force condition's, the preset's {:g} µm where they give none sets no limit)",
                        chip_cells_per_feed(run_settings_resolution(o)), kChipConditionEdgeRadius_um)
          : std::string());
}

static bool edge_radius_names_tool(const Condition& c) { return c.measured && c.measured->edge_radius_names_tool; }

std::string material_data_mismatch(const ConditionRunSettings& s, const ForceData& data) {
  if (!data.builtin) return "";
  const std::string material = s.material.empty() ? "ti64-cutting" : s.material;
  // A library Ti-6Al-4V set is what the data are of; another set (a file's may inherit one) may not be.
  if (s.material_definitions.empty() && material.starts_with("ti64")) return "";
  return fmt::format("the built-in measurements are of Ti-6Al-4V (Klippel et al. 2024, Sutter & List 2013), and the "
                     "runs cut the set \"{}\" ({}): unless it is a Ti-6Al-4V set, compare it with its own "
                     "measurements (--measurements FILE, docs/results.md)",
                     material, s.material_note);
}

// The tool of a condition as the measurements give it: its angles, and its edge radius where the file's tools differ
// in it ("" where they give none).
std::string tool_text(const Condition& c, bool with_edge_radius) {
  std::string t = c.rake_deg ? fmt::format("rake {:g}°", *c.rake_deg) : "";
  if (c.clearance_deg) t += (t.empty() ? "" : ", ") + fmt::format("clearance {:g}°", *c.clearance_deg);
  if (with_edge_radius && edge_radius_names_tool(c)) t += (t.empty() ? "" : ", ") + fmt::format("r_n {:g} µm", c.edge_radius_um);
  return t;
}

// Conditions cut with the same tool (as far as the measurements give it).
bool same_tool(const Condition& a, const Condition& b) {
  return a.rake_deg == b.rake_deg && a.clearance_deg == b.clearance_deg &&
         (!edge_radius_names_tool(a) || a.edge_radius_um == b.edge_radius_um);
}

}  // namespace mpmcut::validation
