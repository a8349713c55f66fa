#include "app/validation_report.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "cutting/cutting_forces.hpp"
#include "cutting/cutting_resolution.hpp"
#include "cutting/cutting_scene.hpp"
#include "io/atomic_file.hpp"
#include "io/scene_writer.hpp"
#include "run/run_summary.hpp"
#include "studies/validation_metrics.hpp"

namespace mpmcut::validation {

namespace {

namespace fs = std::filesystem;

// Goals of the validation (issue 11): what the model should reach on the measured matrix without a
// parameter tuned per condition.
constexpr double kGoalRatioError = 0.15;      // Ft/Fc within +-15 % at every condition
constexpr double kGoalThicknessError = 0.10;  // Fc(h)/Fc(0.1 mm) within +-10 %
constexpr double kGoalMeanFcError = 0.15;     // mean |dFc| / Fc < 15 % (b = 1 mm assumed)

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

std::string condition_label(const Condition& c) {
  const MeasuredForces& m = *c.measured;
  const std::string tool = tool_text(c, false);
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

// How the measured forces became N/mm: how many force conditions there are and how many carry the tests' width.
struct WidthCounts {
  long forces = 0, with_width = 0;
  std::string basis() const {
    return with_width == 0        ? "b = 1 mm assumed"
           : with_width == forces ? "b of the data file"
                                  : "b of the data file, 1 mm assumed where it gives none";
  }
};

WidthCounts width_counts(const std::vector<Condition>& conditions) {
  WidthCounts w;
  w.forces = std::count_if(conditions.begin(), conditions.end(), [](const Condition& c) { return c.measured.has_value(); });
  w.with_width = std::count_if(conditions.begin(), conditions.end(),
                               [](const Condition& c) { return c.measured && c.measured->width_mm; });
  return w;
}

// Force conditions with fewer than kResolvedCellsPerThermalLength cells across their thermal length, as
// "h = 0.1 mm at 381.3 m/min (0.821)".
std::vector<std::string> unresolved_bands(const std::vector<Condition>& conditions, double kappa) {
  std::vector<std::string> unresolved;
  for (const Condition& c : conditions)
    if (const auto n = c.cells_per_thermal_length(kappa); c.compared() && n && *n < kResolvedCellsPerThermalLength)
      unresolved.push_back(fmt::format("h = {:g} mm at {:g} m/min ({:.3g})", c.h_mm, c.speed_m_per_min(), *n));
  return unresolved;
}

  // Per-run results, for the plots and for anyone who wants the numbers.
void write_runs_table(const std::vector<Condition>& conditions, double kappa, const fs::path& out) {
  TextTable runs_table;
  runs_table.columns = {"condition", "kind", "speed_m_per_s", "speed_m_per_min", "h_mm", "edge_radius_um",
                        "measured_status", "origin", "status", "cutting_force_N_per_mm", "thrust_force_N_per_mm",
                        "force_window", "Fc_drift_in_window_percent", "Ft_drift_in_window_percent",
                        "rake_normal_force_N_per_mm", "rake_friction_force_N_per_mm", "edge_flank_cutting_force_N_per_mm",
                        "edge_flank_thrust_force_N_per_mm", "rake_friction_work_per_travel_N_per_mm",
                        "edge_flank_friction_work_per_travel_N_per_mm", "rake_mean_slip_speed_m_per_s",
                        "edge_arc_normal_thrust_N_per_mm", "edge_arc_friction_thrust_N_per_mm",
                        "flank_normal_thrust_N_per_mm", "flank_friction_thrust_N_per_mm", "chip_thickness_ratio", "chip_thickness_um",
                        "chip_thickness_by_area_um", "cell_size_um", "cells_per_thermal_length", "mass_scaling_factor",
                        "max_temperature_K", "tool_chip_interface_max_K", "tool_heat_share_of_work", "chip_classification", "segmentation_degree", "segmentation_degree_mean",
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
                               format_number(c.result.tool_force_split.edge_arc_normal_thrust_N_per_mm),
                               format_number(c.result.tool_force_split.edge_arc_friction_thrust_N_per_mm),
                               format_number(c.result.tool_force_split.flank_normal_thrust_N_per_mm),
                               format_number(c.result.tool_force_split.flank_friction_thrust_N_per_mm),
                               format_number(c.result.chip_thickness_ratio), format_number(c.chip_thickness_um()),
                               format_number(c.chip_thickness_by_area_um()),
                               format_number(c.result.cell_size_um), format_number(c.cells_per_thermal_length(kappa), 3),
                               format_number(c.result.mass_scaling_factor),
                               format_number(c.result.max_temperature_K), format_number(c.result.tool_chip_max_K),
                               format_number(c.result.tool_heat_share, 3),
                               c.result.chip_classification,
                               format_number(c.result.segmentation_degree, 3),
                               format_number(c.result.segmentation_degree_mean, 3),
                               format_number(c.result.segmentation_degree_min, 3),
                               format_number(c.result.segmentation_degree_max, 3),
                               format_number(c.result.wall_time_s), c.result.source_revision, (out / c.id).string(),
                               c.result.message});
  }
  runs_table.write_csv(out / "validation_runs.csv");
}

  // The measurements as this report read them (forces per mm of width: the row's width_mm, blank = 1 mm assumed;
  // ranges filled in, tool angles as text), one row per force condition:
  // what the plots draw, so that they need not read the data file again.
void write_measured_table(const std::vector<Condition>& conditions, const ForceData& data,
                          const std::string& measurements, const fs::path& out) {
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
                                   data.builtin ? "Klippel et al. 2024" : measurements});
  }
  measured_table.write_csv(out / "validation_measured.csv");
}

struct ThicknessRatio {
  const Condition* c;
  double measured, simulated;
};

// The comparison of every reported force and chip-type condition with its measurement (validation.csv), and the
// errors of the compared conditions (complete force runs) in matrix order.
struct Comparison {
  TextTable table;
  std::vector<const Condition*> compared;
  std::vector<std::optional<double>> err_fc, err_ft, err_ratio, err_tc;
  // The same over the runs that reached a steady state (both forces' drift within the run's warning limit);
  // none for the others, so that the indices stay those of `compared`.
  std::vector<std::optional<double>> steady_fc, steady_ft, steady_ratio;
  std::vector<std::string> drifting;  // the compared runs that are not steady, with their drifts
  std::vector<ThicknessRatio> thickness_ratios;  // Fc(h)/Fc(0.1 mm), measured and simulated
};

// Whether a complete chip-type condition's simulated chip is the observed one ("yes" / "no"; "" without a simulated
// type). An observed "serrated->discontinuous" (a transition within the source's range) admits either.
std::string chip_type_agreement(const Condition& c) {
  const std::string& sim = c.result.chip_classification;
  if (!c.complete() || sim.empty() || !c.chip) return "";
  const std::string& seen = c.chip->chip_type;
  const bool agrees = sim == seen || (seen == "serrated->discontinuous" && (sim == "serrated" || sim == "discontinuous"));
  return agrees ? "yes" : "no";
}

Comparison compare(const std::vector<Condition>& conditions, const ForceData& data, const fs::path& out) {
  Comparison k;
  TextTable& table = k.table;
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
      k.thickness_ratios.push_back({&c, meas, sim});
    }
    if (!ok) continue;
    k.compared.push_back(&c);
    k.err_fc.push_back(relative_error(fc, m.fc_N));
    k.err_ft.push_back(relative_error(ft, m.ff_N));
    k.err_ratio.push_back(relative_error(ratio, m.ff_N / m.fc_N));
    k.err_tc.push_back(relative_error(tc, measured_tc));
    const bool is_steady = steady(c);
    k.steady_fc.push_back(is_steady ? relative_error(fc, m.fc_N) : std::nullopt);
    k.steady_ft.push_back(is_steady ? relative_error(ft, m.ff_N) : std::nullopt);
    k.steady_ratio.push_back(is_steady ? relative_error(ratio, m.ff_N / m.fc_N) : std::nullopt);
    if (!is_steady) k.drifting.push_back(fmt::format("`{}` (Fc {:+.0f} %, Ft {:+.0f} %)", c.id,
                                                   c.result.cutting_force_drift_percent.value_or(NAN),
                                                   c.result.thrust_force_drift_percent.value_or(NAN)));
  }
  for (const Condition& c : conditions) {
    if (c.kind != "chip" || c.origin.empty()) continue;
    const std::string sim = c.result.status != "complete" ? c.result.status
                            : c.result.chip_classification.empty() ? "n/a (no chip analysis in summary.json)"
                                                                   : c.result.chip_classification;
    const ChipObservation& seen = *c.chip;
    const std::string tool = tool_text(c);
    const std::string note = seen.cell("note");
    const std::string tag = seen.cell("tag");
    table.rows.push_back({fmt::format("h = {:g} mm, V = {:g} m/s ({:g} m/min), {}, r_n {:g} µm{}", c.h_mm,
                                      c.speed_m_per_s, c.speed_m_per_min(), tool.empty() ? "rake 0° (assumed)" : tool,
                                      c.edge_radius_um, c.edge_radius_given ? "" : " (assumed)"),
                          "chip type", "-", seen.chip_type, "", "", sim, "", chip_type_agreement(c),
                          seen.cell("statement") + (note.empty() ? "" : " (" + note + ")"),
                          seen.cell("source") + (tag.empty() ? "" : " [" + tag + "]")});
  }
  table.write_csv(out / "validation.csv");
  return k;
}

// Mean and worst absolute errors (validation_errors.csv), with the summaries the goals are judged on.
struct ErrorTable {
  TextTable table;
  ErrorSummary fc, ratio, thickness;
};

ErrorTable error_table(const Comparison& k, const std::string& b_basis, const fs::path& out) {
  TextTable errors;
  errors.columns = {"quantity", "unit", "conditions", "mean_abs_error_percent", "worst_abs_error_percent", "worst_condition"};
  errors.headings = {"quantity", "unit", "conditions with a value", "mean abs. error %", "worst abs. error %", "worst at"};
  const auto error_row = [&](const std::string& q, const std::string& unit, const std::vector<std::optional<double>>& e) {
    const ErrorSummary s = summarize_errors(e);
    errors.rows.push_back({q, unit, std::to_string(s.count), s.count ? fmt::format("{:.1f}", 100 * s.mean_abs) : "",
                           s.count ? fmt::format("{:.1f}", 100 * s.worst_abs) : "",
                           s.count ? k.compared[s.worst_index]->id : ""});
    return s;
  };
  const ErrorSummary s_fc = error_row("Fc", "N/mm (" + b_basis + ")", k.err_fc);
  error_row("Ft", "N/mm (" + b_basis + ")", k.err_ft);
  const ErrorSummary s_ratio = error_row("Ft/Fc", "-", k.err_ratio);
  error_row("t_c", "µm", k.err_tc);
  error_row("Fc, steady runs", "N/mm (" + b_basis + ")", k.steady_fc);
  error_row("Ft, steady runs", "N/mm (" + b_basis + ")", k.steady_ft);
  error_row("Ft/Fc, steady runs", "-", k.steady_ratio);
  std::vector<std::optional<double>> err_thickness;
  for (const auto& t : k.thickness_ratios) err_thickness.push_back(relative_error(t.simulated, t.measured));
  const ErrorSummary s_thick = summarize_errors(err_thickness);
  errors.rows.push_back({"Fc / Fc(h = 0.1 mm)", "-", std::to_string(s_thick.count),
                         s_thick.count ? fmt::format("{:.1f}", 100 * s_thick.mean_abs) : "",
                         s_thick.count ? fmt::format("{:.1f}", 100 * s_thick.worst_abs) : "",
                         s_thick.count ? k.thickness_ratios[s_thick.worst_index].c->id : ""});
  errors.write_csv(out / "validation_errors.csv");
  return {errors, s_fc, s_ratio, s_thick};
}

  // Speed trends: the least-squares slope of Fc over ln v at each h with two or more compared speeds; the
  // measured slope over the same speeds, so that the two see the same conditions. Also in % of the mean Fc
  // per e-fold (a slope of 1 N/mm is flat at h = 0.1 mm, not at 0.01 mm). Where tests of status "short" are
  // among them (their cut may not have been steady: data file, caveat 4), the same over the "ok" tests only;
  // the goal counts the rows over all tests.
struct SpeedTrends {
  TextTable table;
  int total = 0, right = 0;  // rows over all tests, and those of them whose sign is right
};

SpeedTrends speed_trends(const std::vector<const Condition*>& compared, const std::string& b_basis, const fs::path& out) {
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
  return {trends, trends_total, trends_right};
}

// The goals of the validation against what the matrix gave (validation_goals.csv).
TextTable goal_table(const ErrorTable& e, const SpeedTrends& t, const std::string& b_basis, const fs::path& out) {
  const ErrorSummary &s_fc = e.fc, &s_ratio = e.ratio, &s_thick = e.thickness;
  const int trends_total = t.total, trends_right = t.right;
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
  return goals;
}

// How the tool takes heat in these runs: adiabatic, a heat sink at its temperature, or conducting.
std::string tool_heat_text(const ConditionRunSettings& settings) {
  if (!settings.tool_heat_transfer_coefficient) return "; the tool surface is adiabatic";
  const std::string temperature =
      settings.tool_temperature ? fmt::format("{:g} K", *settings.tool_temperature) : std::string("the initial temperature");
  if (!settings.tool_conductivity)
    return fmt::format("; the tool is a heat sink at {} with a heat transfer coefficient of {:g} W/(m² K)", temperature,
                       *settings.tool_heat_transfer_coefficient);
  const bool transient = settings.tool_volumetric_heat_capacity && *settings.tool_volumetric_heat_capacity > 0.0;
  return fmt::format("; the tool conducts heat ({:g} W/(m K), {}), held at {} on its back and top and heated through "
                     "a heat transfer coefficient of {:g} W/(m² K)",
                     *settings.tool_conductivity,
                     transient ? fmt::format("transient, {:g} J/(m³ K)", *settings.tool_volumetric_heat_capacity)
                               : std::string("steady"),
                     temperature, *settings.tool_heat_transfer_coefficient);
}


// Everything validation.md says, gathered by write_validation_report.
struct ReportParts {
  const std::vector<Condition>& conditions;
  const ReportContext& context;
  const Comparison& comparison;
  const ErrorTable& errors;
  const SpeedTrends& trends;
  const TextTable& goals;
  std::vector<std::string> unresolved_bands;
  WidthCounts width;
};

// The report's assumptions: width of cut, tool, friction and heat, contact, material, force windows.
std::string assumptions_section(const ReportParts& r) {
  const Options& o = r.context.options;
  const ConditionRunSettings& settings = r.context.settings;
  const ForceData& data = r.context.data;
  const long with_width = r.width.with_width, forces = r.width.forces;
  std::ostringstream s;
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
    << tool_heat_text(settings)
    << "; contact detection: "
    << (settings.contact_detection.empty() ? contact_detection_name(kCuttingPresetContact) + " (the preset's)"
                                           : settings.contact_detection + " (--contact-detection)")
    << "; volumetric strain rate: "
    << (settings.volumetric_average.empty() ? std::string("each particle's own (the preset's)")
                                            : settings.volumetric_average + " (--volumetric-average)")
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
    << (data.builtin ? std::string("- The measured speeds (≤ 6.4 m/s) are below the ultra-high-speed range of the target "
                                   "paper") +
                           (data.chips_builtin ? "; chip-type data at 5–75 m/s exist only as abstract statements "
                                                 "without the transition speed.\n"
                                               : ".\n")
                     : std::string())
    << "\n";
  return s.str();
}

// What the report says of the built-in data where they disagree or are thin.
std::string builtin_data_notes(bool builtin_chips) {
  return std::string("## Where the data disagree or are thin\n\n") +
       "- At h = 0.1 mm and nearly equal speeds the Klippel condition means differ by more than the scatter "
       "within a condition: 222.8 N at 10 m/min (r_n 40.8 µm) vs 209.2 N at 10.5 m/min (r_n 29.4 µm); tests marked "
       "`short` (74.3, 88.9, 159–381 m/min) lie 5–10 % below neighbouring `ok` tests. The edge radius and the "
       "unexplained status explain part of it; validation_forces.png shows every condition with its range "
       "rather than a single curve.\n"
       "- Ff/Fc: Klippel et al. give 0.6–0.7 at h = 0.1 mm and Ff > Fc at h ≤ 0.04 mm (r_n ≈ 37 µm ≥ h: "
       "ploughing); Ducobu, Pantalé & Lauwers (CIRP JMST, [V]) report Ff ≈ 46 % of Fc at h = 40 µm, 10 m/min, with "
       "a 15° rake, r_β = 20 µm tool in oblique cutting (λs = 6°). The two do not contradict each other — tool "
       "geometry differs — but they show how strongly Ft/Fc depends on rake and edge radius, which this "
       "comparison had to assume.\n" +
       (builtin_chips
            ? "- Chip type: Sutter & List (2013) [A] state serrated chips at the lower speeds of 5–75 m/s and "
              "discontinuous chips at very high speed without the transition speed in the abstract; Ducobu et al. [V] "
              "saw only continuous chips at 5–40 m/min with a 15° rake (not simulated: below 1 m/s the explicit run is "
              "too long, and the tool differs).\n\n"
            : "\n");
}

void write_markdown(const ReportParts& r) {
  const Options& o = r.context.options;
  const ForceData& data = r.context.data;
  const fs::path& out = r.context.out;
  const std::vector<Condition>& conditions = r.conditions;
  const std::vector<const Condition*>& compared = r.comparison.compared;
  const std::vector<std::string>& drifting = r.comparison.drifting;
  const std::vector<std::string>& unresolved_bands = r.unresolved_bands;
  const TextTable &table = r.comparison.table, &errors = r.errors.table, &trends = r.trends.table, &goals = r.goals;
  const long with_width = r.width.with_width, forces = r.width.forces;
  const std::string b_basis = r.width.basis();
  int reported = 0, complete = 0;
  for (const Condition& c : conditions) {
    reported += !c.origin.empty();
    complete += c.complete();
  }
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
    if (const std::string w = material_data_mismatch(r.context.settings, data); !w.empty())
      s << "**Warning: " << w << ".**\n\n";
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
                     reported, r.context.runs_launched, r.context.completed ? "" : ", interrupted",
                     std::count_if(conditions.begin(), conditions.end(), [](const Condition& c) { return c.origin == "earlier run"; }),
                     std::count_if(conditions.begin(), conditions.end(), [](const Condition& c) { return c.origin == "record"; }),
                     o.records_dir.empty() ? "" : " in " + o.records_dir, not_run.size(), not_run.empty() ? "" : " (listed at the end)", compared.size());
    if (const auto chips_compared = std::count_if(conditions.begin(), conditions.end(),
                                                  [](const Condition& c) { return !chip_type_agreement(c).empty(); }))
      s << fmt::format("**Chip type**: the simulated chip is the observed one at {} of the {} chip-type conditions with "
                       "a simulated type (validation.csv, column \"in range\").\n\n",
                       std::count_if(conditions.begin(), conditions.end(),
                                     [](const Condition& c) { return chip_type_agreement(c) == "yes"; }),
                       chips_compared);
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
    s << assumptions_section(r);
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
    if (data.builtin) s << builtin_data_notes(data.chips_builtin);
    if (!hot.empty())
      s << "## Physically odd\n\nMaximum particle temperature above the material's melting temperature in: "
        << join(hot, ", ") << ". Single particles at the tool–chip contact usually; see the chip pictures (mpmcut plot DIR).\n\n";
    s << "## Files\n\nvalidation.csv (the comparison table), validation_goals.csv, validation_errors.csv, "
         "validation_trends.csv, validation_runs.csv (one row per reported run), validation_measured.csv (the "
         "measurements as read, one row per force condition), validation_parity.png, "
         "validation_speed.png, validation_thickness.png, validation_forces.png, validation_ratio.png (the plots: drawn once every "
         "selected run is complete, unless --no-plots or without Python's matplotlib), cases/*.toml (the "
         "run inputs), <condition>/ (result directories), logs/.\n\n"
      << (data.builtin ? std::string("Data: data/experiments/ti64_klippel2024_orthogonal_forces.csv") +
                             (data.chips_builtin ? " and ti64_chip_morphology.csv" : "") +
                             " (sources and caveats in their headers)"
                       : "Data: " + o.measurements + " (--measurements)")
      << (!data.chips_builtin ? "; chip types: " + o.chip_observations + " (--chip-observations)" : std::string())
      << ".\n";
  });
}

}  // namespace

void write_validation_report(const std::vector<Condition>& conditions, const ReportContext& context) {
  const fs::path& out = context.out;
  // The workpiece's thermal diffusivity, for the cells across each run's thermal length.
  const double kappa = workpiece_thermal_diffusivity_m2_per_s(context.settings);
  write_runs_table(conditions, kappa, out);
  write_measured_table(conditions, context.data, context.options.measurements, out);
  const WidthCounts width = width_counts(conditions);
  const Comparison comparison = compare(conditions, context.data, out);
  const ErrorTable errors = error_table(comparison, width.basis(), out);
  const SpeedTrends trends = speed_trends(comparison.compared, width.basis(), out);
  const TextTable goals = goal_table(errors, trends, width.basis(), out);
  write_markdown({conditions, context, comparison, errors, trends, goals, unresolved_bands(conditions, kappa), width});
  std::cout << "wrote " << (out / "validation.md").string()
            << ", validation.csv, validation_goals.csv, validation_errors.csv, validation_trends.csv, validation_runs.csv, "
               "validation_measured.csv\n";
}

}  // namespace mpmcut::validation
