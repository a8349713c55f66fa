#include "studies/calibration.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <regex>
#include <sstream>

#include <fmt/format.h>
#include <nlopt.h>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "cutting/cutting_parameters.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/whole_file.hpp"
#include "run/case_loading.hpp"
#include "solver/model_version.hpp"
#include "studies/task_farm.hpp"

namespace mpmcut {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// The relative error a failed run counts with, for each of its quantities: large enough that the
// optimizer leaves that region, finite so that its arithmetic stays sane.
constexpr double kFailedRunError = 10.0;
// The relative error of a chip thickness that was measured but that the chip analysis could not give.
constexpr double kMissingChipThicknessError = 1.0;

// The condition's result directory: the id validate gives it, less validate's "forces_" prefix.
std::string condition_id(const MeasuredForces& m) { return force_condition_id(m).substr(std::string("forces_").size()); }

// A parameter's column in evaluations.csv: its name with its unit as the other columns spell units (jc_A_Pa,
// fracture_energy_J_per_m2, thermal_conductivity_W_per_m_K); a ratio and friction go bare, as the other
// dimensionless columns do.
std::string column_name(const CalibrationParameter& p) {
  if (p.unit.empty()) return p.name;
  std::string unit;
  std::string_view u = p.unit;
  if (u.starts_with("1/")) u.remove_prefix(1);  // 1/s -> per_s
  for (const char c : u) {
    if (c == '/') unit += "_per_";
    else if (c == ' ') unit += '_';
    else if (c != '(' && c != ')' && c != '^') unit += c;
  }
  if (unit.starts_with('_')) unit.erase(0, 1);
  return p.name + "_" + unit;
}

// The tool's heat as the runs had it ("" for an adiabatic tool), for the provenance of the set: a set fitted with
// a conducting tool is another set with an adiabatic one.
std::string tool_heat_text(const ConditionRunSettings& r) {
  std::string out;
  if (r.tool_heat_transfer_coefficient)
    out += fmt::format("; tool heat transfer coefficient {:g} W/(m^2 K)", *r.tool_heat_transfer_coefficient);
  if (r.tool_conductivity) out += fmt::format(", conducting tool {:g} W/(m K)", *r.tool_conductivity);
  if (r.tool_volumetric_heat_capacity)
    out += fmt::format(", rho c {:g} J/(m^3 K)", *r.tool_volumetric_heat_capacity);
  if (r.tool_temperature) out += fmt::format(", tool at {:g} K", *r.tool_temperature);
  if (r.friction_heat_share)
    out += fmt::format("; frictional heat share into the workpiece {:g}", *r.friction_heat_share);
  return out;
}

CuttingCondition cutting_condition(const MeasuredForces& m) {
  CuttingCondition c = force_condition(m);
  c.id = condition_id(m);
  return c;
}

// One condition's simulated result, as far as the objective uses it.
struct ConditionResult {
  std::string status;  // "complete" or why not
  std::optional<double> fc_N_per_mm, ft_N_per_mm, chip_thickness_um;
};

json to_json(const std::optional<double>& x) { return x ? json(*x) : json(nullptr); }
std::optional<double> from_json(const json& j) {
  return j.is_number() ? std::optional<double>(j.get<double>()) : std::nullopt;
}

// One evaluation: the optimizer's point, the parameter values and the outcome.
struct Evaluation {
  std::vector<double> u;       // the optimizer's variables, each in [0, 1]
  std::vector<double> values;  // the parameters, in their units
  double objective = 0;
  std::vector<ConditionResult> conditions;  // per training condition
  int model_version = 0;  // of the runs' scenes (solver/model_version.hpp); 0 in caches written before it was kept
};

json to_json(const Evaluation& e) {
  json c = json::array();
  for (const ConditionResult& r : e.conditions)
    c.push_back({{"status", r.status}, {"Fc_N_per_mm", to_json(r.fc_N_per_mm)}, {"Ft_N_per_mm", to_json(r.ft_N_per_mm)},
                 {"chip_thickness_um", to_json(r.chip_thickness_um)}});
  return {{"u", e.u}, {"values", e.values}, {"objective", e.objective}, {"conditions", c},
          {"model_version", e.model_version}};
}
Evaluation evaluation_from_json(const json& j) {
  Evaluation e;
  e.u = j.at("u").get<std::vector<double>>();
  e.values = j.at("values").get<std::vector<double>>();
  e.objective = j.at("objective").get<double>();
  for (const json& c : j.at("conditions"))
    e.conditions.push_back({c.at("status").get<std::string>(), from_json(c.at("Fc_N_per_mm")),
                            from_json(c.at("Ft_N_per_mm")), from_json(c.at("chip_thickness_um"))});
  if (j.contains("model_version")) e.model_version = j.at("model_version").get<int>();
  return e;
}

// The cache key of a point: the exact bits of each variable (hexadecimal floating point), so that a
// replayed optimizer, which proposes bit-identical points, finds its earlier evaluations.
std::string point_key(const std::vector<double>& u) {
  std::string key;
  for (double x : u) key += fmt::format("{}{:a}", key.empty() ? "" : ",", x);
  return key;
}

std::string number_text(const std::optional<double>& x, int digits = 4) {
  return x && std::isfinite(*x) ? fmt::format("{:.{}g}", *x, digits) : std::string();
}
std::string percent(const std::optional<double>& e) { return e ? fmt::format("{:+.1f}", 100.0 * *e) : std::string(); }

}  // namespace

ConditionRunSettings condition_run_settings(const CalibrationConfig& config, const MeasuredForces& condition) {
  ConditionRunSettings s = config.runs;
  if (const auto it = config.cells_per_feed_by_line.find(condition.line); it != config.cells_per_feed_by_line.end())
    s.cells_per_feed = it->second;
  return s;
}

double parameter_unit(const CalibrationParameter& p, double value) {
  return p.log_scale ? std::log(value / p.min) / std::log(p.max / p.min) : (value - p.min) / (p.max - p.min);
}

double parameter_value(const CalibrationParameter& p, double u) {
  if (u == parameter_unit(p, p.start)) return p.start;
  return p.log_scale ? p.min * std::pow(p.max / p.min, u) : p.min + u * (p.max - p.min);
}

namespace {

class Calibrator {
 public:
  Calibrator(const CalibrationConfig& c, fs::path out, int jobs, double progress_interval_s)
      : c_(c), out_(std::move(out)), jobs_(jobs), progress_interval_s_(progress_interval_s) {}

  int run();

 private:
  double value_of(std::size_t i, double u) const { return parameter_value(c_.parameters[i], u); }
  double u_of(std::size_t i, double value) const { return parameter_unit(c_.parameters[i], value); }

  ConditionRunSettings settings_for(const std::vector<double>& values) const;
  ConditionRunSettings condition_settings(const MeasuredForces& m, const ConditionRunSettings& trial) const;
  // The model version of the training runs at `values`: the newest over their scenes.
  int model_version_at(const std::vector<double>& values) const;
  std::vector<ConditionResult> run_conditions(const std::vector<MeasuredForces>& conditions,
                                              const std::vector<double>& values, const fs::path& dir, bool& completed);
  // Relative errors of one condition (nullopt where not measured), the failed-run error where it failed.
  struct Errors {
    std::optional<double> fc, ft, chip_thickness;
  };
  Errors errors(const MeasuredForces& m, const ConditionResult& r) const;
  double objective(const std::vector<MeasuredForces>& conditions, const std::vector<ConditionResult>& results) const;

  static double nlopt_objective(unsigned n, const double* x, double* grad, void* self);
  double evaluate(const std::vector<double>& u);
  void optimize_stage(const std::string& algorithm, int budget, std::vector<double>& u);

  void load_cache();
  void append_to_cache(const std::string& key, const Evaluation& e);
  void write_evaluations_csv() const;
  void write_results(const Evaluation& best, const std::vector<ConditionResult>& held_back, bool held_back_complete);

  const CalibrationConfig& c_;
  fs::path out_;
  int jobs_;
  double progress_interval_s_;  // 0: no periodic progress lines
  std::map<std::string, Evaluation> cache_;
  std::vector<std::pair<std::string, std::string>> sequence_;  // (stage, key) of every evaluation, in order
  std::string stage_;
  nlopt_opt current_ = nullptr;
  bool interrupted_ = false;
  int ran_ = 0, replayed_ = 0;
};

ConditionRunSettings Calibrator::settings_for(const std::vector<double>& values) const {
  ConditionRunSettings s = c_.runs;
  s.snapshots = 2;  // the last one is what the chip analysis reads; more would only fill the disk
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (c_.parameters[i].name == "friction") {
      s.friction = values[i];
      s.friction_note = "calibration trial value";
    } else {
      s.material_overrides.emplace_back(c_.parameters[i].name, values[i]);
    }
  }
  return s;
}

ConditionRunSettings Calibrator::condition_settings(const MeasuredForces& m, const ConditionRunSettings& trial) const {
  ConditionRunSettings settings = trial;
  settings.cells_per_feed = condition_run_settings(c_, m).cells_per_feed;
  return settings;
}

int Calibrator::model_version_at(const std::vector<double>& values) const {
  const ConditionRunSettings trial = settings_for(values);
  int version = 0;
  for (const MeasuredForces& m : c_.training) {
    const CuttingCondition cc = cutting_condition(m);
    const Case c = parse_case(condition_case_text(cc, condition_settings(m, trial)), "the case of " + cc.id);
    version = std::max(version, model_version(c.scene));
  }
  return version;
}

std::vector<ConditionResult> Calibrator::run_conditions(const std::vector<MeasuredForces>& conditions,
                                                        const std::vector<double>& values, const fs::path& dir,
                                                        bool& completed) {
  const ConditionRunSettings trial = settings_for(values);
  fs::create_directories(dir / "cases");
  fs::create_directories(dir / "logs");
  std::vector<ChildRun> runs;
  for (const MeasuredForces& m : conditions) {
    const CuttingCondition cc = cutting_condition(m);
    const fs::path case_file = dir / "cases" / (cc.id + ".toml");
    write_file_atomically(case_file, [&](std::ostream& s) { s << condition_case_text(cc, condition_settings(m, trial)); });
    ChildRun r;
    r.name = dir.filename().string() + "/" + cc.id;
    // --keep-complete: an evaluation cut short (a stop, the end of a working session) resumes its runs from their
    // checkpoints when the calibration is started again, instead of running them from the start; the optimizer's
    // replay brings the same point to the same folder, and a changed scene is never resumed (the scene hash).
    r.args = {"run", case_file.string(), "--out", (dir / cc.id).string(), "--keep-complete", "--no-progress", "--no-plots",
              "--threads", std::to_string(c_.threads)};
    r.log_file = dir / "logs" / (cc.id + ".log");
    runs.push_back(r);
  }
  completed = run_cases(runs, jobs_, true, progress_interval_s_);
  // The chip thickness comes from the chip analysis of the last snapshot.
  if (completed && c_.weight_chip_thickness > 0) {
    std::vector<ChildRun> analyses;
    for (std::size_t i = 0; i < conditions.size(); ++i) {
      if (!conditions[i].chip_thickness_um || runs[i].exit_code != 0) continue;
      ChildRun a;
      a.name = runs[i].name + " (analyze)";
      a.args = {"analyze", (dir / cutting_condition(conditions[i]).id).string()};
      a.log_file = dir / "logs" / (cutting_condition(conditions[i]).id + ".analyze.log");
      analyses.push_back(a);
    }
    if (!analyses.empty()) completed = run_cases(analyses, jobs_, false);
  }
  std::vector<ConditionResult> results;
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    const CaseResult r = read_case_result(dir / cutting_condition(conditions[i]).id, runs[i].log_file, runs[i].exit_code);
    ConditionResult cr;
    cr.status = r.status == "complete" ? r.status : fmt::format("{}: {}", r.status, r.message);
    cr.fc_N_per_mm = r.cutting_force_N_per_mm;
    cr.ft_N_per_mm = r.thrust_force_N_per_mm;
    if (r.chip_thickness_ratio && *r.chip_thickness_ratio > 0)
      cr.chip_thickness_um = conditions[i].h_mm * 1e3 / *r.chip_thickness_ratio;  // t_c = t0 / r
    results.push_back(cr);
  }
  return results;
}

Calibrator::Errors Calibrator::errors(const MeasuredForces& m, const ConditionResult& r) const {
  Errors e;
  const bool failed = r.status != "complete" || !r.fc_N_per_mm || !r.ft_N_per_mm;
  const double b = m.width_mm.value_or(c_.width_of_cut_mm);  // the row's width, else the ASSUMED one: N -> N/mm
  e.fc = failed ? kFailedRunError : (*r.fc_N_per_mm - m.fc_N / b) / (m.fc_N / b);
  e.ft = failed ? kFailedRunError : (*r.ft_N_per_mm - m.ff_N / b) / (m.ff_N / b);
  if (m.chip_thickness_um)
    e.chip_thickness = failed               ? kFailedRunError
                       : r.chip_thickness_um ? (*r.chip_thickness_um - *m.chip_thickness_um) / *m.chip_thickness_um
                                             : kMissingChipThicknessError;
  return e;
}

// Weighted root-mean-square relative error over the conditions and quantities (dimensionless):
// J = sqrt( sum w_q e_iq^2 / sum w_q ), the chip thickness only where it was measured.
double Calibrator::objective(const std::vector<MeasuredForces>& conditions,
                             const std::vector<ConditionResult>& results) const {
  double sum = 0, weights = 0;
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    const Errors e = errors(conditions[i], results[i]);
    sum += c_.weight_fc * *e.fc * *e.fc + c_.weight_ft * *e.ft * *e.ft;
    weights += c_.weight_fc + c_.weight_ft;
    if (e.chip_thickness && c_.weight_chip_thickness > 0) {
      sum += c_.weight_chip_thickness * *e.chip_thickness * *e.chip_thickness;
      weights += c_.weight_chip_thickness;
    }
  }
  return std::sqrt(sum / weights);
}

double Calibrator::nlopt_objective(unsigned n, const double* x, double*, void* self) {
  return static_cast<Calibrator*>(self)->evaluate(std::vector<double>(x, x + n));
}

double Calibrator::evaluate(const std::vector<double>& u) {
  const std::string key = point_key(u);
  const std::size_t index = sequence_.size() + 1;
  Evaluation e;
  e.u = u;
  for (std::size_t i = 0; i < u.size(); ++i) e.values.push_back(value_of(i, u[i]));
  e.model_version = model_version_at(e.values);
  if (const auto it = cache_.find(key); it != cache_.end()) {
    if (it->second.model_version >= e.model_version) {
      sequence_.emplace_back(stage_, key);
      ++replayed_;
      return it->second.objective;
    }
    // Made by an older model of these runs (solver/model_version.hpp): its runs are outdated and run again.
    if (!interrupted_)
      std::cout << fmt::format("evaluation {}: the cached result is of model version {}, these runs are of version "
                               "{}; running it again\n",
                               index, it->second.model_version, e.model_version);
  }
  if (interrupted_) return HUGE_VAL;  // NLopt is stopping; nothing more runs
  std::string values;
  for (std::size_t i = 0; i < u.size(); ++i)
    values += fmt::format("{}{} = {:.6g}{}", values.empty() ? "" : ", ", c_.parameters[i].name, e.values[i],
                          c_.parameters[i].unit.empty() ? "" : " " + c_.parameters[i].unit);
  std::cout << fmt::format("evaluation {} ({} stage): {}\n", index, stage_, values) << std::flush;
  bool completed = true;
  e.conditions = run_conditions(c_.training, e.values, out_ / "evaluations" / fmt::format("e{:04d}", index), completed);
  if (!completed) {
    // Not cached: the next start runs this evaluation again.
    interrupted_ = true;
    nlopt_force_stop(current_);
    return HUGE_VAL;
  }
  e.objective = objective(c_.training, e.conditions);
  cache_[key] = e;
  append_to_cache(key, e);
  sequence_.emplace_back(stage_, key);
  ++ran_;
  write_evaluations_csv();
  std::cout << fmt::format("evaluation {}: objective {:.4g} (weighted RMS relative error)\n", index, e.objective)
            << std::flush;
  return e.objective;
}

void Calibrator::optimize_stage(const std::string& algorithm, int budget, std::vector<double>& u) {
  if (algorithm == "none" || budget <= 0 || interrupted_) return;
  const std::size_t n = u.size();
  nlopt_opt opt = nlopt_create(nlopt_algorithm_from_string(algorithm.c_str()), static_cast<unsigned>(n));
  current_ = opt;
  const std::vector<double> lower(n, 0.0), upper(n, 1.0);
  nlopt_set_lower_bounds(opt, lower.data());
  nlopt_set_upper_bounds(opt, upper.data());
  nlopt_set_min_objective(opt, &Calibrator::nlopt_objective, this);
  nlopt_set_maxeval(opt, budget);
  // The same seed before each stage: a replay after a restart proposes the same points.
  nlopt_srand(c_.seed);
  double f = 0;
  const nlopt_result r = nlopt_optimize(opt, u.data(), &f);
  if (!interrupted_)
    std::cout << fmt::format("{} stage ({}): {}\n", stage_, algorithm, nlopt_result_to_string(r)) << std::flush;
  nlopt_destroy(opt);
  current_ = nullptr;
}

void Calibrator::load_cache() {
  const fs::path file = out_ / "cache.jsonl";
  std::ifstream in(file);
  std::string complete;  // the lines that parse, each with its newline
  bool damaged = false;
  for (std::string line; std::getline(in, line);) {
    const json j = json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.contains("key") || in.eof()) {  // a line cut short by a kill
      damaged = true;
      continue;
    }
    cache_[j.at("key").get<std::string>()] = evaluation_from_json(j.at("evaluation"));
    complete += line + "\n";
  }
  in.close();
  // Without its cut-short tail, so that the next line appended starts on a line of its own.
  if (damaged) write_file_atomically(file, [&](std::ostream& s) { s << complete; });
}

void Calibrator::append_to_cache(const std::string& key, const Evaluation& e) {
  // One line per completed evaluation, flushed to the disk before the optimizer goes on: a kill -9 loses at
  // most the evaluation that was running. A line cut short is skipped when the cache is read.
  const std::string line = json{{"key", key}, {"evaluation", to_json(e)}}.dump() + "\n";
  const int fd = ::open((out_ / "cache.jsonl").c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd < 0) throw std::runtime_error(fmt::format("cannot write {}", (out_ / "cache.jsonl").string()));
  const bool ok = ::write(fd, line.data(), line.size()) == static_cast<ssize_t>(line.size()) && ::fsync(fd) == 0;
  ::close(fd);
  if (!ok) throw std::runtime_error(fmt::format("cannot write {}", (out_ / "cache.jsonl").string()));
}

void Calibrator::write_evaluations_csv() const {
  write_file_atomically(out_ / "evaluations.csv", [&](std::ostream& s) {
    s << "evaluation,stage";
    for (const CalibrationParameter& p : c_.parameters) s << "," << column_name(p);
    s << ",objective,best_objective";
    for (const MeasuredForces& m : c_.training) {
      const std::string id = condition_id(m);
      s << "," << id << "_Fc_N_per_mm," << id << "_Ft_N_per_mm," << id << "_chip_thickness_um," << id << "_status";
    }
    s << "\n";
    double best = HUGE_VAL;
    for (std::size_t k = 0; k < sequence_.size(); ++k) {
      const Evaluation& e = cache_.at(sequence_[k].second);
      best = std::min(best, e.objective);
      s << k + 1 << "," << sequence_[k].first;
      for (double v : e.values) s << fmt::format(",{}", v);
      s << fmt::format(",{},{}", e.objective, best);
      for (const ConditionResult& r : e.conditions) {
        std::string status = r.status;
        for (char& ch : status)
          if (ch == ',' || ch == '"' || ch == '\n') ch = ' ';
        s << "," << number_text(r.fc_N_per_mm, 6) << "," << number_text(r.ft_N_per_mm, 6) << ","
          << number_text(r.chip_thickness_um, 6) << "," << status;
      }
      s << "\n";
    }
  });
}

void Calibrator::write_results(const Evaluation& best, const std::vector<ConditionResult>& held_back,
                               bool held_back_complete) {
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::localtime(&now));
  std::string training_list, held_list;
  for (const MeasuredForces& m : c_.training) training_list += (training_list.empty() ? "" : ", ") + condition_id(m);
  for (const MeasuredForces& m : c_.held_back) held_list += (held_list.empty() ? "" : ", ") + condition_id(m);
  const std::string objective_text = fmt::format(
      "weighted RMS relative error, weights Fc {:g}, Ft {:g}, chip thickness {:g}; measured forces in N divided by "
      "the width of cut of the measurement file's rows (column width_mm) or, where it gives none, an ASSUMED b = {:g} mm",
      c_.weight_fc, c_.weight_ft, c_.weight_chip_thickness, c_.width_of_cut_mm);
  const bool global_stage = c_.global_algorithm != "none" && c_.global_evaluations > 0;
  const bool local_stage = c_.local_algorithm != "none" && c_.evaluations > c_.global_evaluations;
  const std::string budget_text =
      !global_stage ? fmt::format("{} evaluations ({} only), seed {}", c_.evaluations, c_.local_algorithm, c_.seed)
      : local_stage ? fmt::format("{} evaluations ({} global {}, then {}), seed {}", c_.evaluations,
                                  c_.global_evaluations, c_.global_algorithm, c_.local_algorithm, c_.seed)
                    : fmt::format("{} evaluations, all global {} (no local stage: the global stage's budget, "
                                  "min(20, evaluations) unless global_evaluations says otherwise, took them all), "
                                  "seed {}",
                                  c_.evaluations, c_.global_algorithm, c_.seed);
  std::string own_resolutions;  // the conditions with their own cells across t0
  for (const auto* list : {&c_.training, &c_.held_back})
    for (const MeasuredForces& m : *list)
      if (const auto it = c_.cells_per_feed_by_line.find(m.line); it != c_.cells_per_feed_by_line.end())
        own_resolutions += fmt::format("{}t0/{} at {}", own_resolutions.empty() ? "" : ", ", it->second, condition_id(m));
  const std::string resolution =
      (c_.runs.quick ? "quick (cell = t0/4, 1 particle per cell, 4 cells of travel)"
       : c_.runs.cells_per_edge_radius > 0.0
           ? fmt::format("cell = min(t0/{}, r_n/{:g})", c_.runs.cells_per_feed, c_.runs.cells_per_edge_radius)
           : fmt::format("cell = t0/{} (no edge-radius limit)", c_.runs.cells_per_feed)) +
      (own_resolutions.empty() ? std::string()
       : c_.runs.quick         ? " (the conditions' own cells_per_feed, " + own_resolutions + ", are not used by quick runs)"
                               : " with " + own_resolutions + " instead") +
      // The contact only when chosen, so that a configuration without it reports as before.
      (c_.runs.contact_detection.empty() ? std::string()
                                         : fmt::format(", {} contact", c_.runs.contact_detection)) +
      (c_.runs.volumetric_average.empty() ? std::string()
                                          : fmt::format(", volumetric average {}", c_.runs.volumetric_average));

  // The best set, ready to paste into a case file or materials/.
  const auto friction_index = [&]() -> std::optional<std::size_t> {
    for (std::size_t i = 0; i < c_.parameters.size(); ++i)
      if (c_.parameters[i].name == "friction") return i;
    return std::nullopt;
  }();
  // What the set was fitted with besides the material: a set fitted at one friction is another set at another.
  const CuttingParameters preset;
  const std::string process_text =
      (friction_index ? std::string("Coulomb friction fitted (below)")
                      : fmt::format("Coulomb friction {} fixed ({})", c_.runs.friction, c_.runs.friction_note)) +
      fmt::format("; tool: each row's edge_radius_um, and its rake_deg / clearance_deg where the measurement file "
                  "gives them, else rake {:g} deg and clearance {:g} deg (the preset's, ASSUMED)",
                  preset.rake_angle_deg, preset.clearance_angle_deg) +
      tool_heat_text(c_.runs);
  write_file_atomically(out_ / "best_material.toml", [&](std::ostream& s) {
    s << "# Calibrated by `mpmcut calibrate " << c_.file.string() << "` on " << date << ".\n";
    s << "# Data: " << c_.measurements_source << "; training conditions (h, vc): " << training_list << ".\n";
    s << "# Objective: " << objective_text << "; value at this set " << fmt::format("{:.4g}", best.objective) << ".\n";
    s << "# Budget: " << budget_text << "; runs at " << resolution << ".\n";
    s << "# Process: " << process_text << ".\n";
    if (friction_index)
      s << fmt::format("# Tool friction (a [cutting] key, not a material key): friction = {}\n",
                       best.values[*friction_index]);
    s << "[[material]]\n";
    s << fmt::format("name = \"{}\"\n", c_.set_name);
    s << fmt::format("library = \"{}\"\n", c_.base_material);
    s << fmt::format("citation = \"mpmcut calibrate {}: {} fitted to {} training condition(s) of {}, objective {:.4g}\"\n",
                     date, c_.base_material, c_.training.size(), c_.measurements_source, best.objective);
    for (const auto& [key, value] : c_.runs.material_overrides) s << fmt::format("{} = {}  # fixed\n", key, value);
    for (std::size_t i = 0; i < c_.parameters.size(); ++i)
      if (c_.parameters[i].name != "friction") s << fmt::format("{} = {}\n", c_.parameters[i].name, best.values[i]);
  });

  // Per condition: measured, simulated, error, training and held back side by side.
  const auto row = [&](const std::string& set, const MeasuredForces& m, const ConditionResult& r,
                       std::vector<std::string>& cells) {
    const Errors e = errors(m, r);
    const double b = m.width_mm.value_or(c_.width_of_cut_mm);
    const bool ok = r.status == "complete";
    cells = {set, condition_id(m), fmt::format("{:g}", m.h_mm), fmt::format("{:g}", m.vc_m_per_min),
             fmt::format("{:.4g}", m.fc_N / b), number_text(r.fc_N_per_mm), ok ? percent(e.fc) : "",
             fmt::format("{:.4g}", m.ff_N / b), number_text(r.ft_N_per_mm), ok ? percent(e.ft) : "",
             m.chip_thickness_um ? fmt::format("{:.4g}", *m.chip_thickness_um) : "", number_text(r.chip_thickness_um),
             ok && r.chip_thickness_um ? percent(e.chip_thickness) : "", r.status};
  };
  TextTable table;
  table.columns = {"set", "condition", "h_mm", "vc_m_per_min", "measured_Fc_N_per_mm", "simulated_Fc_N_per_mm",
                   "Fc_error_percent", "measured_Ft_N_per_mm", "simulated_Ft_N_per_mm", "Ft_error_percent",
                   "measured_chip_thickness_um", "simulated_chip_thickness_um", "chip_thickness_error_percent",
                   "status"};
  table.headings = {"set", "condition", "h (mm)", "vc (m/min)", "Fc measured (N/mm)", "Fc simulated (N/mm)",
                    "Fc error %", "Ft measured (N/mm)", "Ft simulated (N/mm)", "Ft error %",
                    "chip thickness measured (µm)", "simulated (µm)", "error %", "status"};
  for (std::size_t i = 0; i < c_.training.size(); ++i) row("training", c_.training[i], best.conditions[i], table.rows.emplace_back());
  for (std::size_t i = 0; i < held_back.size(); ++i) row("held back", c_.held_back[i], held_back[i], table.rows.emplace_back());
  table.write_csv(out_ / "calibration_best.csv");
  const double held_objective = c_.held_back.empty() ? NAN : objective(c_.held_back, held_back);

  write_file_atomically(out_ / "calibration.md", [&](std::ostream& s) {
    s << "# Calibration " << c_.set_name << "\n\n";
    if (c_.runs.quick)
      s << "**quick runs (cell = t0/4, 1 particle per cell, 4 cells of tool travel): a pipeline check; the forces "
           "are not converged and this set must not be used.**\n\n";
    s << fmt::format("Configuration `{}`, {}. Base set `{}`; free parameters:\n\n", c_.file.string(), date,
                     c_.base_material);
    s << "| parameter | unit | min | max | start | scale | best |\n|---|---|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < c_.parameters.size(); ++i) {
      const CalibrationParameter& p = c_.parameters[i];
      s << fmt::format("| {} | {} | {:g} | {:g} | {:g} | {} | {:.6g} |\n", p.name, p.unit.empty() ? "–" : p.unit,
                       p.min, p.max, p.start, p.log_scale ? "log" : "linear", best.values[i]);
    }
    s << "\n## Objective\n\n" << objective_text << ". A failed run counts as a relative error of "
      << kFailedRunError << " in each of its quantities; a measured chip thickness that the chip analysis could not "
         "give, as "
      << kMissingChipThicknessError << ".\n\n";
    const auto conditions = [](std::size_t n) { return fmt::format("{} condition{}", n, n == 1 ? "" : "s"); };
    s << fmt::format("- training ({}): **{:.4g}** at the best set\n", conditions(c_.training.size()), best.objective);
    if (!c_.held_back.empty())
      s << fmt::format("- held back ({}, not used by the optimizer): **{:.4g}**{}\n", conditions(c_.held_back.size()),
                       held_objective, held_back_complete ? "" : " (some runs did not complete)");
    s << "\n## Budget\n\n" << budget_text << fmt::format("; {} evaluations in this directory. Runs at {}.\n\n",
                                                         sequence_.size(), resolution);
    s << "Process: " << process_text << ".\n\n";
    s << "## Errors at the best set: training and held back\n\n" << table.markdown() << "\n";
    s << "Error % = (simulated − measured) / measured; measured N/mm = measured N / b with b the row's width_mm "
      << "where the data file gives it, else b = " << c_.width_of_cut_mm << " mm ASSUMED.\n\n";
    s << "Data: " << c_.measurements_source << ".\n\n";
    s << "## Files\n\nbest_material.toml (the set, with its provenance), evaluations.csv (every evaluation: "
         "parameters, per-condition forces, objective), calibration_best.csv (this table), convergence.png, "
         "parity.png, evaluations/eNNNN/ (the runs of each evaluation), best_held_back/ (the held-back runs), "
         "cache.jsonl (completed evaluations, replayed on a restart).\n";
  });
}

int Calibrator::run() {
  fs::create_directories(out_);
  load_cache();
  if (!cache_.empty())
    std::cout << fmt::format("mpmcut calibrate: {} completed evaluations in {}, replayed to the optimizer\n",
                             cache_.size(), (out_ / "cache.jsonl").string());
  std::cout << fmt::format("mpmcut calibrate: {} parameters, {} training and {} held-back conditions, {} evaluations "
                           "of {} runs each, {}; results in {}\n",
                           c_.parameters.size(), c_.training.size(), c_.held_back.size(), c_.evaluations,
                           c_.training.size(), concurrency_text(jobs_), out_.string())
            << std::flush;

  std::vector<double> u;
  for (std::size_t i = 0; i < c_.parameters.size(); ++i) u.push_back(u_of(i, c_.parameters[i].start));
  stage_ = "global";
  optimize_stage(c_.global_algorithm, c_.global_evaluations, u);
  // The local stage starts from the best point so far (the start itself without a global stage).
  std::string best_key;
  for (const auto& [stage, key] : sequence_)
    if (best_key.empty() || cache_.at(key).objective < cache_.at(best_key).objective) best_key = key;
  if (!best_key.empty()) u = cache_.at(best_key).u;
  stage_ = "local";
  optimize_stage(c_.local_algorithm, c_.evaluations - static_cast<int>(sequence_.size()), u);
  write_evaluations_csv();
  if (interrupted_) {
    std::cerr << fmt::format("mpmcut calibrate: interrupted after {} evaluations; the same command resumes (the {} "
                             "completed ones are not run again)\n",
                             sequence_.size(), cache_.size());
    return 130;
  }
  for (const auto& [stage, key] : sequence_)
    if (best_key.empty() || cache_.at(key).objective < cache_.at(best_key).objective) best_key = key;
  const Evaluation& best = cache_.at(best_key);
  std::cout << fmt::format("mpmcut calibrate: {} evaluations ({} run now, {} from the cache); best objective {:.4g}\n",
                           sequence_.size(), ran_, replayed_, best.objective);

  // The held-back conditions at the best set, cached like an evaluation (under their own key).
  std::vector<ConditionResult> held_back;
  const std::string held_key = "held_back:" + best_key;
  if (const auto it = cache_.find(held_key); it != cache_.end()) {
    held_back = it->second.conditions;
  } else if (!c_.held_back.empty()) {
    std::cout << "mpmcut calibrate: the held-back conditions at the best set\n" << std::flush;
    bool completed = true;
    held_back = run_conditions(c_.held_back, best.values, out_ / "best_held_back", completed);
    if (!completed) {
      std::cerr << "mpmcut calibrate: interrupted in the held-back runs; the same command resumes them (the "
                   "evaluations are not run again)\n";
      return 130;
    }
    Evaluation e = best;
    e.conditions = held_back;
    e.objective = objective(c_.held_back, held_back);
    cache_[held_key] = e;
    append_to_cache(held_key, e);
  }
  bool held_back_complete = true;
  for (const ConditionResult& r : held_back) held_back_complete = held_back_complete && r.status == "complete";
  write_results(best, held_back, held_back_complete);
  std::cout << "wrote " << (out_ / "calibration.md").string() << ", best_material.toml, evaluations.csv, "
            << "calibration_best.csv\n";
  return held_back_complete ? 0 : 1;
}

// The keys (dotted) whose values differ between two tables, or that one of them lacks.
void differing_keys(const toml::table& a, const toml::table& b, const std::string& prefix,
                    std::vector<std::string>& out) {
  std::set<std::string> keys;
  for (const auto& [k, v] : a) keys.insert(std::string(k.str()));
  for (const auto& [k, v] : b) keys.insert(std::string(k.str()));
  for (const std::string& k : keys) {
    const toml::node* x = a.get(k);
    const toml::node* y = b.get(k);
    if (x && y && x->is_table() && y->is_table())
      differing_keys(*x->as_table(), *y->as_table(), prefix + k + ".", out);
    else if (!x || !y || toml::node_view<const toml::node>(x) != toml::node_view<const toml::node>(y))
      out.push_back(prefix + k);
  }
}

// Which keys and values differ between two configuration texts (none: the same problem): comments, blank lines,
// the order of keys and the spelling of numbers (1e-3, 0.001) do not change the problem a calibration solves.
std::vector<std::string> configuration_differences(const std::string& a, const std::string& b) {
  std::vector<std::string> out;
  try {
    differing_keys(toml::parse(a), toml::parse(b), "", out);
  } catch (const toml::parse_error&) {
    if (a != b) out.push_back("(the text)");
  }
  return out;
}

// The measured rows a calibration uses, as text: an edited measurement file changes the objective of every cached
// evaluation, which a rerun would otherwise report as if computed from the new data.
std::string measurements_text(const CalibrationConfig& c) {
  std::string s = "# the measured rows of this calibration, as read from its measurement file\n";
  for (const auto& [list, rows] : {std::pair{"training", &c.training}, std::pair{"held_back", &c.held_back}})
    for (const MeasuredForces& m : *rows)
      s += fmt::format("{} line {}: h {} mm, vc {} m/min, r_n {} um, Fc {} [{}, {}] N, Ff {} [{}, {}] N, chip {} um, "
                       "width {} mm, rake {} deg, clearance {} deg\n",
                       list, m.line, m.h_mm, m.vc_m_per_min, m.edge_radius_um, m.fc_N, m.fc_min_N, m.fc_max_N, m.ff_N,
                       m.ff_min_N, m.ff_max_N, m.chip_thickness_um.value_or(NAN), m.width_mm.value_or(NAN),
                       m.rake_deg.value_or(NAN), m.clearance_deg.value_or(NAN));
  return s;
}

// The rows without their line numbers: a comment or blank line added to the measurement file moves them, and that
// changes no measured value (a resume was refused for it).
std::string without_line_numbers(const std::string& rows) {
  static const std::regex line_number(R"((^|\n)(\w+) line \d+: )");
  return std::regex_replace(rows, line_number, "$1$2: ");
}

// Empty when the file cannot be read: every caller compares it with the text it expects.
std::string read_text(const fs::path& file) { return read_whole_file(file).value_or(""); }

}  // namespace

int run_calibration(const CalibrationConfig& config, const fs::path& out, int jobs, double progress_interval_s) {
  // A directory holds one calibration: resuming with a changed configuration would replay a cache that
  // belongs to another problem.
  const std::string text = read_text(config.file);
  const fs::path copy = out / "calibration.toml";
  if (fs::exists(copy)) {
    const std::vector<std::string> changed = configuration_differences(read_text(copy), text);
    if (!changed.empty()) {
      std::string keys;
      for (const std::string& k : changed) keys += (keys.empty() ? "" : ", ") + k;
      throw InputError(fmt::format("{}: holds a calibration of a different configuration than {} (changed: {}; "
                                   "differences would make its cache of evaluations wrong); use another --out, or "
                                   "--force to start this one afresh",
                                   copy.string(), config.file.string(), keys));
    }
  }
  // The measured rows too (a directory of an earlier version has no record of them: it gets one now).
  const fs::path rows = out / "measurements_used.txt";
  const std::string rows_text = measurements_text(config);
  if (fs::exists(rows)) {
    const std::string old_rows = without_line_numbers(read_text(rows));
    if (old_rows != without_line_numbers(rows_text)) {
      std::istringstream was(old_rows), is(without_line_numbers(rows_text));
      std::string a, b;
      for (;;) {
        const bool more_a = static_cast<bool>(std::getline(was, a)), more_b = static_cast<bool>(std::getline(is, b));
        if (!more_a) a = "(no row)";
        if (!more_b) b = "(no row)";
        if (!more_a || !more_b || a != b) break;
      }
      throw InputError(fmt::format("{}: the measured rows of this calibration changed since its evaluations were "
                                   "made (was \"{}\", now \"{}\"): their objectives would be those of the old data; "
                                   "use another --out, or --force to start afresh",
                                   config.measurements_source, a, b));
    }
  }
  fs::create_directories(out);
  write_file_atomically(copy, [&](std::ostream& s) { s << text; });
  write_file_atomically(rows, [&](std::ostream& s) { s << rows_text; });
  return Calibrator(config, out, jobs, progress_interval_s).run();
}

}  // namespace mpmcut
