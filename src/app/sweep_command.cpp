#include "app/sweep_command.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/plot_command.hpp"
#include "app/stop_signal.hpp"
#include "io/scene_parser.hpp"
#include "io/atomic_file.hpp"

namespace mpmcut {

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

volatile std::sig_atomic_t g_stop_signals = 0;
void on_stop_signal(int) { g_stop_signals = g_stop_signals + 1; }

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
  // instead of running on as orphans.
  die_with_parent(parent);
  const int in = open("/dev/null", O_RDONLY);
  const int log = open(run.log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (in >= 0) dup2(in, STDIN_FILENO);
  if (log >= 0) {
    dup2(log, STDOUT_FILENO);
    dup2(log, STDERR_FILENO);
  }
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  execv(c_argv[0], c_argv.data());
  _exit(127);
}

std::string exit_text(int code) {
  if (code == 0) return "complete";
  if (code == 130) return "interrupted";
  if (code == 127) return "could not start";
  if (code > 128) return fmt::format("killed by signal {}", code - 128);
  return fmt::format("failed (exit status {})", code);
}

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

std::optional<double> number_of(const json& v) {
  if (v.is_number()) return v.get<double>();
  if (v.is_object()) {
    for (const char* k : {"mean", "value"})
      if (v.contains(k) && v[k].is_number()) return v[k].get<double>();
  }
  return std::nullopt;
}

// The analysis (mpmcut analyze) names its results with units in the keys; accept the stems below with any
// of the given unit suffixes, in `obj` or one level down (e.g. chip.segmentation.pitch_m).
std::optional<double> find_quantity(const json& obj, const std::vector<std::string>& stems,
                                    const std::vector<std::pair<std::string, double>>& units) {
  if (!obj.is_object()) return std::nullopt;
  for (const std::string& stem : stems)
    for (const auto& [suffix, factor] : units)
      if (obj.contains(stem + suffix))
        if (auto x = number_of(obj[stem + suffix])) return *x * factor;
  for (const auto& [key, value] : obj.items())
    if (value.is_object())
      if (auto x = find_quantity(value, stems, units)) return x;
  return std::nullopt;
}

std::string find_text(const json& obj, const std::vector<std::string>& keys) {
  if (!obj.is_object()) return {};
  for (const std::string& k : keys)
    if (obj.contains(k) && obj[k].is_string()) return obj[k].get<std::string>();
  return {};
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

bool run_children(std::vector<ChildRun>& runs, int jobs, bool print_progress) {
  g_stop_signals = 0;
  struct sigaction action {}, old_int{}, old_term{};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &old_int);
  sigaction(SIGTERM, &action, &old_term);

  const std::string exe = self_executable();
  using clock = std::chrono::steady_clock;
  std::map<pid_t, std::pair<std::size_t, clock::time_point>> running;
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
                                      "Ctrl-C again to kill them)\n"
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
      ChildRun& run = runs[it->second.first];
      run.exit_code = r < 0 ? 127 : WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      run.wall_time_s = std::chrono::duration<double>(clock::now() - it->second.second).count();
      ++finished;
      if (print_progress)
        std::cout << fmt::format("[{}/{}] {}: {} ({:.1f} s){}\n", finished, runs.size(), run.name,
                                 exit_text(run.exit_code), run.wall_time_s,
                                 run.exit_code == 0 ? "" : ", log: " + run.log_file.string())
                  << std::flush;
      it = running.erase(it);
      reaped = true;
    }
    if (!reaped) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
  return g_stop_signals == 0;
}

bool has_subcommand(const CLI::App& app, const std::string& name) {
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->get_name() == name) return true;
  return false;
}

CaseResult read_case_result(const fs::path& dir, const fs::path& log_file, int exit_code) {
  CaseResult r;
  json summary;
  {
    std::ifstream in(dir / "summary.json");
    if (in) summary = json::parse(in, nullptr, false);
  }
  if (!summary.is_object()) {
    r.status = exit_code == -1 ? "not run" : "failed";
    r.message = exit_code == -1 ? "interrupted before it started"
                                : fmt::format("{}, no summary.json: {}", exit_text(exit_code), last_lines(log_file, 2));
    return r;
  }
  r.status = find_text(summary, {"status"});
  if (r.status.empty()) r.status = exit_code == 0 ? "complete" : "failed";
  for (const char* k : {"message", "error", "failure"})
    if (summary.contains(k) && summary[k].is_string()) r.message = summary[k].get<std::string>();
  if (summary.contains("messages") && summary["messages"].is_array())
    for (const json& m : summary["messages"])
      if (m.is_string()) r.message += (r.message.empty() ? "" : "; ") + m.get<std::string>();
  if (r.status != "complete" && r.message.empty()) r.message = last_lines(log_file, 2);

  r.cutting_force_N_per_mm = summary.contains("mean_cutting_force_N_per_mm")
                                 ? number_of(summary["mean_cutting_force_N_per_mm"]) : std::nullopt;
  r.thrust_force_N_per_mm = summary.contains("mean_thrust_force_N_per_mm")
                                ? number_of(summary["mean_thrust_force_N_per_mm"]) : std::nullopt;
  if (r.cutting_force_N_per_mm && r.thrust_force_N_per_mm) {
    r.force_basis = "steady window";
  } else if (double fc = 0, ft = 0; last_half_means(dir / "forces.csv", fc, ft)) {
    r.cutting_force_N_per_mm = fc;
    r.thrust_force_N_per_mm = ft;
    r.force_basis = "last half of the cut (no steady window)";
  }
  if (summary.contains("max_temperature_K")) r.max_temperature_K = number_of(summary["max_temperature_K"]);
  if (summary.contains("wall_time_s")) r.wall_time_s = number_of(summary["wall_time_s"]);

  if (summary.contains("temperature") && summary["temperature"].is_object()) {
    const json& t = summary["temperature"];
    if (t.contains("primary_shear_zone")) r.shear_zone_max_K = find_quantity(t["primary_shear_zone"], {"max"}, {{"_K", 1.0}});
    if (t.contains("tool_chip_interface")) r.tool_chip_max_K = find_quantity(t["tool_chip_interface"], {"max"}, {{"_K", 1.0}});
  }
  if (summary.contains("chip") && summary["chip"].is_object()) {
    const json& chip = summary["chip"];
    r.chip_classification = find_text(chip, {"classification", "chip_type", "type", "morphology", "class"});
    r.segmentation_degree = find_quantity(chip, {"segmentation_degree", "degree_of_segmentation", "mean_segmentation_degree"},
                                          {{"", 1.0}, {"_1", 1.0}});
    r.pitch_um = find_quantity(chip, {"pitch", "segment_pitch", "mean_pitch", "segmentation_pitch"},
                               {{"_um", 1.0}, {"_m", 1e6}, {"_mm", 1e3}});
    r.frequency_kHz = find_quantity(chip, {"segmentation_frequency", "frequency", "segment_frequency"},
                                    {{"_kHz", 1.0}, {"_Hz", 1e-3}, {"_MHz", 1e3}});
  }
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
  const auto& head = headings.size() == columns.size() ? headings : columns;
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

namespace {

struct SweepOptions {
  std::string case_file;
  std::vector<double> speeds_m_per_s;
  std::vector<double> feeds_m;
  int jobs = 0;
  int threads = 1;
  std::string out_dir;
  std::vector<std::string> overrides;
  bool no_plots = false;
};

int run_sweep(const SweepOptions& o, const CLI::App& app) {
  if (!fs::exists(o.case_file)) {
    std::cerr << "error: case file " << o.case_file << " not found\n";
    return 2;
  }
  const fs::path out = o.out_dir.empty() ? fs::path("results") / ("sweep_" + fs::path(o.case_file).stem().string())
                                         : fs::path(o.out_dir);
  std::vector<double> feeds_m = o.feeds_m;
  if (feeds_m.empty()) {  // the case's own feed (load_scene also checks the case before anything runs)
    const Scene scene = load_scene(o.case_file, o.overrides);
    if (!scene.cutting) {
      std::cerr << "error: " << o.case_file << " has no [cutting] table: sweep needs a cutting case\n";
      return 2;
    }
    feeds_m = {scene.cutting->uncut_chip_thickness};
  }
  fs::create_directories(out / "logs");
  const int jobs = o.jobs > 0 ? o.jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / o.threads);

  struct Case {
    double speed, feed;
    fs::path dir;
  };
  std::vector<Case> cases;
  std::vector<ChildRun> runs;
  for (double h : feeds_m)
    for (double v : o.speeds_m_per_s) {
      const std::string name = fmt::format("v{:g}mps_h{:g}mm", v, h * 1e3);
      cases.push_back({v, h, out / name});
      ChildRun run;
      run.name = name;
      run.args = {"run", fs::absolute(o.case_file).string(), "--out", (out / name).string(), "--force",
                  "--no-progress", "--threads", std::to_string(o.threads)};
      for (const std::string& s : o.overrides) run.args.insert(run.args.end(), {"--set", s});
      // After the user's --set: the grid values win.
      run.args.insert(run.args.end(), {"--set", fmt::format("cutting.cutting_speed={}", v), "--set",
                                       fmt::format("cutting.uncut_chip_thickness={}", h)});
      run.log_file = out / "logs" / (name + ".log");
      runs.push_back(run);
    }
  std::cout << fmt::format("mpmcut sweep: {} cases ({} speeds x {} feeds) from {}, at most {} at a time, each with "
                           "--threads {} (change with --jobs/--threads); results in {}\n",
                           runs.size(), o.speeds_m_per_s.size(), feeds_m.size(), o.case_file, jobs, o.threads,
                           out.string())
            << std::flush;
  const bool completed = run_children(runs, jobs, true);

  // The chip analysis, where the program has it and the runs did not do it themselves.
  if (completed && has_subcommand(app, "analyze")) {
    std::vector<ChildRun> analyses;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      std::ifstream in(cases[i].dir / "summary.json");
      const json s = in ? json::parse(in, nullptr, false) : json();
      if (!s.is_object() || s.contains("chip")) continue;
      ChildRun a;
      a.name = runs[i].name + " (analyze)";
      a.args = {"analyze", cases[i].dir.string()};
      a.log_file = out / "logs" / (runs[i].name + ".analyze.log");
      analyses.push_back(a);
    }
    if (!analyses.empty()) {
      std::cout << "mpmcut sweep: chip analysis of " << analyses.size() << " cases\n";
      run_children(analyses, jobs, false);
    }
  }

  TextTable table;
  table.columns = {"case", "speed_m_per_s", "speed_m_per_min", "feed_mm", "status", "mean_cutting_force_N_per_mm",
                   "mean_thrust_force_N_per_mm", "force_window", "max_temperature_K", "shear_zone_max_temperature_K",
                   "tool_chip_max_temperature_K", "chip_classification",
                   "segmentation_degree", "pitch_um", "segmentation_frequency_kHz", "wall_time_s", "message"};
  table.headings = {"case", "V (m/s)", "V (m/min)", "h (mm)", "status", "Fc (N/mm)", "Ft (N/mm)", "force window",
                    "T max (K)", "T shear zone (K)", "T tool–chip (K)", "chip", "segmentation degree", "pitch (µm)", "frequency (kHz)", "wall (s)", "message"};
  int failed = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const CaseResult r = read_case_result(cases[i].dir, runs[i].log_file, runs[i].exit_code);
    if (r.status != "complete") ++failed;
    table.rows.push_back({runs[i].name, fmt::format("{:g}", cases[i].speed), fmt::format("{:g}", cases[i].speed * 60.0),
                          fmt::format("{:g}", cases[i].feed * 1e3), r.status, format_number(r.cutting_force_N_per_mm),
                          format_number(r.thrust_force_N_per_mm), r.force_basis, format_number(r.max_temperature_K),
                          format_number(r.shear_zone_max_K), format_number(r.tool_chip_max_K), r.chip_classification, format_number(r.segmentation_degree, 3), format_number(r.pitch_um, 3),
                          format_number(r.frequency_kHz, 3),
                          format_number(r.wall_time_s ? r.wall_time_s : std::optional<double>(runs[i].wall_time_s), 3),
                          r.message});
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
                     "analysis in summary.json and are blank where it did not provide them.\n\n",
                     cases.size(), cases.size() - failed, failed);
    s << table.markdown() << "\n";
    s << "Plots: forces_vs_speed.png, chip_vs_speed.png, chip_map.png. Each case: its result directory "
         "(mpmcut plot DIR draws it) and logs/<case>.log.\n";
  });
  std::cout << "wrote " << (out / "sweep.csv").string() << " and " << (out / "sweep.md").string() << "\n";

  if (!o.no_plots && completed) {  // an interrupted sweep stops here: no plots of a partial sweep
    std::string why;
    if (!python_plotting_available(false, why)) {
      std::cerr << "warning: no sweep plots: " << why << "\n";
    } else if (int code = run_python_tool("plot_sweep.py", {out.string()}); code != 0) {
      std::cerr << "warning: plot_sweep.py failed (exit status " << code << ")\n";
    }
  }
  if (!completed) return 130;
  if (failed) {
    std::cerr << fmt::format("mpmcut sweep: {} of {} cases did not complete (see sweep.md and logs/)\n", failed,
                             cases.size());
    return 1;
  }
  return 0;
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* sweep = app.add_subcommand(
      "sweep", "Run a cutting case over a grid of cutting speeds and uncut chip thicknesses (separate processes), "
               "then tabulate (sweep.csv, sweep.md) and plot the results");
  sweep->add_option("case", o->case_file, "Cutting case file (TOML with a [cutting] table)")->required();
  sweep->add_option("--speeds", o->speeds_m_per_s, "Cutting speeds in m/s, comma separated, e.g. 2,5,10,20,50,100")
      ->required()->delimiter(',')->check(CLI::PositiveNumber);
  sweep->add_option("--feeds", o->feeds_m,
                    "Uncut chip thicknesses (feeds) in m, comma separated, e.g. 0.05e-3,0.1e-3 (default: the case's own)")
      ->delimiter(',')->check(CLI::PositiveNumber);
  sweep->add_option("-j,--jobs", o->jobs, "Cases run at the same time (default: cores / threads)")->check(CLI::Range(1, 1024));
  sweep->add_option("-t,--threads", o->threads, "OpenMP threads of each case (default: 1)")->check(CLI::Range(1, 1024));
  sweep->add_option("-o,--out", o->out_dir, "Sweep directory (default: results/sweep_<case name>)");
  sweep->add_option("-s,--set", o->overrides, "Override an input key of every case, as for run (repeatable)");
  sweep->add_flag("--no-plots", o->no_plots, "Only the tables");
  sweep->callback([o, &app]() {
    int code = 0;
    try {
      code = run_sweep(*o, app);
    } catch (const std::exception& e) {
      std::cerr << "error: " << e.what() << "\n";
      code = 4;
    }
    throw CLI::RuntimeError(code);
  });
}

}  // namespace mpmcut
