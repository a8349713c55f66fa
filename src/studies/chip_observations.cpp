#include "studies/chip_observations.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "io/input_error.hpp"

namespace mpmcut {

std::string ChipObservation::cell(const std::string& column) const {
  const auto it = cells.find(column);
  return it == cells.end() ? std::string() : it->second;
}

const std::vector<std::string>& chip_types() {
  static const std::vector<std::string> types{"continuous", "serrated", "discontinuous", "serrated->discontinuous"};
  return types;
}

const std::vector<std::string>& required_chip_columns() {
  static const std::vector<std::string> columns{"id", "chip_type", "simulate_speed_m_per_s", "h_min_mm"};
  return columns;
}

const std::vector<std::string>& optional_chip_columns() {
  static const std::vector<std::string> columns{"rake_deg", "clearance_deg", "edge_radius_um", "statement", "source",
                                                "tag", "note", "speed_min_m_per_s", "speed_max_m_per_s", "h_max_mm"};
  return columns;
}

std::vector<ChipObservation> read_chip_observations(const DataFile& file) {
  file.require_columns(required_chip_columns());
  std::vector<std::string> known = required_chip_columns();
  known.insert(known.end(), optional_chip_columns().begin(), optional_chip_columns().end());
  file.refuse_misspelt_columns(known);  // edge_radus_um ran with the preset's 5 um edge
  if (file.rows.empty())
    throw InputError(fmt::format("{}:{}: no data rows after the header line: no chip type to compare with", file.source,
                                 file.header_line));
  std::vector<ChipObservation> out;
  std::map<std::string, int> line_of_id;
  for (const DataFile::Row& r : file.rows) {
    ChipObservation o;
    o.line = r.line;
    o.cells = r.cells;
    const auto fail = [&](const std::string& column, const std::string& what) {
      throw InputError(fmt::format("{}:{}: column '{}': {}", file.source, r.line, column, what));
    };
    o.id = o.cell("id");
    if (o.id.empty()) fail("id", "a name is needed in every row");
    // It names the condition's result directory: chip_<id>_v<speed>mps.
    if (!std::all_of(o.id.begin(), o.id.end(), [](unsigned char ch) { return std::isalnum(ch) || ch == '_' || ch == '-' || ch == '.'; }))
      fail("id", fmt::format("\"{}\": letters, digits, '_', '-' and '.' only (it names the condition's directory)", o.id));
    if (const auto [it, added] = line_of_id.emplace(o.id, r.line); !added)
      fail("id", fmt::format("\"{}\" is on line {} already", o.id, it->second));
    o.chip_type = o.cell("chip_type");
    if (std::find(chip_types().begin(), chip_types().end(), o.chip_type) == chip_types().end())
      fail("chip_type", fmt::format("must be one of continuous, serrated, discontinuous, serrated->discontinuous; got \"{}\"",
                                    o.chip_type));
    const auto number_in = [&](const char* column, double lo, double hi, bool lo_open, const char* unit) {
      const double x = file.number(r, column);
      if (std::isnan(x) && o.cell(column).empty()) return std::optional<double>();
      if (!(std::isfinite(x) && (lo_open ? x > lo : x >= lo) && x < hi))
        fail(column, fmt::format("must be in {}{:g}, {:g}) {}, got {}", lo_open ? '(' : '[', lo, hi, unit, o.cell(column)));
      return std::optional<double>(x);
    };
    o.simulate_speed_m_per_s = number_in("simulate_speed_m_per_s", 0.0, 1000.0, true, "m/s");
    const std::optional<double> h = number_in("h_min_mm", 0.0, 100.0, true, "mm");
    if (o.simulate_speed_m_per_s && !h) fail("h_min_mm", "a value is needed where simulate_speed_m_per_s is given");
    o.h_mm = h.value_or(0.0);
    o.rake_deg = number_in("rake_deg", -45.0, 45.0, true, "degrees");
    o.clearance_deg = number_in("clearance_deg", 0.0, 45.0, true, "degrees");
    o.edge_radius_um = number_in("edge_radius_um", 0.0, 1000.0, false, "um");
    if (o.edge_radius_um && h && !(*o.edge_radius_um < 10.0 * 1e3 * *h))  // the cutting preset's limit
      fail("edge_radius_um", fmt::format("must be below 10 h_min_mm = {:g} um, got {:g}", 1e4 * *h, *o.edge_radius_um));
    out.push_back(o);
  }
  if (std::none_of(out.begin(), out.end(), [](const ChipObservation& o) { return o.simulate_speed_m_per_s.has_value(); }))
    throw InputError(fmt::format("{}: no row gives simulate_speed_m_per_s: nothing to simulate and compare", file.source));
  return out;
}

}  // namespace mpmcut
