// Reading and checking a calibration configuration (studies/calibration.hpp; docs/calibration.md).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include <fmt/format.h>
#include <nlopt.h>

#include "cutting/tool_heat_settings.hpp"
#include "io/material_keys.hpp"
#include "io/material_library.hpp"
#include "io/scene_writer.hpp"
#include "io/toml_reader.hpp"
#include "io/whole_file.hpp"
#include "run/run_case.hpp"
#include "studies/calibration.hpp"

namespace mpmcut {

namespace {

namespace fs = std::filesystem;

// Whether the base set with `key = value` is a valid material; the reader's message if not.
std::string material_problem(const std::string& base, const std::string& key, double value) {
  const std::string text = fmt::format("[[material]]\nname = \"check\"\nlibrary = \"{}\"\n{} = {}\n", base, key, value);
  try {
    const toml::table root = parse_toml(text, "calibration trial");
    TableReader file(root, "", std::make_shared<InputSource>(InputSource{"calibration trial", {}}));
    for (TableReader& t : file.array_of_tables("material")) read_material(t, builtin_material_library());
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

nlopt_algorithm algorithm(TableReader& t, const char* key, const std::string& name, const char* prefix) {
  const nlopt_algorithm a = nlopt_algorithm_from_string(name.c_str());
  if (static_cast<int>(a) < 0 || !name.starts_with(prefix))
    t.fail(key, fmt::format("\"{}\" is not an NLopt {} algorithm without derivatives (names as in NLopt without "
                            "\"NLOPT_\", starting with {}: e.g. {}), or \"none\"",
                            name, std::string_view(prefix) == "GN_" ? "global" : "local", prefix,
                            std::string_view(prefix) == "GN_" ? "GN_CRS2_LM, GN_ISRES, GN_DIRECT_L"
                                                              : "LN_BOBYQA, LN_COBYLA, LN_NELDERMEAD"));
  return a;
}

}  // namespace

CalibrationConfig read_calibration_config(const fs::path& file, std::string_view builtin_forces_csv) {
  const std::optional<std::string> text = read_whole_file(file);
  if (!text)
    throw InputError(fmt::format("{}: cannot read the calibration file: {}", file.string(), unreadable_reason(file)));
  const toml::table root = parse_toml(*text, file.string());
  TableReader t(root, "", std::make_shared<InputSource>(InputSource{file.string(), {}}));

  CalibrationConfig c;
  c.file = file;
  t.require_key("name", "the name of the calibrated [[material]] set, e.g. \"ti64-calibrated\"");
  c.set_name = t.string("name", "");
  t.check("name", !c.set_name.empty(), "a non-empty string", 0.0);
  c.base_material = t.string("base_material", "ti64-cutting");
  const MaterialParameters* base = builtin_material_library().find(c.base_material);
  if (base == nullptr)
    t.fail("base_material", fmt::format("no material set \"{}\" in the library (docs/materials.md)", c.base_material));
  const std::map<std::string, double> keys = numeric_material_keys(*base);
  std::string key_list;
  for (const auto& [k, v] : keys) key_list += (key_list.empty() ? "" : ", ") + k;
  c.runs.purpose = "calibration";
  c.runs.material = c.base_material;
  c.runs.material_note = "the library set being calibrated (with the trial values)";

  // How each condition is run.
  if (auto r = t.optional_table("runs")) {
    c.runs.quick = r->boolean("quick", false);
    c.runs.cells_per_feed = static_cast<int>(r->integer("cells_per_feed", c.runs.cells_per_feed));
    r->check("cells_per_feed", c.runs.cells_per_feed >= 2 && c.runs.cells_per_feed <= 100, "an integer from 2 to 100",
             c.runs.cells_per_feed);
    c.runs.cells_per_edge_radius = r->number("cells_per_edge_radius", c.runs.cells_per_edge_radius);
    r->check("cells_per_edge_radius", c.runs.cells_per_edge_radius >= 0.0 && c.runs.cells_per_edge_radius <= 100.0,
             "a number from 0 (no limit) to 100", c.runs.cells_per_edge_radius);
    c.runs.cells_per_thermal_length = r->number("cells_per_thermal_length", c.runs.cells_per_thermal_length);
    r->check("cells_per_thermal_length", c.runs.cells_per_thermal_length >= 0.0 && c.runs.cells_per_thermal_length <= 100.0,
             "a number from 0 (no limit) to 100", c.runs.cells_per_thermal_length);
    c.threads = static_cast<int>(r->integer("threads", 1));
    r->check("threads", c.threads >= 1 && c.threads <= kMaxThreads, fmt::format("an integer from 1 to {}", kMaxThreads), c.threads);
    c.runs.friction = r->number("friction", c.runs.friction);
    r->check("friction", c.runs.friction >= 0.0 && c.runs.friction <= 2.0, "a Coulomb coefficient in [0, 2]",
             c.runs.friction);
    // The case files say where a fixed friction came from (it said "preset default" for a value given here).
    if (r->has("friction")) c.runs.friction_note = "the calibration's [runs] friction";
    // The contact of every run, as `validate --contact-detection` (empty: the preset's, and the case files carry no
    // [solver] table, as before the key existed).
    // Likewise the volumetric strain rate, as `validate --volumetric-average`.
    const auto solver_choice = [&](const char* key, const std::vector<std::string>& names) {
      const std::string value = r->string(key, "");
      if (!r->has(key)) return value;
      std::string allowed;
      for (const std::string& n : names) allowed += (allowed.empty() ? "one of \"" : " | \"") + n + "\"";
      if (std::find(names.begin(), names.end(), value) == names.end())
        r->fail(key, fmt::format("must be {}, got \"{}\"", allowed, value));
      return value;
    };
    c.runs.contact_detection = solver_choice("contact_detection", contact_detection_names());
    c.runs.volumetric_average = solver_choice("volumetric_average", volumetric_average_names());
    // The tool's heat, as validate's thermal options (none given: an adiabatic tool, the case text as before), with
    // the bounds of their [cutting] keys and the conditions between them checked here, at the config's line, before
    // any run.
    const auto thermal = [&](const ToolHeatKey& key) {
      std::optional<double> value = r->optional_number(key.key);
      if (value) r->check(key.key, *value, key.range);
      return value;
    };
    c.runs.friction_heat_share = thermal(kFrictionHeatShare);
    c.runs.tool_heat_transfer_coefficient = thermal(kToolHeatTransferCoefficient);
    c.runs.tool_temperature = thermal(kToolTemperature);
    c.runs.tool_conductivity = thermal(kToolConductivity);
    c.runs.tool_volumetric_heat_capacity = thermal(kToolVolumetricHeatCapacity);
    if (const auto conflict = tool_heat_conflict({c.runs.friction_heat_share.value_or(1.0),
                                                  c.runs.tool_heat_transfer_coefficient.value_or(0.0),
                                                  c.runs.tool_conductivity.value_or(0.0),
                                                  c.runs.tool_volumetric_heat_capacity.value_or(0.0)},
                                                 "runs."))
      r->check(conflict->key, false, conflict->allowed, conflict->value);
    r->reject_unknown_keys();
  }

  // Material keys held at other values than the base set's: part of the fitted set, not free.
  std::map<std::string, double> fixed;
  if (auto f = t.optional_table("fixed")) {
    std::vector<std::string> given;  // in toml++'s order (by name)
    for (const auto& [key, node] : *root["fixed"].as_table()) given.emplace_back(key.str());
    for (const std::string& key : given) {
      if (!keys.contains(key))
        f->fail(key, fmt::format("unknown key \"{}\": a fixed key is a numeric key of the material set \"{}\": {}", key,
                                 c.base_material, key_list));
      const double value = f->number(key, 0.0);
      if (const std::string problem = material_problem(c.base_material, key, value); !problem.empty())
        f->fail(key, fmt::format("the material is not valid with this value: {}", problem));
      fixed[key] = value;
      c.runs.material_overrides.emplace_back(key, value);
    }
  }

  // The free parameters.
  std::vector<TableReader> params = t.array_of_tables("parameter");
  if (params.empty()) t.fail_table("no [[parameter]] tables: name at least one free parameter");
  for (TableReader& p : params) {
    CalibrationParameter q;
    p.require_key("name", "a numeric material key (e.g. jc_A) or \"friction\"");
    q.name = p.string("name", "");
    q.location = p.location("name");
    const bool friction = q.name == "friction";
    if (!friction) q.unit = material_key_unit(q.name);
    if (!friction && !keys.contains(q.name))
      p.fail("name", fmt::format("unknown parameter \"{}\": a free parameter is \"friction\" or a numeric key of the "
                                 "material set \"{}\": {}",
                                 q.name, c.base_material, key_list));
    for (const CalibrationParameter& other : c.parameters)
      if (other.name == q.name) p.fail("name", fmt::format("\"{}\" is already free (at {})", q.name, other.location));
    if (fixed.contains(q.name))
      p.fail("name", fmt::format("\"{}\" is fixed in [fixed]: a key is free or fixed, not both", q.name));
    p.require_key("min", "lower bound, in the key's unit");
    p.require_key("max", "upper bound, in the key's unit");
    q.min = p.number("min", 0.0);
    q.max = p.number("max", 0.0);
    p.check("max", q.max > q.min, fmt::format("greater than min ({})", q.min), q.max);
    q.log_scale = p.boolean("log_scale", false);
    if (q.log_scale) p.check("min", q.min > 0.0, "> 0 with log_scale = true", q.min);
    const double base_value = friction ? c.runs.friction : keys.at(q.name);
    q.start = p.number("start", base_value);
    if (!(q.start >= q.min && q.start <= q.max)) {
      const std::string what =
          p.has("start")  ? ""
          : friction ? fmt::format(" (the start value is [runs] friction = {})", base_value)
                     : fmt::format(" (the start value is {}'s {} = {})", c.base_material, q.name, base_value);
      p.fail(p.has("start") ? "start" : "min",
             fmt::format("the bounds [{}, {}] exclude the start value {}{}", q.min, q.max, q.start, what));
    }
    for (const char* bound : {"min", "max"}) {
      const double value = std::string_view(bound) == "min" ? q.min : q.max;
      if (friction) {
        p.check(bound, value >= 0.0 && value <= 2.0, "a Coulomb coefficient in [0, 2] for \"friction\"", value);
      } else if (const std::string problem = material_problem(c.base_material, q.name, value); !problem.empty()) {
        p.fail(bound, fmt::format("the material is not valid at this bound: {}", problem));
      }
    }
    p.reject_unknown_keys();
    c.parameters.push_back(q);
  }

  // The measurements and the conditions.
  TableReader data = t.table("data");
  DataFile measurements;
  if (data.has("measurements")) {
    const std::string name = data.string("measurements", "");
    const fs::path path = name.starts_with('/') ? fs::path(name) : file.parent_path() / name;
    const std::optional<std::string> text = read_whole_file(path);
    if (!text)
      data.fail("measurements",
                fmt::format("cannot read the measurement file {}: {}", path.string(), unreadable_reason(path)));
    c.measurements_source = path.string();
    measurements = read_data_file(*text, c.measurements_source);
  } else {
    c.measurements_source = kBuiltinForcesFile;
    measurements = read_data_file(builtin_forces_csv, c.measurements_source);
  }
  const std::vector<MeasuredForces> rows = read_measured_forces(measurements);
  const auto select = [&](const char* key, std::vector<MeasuredForces>& into) {
    for (TableReader& s : data.array_of_tables(key)) {
      s.require_key("h_mm", "uncut chip thickness of a row of the measurement file, mm");
      s.require_key("vc_m_per_min", "cutting speed of a row of the measurement file, m/min");
      const double h = s.number("h_mm", 0.0), vc = s.number("vc_m_per_min", 0.0);
      // The tool's angles pick a row among rows of one h and speed (measurements with rake_deg / clearance_deg).
      std::optional<double> rake, clearance;
      if (s.has("rake_deg")) rake.emplace(s.number("rake_deg", 0.0));
      if (s.has("clearance_deg")) clearance.emplace(s.number("clearance_deg", 0.0));
      // And the edge radius among rows of one tool's angles (a file with several edge radii).
      std::optional<double> edge_radius;
      if (s.has("edge_radius_um")) edge_radius.emplace(s.number("edge_radius_um", 0.0));
      const int cells_per_feed = static_cast<int>(s.integer("cells_per_feed", 0));  // 0: [runs] cells_per_feed
      if (s.has("cells_per_feed"))
        s.check("cells_per_feed", cells_per_feed >= 2 && cells_per_feed <= 100,
                "an integer from 2 to 100 (this condition's cells across t0)", cells_per_feed);
      s.reject_unknown_keys();
      const auto same_angle = [](const std::optional<double>& wanted, const std::optional<double>& row) {
        return !wanted || (row && std::abs(*row - *wanted) < 1e-9);
      };
      const MeasuredForces* found = nullptr;
      std::string matching_lines;
      int matches = 0;
      for (const MeasuredForces& r : rows)
        if (std::abs(r.h_mm - h) < 1e-9 && std::abs(r.vc_m_per_min - vc) < 1e-6 && same_angle(rake, r.rake_deg) &&
            same_angle(clearance, r.clearance_deg) &&
            (!edge_radius || std::abs(r.edge_radius_um - *edge_radius) < 1e-9)) {
          found = &r;
          ++matches;
          matching_lines += (matching_lines.empty() ? "" : ", ") + std::to_string(r.line);
        }
      const std::string angles = (rake ? fmt::format(", rake_deg = {}", *rake) : std::string()) +
                                 (clearance ? fmt::format(", clearance_deg = {}", *clearance) : std::string()) +
                                 (edge_radius ? fmt::format(", edge_radius_um = {}", *edge_radius) : std::string());
      if (!found)
        s.fail("vc_m_per_min", fmt::format("no row with h_mm = {} and vc_m_per_min = {}{} in {}", h, vc, angles,
                                           c.measurements_source));
      if (matches > 1)
        s.fail("vc_m_per_min",
               fmt::format("{} rows of {} match h_mm = {}, vc_m_per_min = {}{} (lines {}): name one with rake_deg, "
                           "clearance_deg and/or edge_radius_um",
                           matches, c.measurements_source, h, vc, angles, matching_lines));
      for (const auto& [name, list] : {std::pair{"training", &c.training}, std::pair{"held_back", &c.held_back}})
        for (const MeasuredForces& r : *list)
          if (r.line == found->line)
            s.fail("vc_m_per_min", fmt::format("the condition h_mm = {}, vc_m_per_min = {} is selected twice (it is "
                                               "in {} already): a condition is fitted or held back, once",
                                               h, vc, name));
      into.push_back(*found);
      if (cells_per_feed > 0) c.cells_per_feed_by_line[found->line] = cells_per_feed;
    }
  };
  data.require_key("training", "the training conditions: [{h_mm = 0.1, vc_m_per_min = 100.0}, ...]");
  select("training", c.training);
  if (c.training.empty())
    data.fail("training", "empty training set: select at least one condition of the measurement file");
  select("held_back", c.held_back);
  data.reject_unknown_keys();

  // The objective.
  if (auto o = t.optional_table("objective")) {
    c.weight_fc = o->number("weight_Fc", c.weight_fc);
    c.weight_ft = o->number("weight_Ft", c.weight_ft);
    c.weight_chip_thickness = o->number("weight_chip_thickness", c.weight_chip_thickness);
    for (const char* k : {"weight_Fc", "weight_Ft", "weight_chip_thickness"})
      o->check(k, o->number(k, 0.0) >= 0.0, ">= 0", o->number(k, 0.0));
    o->check("weight_Fc", c.weight_fc + c.weight_ft + c.weight_chip_thickness > 0.0,
             "such that at least one weight is positive", c.weight_fc);
    c.width_of_cut_mm = o->number("width_of_cut_mm", c.width_of_cut_mm);
    o->check("width_of_cut_mm", c.width_of_cut_mm > 0.0, "a positive width (mm)", c.width_of_cut_mm);
    o->reject_unknown_keys();
  }
  // Every condition must have a measured quantity the objective weighs: a row without chip thickness, with only
  // weight_chip_thickness > 0, made the objective 0/0 (NaN, reported as the best value).
  for (const auto& [list, conditions] : {std::pair{"training", &c.training}, std::pair{"held_back", &c.held_back}})
    for (const MeasuredForces& m : *conditions)
      if (c.weight_fc + c.weight_ft + (m.chip_thickness_um ? c.weight_chip_thickness : 0.0) <= 0.0)
        data.fail(list, fmt::format("the condition h_mm = {}, vc_m_per_min = {} (line {} of {}) has no measured "
                                    "quantity that the objective weighs: weight_Fc = {} and weight_Ft = {}, and the "
                                    "row gives no chip_thickness_um; weigh a force, or pick a row with a chip "
                                    "thickness",
                                    m.h_mm, m.vc_m_per_min, m.line, c.measurements_source, c.weight_fc, c.weight_ft));

  // The optimizer.
  if (auto o = t.optional_table("optimizer")) {
    c.global_algorithm = o->string("global", c.global_algorithm);
    c.local_algorithm = o->string("local", c.local_algorithm);
    c.evaluations = static_cast<int>(o->integer("evaluations", c.evaluations));
    o->check("evaluations", c.evaluations >= 1 && c.evaluations <= 100000, "an integer from 1 to 100000",
             c.evaluations);
    c.global_evaluations = static_cast<int>(o->integer("global_evaluations", std::min(c.global_evaluations, c.evaluations)));
    o->check("global_evaluations", c.global_evaluations >= 0 && c.global_evaluations <= c.evaluations,
             fmt::format("an integer from 0 to evaluations ({})", c.evaluations), c.global_evaluations);
    const long long seed = o->integer("seed", c.seed);
    o->check("seed", seed >= 0 && seed <= 4294967295LL, "an integer from 0 to 4294967295", seed);
    c.seed = static_cast<unsigned>(seed);
    if (c.global_algorithm != "none") algorithm(*o, "global", c.global_algorithm, "GN_");
    if (c.local_algorithm != "none") algorithm(*o, "local", c.local_algorithm, "LN_");
    if (c.global_algorithm == "none" && c.local_algorithm == "none")
      o->fail("local", "both stages are \"none\": name at least one algorithm");
    o->reject_unknown_keys();
  }
  if (c.global_algorithm == "none") c.global_evaluations = 0;
  if (c.local_algorithm == "none") c.global_evaluations = c.evaluations;

  t.reject_unknown_keys();
  return c;
}

}  // namespace mpmcut
