#include "run/case_run.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "run/case_loading.hpp"
#include "run/mass_scaling_report.hpp"
#include "run/start_warnings.hpp"

namespace mpmcut {

namespace fs = std::filesystem;

namespace {

// How a run ended before its end time, for its summary's message.
constexpr std::string_view kStopRequested = "stopped on request (a stop signal, or a stop asked by the program driving the run)";
constexpr std::string_view kEndedByCaller = "ended by the caller before the end time";

// fsync of a file or folder by path: the data reaches the disk, not only the page cache.
void sync_path(const fs::path& p, bool folder = false) {
  const int fd = ::open(p.c_str(), O_RDONLY | O_CLOEXEC | (folder ? O_DIRECTORY : 0));
  if (fd < 0) return;  // not there (e.g. no snapshots): nothing to make durable
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

CaseRun::CaseRun(const Case& c, fs::path root, const RunOptions& options, int threads)
    : root_(std::move(root)),
      options_(options),
      threads_(threads),
      stop_(options.stop ? options.stop : &own_stop_),
      sim_(c.scene),
      cutting_(c.cutting),
      scene_hash_(scene_hash(c)),
      store_(root_) {
  if (options.tune_threads && threads > 1) tuner_.emplace(threads);
}

void CaseRun::start() {
  out_.emplace(root_, sim_, cutting_, false);
  out_->history_row();
  out_->rigid_row();
  out_->snapshot();
  const OutputSpec& o = sim_.scene().output;
  next_snapshot_ = o.snapshot_interval > 0 ? o.snapshot_interval : sim_.scene().solver.end_time;
  next_history_ = o.history_interval > 0 ? o.history_interval : 0.0;
}

void CaseRun::resume(Checkpoint&& c, const fs::path& file) {
  cut_back_outputs(c.loop);
  const RunLoopState loop = c.loop;
  const long step = c.state.step;
  std::move(c).restore(sim_);
  out_.emplace(root_, sim_, cutting_, true);
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

bool CaseRun::finished() const {
  const SolverSpec& s = sim_.scene().solver;
  return sim_.time() >= s.end_time - 1e-12 * s.end_time || (s.max_steps > 0 && sim_.step_count() >= s.max_steps);
}

bool CaseRun::checkpoint_due() const {
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

void CaseRun::begin() {
  if (progress_) return;
  progress_.emplace(sim_.scene().solver.end_time, std::cerr,
                    options_.progress ? std::nullopt : std::optional<bool>(false));
  std::cerr << console_line(mass_scaling_report(sim_, cutting_));
  if (cutting_) std::cerr << cut_start_warning_lines(*cutting_, sim_.scene());
}

bool CaseRun::advance() {
  begin();
  if (ended_ || finished()) return false;
  if (stop_->stop_requested()) return stopped(stop_description());  // asked between steps
  const Scene& scene = sim_.scene();
  try {
    RunOutputs& out = *out_;
    const double end = scene.solver.end_time;
    const double snap_dt = scene.output.snapshot_interval;
    const double hist_dt = scene.output.history_interval;
    const double eps = 1e-12 * end;
    try {
      // Land exactly on the next output time (and on the end time). A snapshot time within eps of the next
      // history time is that history time: both are running sums of their intervals, which differ in the last
      // bits even where one interval is a multiple of the other, and the steps (so the results, which a
      // serrated cut turns from round-off into per cent) would then depend on the number of snapshots.
      double target = std::min(next_snapshot_, end);
      if (hist_dt > 0) {
        const double history = std::min(next_history_, end);
        target = std::abs(target - history) <= eps ? history : std::min(target, history);
      }
      if (tuner_) tuner_->before_step();
      sim_.step(target - sim_.time());
      if (tuner_) tuner_->after_step();
      out.after_step();
      // The last step is a history row too: an interval that does not divide the end time left the final state out.
      if (hist_dt <= 0 || sim_.time() >= next_history_ - eps || finished()) {
        out.history_row();
        out.rigid_row();
        while (hist_dt > 0 && next_history_ <= sim_.time() + eps) next_history_ += hist_dt;
      }
      if (sim_.time() >= next_snapshot_ - eps) {
        out.snapshot();
        while (next_snapshot_ <= sim_.time() + eps) next_snapshot_ += snap_dt > 0 ? snap_dt : end;
      }
      if (options_.progress) progress_->update(sim_.time(), sim_.step_count(), sim_.last_dt());
      if (stop_->stop_requested()) return stopped(stop_description());
      if (checkpoint_due()) write_checkpoint();
    } catch (const SimulationError& e) {
      status_ = run_status::failed;
      message_ = e.what();
      exit_code_ = kExitSimulationFailed;
      ended_ = true;
      // The state at failure is the most useful picture for finding the cause.
      try {
        out.snapshot();
      } catch (...) {
      }
      out.flush();
      return false;
    }
  } catch (const std::exception& e) {  // output errors: disk full, unwritable directory, file too large
    output_failed(e);
    return false;
  }
  return !finished();
}

std::string CaseRun::stop_description() const {
  // A signal first: a request_stop(why) may be older (a loop that began since forgot it).
  switch (stop_->signal_number()) {
    case SIGINT: return "stopped on request: SIGINT (Ctrl-C)";
    case SIGTERM: return "stopped on request: SIGTERM";
    default: break;
  }
  return stop_reason_.empty() ? std::string(kStopRequested) : fmt::format("stopped on request: {}", stop_reason_);
}

bool CaseRun::stopped(std::string_view how) {
  status_ = run_status::interrupted;
  message_ = fmt::format("{} at step {}, time {:.6g} s; continue with: mpmcut resume {}", how, sim_.step_count(),
                         sim_.time(), root_.string());
  exit_code_ = kExitInterrupted;
  ended_ = true;
  return false;
}

void CaseRun::output_failed(const std::exception& e) {
  status_ = run_status::failed;
  message_ = std::string("output error: ") + e.what();
  if (!last_checkpoint_.empty())
    message_ += fmt::format("; the last checkpoint ({}) is intact: fix the cause, then mpmcut resume {}",
                            last_checkpoint_, root_.string());
  exit_code_ = kExitOutputError;
  ended_ = true;
}

int CaseRun::finish() {
  begin();
  // Finished early by a library caller: after a stop request (Ctrl-C in Python, Run.stop()) it reads as the CLI's.
  if (exit_code_ == kExitComplete && !finished())
    stopped(stop_->stop_requested() ? stop_description() : std::string(kEndedByCaller));
  const SolverSpec& solver = sim_.scene().solver;
  if (exit_code_ == kExitComplete && sim_.time() < solver.end_time - 1e-12 * solver.end_time)  // ended by max_steps
    message_ = fmt::format("ended at solver.max_steps = {} at t = {:.6g} s, before solver.end_time = {:.6g} s: the "
                           "results cover that part of the run only",
                           solver.max_steps, sim_.time(), solver.end_time);
  if (exit_code_ == kExitComplete || exit_code_ == kExitInterrupted) {
    try {
      // Before the extra snapshot below, which a resumed run does not have (it is dropped on resume).
      if (exit_code_ == kExitInterrupted && last_checkpoint_step_ != sim_.step_count()) write_checkpoint();
      if (out_->last_snapshot_time() < sim_.time()) out_->snapshot();
      out_->flush();
    } catch (const std::exception& e) {
      output_failed(e);
    }
  }
  ended_ = true;
  if (options_.progress) progress_->finish(status_);
  const double wall_s = wall_before_s_ + session_wall_s();
  std::string energy_warning, drift_warning, chip_note, forces_line, input_reminder;
  try {
    nlohmann::json sections = to_json(summarize(sim_, cutting_, status_, wall_s, message_, threads_));
    energy_warning = sections["energy_balance"].value("warning", "");
    if (tuner_) sections["thread_tuning"] = {{"threads_in_use_at_end", tuner_->chosen()}, {"trials", tuner_->trials()}};
    if (!last_checkpoint_.empty()) sections["last_checkpoint"] = "checkpoints/" + last_checkpoint_;
    if (!resumed_from_.empty()) sections["resumed_from"] = "checkpoints/" + resumed_from_;
    if (out_) out_->finish(sections);
    // A cut's result on the console too (the outputs add the cut's sections): its mean forces, and whether they
    // had settled.
    if (sections.contains("steady_window") && sections["steady_window"].contains("drift"))
      drift_warning = sections["steady_window"]["drift"].value("warning", "");
    // A cut long enough for the start's check can still be too short for the chip's statistics over time
    // (they need a chip of twice the entry chip's area in the window): say so where the forces are printed.
    if (sections.contains("chip_over_time") && sections["chip_over_time"].contains("note") &&
        sections["chip_over_time"]["note"].is_string())
      chip_note = "chip statistics over time: " + sections["chip_over_time"]["note"].get<std::string>();
    // The start's input warnings scroll away above a long run's progress: the end says that they stand.
    if (sections.contains("input_warnings") && sections["input_warnings"].is_array() &&
        !sections["input_warnings"].empty()) {
      std::string first = sections["input_warnings"][0].get<std::string>();
      if (first.size() > 120) first = first.substr(0, 120) + "...";
      input_reminder = fmt::format("warning: these results rest on {} input(s) flagged at the start (summary.json "
                                   "input_warnings), first: {}\n",
                                   sections["input_warnings"].size(), first);
    }
    if (sections.contains("mean_cutting_force_N_per_mm") && sections["mean_cutting_force_N_per_mm"].is_number() &&
        sections["mean_thrust_force_N_per_mm"].is_number())
      forces_line = fmt::format("mean forces over the steady window: Fc {:.4g} N/mm, Ft {:.4g} N/mm (per mm of width)\n",
                                sections["mean_cutting_force_N_per_mm"].get<double>(),
                                sections["mean_thrust_force_N_per_mm"].get<double>());
    // Through the struct, so that what is written is what the readers read.
    write_summary(root_ / "summary.json", summary_from_json(sections));
  } catch (const std::exception& e) {
    // summary.json could not be written: what it holds on disk is stale, and the run is not complete.
    std::cerr << "error: " << e.what() << "\n";
    if (!message_.empty()) std::cerr << "error: " << message_ << "\n";
    status_ = run_status::failed;
    message_ = std::string("output error: ") + e.what() + (message_.empty() ? "" : "; " + message_);
    exit_code_ = kExitOutputError;
    return kExitOutputError;
  }
  if (!message_.empty())
    std::cerr << (exit_code_ == kExitInterrupted ? "" : exit_code_ == kExitComplete ? "warning: " : "error: ")
              << message_ << "\n";
  if (exit_code_ == kExitComplete && !energy_warning.empty()) std::cerr << "warning: " << energy_warning << "\n";
  if (exit_code_ == kExitComplete && !drift_warning.empty()) std::cerr << "warning: " << drift_warning << "\n";
  if (exit_code_ == kExitComplete && !chip_note.empty()) std::cerr << "warning: " << chip_note << "\n";
  std::cerr << forces_line << input_reminder;
  std::cerr << fmt::format(
      "{}: {} particles, {} steps, {:.3g} s simulated in {:.1f} s wall ({:.3g} particle-steps/s); results in {}\n",
      status_, sim_.particles().size(), sim_.step_count(), sim_.time(), wall_s,
      wall_s > 0 ? sim_.particles().size() * static_cast<double>(sim_.step_count()) / wall_s : 0.0, root_.string());
  lock_.release();  // the directory's files are final: another run (a rerun with --force) may take it
  if (exit_code_ == kExitComplete) stop_->mark_results_complete();
  return exit_code_;
}

int CaseRun::run_to_end() {
  // From here a stop request stops the loop after a step, with a checkpoint.
  const StopToken::LoopScope stops(*stop_);
  while (advance()) {
  }
  return finish();
}

RunSummary CaseRun::summary() const {
  RunSummary s = summarize(sim_, cutting_, ended_ ? status_ : run_status::running, wall_before_s_ + session_wall_s(), message_,
                           threads_);
  if (!last_checkpoint_.empty()) s.last_checkpoint = "checkpoints/" + last_checkpoint_;
  if (!resumed_from_.empty()) s.resumed_from = "checkpoints/" + resumed_from_;
  return s;
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
fs::path CaseRun::write_checkpoint() {
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
  return file;
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

}  // namespace mpmcut
