#include "studies/grid_convergence_report.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include <fmt/format.h>

#include "analysis/grid_convergence.hpp"
#include "io/input_error.hpp"
#include "io/whole_file.hpp"
#include "studies/measured_conditions.hpp"

namespace mpmcut {

namespace fs = std::filesystem;

namespace {

struct Quantity {
  const char* column;  // in sweep.csv
  const char* name;    // in the table
  const char* unit;
};

// The headline results of a cut and its energy partition.
constexpr Quantity kQuantities[] = {
    {"mean_cutting_force_N_per_mm", "Fc", "N/mm"},
    {"mean_thrust_force_N_per_mm", "Ft", "N/mm"},
    {"chip_thickness_ratio", "t0/tc", "-"},
    {"damage_fraction", "damage / tool work", "-"},
    {"friction_fraction", "friction / tool work", "-"},
};

std::string value_text(double x) { return fmt::format("{:.4g}", x); }
std::string percent_text(const std::optional<double>& f) {
  return f ? fmt::format("{:.1f}", 100.0 * *f) : std::string();
}

}  // namespace

GridConvergenceReport grid_convergence_report(const fs::path& sweep_csv) {
  const std::optional<std::string> text = read_whole_file(sweep_csv);
  if (!text)
    throw InputError(fmt::format("{}: cannot read (a sweep directory has sweep.csv once the sweep ran)",
                                 sweep_csv.string()));
  const DataFile f = read_data_file(*text, sweep_csv.string());
  std::vector<std::string> needed{"speed_m_per_s", "feed_mm", "cells_per_feed", "status"};
  for (const Quantity& q : kQuantities) needed.push_back(q.column);
  f.require_columns(needed);

  // Complete runs of each condition, by cell size.
  struct Run {
    double cell_um;
    int cells_per_feed;
    const DataFile::Row* row;
  };
  std::map<std::pair<double, double>, std::vector<Run>> by_condition;
  std::vector<std::string> left_out;  // runs of a resolution that did not complete: the finest may be among them
  for (const DataFile::Row& row : f.rows) {
    if (row.cells.at("status") != "complete") {
      if (const double n = f.number(row, "cells_per_feed"); std::isfinite(n) && n > 0.0)
        left_out.push_back(fmt::format("V = {:g} m/s, h = {:g} mm at {:g} cells across h ({})",
                                       f.number(row, "speed_m_per_s"), f.number(row, "feed_mm"), n,
                                       row.cells.at("status")));
      continue;
    }
    const double n = f.number(row, "cells_per_feed"), feed_mm = f.number(row, "feed_mm");
    if (!std::isfinite(n) || !(n > 0.0)) continue;  // a sweep at the case's own cell size
    // The cell from the feed and N exactly (cell_size_um is rounded in the table).
    by_condition[{f.number(row, "speed_m_per_s"), feed_mm}].push_back({1e3 * feed_mm / n, static_cast<int>(n), &row});
  }

  GridConvergenceReport r;
  r.table.columns = {"speed_m_per_s", "feed_mm", "quantity", "unit", "cells_per_feed", "values", "behaviour",
                     "last_change_percent", "observed_order", "order_plausible", "extrapolated",
                     "finest_vs_extrapolated_percent", "gci_fine_percent"};
  r.table.headings = {"V (m/s)", "h (mm)", "quantity", "unit", "cells across h", "values (coarse → fine)",
                      "behaviour", "last change (%)", "observed order p", "p in 0.5–3", "extrapolated (h → 0)",
                      "finest − extrapolated (%)", "GCI fine (%)"};
  for (auto& [condition, runs] : by_condition) {
    std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.cell_um < b.cell_um; });
    // A merged or edited table may hold one resolution twice: name it (it stopped with "0 < h1 < h2 < h3").
    for (std::size_t i = 1; i < runs.size(); ++i)
      if (runs[i].cells_per_feed == runs[i - 1].cells_per_feed)
        throw InputError(fmt::format("{}:{}: the condition V = {:g} m/s, h = {:g} mm has a complete run at "
                                     "cells_per_feed = {} on line {} already: one run per resolution",
                                     f.source, std::max(runs[i].row->line, runs[i - 1].row->line), condition.first,
                                     condition.second, runs[i].cells_per_feed,
                                     std::min(runs[i].row->line, runs[i - 1].row->line)));
    if (runs.size() < 3) continue;
    ++r.conditions;
    const Run &fine = runs[0], &medium = runs[1], &coarse = runs[2];
    for (const Quantity& q : kQuantities) {
      const double v1 = f.number(*fine.row, q.column), v2 = f.number(*medium.row, q.column),
                   v3 = f.number(*coarse.row, q.column);
      std::vector<std::string> row{fmt::format("{:g}", condition.first), fmt::format("{:g}", condition.second), q.name,
                                   q.unit,
                                   fmt::format("{}, {}, {}", coarse.cells_per_feed, medium.cells_per_feed,
                                               fine.cells_per_feed)};
      if (!std::isfinite(v1) || !std::isfinite(v2) || !std::isfinite(v3)) {
        row.insert(row.end(), {"", "not reported by every run", "", "", "", "", "", ""});
        r.table.rows.push_back(row);
        continue;
      }
      const GridConvergenceEstimate e = three_grid_convergence(fine.cell_um, v1, medium.cell_um, v2, coarse.cell_um, v3);
      std::optional<double> gap;  // signed: (finest - extrapolated) / extrapolated
      if (e.extrapolated && *e.extrapolated != 0.0) gap = (v1 - *e.extrapolated) / std::abs(*e.extrapolated);
      const std::string last_change = v2 != 0.0 ? fmt::format("{:+.1f}", 100.0 * (v1 - v2) / std::abs(v2)) : "";
      row.insert(row.end(), {fmt::format("{}, {}, {}", value_text(v3), value_text(v2), value_text(v1)), e.behaviour,
                             last_change, e.observed_order ? fmt::format("{:.2f}", *e.observed_order) : std::string(),
                             e.observed_order ? (e.order_plausible ? "yes" : "no") : "",
                             e.extrapolated ? value_text(*e.extrapolated) : std::string(),
                             gap ? fmt::format("{:+.1f}", 100.0 * *gap) : std::string(), percent_text(e.gci_fine)});
      r.table.rows.push_back(row);
    }
  }
  std::ostringstream md;
  md << "## Richardson extrapolation\n\n";
  if (r.conditions == 0) {
    md << "No condition has three complete resolutions: the observed order and the extrapolated values need "
          "three (e.g. --cells-per-feed 12,16,24).\n\n";
  } else {
    md << "From the three finest complete resolutions of each condition (procedure of Celik et al. 2008 for "
          "unequal refinement ratios, after Roache's grid convergence index; docs/references.md): the observed "
          "order p, the value extrapolated to a zero cell size, how far the finest run is from it, and the GCI — "
          "an error band around the finest run with a safety factor of 1.25. \"oscillatory\": the changes "
          "alternate in sign, no order fits and the band is half the spread of the three; \"not shrinking\": the "
          "changes do not shrink with the grid for any positive order (at changes of a few per cent this is "
          "scatter between runs rather than divergence). An order far from the method's (about 1 for MPM "
          "quantities that hinge on an interface resolved to a cell, up to 2 for smooth fields) means the grids "
          "are not in the asymptotic range and the extrapolation is indicative only: column \"p in 0.5–3\" says "
          "no there.\n\n"
       << r.table.markdown() << "\n";
  }
  if (!left_out.empty()) {
    md << "Left out, not complete:";
    for (std::size_t i = 0; i < left_out.size(); ++i) md << (i ? "; " : " ") << left_out[i];
    md << ".\n\n";
  }
  r.markdown = md.str();
  return r;
}

}  // namespace mpmcut
