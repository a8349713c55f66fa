#include "studies/case_runs.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include <fmt/format.h>

#include "io/atomic_file.hpp"
#include "run/repeated_signal.hpp"
#include "run/run_case.hpp"
#include "run/run_summary.hpp"
#include "studies/study_progress.hpp"

namespace mpmcut {

namespace {

namespace fs = std::filesystem;

volatile std::sig_atomic_t g_stop_signals = 0;
RepeatedSignalFilter g_repeats;
void on_stop_signal(int) {
  if (g_repeats.is_new_stop()) g_stop_signals = g_stop_signals + 1;
}

std::string self_executable() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("/proc/self/exe") : p.string();
}

// fork + exec of this program in a process group of its own (so that a Ctrl-C at the terminal reaches
// only the sweep, which passes it on exactly once: a run stops with a checkpoint on the first SIGINT
// and exits at once on the second).
pid_t spawn_child(const std::string& exe, const ChildRun& run) {
  std::vector<std::string> argv{exe};
  argv.insert(argv.end(), run.args.begin(), run.args.end());
  std::vector<char*> c_argv;
  for (std::string& a : argv) c_argv.push_back(a.data());
  c_argv.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid != 0) return pid;
  setpgid(0, 0);
  // If the sweep itself dies (even by SIGKILL) its runs get SIGTERM: they checkpoint and stop
  // instead of running on as orphans (docs/reliability.md, "Signals").
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (getppid() != parent) _exit(130);  // the sweep died before prctl took effect
  const int in = open("/dev/null", O_RDONLY);
  const int log = open(run.log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (in >= 0) dup2(in, STDIN_FILENO);
  if (log >= 0) {
    dup2(log, STDOUT_FILENO);
    dup2(log, STDERR_FILENO);
  }
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  // The program this study started as, even if its file was replaced since (a rebuild relinks
  // build/mpmcut under a running study): /proc/self/exe is the running image, not the path. argv[0]
  // keeps the readable path for ps and the logs.
  execv("/proc/self/exe", c_argv.data());
  execv(c_argv[0], c_argv.data());  // no /proc: the path
  _exit(127);
}

std::string exit_text(int code) {
  if (code == 0) return "complete";
  if (code == 130) return "interrupted";
  if (code == 127) return "could not start";
  if (code > 128) return fmt::format("killed by signal {}", code - 128);
  return fmt::format("failed (exit status {})", code);
}

}  // namespace

std::string finished_case_text(const ChildRun& run) {
  if (run.exit_code == 130) {
    try {
      if (read_summary(result_dir_of_args(run.args) / "summary.json").status == "complete")
        return "complete (the stop came after its last step)";
    } catch (const std::exception&) {
    }
  }
  return exit_text(run.exit_code);
}

namespace {

std::string last_lines(const fs::path& file, int count) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    // Progress bars rewrite one line with carriage returns: keep what follows the last one.
    if (const auto cr = line.rfind('\r'); cr != std::string::npos) line = line.substr(cr + 1);
    if (!line.empty()) lines.push_back(line);
  }
  std::string out;
  for (std::size_t i = lines.size() > std::size_t(count) ? lines.size() - count : 0; i < lines.size(); ++i)
    out += (out.empty() ? "" : " | ") + lines[i];
  return out;
}

// Mean raw forces over the last half of the tool travel: the fallback when the run ended before its
// steady window began (short test and --quick cuts). Says so in CaseResult::force_basis.
bool last_half_means(const fs::path& forces_csv, double& fc, double& ft) {
  std::ifstream in(forces_csv);
  std::string header;
  if (!std::getline(in, header)) return false;
  std::vector<std::string> names;
  for (std::stringstream ss(header); std::getline(ss, header, ',');) names.push_back(header);
  const auto column = [&](std::initializer_list<const char*> candidates) -> int {
    for (const char* c : candidates)
      for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == c) return static_cast<int>(i);
    return -1;
  };
  const int ic = column({"cutting_force_raw_N_per_mm", "cutting_force_N_per_mm"});
  const int it = column({"thrust_force_raw_N_per_mm", "thrust_force_N_per_mm"});
  const int id = column({"tool_displacement_m", "time_s"});
  if (ic < 0 || it < 0 || id < 0) return false;
  std::vector<std::array<double, 3>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> v;
    for (std::stringstream ss(line); std::getline(ss, line, ',');) v.push_back(std::strtod(line.c_str(), nullptr));
    if (v.size() == names.size()) rows.push_back({std::abs(v[id]), v[ic], v[it]});
  }
  if (rows.size() < 4) return false;
  const double half = 0.5 * rows.back()[0];
  double sc = 0, st = 0;
  int n = 0;
  for (const auto& r : rows)
    if (r[0] >= half) sc += r[1], st += r[2], ++n;
  if (n == 0) return false;
  fc = sc / n;
  ft = st / n;
  return true;
}

std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return q + "\"";
}

}  // namespace

bool run_children(std::vector<ChildRun>& runs, int jobs, bool print_progress, double progress_interval_s) {
  g_stop_signals = 0;
  g_repeats.reset();
  struct sigaction action {}, old_int{}, old_term{};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &old_int);
  sigaction(SIGTERM, &action, &old_term);

  const std::string exe = self_executable();
  using clock = std::chrono::steady_clock;
  std::map<pid_t, std::pair<std::size_t, clock::time_point>> running;
  // Per running case: the study's wall time and the case's progress when its progress was first seen (for the
  // estimate of what is left: a resumed case starts part-way).
  std::map<pid_t, std::pair<double, double>> first_seen;
  const clock::time_point study_start = clock::now();
  clock::time_point last_report = study_start, last_sample = study_start;
  std::size_t next = 0, finished = 0;
  int forwarded = 0;
  jobs = std::max(1, jobs);
  while (true) {
    while (g_stop_signals == 0 && static_cast<int>(running.size()) < jobs && next < runs.size()) {
      const pid_t pid = spawn_child(exe, runs[next]);
      if (pid < 0) {
        runs[next].exit_code = 127;
        ++next;
        continue;
      }
      running[pid] = {next++, clock::now()};
    }
    if (running.empty()) break;
    if (g_stop_signals > forwarded) {
      forwarded = g_stop_signals;
      const int sig = forwarded == 1 ? SIGINT : SIGKILL;
      if (print_progress)
        std::cerr << (sig == SIGINT ? "\ninterrupted: stopping the running cases (they write a checkpoint; "
                                      "Ctrl-C again, half a second or more later, to kill them)\n"
                                    : "\nkilling the running cases\n");
      for (const auto& [pid, info] : running) kill(-pid, sig);
    }
    bool reaped = false;
    for (auto it = running.begin(); it != running.end();) {
      int status = 0;
      const pid_t r = waitpid(it->first, &status, WNOHANG);
      if (r == 0 || (r < 0 && errno == EINTR)) {
        ++it;
        continue;
      }
      first_seen.erase(it->first);
      ChildRun& run = runs[it->second.first];
      run.exit_code = r < 0 ? 127 : WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      run.wall_time_s = std::chrono::duration<double>(clock::now() - it->second.second).count();
      ++finished;
      if (print_progress) {
        const std::string text = finished_case_text(run);
        std::cout << fmt::format("[{}/{}] {}: {} ({:.1f} s){}\n", finished, runs.size(), run.name, text,
                                 run.wall_time_s, text.starts_with("complete") ? "" : ", log: " + run.log_file.string())
                  << std::flush;
      }
      if (run.on_finished) run.on_finished(run);
      it = running.erase(it);
      reaped = true;
    }
    const clock::time_point now = clock::now();
    // The first progress of each case is sampled early (once a minute until it shows), so that the first report
    // can already say what is left.
    if (print_progress && std::chrono::duration<double>(now - last_sample).count() >= 60.0) {
      last_sample = now;
      const double study_s = std::chrono::duration<double>(now - study_start).count();
      for (const auto& [pid, info] : running)
        if (!first_seen.contains(pid))
          if (const auto f = run_fraction_done(result_dir_of_args(runs[info.first].args)))
            first_seen.emplace(pid, std::pair{study_s, *f});
    }
    if (print_progress && progress_interval_s > 0.0 && !running.empty() &&
        std::chrono::duration<double>(now - last_report).count() >= progress_interval_s) {
      last_report = now;
      const double study_s = std::chrono::duration<double>(now - study_start).count();
      std::vector<RunningCase> cases;
      for (const auto& [pid, info] : running) {
        RunningCase c;
        c.name = runs[info.first].name;
        c.wall_s = std::chrono::duration<double>(now - info.second).count();
        c.fraction = run_fraction_done(result_dir_of_args(runs[info.first].args));
        if (c.fraction) {
          const auto [seen_s, seen_fraction] = first_seen.try_emplace(pid, study_s, *c.fraction).first->second;
          if (*c.fraction > seen_fraction && study_s > seen_s)
            c.remaining_s = (1.0 - *c.fraction) * (study_s - seen_s) / (*c.fraction - seen_fraction);
        }
        cases.push_back(c);
      }
      std::cout << progress_report_line(cases) << "\n" << std::flush;
    }
    if (!reaped) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
  return g_stop_signals == 0;
}

CaseResult read_case_result(const fs::path& dir, const fs::path& log_file, int exit_code) {
  CaseResult r;
  std::optional<RunSummary> summary;
  try {
    summary = read_summary(dir / "summary.json");
  } catch (const std::exception&) {
  }
  if (!summary) {
    r.status = exit_code == -1 ? "not run" : "failed";
    r.message = exit_code == -1 ? "interrupted before it started"
                                : fmt::format("{}, no summary.json: {}", exit_text(exit_code), last_lines(log_file, 2));
    return r;
  }
  const RunSummary& s = *summary;
  r.status = s.status;
  if (r.status.empty()) r.status = exit_code == 0 ? "complete" : "failed";
  r.message = s.message;
  // The run's warnings on its numbers go with them into the study's table (sweep.csv's message was empty beside
  // a run that warned of a window in the entry transient or a drifting force).
  {
    std::vector<std::string> warnings;
    const auto warning_of = [&](const nlohmann::json& section) {
      if (section.is_object() && section.contains("warning") && section["warning"].is_string())
        warnings.push_back(section["warning"].get<std::string>());
    };
    // The inputs first: a value in the wrong unit makes every other number wrong.
    if (const auto inputs = s.sections.find("input_warnings"); inputs != s.sections.end() && inputs->is_array())
      for (const nlohmann::json& w : *inputs)
        if (w.is_string()) warnings.push_back(w.get<std::string>());
    if (const auto window = s.sections.find("steady_window"); window != s.sections.end()) {
      warning_of(*window);
      if (window->is_object() && window->contains("drift")) warning_of((*window)["drift"]);
    }
    if (const std::string w = energy_residual_warning(s.energy_relative_residual); !w.empty()) warnings.push_back(w);
    for (const std::string& w : warnings) r.message += (r.message.empty() ? "warning: " : "; warning: ") + w;
  }
  r.source_revision = s.source_revision.empty() ? "unrecorded" : s.source_revision;
  if (r.status != "complete" && r.message.empty()) r.message = last_lines(log_file, 2);
  // A complete run of an older model of its scene (a study stopped before it ran it again): not a result of today's
  // model (solver/model_version.hpp).
  if (r.status == "complete")
    if (const std::string why = outdated_run_reason(dir); !why.empty()) {
      r.status = "outdated";
      r.message = fmt::format("{}; run the study again to rerun it", why);
    }

  // A run that did not complete (interrupted, failed) has cut only part of its length: its mean forces would sit in
  // the study's table beside the complete ones as if they were results.
  if (r.status == "outdated") {
    r.message += "; forces left out: they are of the older model";
  } else if (r.status != "complete") {
    r.message += fmt::format("{}forces left out: the run did not complete (its forces.csv holds the cut so far)",
                             r.message.empty() ? "" : "; ");
  } else if (s.mean_cutting_force_N_per_mm && s.mean_thrust_force_N_per_mm) {
    r.cutting_force_N_per_mm = s.mean_cutting_force_N_per_mm;
    r.thrust_force_N_per_mm = s.mean_thrust_force_N_per_mm;
    r.force_basis = "steady window";
    r.cutting_force_drift_percent = steady_drift_percent(s, "cutting");
    r.thrust_force_drift_percent = steady_drift_percent(s, "thrust");
  } else if (double fc = 0, ft = 0; last_half_means(dir / "forces.csv", fc, ft)) {
    r.cutting_force_N_per_mm = fc;
    r.thrust_force_N_per_mm = ft;
    r.force_basis = "last half of the cut (no steady window)";
  }
  const auto finite = [](double x) { return std::isfinite(x) ? std::optional<double>(x) : std::nullopt; };
  r.max_temperature_K = finite(s.max_temperature_K);
  r.wall_time_s = finite(s.wall_time_s);
  if (s.steps > 0) r.steps = static_cast<double>(s.steps);
  if (s.threads > 0 && s.particle_steps_per_s > 0.0) r.core_seconds_per_particle_step = s.threads / s.particle_steps_per_s;
  if (s.cell_size_m > 0.0) r.cell_size_um = s.cell_size_m * 1e6;
  r.mass_scaling_factor = mass_scaling_factor(s);
  r.tool_force_split = tool_force_split(s);
  r.tool_heat_share = tool_heat_share(s);
  // The tool's work and where it went (energy_J_per_m; the tool is the only rigid body of a cut).
  const EnergySummary& e = s.energy_J_per_m;
  r.tool_work_J_per_m = e.external_work;
  r.plastic_work_J_per_m = e.plastic_work;
  r.damage_J_per_m = e.damage_dissipation;
  r.friction_J_per_m = e.friction_work;
  r.kinetic_elastic_J_per_m = e.kinetic + e.elastic;
  r.numerical_J_per_m = e.external_work - e.plastic_work - e.damage_dissipation - e.friction_work -
                        (e.kinetic + e.elastic) - e.viscous_dissipation;

  const ChipHeadline chip = chip_headline(s);
  r.shear_zone_max_K = chip.shear_zone_max_K;
  r.tool_chip_max_K = chip.tool_chip_max_K;
  r.chip_classification = chip.classification;
  r.chip_classification_confidence = chip.classification_confidence;
  r.segmentation_degree = chip.segmentation_degree;
  if (chip.pitch_m) r.pitch_um = *chip.pitch_m * 1e6;
  if (chip.segmentation_frequency_Hz) r.frequency_kHz = *chip.segmentation_frequency_Hz * 1e-3;
  r.chip_thickness_ratio = chip.chip_thickness_ratio;
  r.chip_thickness_ratio_from_area = chip.chip_thickness_ratio_from_area;
  r.segmentation_degree_mean = chip.segmentation_degree_mean;
  r.segmentation_degree_min = chip.segmentation_degree_min;
  r.segmentation_degree_max = chip.segmentation_degree_max;
  return r;
}

std::string format_number(const std::optional<double>& x, int digits) {
  if (!x || !std::isfinite(*x)) return "";
  return fmt::format("{:.{}g}", *x, digits);
}

void TextTable::write_csv(const fs::path& file) const {
  write_file_atomically(file, [&](std::ostream& out) {
    for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << csv_cell(columns[i]);
    out << "\n";
    for (const auto& row : rows) {
      for (std::size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << csv_cell(row[i]);
      out << "\n";
    }
  });
}

std::string TextTable::markdown() const {
  const auto& head = headings.empty() ? columns : headings;
  std::string out = "|";
  for (const auto& h : head) out += " " + h + " |";
  out += "\n|";
  for (std::size_t i = 0; i < head.size(); ++i) out += "---|";
  out += "\n";
  for (const auto& row : rows) {
    out += "|";
    for (std::string cell : row) {
      for (char& c : cell)
        if (c == '|' || c == '\n') c = '/';
      out += " " + cell + " |";
    }
    out += "\n";
  }
  return out;
}

}  // namespace mpmcut
