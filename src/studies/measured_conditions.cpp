#include "studies/measured_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include <fmt/format.h>

#include "analysis/chip_analysis.hpp"
#include "cutting/cutting_parameters.hpp"
#include "cutting/cutting_resolution.hpp"
#include "cutting/tool_geometry.hpp"
#include "io/edit_distance.hpp"
#include "io/input_error.hpp"
#include "io/material_library.hpp"
#include "io/toml_reader.hpp"

namespace mpmcut {

namespace {

// The cells of one CSV line; a cell in double quotes may hold commas, and "" in it is one quote (as the tables
// this program writes quote them: TextTable::write_csv).
std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"') cells.back() += c;
      else if (i + 1 < line.size() && line[i + 1] == '"') cells.back() += line[++i];
      else quoted = false;
    } else if (c == '"' && cells.back().empty()) {
      quoted = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

}  // namespace

DataFile read_data_file(std::string_view text, const std::string& source) {
  DataFile f;
  f.source = source;
  std::istringstream in{std::string(text)};
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // The byte-order mark that spreadsheet programs put at the start of a "CSV UTF-8" file is not text.
    if (line_number == 1 && line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3);
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> cells = split_csv_line(line);
    if (f.columns.empty()) {
      for (std::size_t i = 0; i < cells.size(); ++i)
        if (std::find(cells.begin(), cells.begin() + static_cast<std::ptrdiff_t>(i), cells[i]) !=
            cells.begin() + static_cast<std::ptrdiff_t>(i))
          throw InputError(fmt::format("{}:{}: the column '{}' appears twice in the header line", source, line_number,
                                       cells[i]));
      f.columns = cells;
      f.header_line = line_number;
      continue;
    }
    if (cells.size() > f.columns.size())
      throw InputError(fmt::format("{}:{}: {} cells, but the header line (line {}) names {} columns", source,
                                   line_number, cells.size(), f.header_line, f.columns.size()));
    DataFile::Row row;
    row.line = line_number;
    for (std::size_t i = 0; i < f.columns.size(); ++i) row.cells[f.columns[i]] = i < cells.size() ? cells[i] : "";
    f.rows.push_back(std::move(row));
  }
  return f;
}

void DataFile::require_columns(const std::vector<std::string>& names) const {
  std::string missing;
  for (const std::string& n : names)
    if (std::find(columns.begin(), columns.end(), n) == columns.end()) missing += (missing.empty() ? "'" : ", '") + n + "'";
  if (missing.empty()) return;
  std::string have;
  for (const std::string& c : columns) have += (have.empty() ? "" : ", ") + c;
  throw InputError(fmt::format("{}:{}: missing column(s) {} (the header line has: {})", source,
                               header_line > 0 ? header_line : 1, missing, have.empty() ? "no header line" : have));
}

double DataFile::number(const Row& row, const std::string& column) const {
  const auto it = row.cells.find(column);
  if (it == row.cells.end() || it->second.empty()) return NAN;
  const char* begin = it->second.c_str();
  char* end = nullptr;
  const double x = std::strtod(begin, &end);
  if (end == begin || *end != '\0')
    throw InputError(fmt::format("{}:{}: column '{}': must be a number, got \"{}\"", source, row.line, column, it->second));
  return x;
}

std::optional<double> DataFile::number_in(const Row& row, const std::string& column, const Range& range) const {
  const double x = number(row, column);
  if (std::isnan(x)) {
    const auto it = row.cells.find(column);
    if (it == row.cells.end() || it->second.empty()) return std::nullopt;
  }
  if (!range.contains(x))  // NaN too
    throw InputError(fmt::format("{}:{}: column '{}': must be {}, got {}", source, row.line, column, range.text(),
                                 row.cells.at(column)));
  return x;
}

void DataFile::refuse_misspelt_columns(const std::vector<std::string>& known) const {
  for (const std::string& column : columns) {
    if (std::find(known.begin(), known.end(), column) != known.end()) continue;
    for (const std::string& name : known)
      if (levenshtein(column, name) <= (name.size() >= 8 ? 2u : 1u))  // "notes" is no misspelt "tests"
        throw InputError(fmt::format("{}:{}: column '{}' is not one this file format knows: did you mean '{}'?", source,
                                     header_line, column, name));
  }
}

const std::vector<std::string>& required_force_columns() {
  static const std::vector<std::string> columns{"h_mm", "vc_m_per_min", "Fc_mean_N", "Ff_mean_N", "edge_radius_um"};
  return columns;
}

// The columns a force file may have besides the required ones (the built-in file's own extra ones included).
const std::vector<std::string>& optional_force_columns() {
  static const std::vector<std::string> columns{
      "n_tests",     "Fc_min_N", "Fc_max_N",      "Ff_min_N",          "Ff_max_N", "chip_thickness_um",
      "status",      "rake_deg", "clearance_deg", "width_mm",          "tests",    "chip_thickness_n"};
  return columns;
}

std::vector<MeasuredForces> read_measured_forces(const DataFile& file) {
  file.require_columns(required_force_columns());
  if (file.rows.empty())
    throw InputError(fmt::format("{}:{}: no data rows after the header line: nothing to compare with", file.source,
                                 file.header_line));
  std::vector<std::string> known = required_force_columns();
  known.insert(known.end(), optional_force_columns().begin(), optional_force_columns().end());
  file.refuse_misspelt_columns(known);
  std::vector<MeasuredForces> out;
  // The tool as simulated: angles left out are the preset's, so a row giving those explicitly is the same cut.
  const CuttingParameters preset;
  std::map<std::tuple<double, double, double, double, double>, int> line_of_cut;
  for (const DataFile::Row& r : file.rows) {
    MeasuredForces m;
    m.line = r.line;
    for (const std::string& key : required_force_columns())
      if (const double x = file.number(r, key); !std::isfinite(x))
        throw InputError(std::isnan(x) && r.cells.at(key).empty()
                             ? fmt::format("{}:{}: column '{}': a value is needed in every row", file.source, r.line, key)
                             : fmt::format("{}:{}: column '{}': must be a finite number, got \"{}\"", file.source,
                                           r.line, key, r.cells.at(key)));
    m.h_mm = file.number(r, "h_mm");
    m.vc_m_per_min = file.number(r, "vc_m_per_min");
    m.fc_N = file.number(r, "Fc_mean_N");
    m.ff_N = file.number(r, "Ff_mean_N");
    m.edge_radius_um = file.number(r, "edge_radius_um");
    const auto or_mean = [&](const char* key, double mean) {
      const double x = file.number(r, key);
      return std::isfinite(x) ? x : mean;
    };
    m.fc_min_N = or_mean("Fc_min_N", m.fc_N);
    m.fc_max_N = or_mean("Fc_max_N", m.fc_N);
    m.ff_min_N = or_mean("Ff_min_N", m.ff_N);
    m.ff_max_N = or_mean("Ff_max_N", m.ff_N);
    // The range of the tests holds their mean: an inverted or misplaced one made "in range" and the ratio's range
    // meaningless.
    for (const auto& [force, mean, lo, hi] : {std::tuple{"Fc", m.fc_N, m.fc_min_N, m.fc_max_N},
                                              std::tuple{"Ff", m.ff_N, m.ff_min_N, m.ff_max_N}})
      if (!(lo <= mean && mean <= hi))
        throw InputError(fmt::format("{}:{}: columns '{}_min_N', '{}_mean_N', '{}_max_N': the mean {:g} N must lie in "
                                     "[min, max] = [{:g}, {:g}] N",
                                     file.source, r.line, force, force, force, mean, lo, hi));
    const double n = file.number(r, "n_tests");
    m.n_tests = std::isfinite(n) ? static_cast<int>(n) : 1;
    // Given: positive (a 0 or a negative was dropped silently, the chip term with it).
    m.chip_thickness_um = file.number_in(r, "chip_thickness_um", Range::open_closed(0.0, 1e5, "um"));
    m.rake_deg = file.number_in(r, "rake_deg", kRakeColumn);
    m.clearance_deg = file.number_in(r, "clearance_deg", kClearanceColumn);
    m.width_mm = file.number_in(r, "width_mm", Range::open_closed(0.0, 1000.0, "mm"));
    const auto status = r.cells.find("status");
    m.status = status == r.cells.end() || status->second.empty() ? "ok" : status->second;
    for (const auto& [key, value] : {std::pair{"h_mm", m.h_mm}, {"vc_m_per_min", m.vc_m_per_min},
                                     {"Fc_mean_N", m.fc_N}})
      if (!(value > 0))
        throw InputError(fmt::format("{}:{}: column '{}': must be positive, got {}", file.source, r.line, key, value));
    // 0 is a sharp edge, as cutting.edge_radius allows (the case checks the upper bound, 10 t0).
    if (!(m.edge_radius_um >= 0))
      throw InputError(fmt::format("{}:{}: column 'edge_radius_um': must be 0 (a sharp edge) or positive, got {}",
                                   file.source, r.line, m.edge_radius_um));
    const std::tuple cut{m.h_mm, m.vc_m_per_min, m.edge_radius_um, m.rake_deg.value_or(preset.rake_angle_deg),
                         m.clearance_deg.value_or(preset.clearance_angle_deg)};
    if (const auto [it, added] = line_of_cut.emplace(cut, m.line); !added)
      throw InputError(fmt::format("{}:{}: the same cut as line {} (h, speed, edge radius and tool angles; a row "
                                   "without angles has the preset's, rake {:g} deg and clearance {:g} deg): one row "
                                   "per cut, rows of repeated tests averaged into one as in the data files",
                                   file.source, r.line, it->second, preset.rake_angle_deg, preset.clearance_angle_deg));
    out.push_back(m);
  }
  // One cut with several edge radii: the file's tools differ in r_n (ids and tools name it; files without, such as
  // the built-in one whose r_n was measured per test, keep theirs).
  std::map<std::string, std::set<double>> radii_of_id;
  for (const MeasuredForces& m : out) radii_of_id[force_condition_id(m)].insert(m.edge_radius_um);
  const bool by_radius = std::any_of(radii_of_id.begin(), radii_of_id.end(), [](const auto& r) { return r.second.size() > 1; });
  for (MeasuredForces& m : out) m.edge_radius_names_tool = by_radius;
  return out;
}

MeasuredForces MeasuredForces::per_mm_of_width(double assumed_width_mm) const {
  MeasuredForces m = *this;
  const double b = width_mm.value_or(assumed_width_mm);
  for (double* force : {&m.fc_N, &m.fc_min_N, &m.fc_max_N, &m.ff_N, &m.ff_min_N, &m.ff_max_N}) *force /= b;
  return m;
}

std::string force_condition_id(const MeasuredForces& m) {
  std::string id = fmt::format("forces_h{:g}mm_vc{:g}mpmin", m.h_mm, m.vc_m_per_min);
  if (m.rake_deg) id += fmt::format("_rake{:g}deg", *m.rake_deg);
  if (m.clearance_deg) id += fmt::format("_clearance{:g}deg", *m.clearance_deg);
  if (m.edge_radius_names_tool) id += fmt::format("_rn{:g}um", m.edge_radius_um);
  return id;
}

CuttingCondition force_condition(const MeasuredForces& m) {
  CuttingCondition c;
  c.id = force_condition_id(m);
  c.kind = "forces";
  c.speed_m_per_s = m.vc_m_per_min / 60.0;
  c.h_mm = m.h_mm;
  c.edge_radius_um = m.edge_radius_um;
  c.rake_deg = m.rake_deg;
  c.clearance_deg = m.clearance_deg;
  c.width_mm = m.width_mm;
  return c;
}

int chip_cells_per_feed(const ConditionRunSettings& o) {
  return std::max({o.cells_per_feed, o.chip_type_cells_per_feed,
                   static_cast<int>(std::ceil(ChipThresholds{}.resolved_cells_per_feed))});
}

double validation_cell_size_m(double t0, double edge_radius, int cells_per_feed, double cells_per_edge_radius,
                              double thermal_length, double cells_per_thermal_length) {
  double cell = t0 / cells_per_feed;
  if (cells_per_edge_radius > 0.0 && edge_radius > 0.0) cell = std::min(cell, edge_radius / cells_per_edge_radius);
  if (cells_per_thermal_length > 0.0 && thermal_length > 0.0)
    cell = std::min(cell, thermal_length / cells_per_thermal_length);
  return cell;
}

namespace {

// The [[material]] tables a case of these settings holds before [cutting], and the name [cutting] uses.
std::pair<std::string, std::string> case_materials_text(const ConditionRunSettings& o) {
  std::string s, material = o.material;
  if (!o.material_definitions.empty()) {
    s += "\n# the material file given to the study (its [[material]] sets, as read):\n";
    s += o.material_definitions;
    if (s.back() != '\n') s += '\n';
    s += "\n";
  }
  if (!o.material_overrides.empty()) {
    // The trial set: the library set with the changed keys; each value written so that it reads back as exactly the
    // optimizer's value.
    material = "trial";
    s += "\n[[material]]\n";
    s += "name = \"trial\"\n";
    s += fmt::format("library = \"{}\"\n", o.material);
    for (const auto& [key, value] : o.material_overrides) s += fmt::format("{} = {}\n", key, value);  // {} is the shortest text that reads back exactly
    s += "\n";
  }
  return {s, material};
}

}  // namespace

double workpiece_thermal_diffusivity_m2_per_s(const ConditionRunSettings& o) {
  const auto [text, name] = case_materials_text(o);
  const toml::table root = parse_toml(text, "the study's material sets");
  TableReader top(root, "", std::make_shared<InputSource>(InputSource{"the study's material sets", {}}));
  MaterialLibrary library = builtin_material_library();
  read_case_materials(top, library);
  const MaterialParameters* m = library.find(name);
  if (m == nullptr) throw InputError(fmt::format("material \"{}\": no such set in the library or the study's file", name));
  return m->thermal_diffusivity();
}

double validation_cut_length_m(double t0, double edge_radius) { return 6.0 * std::max(t0, edge_radius); }

double validation_workpiece_height_m(double t0, double edge_radius) {
  return t0 + std::max(3.0 * t0, 2.0 * edge_radius);
}

std::string condition_case_text(const CuttingCondition& c, const ConditionRunSettings& o) {
  const double h = c.h_mm * 1e-3;
  const double r_n = c.edge_radius_um * 1e-6;
  const int cells_per_feed = c.kind == "chip" ? chip_cells_per_feed(o) : o.cells_per_feed;
  // The edge-radius limit is for measured edges: the force conditions' and a chip-type condition's whose source gives
  // one; the others have the preset's 5 um edge, which at r_n/M would be a 1 um cell at 75 m/s.
  const bool measured_edge = c.kind == "forces" || c.edge_radius_given;
  const double cells_per_edge_radius = measured_edge ? o.cells_per_edge_radius : 0.0;
  const double l_th = o.cells_per_thermal_length > 0.0
                          ? thermal_length_m(workpiece_thermal_diffusivity_m2_per_s(o), h, c.speed_m_per_s)
                          : 0.0;
  const double cell = o.quick ? 0.25 * h
                              : validation_cell_size_m(h, r_n, cells_per_feed, cells_per_edge_radius, l_th,
                                                       o.cells_per_thermal_length);
  // quick: four cells of tool travel (pipeline check, numbers not meaningful) after the tool meets the workpiece (an
  // edge radius above h meets it late: at h = 0.01 mm, r_n = 39.8 um, the quick cut never touched it).
  CuttingParameters tool;
  tool.uncut_chip_thickness = h;
  tool.edge_radius = r_n;
  if (c.rake_deg) tool.rake_angle_deg = *c.rake_deg;
  if (c.clearance_deg) tool.clearance_angle_deg = *c.clearance_deg;
  const double cut = o.quick ? 4.0 * cell + tool_engagement_travel(tool) : validation_cut_length_m(h, r_n);
  const double height = validation_workpiece_height_m(h, r_n);
  std::string s;
  s += fmt::format("title = \"{} {}: V = {:g} m/s ({:g} m/min), h = {:g} mm\"\n", o.purpose, c.id, c.speed_m_per_s,
                   c.speed_m_per_s * 60.0, c.h_mm);
  const auto [materials, material] = case_materials_text(o);
  s += materials;
  s += "[cutting]\n";
  s += fmt::format("material = \"{}\"  # {}\n", material, o.material_note);
  s += fmt::format("cutting_speed = {}\n", c.speed_m_per_s);
  s += fmt::format("uncut_chip_thickness = {}\n", h);
  const char* angles_from = c.kind == "forces" ? "from the measurements" : "from the chip observations";
  s += c.kind == "chip" ? "width_of_cut = 1e-3  # per mm of width: a chip-type condition compares no forces\n"
       : c.width_mm     ? fmt::format("width_of_cut = 1e-3  # per mm: the measured forces are divided by the tests' width "
                                "b = {:g} mm\n",
                                *c.width_mm)
                  : "width_of_cut = 1e-3  # ASSUMPTION b = 1 mm: the width of cut is not in the Klippel data file\n";
  // Without the angles in the measurements, the text of the runs made before they could be given (records match).
  s += c.rake_deg ? fmt::format("rake_angle_deg = {}  # {}\n", *c.rake_deg, angles_from)
                  : "rake_angle_deg = 0.0       # ASSUMPTION: not in the data file\n";
  s += c.clearance_deg ? fmt::format("clearance_angle_deg = {}  # {}\n", *c.clearance_deg, angles_from)
                       : "clearance_angle_deg = 11.0 # ASSUMPTION: not in the data file\n";
  s += fmt::format("edge_radius = {}  # {}\n", c.edge_radius_um * 1e-6,
                   c.kind == "forces"     ? "measured mean r_n of the tests"
                   : c.edge_radius_given ? "from the chip observations"
                                         : "preset default: not stated in the source");
  s += fmt::format("friction = {}  # {}\n", o.friction, o.friction_note);
  // Where a thermal setting came from: validate's option, or the calibration's [runs] key of the same name.
  const auto chosen = [&](const char* option) {
    return o.purpose == "calibration" ? std::string("chosen in the calibration's [runs]")
                                      : fmt::format("chosen with {}", option);
  };
  const auto or_chosen = [&](const std::string& note, const char* option) {
    return note.empty() ? chosen(option) : note;
  };
  if (o.friction_heat_share)
    s += fmt::format("friction_heat_share = {}  # {} (the rest flows into the tool)\n", *o.friction_heat_share,
                     chosen("--friction-heat-share"));
  if (o.tool_heat_transfer_coefficient)
    s += fmt::format("tool_heat_transfer_coefficient = {}  # W/(m^2 K), {}\n", *o.tool_heat_transfer_coefficient,
                     or_chosen(o.tool_heat_transfer_note, "--tool-heat-transfer-coefficient"));
  if (o.tool_temperature)
    s += fmt::format("tool_temperature = {}  # K, {}\n", *o.tool_temperature, chosen("--tool-temperature"));
  if (o.tool_conductivity)
    s += fmt::format("tool_conductivity = {}  # W/(m K), {}\n", *o.tool_conductivity, or_chosen(o.tool_conductivity_note, "--tool-conductivity"));
  if (o.tool_volumetric_heat_capacity)
    s += fmt::format("tool_volumetric_heat_capacity = {}  # J/(m^3 K), {}\n", *o.tool_volumetric_heat_capacity,
                     chosen("--tool-volumetric-heat-capacity"));
  s += fmt::format("cell_size = {}  # {}\n", cell,
                   o.quick ? "quick: t0/4 (pipeline check, not converged)"
                   : o.cells_per_thermal_length > 0.0
                       ? fmt::format("min(t0/N, r_n/M, l_th/K), N = {} cells across t0, M = {:g} across r_n, K = {:g} "
                                     "across the thermal length l_th = sqrt(kappa t0/V) = {:.3g} um: {:.3g}, {:.3g} and "
                                     "{:.3g} cells",
                                     cells_per_feed, cells_per_edge_radius, o.cells_per_thermal_length, l_th * 1e6,
                                     h / cell, r_n / cell, l_th / cell)
                       : fmt::format("min(t0/N, r_n/M), N = {} cells across t0, M = {:g} across r_n: {:.3g} and {:.3g} "
                                     "cells",
                                     cells_per_feed, cells_per_edge_radius, h / cell, r_n / cell));
  s += fmt::format("cut_length = {}  # {}\n", cut, o.quick ? "quick: 4 cells" : "6 max(t0, r_n)");
  s += fmt::format("workpiece_height = {}  # t0 + max(3 t0, 2 r_n)\n", height);
  s += "mass_scaling = \"auto\"     # workpiece inertia up to an inertia number of 0.002 (docs/mass_scaling.md)\n";
  s += fmt::format("particles_per_cell = {}\n", o.quick ? 1 : 2);
  s += fmt::format("snapshots = {}\n", o.snapshots > 0 ? o.snapshots : o.quick ? 2 : 20);
  std::string solver;
  if (!o.contact_detection.empty())
    solver += fmt::format("contact_detection = \"{}\"  # chosen with --contact-detection\n", o.contact_detection);
  if (!o.volumetric_average.empty())
    solver += fmt::format("volumetric_average = \"{}\"  # chosen with --volumetric-average\n", o.volumetric_average);
  if (!solver.empty()) s += "\n[solver]\n" + solver;
  return s;
}

}  // namespace mpmcut
