#include "studies/chip_observations.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>
#include <fmt/ranges.h>

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
      fail("chip_type", fmt::format("must be one of {}; got \"{}\"", fmt::join(chip_types(), ", "), o.chip_type));
    o.simulate_speed_m_per_s = file.number_in(r, "simulate_speed_m_per_s", Range::open(0.0, 1000.0, "m/s"));
    const std::optional<double> h = file.number_in(r, "h_min_mm", Range::open(0.0, 100.0, "mm"));
    if (o.simulate_speed_m_per_s && !h) fail("h_min_mm", "a value is needed where simulate_speed_m_per_s is given");
    o.h_mm = h.value_or(0.0);
    o.rake_deg = file.number_in(r, "rake_deg", kRakeColumn);
    o.clearance_deg = file.number_in(r, "clearance_deg", kClearanceColumn);
    o.edge_radius_um = file.number_in(r, "edge_radius_um", Range::closed_open(0.0, 1000.0, "um"));
    if (o.edge_radius_um && h && !(*o.edge_radius_um < 10.0 * 1e3 * *h))  // the cutting preset's limit
      fail("edge_radius_um", fmt::format("must be below 10 h_min_mm = {:g} um, got {:g}", 1e4 * *h, *o.edge_radius_um));
    out.push_back(o);
  }
  if (std::none_of(out.begin(), out.end(), [](const ChipObservation& o) { return o.simulate_speed_m_per_s.has_value(); }))
    throw InputError(fmt::format("{}: no row gives simulate_speed_m_per_s: nothing to simulate and compare", file.source));
  return out;
}

}  // namespace mpmcut
