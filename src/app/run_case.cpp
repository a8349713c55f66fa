#include "app/run_case.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <charconv>
#include <cmath>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <sstream>
#include <iostream>
#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/stop_signal.hpp"
#include "core/run_estimate.hpp"
#include "core/simulation.hpp"
#include "core/thread_tuner.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/csv_writer.hpp"
#include "io/input_error.hpp"
#include "app/mass_scaling_report.hpp"
#include "io/json_summary.hpp"
#include "io/progress.hpp"
#include "io/pvd_writer.hpp"
#include "io/result_directory.hpp"
#include "io/run_observer.hpp"
#include "io/scene_observers.hpp"
#include "io/scene_parser.hpp"
#include "io/scene_writer.hpp"
#include "io/vtu_writer.hpp"

namespace mpmcut {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// --checkpoint-every

std::string CheckpointInterval::text() const {
  switch (kind) {
    case Kind::Off: return "off";
    case Kind::Steps: return fmt::format("every {} steps", value);
    case Kind::WallSeconds: return fmt::format("every {} s of wall time", value);
  }
  return "?";
}

CheckpointInterval parse_checkpoint_interval(std::string_view text) {
  const auto bad = [&](const std::string& why) {
    return InputError(fmt::format("--checkpoint-every '{}': {}; use a step count (5000, 5000steps), a wall time "
                                  "(600s, 10min, 2h) or off",
                                  text, why));
  };
  std::string s;
  for (const char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (s == "off" || s == "never" || s == "0") return {CheckpointInterval::Kind::Off, 0.0};
  double value = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || !(value > 0.0) || !std::isfinite(value)) throw bad("expected a positive number first");
  const std::string unit = s.substr(static_cast<std::size_t>(end - s.data()));
  if (unit.empty() || unit == "step" || unit == "steps") {
    if (value != std::floor(value)) throw bad("a step count must be a whole number");
    return {CheckpointInterval::Kind::Steps, value};
  }
  if (unit == "s" || unit == "sec" || unit == "secs" || unit == "second" || unit == "seconds")
    return {CheckpointInterval::Kind::WallSeconds, value};
  if (unit == "min" || unit == "mins" || unit == "minute" || unit == "minutes" || unit == "m")
    return {CheckpointInterval::Kind::WallSeconds, 60.0 * value};
  if (unit == "h" || unit == "hour" || unit == "hours") return {CheckpointInterval::Kind::WallSeconds, 3600.0 * value};
  throw bad(fmt::format("unknown unit '{}'", unit));
}

namespace {

// ---------------------------------------------------------------------------------------------
// Signals

// SIGINT/SIGTERM are handled program-wide (app/stop_signal): during set-up a signal exits at once;
// in the step loop (DeferStops in run_to_end) the first asks the loop to stop after the current step
// (it then writes a checkpoint and the outputs so far), a second exits at once (the directory stays
// resumable from the last checkpoint). SIGXFSZ is ignored so that a file-size limit surfaces as an
// EFBIG write error with a message instead of killing the process.
struct SignalGuard {
  struct sigaction old_xfsz {};
  SignalGuard() {
    install_stop_handlers();
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGXFSZ, &ignore, &old_xfsz);
  }
  ~SignalGuard() { sigaction(SIGXFSZ, &old_xfsz, nullptr); }
};

// ---------------------------------------------------------------------------------------------
// Outputs

std::vector<std::string> history_columns() {
  return {"time_s",
          "step",
          "dt_s",
          "kinetic_energy_J_per_m",
          "elastic_energy_J_per_m",
          "plastic_work_J_per_m",
          "heat_J_per_m",
          "damage_dissipation_J_per_m",
          "friction_work_J_per_m",
          "viscous_dissipation_J_per_m",
          "external_work_J_per_m",
          "transfer_dissipation_J_per_m",
          "contact_safeguard_J_per_m",
          "removed_energy_J_per_m",
          "momentum_x_kg_m_per_s_per_m",
          "momentum_y_kg_m_per_s_per_m",
          "max_temperature_K"};
}

std::vector<std::string> rigid_force_columns(const Simulation& sim) {
  std::vector<std::string> cols{"time_s"};
  for (const auto& r : sim.rigid_bodies()) {
    cols.push_back(r.name + "_force_x_N_per_m");
    cols.push_back(r.name + "_force_y_N_per_m");
    cols.push_back(r.name + "_displacement_x_m");
    cols.push_back(r.name + "_displacement_y_m");
  }
  return cols;
}

std::string snapshot_name(int index) { return fmt::format("snapshots/particles_{:06d}.vtu", index); }

// Number of a snapshot file name "particles_NNNNNN.vtu", or -1.
long snapshot_index(const std::string& file_name) {
  constexpr std::string_view prefix = "particles_", suffix = ".vtu";
  if (!file_name.starts_with(prefix) || !file_name.ends_with(suffix)) return -1;
  const std::string digits = file_name.substr(prefix.size(), file_name.size() - prefix.size() - suffix.size());
  if (digits.empty() || digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), ::isdigit)) return -1;
  return std::stol(digits);
}

// The observers of one run: they read the simulation between steps and write files. With
// `resume` the CSV files are opened for appending (the caller has cut them back already).
class RunOutputs {
 public:
  RunOutputs(const fs::path& root, Simulation& sim, bool resume)
      : root_(root),
        sim_(sim),
        history_(root / "history.csv", history_columns(), resume ? CsvWriter::Mode::Append : CsvWriter::Mode::Create) {
    observers_ = make_scene_observers(sim.scene(), root, resume);
    if (!sim.rigid_bodies().empty())
      rigid_.emplace(root / "rigid_forces.csv", rigid_force_columns(sim),
                     resume ? CsvWriter::Mode::Append : CsvWriter::Mode::Create);
    fs::create_directories(root / "snapshots");
  }

  void after_step() {
    for (auto& o : observers_) o->after_step(sim_);
  }

  void history_row() {
    for (auto& o : observers_) o->at_history(sim_);
    sim_.refresh_energy();
    const EnergyTotals& e = sim_.energy();
    const Vec2 m = sim_.total_momentum();
    history_.row({sim_.time(), static_cast<double>(sim_.step_count()), sim_.last_dt(), e.kinetic, e.elastic,
                  e.plastic_work, e.heat, e.damage_dissipation, e.friction, e.viscous, e.external_work, e.transfer_dissipation, e.contact_safeguard,
                  e.removed_energy, m.x(), m.y(),
                  sim_.max_temperature()});
  }

  void rigid_row() {
    if (!rigid_) return;
    std::vector<double> row{sim_.time()};
    for (const auto& r : sim_.rigid_bodies()) {
      row.insert(row.end(), {r.force.x(), r.force.y(), r.displacement.x(), r.displacement.y()});
    }
    rigid_->row(row);
  }

  void snapshot() {
    if (!sim_.scene().output.vtu) return;
    const std::string name = snapshot_name(snapshots_++);
    write_particles_vtu(sim_.particles(), root_ / name, sim_.time());
    pvd_.add(sim_.time(), name);
    pvd_.write(root_ / "particles.pvd");
    last_snapshot_time_ = sim_.time();
  }
  double last_snapshot_time() const { return last_snapshot_time_; }
  int snapshot_count() const { return snapshots_; }

  void flush() {
    history_.flush();
    if (rigid_) rigid_->flush();
    for (auto& o : observers_) o->flush();
  }

  void finish(nlohmann::json& summary) {
    for (auto& o : observers_) o->at_finish(sim_, summary);
  }

  // Checkpoints: the outputs' part of the run-loop state.
  void save(RunLoopState& s) const {
    s.snapshot_count = snapshots_;
    s.last_snapshot_time_s = last_snapshot_time_;
    s.pvd = pvd_.entries();
    s.observer_states.clear();
    for (const auto& o : observers_) s.observer_states.push_back(o->checkpoint_state());
  }
  void restore(const RunLoopState& s) {
    if (s.observer_states.size() != observers_.size()) {
      throw CheckpointError(fmt::format("the checkpoint has the state of {} observers, this scene has {}",
                                        s.observer_states.size(), observers_.size()));
    }
    for (std::size_t k = 0; k < observers_.size(); ++k) observers_[k]->restore_checkpoint_state(s.observer_states[k]);
    snapshots_ = s.snapshot_count;
    last_snapshot_time_ = s.last_snapshot_time_s;
    pvd_ = PvdSeries();
    for (const auto& e : s.pvd) pvd_.add(e.time_s, e.file);
    if (sim_.scene().output.vtu) pvd_.write(root_ / "particles.pvd");
  }

 private:
  fs::path root_;
  Simulation& sim_;
  CsvWriter history_;
  std::optional<CsvWriter> rigid_;
  PvdSeries pvd_;
  std::vector<std::unique_ptr<RunObserver>> observers_;
  int snapshots_ = 0;
  double last_snapshot_time_ = -1.0;
};

nlohmann::json summary_json(const Simulation& sim, const char* status, double wall_s, const std::string& message,
                            int threads) {
  nlohmann::json j;
  j["status"] = status;
  j["mpmcut_version"] = MPMCUT_VERSION;
  j["title"] = sim.scene().title;
  j["case_file"] = sim.scene().source_file;
  j["particles"] = sim.particles().size();
  j["grid_nodes"] = sim.grid().node_count();
  j["cell_size_m"] = sim.grid().h;
  j["steps"] = sim.step_count();
  j["simulated_time_s"] = sim.time();
  j["end_time_s"] = sim.scene().solver.end_time;
  j["wall_time_s"] = wall_s;
  j["threads"] = threads;
  j["particle_steps_per_s"] =
      wall_s > 0 ? static_cast<double>(sim.particles().size()) * sim.step_count() / wall_s : 0.0;
  const EnergyTotals& e = sim.energy();
  j["energy_J_per_m"] = {{"kinetic", e.kinetic},
                         {"elastic", e.elastic},
                         {"plastic_work", e.plastic_work},
                         {"heat", e.heat},
                         {"damage_dissipation", e.damage_dissipation},
                         {"friction_work", e.friction},
                         {"viscous_dissipation", e.viscous},
                         {"external_work", e.external_work},
                         {"transfer_dissipation", e.transfer_dissipation},
                         {"contact_safeguard", e.contact_safeguard},
                         {"removed_energy", e.removed_energy}};
  // initial energy + external work = the rest, term by term (docs/cutting.md, "Energy balance");
  // the residual is what no term accounts for, relative to the energy that came in.
  const double residual = energy_balance_residual(e);
  j["energy_J_per_m"]["initial"] = e.initial;
  j["energy_balance"] = {{"residual_J_per_m", residual},
                         {"relative_residual", residual / std::max(std::abs(e.initial) + std::abs(e.external_work), 1e-300)}};
  j["max_temperature_K"] = sim.max_temperature();
  j["mass_scaling"] = to_json(mass_scaling_report(sim));
  nlohmann::json rigid = nlohmann::json::array();
  for (const auto& r : sim.rigid_bodies())
    rigid.push_back({{"name", r.name},
                     {"force_N_per_m", {r.force.x(), r.force.y()}},
                     {"impulse_N_s_per_m", {r.impulse.x(), r.impulse.y()}},
                     {"displacement_m", {r.displacement.x(), r.displacement.y()}},
                     {"work_J_per_m", r.work}});
  j["rigid_bodies"] = rigid;
  if (sim.removed_particles() > 0) {
    j["removed_particles"] = sim.removed_particles();
    j["removed_mass_kg_per_m"] = sim.removed_mass();
  }
  if (!message.empty()) j["message"] = message;
  return j;
}

// fsync of a file or folder by path: the data reaches the disk, not only the page cache.
void sync_path(const fs::path& p, bool folder = false) {
  const int fd = ::open(p.c_str(), O_RDONLY | O_CLOEXEC | (folder ? O_DIRECTORY : 0));
  if (fd < 0) return;  // not there (e.g. no snapshots): nothing to make durable
  ::fsync(fd);
  ::close(fd);
}

// ---------------------------------------------------------------------------------------------
// One run, new or resumed: the simulation, its outputs, the output schedule and checkpoints.

class CaseRun {
 public:
  CaseRun(const Scene& scene, fs::path root, const RunOptions& options, int threads)
      : root_(std::move(root)),
        options_(options),
        threads_(threads),
        sim_(scene),
        scene_hash_(scene_hash(scene)),
        store_(root_) {
    if (options.tune_threads && threads > 1) tuner_.emplace(threads);
  }

  // A new run: the outputs at t = 0 and the first output times.
  void start() {
    out_.emplace(root_, sim_, false);
    out_->history_row();
    out_->rigid_row();
    out_->snapshot();
    const OutputSpec& o = sim_.scene().output;
    next_snapshot_ = o.snapshot_interval > 0 ? o.snapshot_interval : sim_.scene().solver.end_time;
    next_history_ = o.history_interval > 0 ? o.history_interval : 0.0;
  }

  // A resumed run: the result directory is cut back to what it was when `c` was written (CSV
  // lengths, snapshots, PVD index), then the state is restored.
  void resume(Checkpoint&& c, const fs::path& file) {
    cut_back_outputs(c.loop);
    const RunLoopState loop = c.loop;
    const long step = c.step;
    std::move(c).restore(sim_);
    out_.emplace(root_, sim_, true);
    out_->restore(loop);
    next_snapshot_ = loop.next_snapshot_s;
    next_history_ = loop.next_history_s;
    wall_before_s_ = loop.wall_time_s;
    resumed_from_ = file.filename().string();
    last_checkpoint_step_ = step;
    last_checkpoint_ = file.filename().string();
    synced_snapshots_ = loop.snapshot_count;
    store_.set_previous(file);
  }

  // The step loop, then the final outputs and summary.json; returns the exit code.
  int run_to_end();

  Simulation& simulation() { return sim_; }

 private:
  using Clock = std::chrono::steady_clock;
  double session_wall_s() const { return std::chrono::duration<double>(Clock::now() - session_start_).count(); }
  bool finished() const {
    const SolverSpec& s = sim_.scene().solver;
    return sim_.time() >= s.end_time - 1e-12 * s.end_time || (s.max_steps > 0 && sim_.step_count() >= s.max_steps);
  }
  bool checkpoint_due() const {
    switch (options_.checkpoint_every.kind) {
      case CheckpointInterval::Kind::Off: return false;
      case CheckpointInterval::Kind::Steps:
        return sim_.step_count() % static_cast<long>(options_.checkpoint_every.value) == 0;
      case CheckpointInterval::Kind::WallSeconds:
        return std::chrono::duration<double>(Clock::now() - last_checkpoint_wall_).count() >=
               options_.checkpoint_every.value;
    }
    return false;
  }
  void write_checkpoint();
  void cut_back_outputs(const RunLoopState& loop) const;
  std::vector<FileLength> csv_lengths() const;

  fs::path root_;
  RunOptions options_;
  int threads_;
  std::optional<ThreadTuner> tuner_;  // picks 1..threads_ by timing (busy machines); none = fixed
  Simulation sim_;
  std::uint64_t scene_hash_;
  CheckpointStore store_;
  std::optional<RunOutputs> out_;
  double next_snapshot_ = 0.0;
  double next_history_ = 0.0;
  Clock::time_point session_start_ = Clock::now();
  Clock::time_point last_checkpoint_wall_ = Clock::now();
  double wall_before_s_ = 0.0;  // wall time of the sessions before a resume
  long last_checkpoint_step_ = -1;
  std::string last_checkpoint_;
  std::string resumed_from_;
  int synced_snapshots_ = 0;  // snapshots already made durable by a checkpoint
};

int CaseRun::run_to_end() {
  const Scene& scene = sim_.scene();
  const DeferStops defer_stops;  // from here a signal stops the loop after a step, with a checkpoint
  Progress progress(scene.solver.end_time, std::cerr, options_.progress ? std::nullopt : std::optional<bool>(false));
  const char* status = run_status::complete;
  std::string message;
  int exit_code = kExitComplete;
  std::cerr << console_line(mass_scaling_report(sim_));
  try {
    RunOutputs& out = *out_;
    const double end = scene.solver.end_time;
    const double snap_dt = scene.output.snapshot_interval;
    const double hist_dt = scene.output.history_interval;
    const double eps = 1e-12 * end;
    try {
      while (!finished()) {
        // Land exactly on the next output time (and on the end time).
        double target = std::min(next_snapshot_, end);
        if (hist_dt > 0) target = std::min(target, next_history_);
        if (tuner_) tuner_->before_step();
        sim_.step(target - sim_.time());
        if (tuner_) tuner_->after_step();
        out.after_step();
        if (hist_dt <= 0 || sim_.time() >= next_history_ - eps) {
          out.history_row();
          out.rigid_row();
          while (hist_dt > 0 && next_history_ <= sim_.time() + eps) next_history_ += hist_dt;
        }
        if (sim_.time() >= next_snapshot_ - eps) {
          out.snapshot();
          while (next_snapshot_ <= sim_.time() + eps) next_snapshot_ += snap_dt > 0 ? snap_dt : end;
        }
        if (options_.progress) progress.update(sim_.time(), sim_.step_count(), sim_.last_dt());
        if (stop_requested()) {
          status = run_status::interrupted;
          message = fmt::format("interrupted by a signal at step {}, time {:.6g} s; continue with: mpmcut resume {}",
                                sim_.step_count(), sim_.time(), root_.string());
          exit_code = kExitInterrupted;
          break;
        }
        if (checkpoint_due()) write_checkpoint();
      }
      // Before the extra snapshot below, which a resumed run does not have (it is dropped on resume).
      if (exit_code == kExitInterrupted && last_checkpoint_step_ != sim_.step_count()) write_checkpoint();
      if (out.last_snapshot_time() < sim_.time()) out.snapshot();
    } catch (const SimulationError& e) {
      status = run_status::failed;
      message = e.what();
      exit_code = kExitSimulationFailed;
      // The state at failure is the most useful picture for finding the cause.
      try {
        out.snapshot();
      } catch (...) {
      }
    }
    out.flush();
  } catch (const std::exception& e) {  // output errors: disk full, unwritable directory, file too large
    status = run_status::failed;
    message = std::string("output error: ") + e.what();
    if (!last_checkpoint_.empty())
      message += fmt::format("; the last checkpoint ({}) is intact: fix the cause, then mpmcut resume {}",
                             last_checkpoint_, root_.string());
    exit_code = kExitOutputError;
  }
  if (options_.progress) progress.finish(status);
  const double wall_s = wall_before_s_ + session_wall_s();
  try {
    nlohmann::json summary = summary_json(sim_, status, wall_s, message, threads_);
    if (tuner_) summary["thread_tuning"] = {{"threads_in_use_at_end", tuner_->chosen()}, {"trials", tuner_->trials()}};
    if (!last_checkpoint_.empty()) summary["last_checkpoint"] = "checkpoints/" + last_checkpoint_;
    if (!resumed_from_.empty()) summary["resumed_from"] = "checkpoints/" + resumed_from_;
    if (out_) out_->finish(summary);
    write_json_atomically(root_ / "summary.json", summary);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    if (!message.empty()) std::cerr << "error: " << message << "\n";
    return kExitOutputError;
  }
  if (!message.empty()) std::cerr << (exit_code == kExitInterrupted ? "" : "error: ") << message << "\n";
  std::cerr << fmt::format(
      "{}: {} particles, {} steps, {:.3g} s simulated in {:.1f} s wall ({:.3g} particle-steps/s); results in {}\n",
      status, sim_.particles().size(), sim_.step_count(), sim_.time(), wall_s,
      wall_s > 0 ? sim_.particles().size() * static_cast<double>(sim_.step_count()) / wall_s : 0.0, root_.string());
  return exit_code;
}

// The CSV files in the result directory and their byte lengths.
std::vector<FileLength> CaseRun::csv_lengths() const {
  std::vector<FileLength> files;
  for (const fs::directory_entry& e : fs::directory_iterator(root_)) {
    if (e.is_regular_file() && e.path().extension() == ".csv")
      files.push_back({e.path().filename().string(), static_cast<std::uint64_t>(e.file_size())});
  }
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.relative_path < b.relative_path; });
  return files;
}

// Everything the outputs have written so far goes to disk first, so that a checkpoint never
// refers to data that a power cut could lose; then the checkpoint itself (atomically).
void CaseRun::write_checkpoint() {
  out_->flush();
  RunLoopState s;
  s.next_snapshot_s = next_snapshot_;
  s.next_history_s = next_history_;
  out_->save(s);
  s.files = csv_lengths();
  s.wall_time_s = wall_before_s_ + session_wall_s();
  s.threads = threads_;
  s.checkpoint_kind = static_cast<int>(options_.checkpoint_every.kind);
  s.checkpoint_value = options_.checkpoint_every.value;
  s.case_file = sim_.scene().source_file;
  s.mpmcut_version = MPMCUT_VERSION;
  for (const FileLength& f : s.files) sync_path(root_ / f.relative_path);
  for (int k = synced_snapshots_; k < s.snapshot_count; ++k) sync_path(root_ / snapshot_name(k));
  sync_path(root_ / "particles.pvd");
  sync_path(root_ / "snapshots", true);
  sync_path(root_, true);
  const fs::path file = store_.write(sim_, scene_hash_, s);
  synced_snapshots_ = s.snapshot_count;
  last_checkpoint_step_ = sim_.step_count();
  last_checkpoint_ = file.filename().string();
  last_checkpoint_wall_ = Clock::now();
}

// Makes the result directory look exactly as it did when the checkpoint was written.
void CaseRun::cut_back_outputs(const RunLoopState& loop) const {
  // CSV rows after the checkpoint go; a CSV that did not exist then goes too.
  for (const FileLength& f : loop.files) {
    const fs::path p = root_ / f.relative_path;
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(p, ec);
    if (ec) throw CheckpointError(fmt::format("'{}' existed at the checkpoint but cannot be read now: {}", p.string(),
                                              ec.message()));
    if (size < f.bytes) {
      throw CheckpointError(fmt::format("'{}' has {} bytes, fewer than the {} it had at the checkpoint: the result "
                                        "directory was changed after the run stopped",
                                        p.string(), size, f.bytes));
    }
    if (size > f.bytes) fs::resize_file(p, f.bytes);
  }
  for (const FileLength& f : csv_lengths()) {
    const bool known = std::any_of(loop.files.begin(), loop.files.end(),
                                   [&](const FileLength& g) { return g.relative_path == f.relative_path; });
    if (!known) fs::remove(root_ / f.relative_path);
  }
  // Snapshots written after the checkpoint, and temporaries a killed process left behind.
  for (const fs::path& folder : {root_, root_ / "snapshots", root_ / "checkpoints"}) {
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
      const std::string name = e.path().filename().string();
      const bool stale_snapshot = folder == root_ / "snapshots" && snapshot_index(name) >= loop.snapshot_count;
      const bool temporary = name.find(".tmp-") != std::string::npos || name == "checkpoint.tmp" || name == "latest.tmp";
      if (e.is_regular_file() && (stale_snapshot || temporary)) fs::remove(e.path());
    }
  }
}

// Writes the expanded scene; a failure is an output error.
void write_expanded_scene(const Scene& scene, const fs::path& root) {
  write_file_atomically(root / "scene.toml", [&](std::ostream& out) { write_scene(scene, out); });
}

int set_threads(int requested) {
  const int threads = requested > 0 ? requested : omp_get_max_threads();  // OMP_NUM_THREADS or all cores
  omp_set_num_threads(threads);
  return threads;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

int run_case(const Scene& scene, const RunOptions& options) {
  // Before the result directory and the first large allocation: a run that cannot fit in memory
  // or cannot finish is the user's input error, not a crash or a hang later.
  try {
    check_run_fits(scene);
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
  SignalGuard signals;
  const int threads = set_threads(options.threads);
  fs::path root;
  try {
    root = ResultDirectory::open(options.out_dir, options.force).root();
    write_expanded_scene(scene, root);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitOutputError;
  }
  std::optional<CaseRun> run;
  try {
    run.emplace(scene, root, options, threads);
    write_json_atomically(root / "summary.json",
                          summary_json(run->simulation(), run_status::running, 0.0, "", threads));
    run->start();
  } catch (const std::invalid_argument& e) {  // a scene the solver cannot build
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const std::exception& e) {
    std::cerr << "error: output error: " << e.what() << "\n";
    return kExitOutputError;
  }
  return run->run_to_end();
}

ExistingRun existing_run(const fs::path& dir, const Scene& scene) {
  std::error_code ec;
  if (!fs::exists(dir / "scene.toml", ec) || !fs::exists(dir / "summary.json", ec)) return ExistingRun::None;
  std::ostringstream expected;
  write_scene(scene, expected);
  std::ifstream in(dir / "scene.toml", std::ios::binary);
  const std::string found((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (found != expected.str()) return ExistingRun::None;
  std::string status;
  try {
    status = read_json(dir / "summary.json").value("status", "");
  } catch (const std::exception&) {
    return ExistingRun::None;
  }
  if (status == run_status::complete) return ExistingRun::Complete;
  return fs::exists(dir / "checkpoints" / "latest", ec) ? ExistingRun::Resumable : ExistingRun::None;
}

int resume_case(const RunOptions& options) {
  SignalGuard signals;
  const fs::path root = options.out_dir;
  const auto refuse = [&](const std::string& why) {
    std::cerr << "error: cannot resume '" << root.string() << "': " << why << "\n";
    return kExitInputError;
  };
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return refuse("no such result directory");
  if (!fs::exists(root / "summary.json") || !fs::exists(root / "scene.toml"))
    return refuse("it has no summary.json and scene.toml, so it is not an mpmcut result directory");
  std::string status;
  try {
    status = read_json(root / "summary.json").value("status", "");
  } catch (const std::exception& e) {
    return refuse(e.what());
  }
  if (status == run_status::complete && !options.force) {
    return refuse(
        "its run is complete (summary.json status \"complete\"); there is nothing to resume. Use --force to "
        "recompute from its last checkpoint to the end");
  }
  if (status == run_status::failed)
    std::cerr << "note: the run had failed (see summary.json \"message\"); continuing from its last checkpoint\n";

  Scene scene;
  try {
    scene = load_scene(root / "scene.toml");
  } catch (const InputError& e) {
    return refuse(e.what());
  }
  CheckpointStore store(root);
  std::optional<CheckpointStore::Loaded> loaded;
  try {
    loaded = store.load_newest_valid();
  } catch (const CheckpointError& e) {
    return refuse(e.what());
  }
  for (const std::string& r : loaded->rejected) std::cerr << "warning: " << r << "\n";
  if (!loaded->rejected.empty())
    std::cerr << "warning: falling back to the previous valid checkpoint '" << loaded->file.string() << "'\n";
  Checkpoint& c = loaded->checkpoint;
  if (c.scene_hash != scene_hash(scene)) {
    return refuse(fmt::format("scene.toml differs from the scene that checkpoint '{}' was written with, so this "
                              "would not continue the same run. Restore the original scene.toml or start a new run",
                              loaded->file.string()));
  }
  scene.source_file = c.loop.case_file;
  try {
    check_run_fits(scene);  // the machine resuming may have less memory than the one that started
  } catch (const InputError& e) {
    return refuse(e.what());
  }
  if (c.loop.mpmcut_version != MPMCUT_VERSION)
    std::cerr << "warning: the checkpoint was written by mpmcut " << c.loop.mpmcut_version << ", this is "
              << MPMCUT_VERSION << "; the continuation may differ from an uninterrupted run\n";
  const int threads = set_threads(options.threads > 0 ? options.threads : c.loop.threads);
  RunOptions resumed = options;
  if (!options.checkpoint_every_given && c.loop.checkpoint_kind >= 0 && c.loop.checkpoint_kind <= 2)
    resumed.checkpoint_every = {static_cast<CheckpointInterval::Kind>(c.loop.checkpoint_kind), c.loop.checkpoint_value};

  std::optional<CaseRun> run;
  try {
    run.emplace(scene, root, resumed, threads);
    run->resume(std::move(c), loaded->file);
    write_json_atomically(root / "summary.json", summary_json(run->simulation(), run_status::running, 0.0, "", threads));
  } catch (const CheckpointError& e) {
    return refuse(e.what());
  } catch (const std::invalid_argument& e) {
    return refuse(e.what());
  } catch (const std::exception& e) {
    std::cerr << "error: output error: " << e.what() << "\n";
    return kExitOutputError;
  }
  std::cerr << fmt::format("resuming '{}' from {} (step {}, t = {:.6g} s)\n", root.string(),
                           loaded->file.filename().string(), run->simulation().step_count(),
                           run->simulation().time());
  return run->run_to_end();
}

}  // namespace mpmcut
