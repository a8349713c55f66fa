#include "app/sweep_command.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>
#include <type_traits>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "app/command_exit.hpp"
#include "app/plot_command.hpp"
#include "app/stop_signal.hpp"
#include "app/path_option.hpp"
#include "app/progress_option.hpp"
#include "run/run_case.hpp"
#include "studies/grid_convergence_report.hpp"
#include "studies/task_farm.hpp"
#include "run/case_loading.hpp"
#include "run/run_options.hpp"
#include "run/run_summary.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"

namespace mpmcut {

bool has_subcommand(const CLI::App& app, const std::string& name) {
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->get_name() == name) return true;
  return false;
}

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

struct SweepOptions {
  std::string case_file;
  std::vector<double> speeds_m_per_s;
  std::vector<double> feeds_m;
  std::vector<int> cells_per_feed;  // empty: the case's own cell size
  int jobs = 0;
  double progress_interval_s = kDefaultProgressIntervalS;
  int threads = 1;
  std::string out_dir;
  std::vector<std::string> overrides;
  std::vector<std::string> vary;  // --vary KEY=V1,V2,... (repeatable): a grid dimension over any key --set takes
  bool no_plots = false;
};

// --vary KEY=V1,V2,...: the key and its values (texts as given, each becomes `--set KEY=value`).
struct VariedKey {
  std::string key;
  std::vector<std::string> values;  // the texts as given
};

VariedKey parse_vary(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw InputError(fmt::format("--vary '{}': expected KEY=V1,V2,... (a key as for --set, e.g. "
                                 "cutting.rake_angle_deg=-5,0,10)",
                                 text));
  VariedKey v{text.substr(0, eq), {}};
  std::stringstream values(text.substr(eq + 1));
  for (std::string value; std::getline(values, value, ',');) {
    if (value.empty()) throw InputError(fmt::format("--vary '{}': an empty value", text));
    if (std::find(v.values.begin(), v.values.end(), value) != v.values.end())
      throw InputError(fmt::format("--vary '{}': the value {} is given twice", text, value));
    v.values.push_back(value);
  }
  return v;
}

// Every --vary, each key once.
std::vector<VariedKey> parse_varied_keys(const std::vector<std::string>& texts) {
  std::vector<VariedKey> keys;
  for (const std::string& text : texts) {
    VariedKey v = parse_vary(text);
    for (const VariedKey& earlier : keys)
      if (earlier.key == v.key)
        throw InputError(fmt::format("--vary {}: the key is varied twice; give all its values in one --vary", v.key));
    keys.push_back(std::move(v));
  }
  return keys;
}

// Every combination of the varied keys' values, the first key's slowest ({{}} when none is varied).
std::vector<std::vector<std::string>> value_combinations(const std::vector<VariedKey>& keys) {
  std::vector<std::vector<std::string>> combinations{{}};
  for (const VariedKey& k : keys) {
    std::vector<std::vector<std::string>> longer;
    for (const auto& c : combinations)
      for (const std::string& value : k.values) {
        longer.push_back(c);
        longer.back().push_back(value);
      }
    combinations = std::move(longer);
  }
  return combinations;
}

// A name part for a case directory: each key's last part and its value, e.g. "_rake_angle_deg-5_friction0.2".
std::string varied_name(const std::vector<VariedKey>& keys, const std::vector<std::string>& values) {
  std::string name;
  for (std::size_t k = 0; k < keys.size(); ++k) name += "_" + keys[k].key.substr(keys[k].key.rfind('.') + 1) + values[k];
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '.' && ch != '_' && ch != '+') ch = '_';
  return name;
}

// "yes" when two runs have the same chip type, else the change, marked where either sits at a threshold
// of the classification (chip_analysis.hpp: a flip there says little about convergence).
std::string chip_type_change(const CaseResult& a, const CaseResult& b) {
  if (a.chip_classification == b.chip_classification) return "yes";
  const bool marginal = a.chip_classification_confidence == "marginal" || b.chip_classification_confidence == "marginal";
  return a.chip_classification + " → " + b.chip_classification + (marginal ? " (marginal)" : "");
}

int run_sweep(const SweepOptions& o, const CLI::App& app) {
  if (!fs::exists(o.case_file)) {
    std::cerr << "error: case file " << o.case_file << " not found\n";
    return 2;
  }
  const fs::path out = o.out_dir.empty() ? fs::path("results") / ("sweep_" + fs::path(o.case_file).stem().string())
                                         : fs::path(o.out_dir);
  const std::vector<VariedKey> varied = parse_varied_keys(o.vary);
  const std::vector<std::vector<std::string>> combinations = value_combinations(varied);
  for (const VariedKey& k : varied) {
    // The grid-convergence report groups runs by speed and feed only.
    if (o.cells_per_feed.size() > 1)
      throw InputError("--vary and a resolution study (--cells-per-feed with two or more values) do not combine: run "
                       "one convergence sweep per value (--set " + k.key + "=...)");
    // The grid's own keys have their own options (the grid's --set would be overridden by --vary's).
    for (const char* own : {"cutting.cutting_speed", "cutting.cutting_speed_m_per_min", "cutting.uncut_chip_thickness"})
      if (k.key == own)
        throw InputError(fmt::format("--vary {}: the sweep's grid sets it; use --speeds (m/s) or --feeds (m)", own));
    if (k.key == "cutting.cell_size" && !o.cells_per_feed.empty())
      throw InputError("--vary cutting.cell_size with --cells-per-feed: give the resolution one way");
  }
  // Every value of the grid and of the varied key must make a valid case: checked before anything runs (file, key,
  // allowed range); `what` names the option and the value in the error.
  const auto check_value_reads = [&](const std::string& what, const std::vector<std::string>& assignments) {
    std::vector<std::string> with = o.overrides;
    with.insert(with.end(), assignments.begin(), assignments.end());
    try {
      (void)load_case(o.case_file, with);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{} makes a case that does not read: {}", what, e.what()));
    }
  };
  for (const VariedKey& k : varied)
    for (const std::string& value : k.values)
      check_value_reads(fmt::format("--vary {}: the value {}", k.key, value), {k.key + "=" + value});
  // Keys that depend on each other (a rake and a clearance that leave no wedge): every combination reads.
  if (varied.size() > 1)
    for (const auto& values : combinations) {
      std::vector<std::string> assignments;
      std::string shown;
      for (std::size_t k = 0; k < varied.size(); ++k) {
        assignments.push_back(varied[k].key + "=" + values[k]);
        shown += (shown.empty() ? "" : ", ") + assignments.back();
      }
      check_value_reads(fmt::format("--vary: the combination {}", shown), assignments);
    }
  // The case itself (load_case checks it before anything runs) and its own feed.
  double own_feed_m = 0.0;
  {
    const Case c = load_case(o.case_file, o.overrides);
    if (!c.cutting) {
      std::cerr << "error: " << o.case_file << " has no [cutting] table: sweep needs a cutting case\n";
      return 2;
    }
    own_feed_m = c.cutting->uncut_chip_thickness;
  }
  // The grid's own values: each given once (two cases would share one directory and one resolution would be
  // "refined" onto itself), and each making a valid case (a feed in mm instead of m, a NaN), before anything runs.
  const auto given_once = [](const auto& values, const char* option) {
    for (std::size_t i = 0; i < values.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (values[i] == values[j]) {
          const auto shown = values[i];
          if constexpr (std::is_floating_point_v<decltype(shown)>)
            throw InputError(fmt::format("{} {:g}: the value is given twice", option, shown));
          else
            throw InputError(fmt::format("{} {}: the value is given twice", option, shown));
        }
  };
  given_once(o.speeds_m_per_s, "--speeds");
  given_once(o.feeds_m, "--feeds");
  given_once(o.cells_per_feed, "--cells-per-feed");
  for (double v : o.speeds_m_per_s)
    check_value_reads(fmt::format("--speeds {:g}: the value", v), {fmt::format("cutting.cutting_speed={}", v)});
  for (double h : o.feeds_m)
    check_value_reads(fmt::format("--feeds {:g}: the value", h), {fmt::format("cutting.uncut_chip_thickness={}", h)});
  std::vector<double> feeds_m = o.feeds_m;
  if (feeds_m.empty()) feeds_m = {own_feed_m};
  const int jobs = o.jobs > 0 ? o.jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / o.threads);

  struct Case {
    double speed, feed;
    int cells_per_feed;  // 0: the case's own cell size
    std::vector<std::string> values;  // of the varied keys (none when none is varied)
    fs::path dir;
  };
  // The plots' series: one per feed and combination of the varied keys' values.
  const auto series_of = [&](const Case& c) {
    std::string s = fmt::format("h = {:g} mm", c.feed * 1e3);
    for (std::size_t k = 0; k < varied.size(); ++k) s += ", " + varied[k].key + " = " + c.values[k];
    return s;
  };
  std::vector<Case> cases;
  std::vector<ChildRun> runs;
  const std::vector<int> resolutions = o.cells_per_feed.empty() ? std::vector<int>{0} : o.cells_per_feed;
  for (int n : resolutions)
    for (double h : feeds_m)
      for (const std::vector<std::string>& values : combinations)
      for (double v : o.speeds_m_per_s) {
        const std::string name = fmt::format("v{:g}mps_h{:g}mm", v, h * 1e3) + (n > 0 ? fmt::format("_n{}", n) : "") +
                                 varied_name(varied, values);
        // Names carry 6 significant digits: two values closer than that would share one directory, and one
        // case's results would replace the other's (--speeds 20,20.0000001 ran both into v20mps_h0.1mm).
        for (const Case& earlier : cases)
          if (earlier.dir == out / name) {
            std::string keys;
            for (std::size_t k = 0; k < varied.size(); ++k)
              keys += fmt::format(", {} {} and {}", varied[k].key, earlier.values[k], values[k]);
            throw InputError(fmt::format(
                "two cases of the grid would share the directory {} (speeds {} and {} m/s, feeds {} and {} m{}): the "
                "case names carry 6 significant digits; give values that differ within them",
                name, earlier.speed, v, earlier.feed, h, keys));
          }
        // The values together (a feed and an edge radius each valid alone, but the radius beyond 10 feeds): every
        // case reads before anything runs or any directory is made.
        std::vector<std::string> assignments = {fmt::format("cutting.cutting_speed={}", v),
                                                fmt::format("cutting.uncut_chip_thickness={}", h)};
        if (n > 0) assignments.push_back(fmt::format("cutting.cell_size={}", h / n));
        for (std::size_t k = 0; k < varied.size(); ++k) assignments.push_back(varied[k].key + "=" + values[k]);
        check_value_reads(fmt::format("the sweep's case {}", name), assignments);
        cases.push_back({v, h, n, values, out / name});
        ChildRun run;
        run.name = name;
        // --keep-complete: a rerun of the sweep keeps the cases already complete and resumes interrupted ones.
        run.args = {"run", fs::absolute(o.case_file).string(), "--out", (out / name).string(), "--keep-complete",
                    "--no-progress", "--threads", std::to_string(o.threads)};
        for (const std::string& s : o.overrides) run.args.insert(run.args.end(), {"--set", s});
        // After the user's --set: the grid values win.
        for (const std::string& s : assignments) run.args.insert(run.args.end(), {"--set", s});
        run.log_file = out / "logs" / (name + ".log");
        runs.push_back(run);
      }
  fs::create_directories(out / "logs");
  std::string varied_text;
  for (const VariedKey& k : varied) varied_text += fmt::format(" x {} values of {}", k.values.size(), k.key);
  std::cout << fmt::format("mpmcut sweep: {} cases ({} speeds x {} feeds x {} resolutions{}) from {}, {}, each with "
                           "--threads {} (change with --jobs/--threads); results in {} (complete cases of an earlier "
                           "sweep there are kept)\n",
                           runs.size(), o.speeds_m_per_s.size(), feeds_m.size(), resolutions.size(),
                           varied_text,
                           o.case_file,
                           concurrency_text(jobs),
                           o.threads, out.string())
            << std::flush;
  const bool completed = run_cases(runs, jobs, true, o.progress_interval_s);
  // Whether the plots will be drawn, known before sweep.md says which there are.
  std::string no_plotting;
  const bool plotting = !o.no_plots && completed && python_plotting_available(false, no_plotting);

  // The chip analysis, where the program has it and the runs did not do it themselves.
  if (completed && has_subcommand(app, "analyze")) {
    std::vector<ChildRun> analyses;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      std::optional<RunSummary> summary;
      try {
        summary = read_summary(cases[i].dir / "summary.json");
      } catch (const std::exception&) {
      }
      if (!summary || summary->sections.contains("chip")) continue;
      ChildRun a;
      a.name = runs[i].name + " (analyze)";
      a.args = {"analyze", cases[i].dir.string()};
      a.log_file = out / "logs" / (runs[i].name + ".analyze.log");
      analyses.push_back(a);
    }
    if (!analyses.empty()) {
      std::cout << "mpmcut sweep: chip analysis of " << analyses.size() << " cases\n";
      run_cases(analyses, jobs, false);
    }
  }

  TextTable table;
  table.columns = {"case", "speed_m_per_s", "speed_m_per_min", "feed_mm", "cell_size_um", "cells_per_feed",
                   "mass_scaling_factor", "status", "mean_cutting_force_N_per_mm",
                   "mean_thrust_force_N_per_mm", "force_window", "chip_thickness_ratio",
                   "chip_thickness_ratio_from_area", "max_temperature_K",
                   "shear_zone_max_temperature_K", "tool_chip_max_temperature_K", "chip_classification",
                   "chip_classification_confidence", "segmentation_degree", "segmentation_degree_mean",
                   "segmentation_degree_min", "segmentation_degree_max", "pitch_um", "segmentation_frequency_kHz", "plastic_work_fraction",
                   "damage_fraction", "friction_fraction", "kinetic_elastic_fraction", "numerical_fraction",
                   "rake_friction_work_per_travel_N_per_mm", "edge_flank_friction_work_per_travel_N_per_mm",
                   "rake_mean_slip_speed_m_per_s", "wall_time_s", "message", "series"};
  table.headings = {"case", "V (m/s)", "V (m/min)", "h (mm)", "cell (µm)", "cells across h", "mass scaling",
                    "status", "Fc (N/mm)", "Ft (N/mm)", "force window", "t0/tc", "t0/tc by area", "T max (K)", "T shear zone (K)",
                    "T tool–chip (K)", "chip", "chip type confidence", "segmentation degree", "Gs mean over time", "Gs min", "Gs max",
                    "pitch (µm)", "frequency (kHz)",
                    "plastic / W", "damage / W", "friction / W", "kinetic+elastic / W", "numerical / W",
                    "rake friction work / travel (N/mm)", "edge+flank friction work / travel (N/mm)",
                    "rake slip speed (m/s)", "wall (s)", "message", "series"};
  // The varied keys' values beside the feed, each under the key's own name.
  for (std::size_t k = 0; k < varied.size(); ++k) {
    table.columns.insert(table.columns.begin() + 4 + k, varied[k].key);
    table.headings.insert(table.headings.begin() + 4 + k, varied[k].key);
  }
  int failed = 0;
  std::vector<CaseResult> results;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const CaseResult r = read_case_result(cases[i].dir, runs[i].log_file, runs[i].exit_code);
    results.push_back(r);
    if (r.status != "complete") ++failed;
    const auto fraction = [&](const std::optional<double>& part) {
      return part && r.tool_work_J_per_m && *r.tool_work_J_per_m > 0 ? std::optional<double>(*part / *r.tool_work_J_per_m)
                                                                       : std::nullopt;
    };
    table.rows.push_back({runs[i].name, fmt::format("{:g}", cases[i].speed), fmt::format("{:g}", cases[i].speed * 60.0),
                          fmt::format("{:g}", cases[i].feed * 1e3), format_number(r.cell_size_um, 3),
                          format_number(r.cell_size_um ? std::optional<double>(cases[i].feed * 1e6 / *r.cell_size_um)
                                                       : std::nullopt, 3),
                          format_number(r.mass_scaling_factor, 3), r.status, format_number(r.cutting_force_N_per_mm),
                          format_number(r.thrust_force_N_per_mm), r.force_basis, format_number(r.chip_thickness_ratio, 3),
                          format_number(r.chip_thickness_ratio_from_area, 3), format_number(r.max_temperature_K),
                          format_number(r.shear_zone_max_K), format_number(r.tool_chip_max_K), r.chip_classification,
                          r.chip_classification_confidence, format_number(r.segmentation_degree, 3),
                          format_number(r.segmentation_degree_mean, 3), format_number(r.segmentation_degree_min, 3),
                          format_number(r.segmentation_degree_max, 3), format_number(r.pitch_um, 3),
                          format_number(r.frequency_kHz, 3), format_number(fraction(r.plastic_work_J_per_m), 3),
                          format_number(fraction(r.damage_J_per_m), 3), format_number(fraction(r.friction_J_per_m), 3),
                          format_number(fraction(r.kinetic_elastic_J_per_m), 3),
                          format_number(fraction(r.numerical_J_per_m), 3),
                          format_number(r.tool_force_split.rake_friction_work_N_per_mm, 3),
                          format_number(r.tool_force_split.edge_flank_friction_work_N_per_mm, 3),
                          format_number(r.tool_force_split.rake_slip_speed_m_per_s, 3),
                          format_number(r.wall_time_s ? r.wall_time_s : std::optional<double>(runs[i].wall_time_s), 3),
                          r.message, series_of(cases[i])});
    table.rows.back().insert(table.rows.back().begin() + 4, cases[i].values.begin(), cases[i].values.end());
  }
  table.write_csv(out / "sweep.csv");
  write_file_atomically(out / "sweep.md", [&](std::ostream& s) {
    s << "# Sweep of " << o.case_file << "\n\n";
    if (!completed)
      s << "**Interrupted** by a signal: the sweep is incomplete; the stopped cases are resumable "
           "(mpmcut resume <case directory>), the cases not started are marked \"not run\".\n\n";
    s << fmt::format("{} cases, {} complete, {} not complete. Forces are means per unit width of cut over the "
                     "steady window of each run (column \"force window\"; where a run ended before its steady "
                     "window, the mean raw force over the last half of the cut). Chip columns come from the chip "
                     "analysis in summary.json and are blank where it did not provide them.{}\n\n",
                     cases.size(), cases.size() - failed, failed,
                     failed > 0 ? " The forces of a case that did not complete are blank (its forces.csv holds "
                                  "the cut so far)."
                                : "");
    s << table.markdown() << "\n";
    if (resolutions.size() > 1) {
      // Grid convergence: per condition, the change between the two finest complete resolutions.
      TextTable conv;  // Markdown only
      conv.headings = {"V (m/s)", "h (mm)", "cells across h", "ΔFc", "ΔFt", "Δ(t0/tc)", "Δpitch", "same chip type"};
      // The CSV carries numbers (per cent, blank where a value is missing) for scripts; the table, text.
      TextTable conv_csv;
      conv_csv.columns = {"speed_m_per_s", "feed_mm", "cells_per_feed_second_finest", "cells_per_feed_finest",
                          "cutting_force_change_percent", "thrust_force_change_percent",
                          "chip_thickness_ratio_change_percent", "pitch_change_percent", "chip_type_same"};
      for (double h : feeds_m)
        for (const std::vector<std::string>& values : combinations)
        for (double v : o.speeds_m_per_s) {
          std::vector<std::size_t> idx;
          for (std::size_t i = 0; i < cases.size(); ++i)
            if (cases[i].speed == v && cases[i].feed == h && cases[i].values == values && results[i].status == "complete")
              idx.push_back(i);
          std::sort(idx.begin(), idx.end(), [&](auto a, auto b) { return cases[a].cells_per_feed < cases[b].cells_per_feed; });
          if (idx.size() < 2) continue;
          const CaseResult &a = results[idx[idx.size() - 2]], &b = results[idx.back()];
          const auto percent = [](const std::optional<double>& x,
                                  const std::optional<double>& y) -> std::optional<double> {
            if (!x || !y || *x == 0.0) return std::nullopt;
            return 100.0 * (*y - *x) / std::abs(*x);
          };
          const auto change = [&](const std::optional<double>& x, const std::optional<double>& y) -> std::string {
            const std::optional<double> c = percent(x, y);
            return c ? fmt::format("{:+.1f} %", *c) : "";
          };
          const auto number = [&](const std::optional<double>& x, const std::optional<double>& y) -> std::string {
            const std::optional<double> c = percent(x, y);
            return c ? fmt::format("{:.2f}", *c) : "";
          };
          const int coarse = cases[idx[idx.size() - 2]].cells_per_feed, fine = cases[idx.back()].cells_per_feed;
          conv.rows.push_back({fmt::format("{:g}", v), fmt::format("{:g}", h * 1e3),
                               fmt::format("{} → {}", coarse, fine),
                               change(a.cutting_force_N_per_mm, b.cutting_force_N_per_mm),
                               change(a.thrust_force_N_per_mm, b.thrust_force_N_per_mm),
                               change(a.chip_thickness_ratio, b.chip_thickness_ratio), change(a.pitch_um, b.pitch_um),
                               chip_type_change(a, b)});
          conv_csv.rows.push_back({fmt::format("{:g}", v), fmt::format("{:g}", h * 1e3), std::to_string(coarse),
                                   std::to_string(fine), number(a.cutting_force_N_per_mm, b.cutting_force_N_per_mm),
                                   number(a.thrust_force_N_per_mm, b.thrust_force_N_per_mm),
                                   number(a.chip_thickness_ratio, b.chip_thickness_ratio),
                                   number(a.pitch_um, b.pitch_um), chip_type_change(a, b)});
        }
      conv_csv.write_csv(out / "convergence.csv");
      s << "## Grid convergence\n\nChange from the second finest to the finest complete resolution of each condition "
           "(relative to the second finest). The study's goals: |ΔFc|, |ΔFt| and |Δ(t0/tc)| < 5 %, |Δpitch| < 10 %, "
           "the same chip type.\n\n"
        << conv.markdown() << "\n";
      // The same Richardson table as `mpmcut convergence DIR`, from the sweep.csv just written.
      const GridConvergenceReport richardson = grid_convergence_report(out / "sweep.csv");
      if (richardson.conditions > 0) richardson.table.write_csv(out / "grid_convergence.csv");
      s << richardson.markdown;
    }
    // The plots are drawn below, after this file, for a complete sweep without --no-plots.
    if (o.no_plots || !completed)
      s << "Plots: none (" << (o.no_plots ? "--no-plots" : "an interrupted sweep") << "; `mpmcut sweep` again without "
        << "--no-plots over this directory draws them, its complete cases kept). ";
    else if (!plotting)
      s << "Plots: none (" << no_plotting << "; `mpmcut sweep` again over this directory once it is installed draws "
        << "them, its complete cases kept). ";
    else if (resolutions.size() > 1)
      s << "Plots: convergence.png (each quantity against the cells across h). ";
    else
      s << "Plots: forces_vs_speed.png, chip_vs_speed.png, chip_map.png, chip_gallery_damage.png and "
           "chip_gallery_temperature.png (the last snapshot of every case). ";
    s << "Each case: its result directory (mpmcut plot DIR draws it) and logs/<case>.log.\n";
  });
  std::cout << "wrote " << (out / "sweep.csv").string() << " and " << (out / "sweep.md").string() << "\n";

  if (!o.no_plots && completed) {  // an interrupted sweep stops here: no plots of a partial sweep
    if (!plotting) {
      std::cerr << "warning: no sweep plots: " << no_plotting << "\n";
    } else {
      const char* tool = resolutions.size() > 1 ? "plot_convergence.py" : "plot_sweep.py";
      if (int code = run_python_tool(tool, {out.string()}); code != 0)
        std::cerr << "warning: " << tool << " failed (exit status " << code << ")\n";
    }
  }
  if (!completed) {
    // The cases the stop came before: the console names them, as sweep.md does ("not run"), so that a user who
    // reads only the console knows what a rerun will still run.
    std::vector<std::string> not_started;
    for (std::size_t i = 0; i < cases.size(); ++i)
      if (runs[i].exit_code == -1) not_started.push_back(runs[i].name);
    if (!not_started.empty())
      std::cerr << fmt::format("mpmcut sweep: interrupted; {} of {} cases not started: {} (a rerun with the same "
                               "options runs them and resumes the stopped ones)\n",
                               not_started.size(), cases.size(), fmt::join(not_started, ", "));
    return 130;
  }
  if (failed) {
    std::cerr << fmt::format("mpmcut sweep: {} of {} cases did not complete (see sweep.md and logs/)\n", failed,
                             cases.size());
    return 1;
  }
  return 0;
}

// A finite value > 0 (CLI11's PositiveNumber let NaN through and named its upper bound, the largest double, in
// 309 digits).
CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value) || !(value > 0.0) || !std::isfinite(value))
          return fmt::format("Value {} is not a positive, finite number", text);
        return {};
      },
      "POSITIVE");
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* sweep = app.add_subcommand(
      "sweep", "Run a cutting case over a grid of cutting speeds and uncut chip thicknesses (separate processes), "
               "then tabulate (sweep.csv, sweep.md) and plot the results");
  sweep->add_option("case", o->case_file, "Cutting case file (TOML with a [cutting] table)")->required();
  sweep->add_option("--speeds", o->speeds_m_per_s, "Cutting speeds in m/s, comma separated, e.g. 2,5,10,20,50,100")
      ->required()->delimiter(',')->check(positive_number());
  sweep->add_option("--feeds", o->feeds_m,
                    "Uncut chip thicknesses (feeds) in m, comma separated, e.g. 0.05e-3,0.1e-3 (default: the case's own)")
      ->delimiter(',')->check(positive_number());
  sweep->add_option("--cells-per-feed", o->cells_per_feed,
                    "Resolutions, cells across the uncut chip thickness, comma separated (cell = h/N), e.g. 8,12,16,24 "
                    "for a convergence study (default: the case's cell size)")
      ->delimiter(',')->check(CLI::Range(2, 200));
  sweep->add_option("-j,--jobs", o->jobs, "Cases run at the same time (default: cores / threads)")->check(CLI::Range(1, 1024));
  sweep->add_option("-t,--threads", o->threads, "OpenMP threads of each case (default: 1)")->check(CLI::Range(1, kMaxThreads));
  sweep->add_option("-o,--out", o->out_dir, "Sweep directory (default: results/sweep_<case name>)")->check(non_empty_path());
  sweep->add_option("-s,--set", o->overrides, "Override an input key of every case, as for run (repeatable)");
  sweep->add_option("--vary", o->vary,
                    "One more grid dimension: KEY=V1,V2,... over any key --set takes, e.g. "
                    "cutting.rake_angle_deg=-5,0,10 or cutting.edge_radius=5e-6,20e-6 or cutting.friction=0.2,0.5; "
                    "repeatable (every combination of the keys' values is a case); every value is checked before "
                    "anything runs (docs/results.md)");
  add_progress_option(sweep, o->progress_interval_s);
  sweep->add_flag("--no-plots", o->no_plots, "Only the tables");
  // A bad case, --set or --vary is an InputError before anything ran.
  sweep->callback([o, &app]() { finish_command([&] { return run_study([&] { return run_sweep(*o, app); }); }); });
}

}  // namespace mpmcut
