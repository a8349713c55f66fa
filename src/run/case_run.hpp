#pragma once
// One run, new or resumed, as a library object: the simulation, its outputs in a result
// directory, the output schedule, checkpoints and the stop token. The command line
// (run/run_case.hpp), the studies' runs and the Python module all step through this class, so
// that a run writes the same files whoever drives it.
//
//   CaseRun run(c, root, options, threads);   // c: a Case (cutting/case.hpp)
//   run.start();                       // or run.resume(checkpoint, file)
//   while (run.advance()) { ... }      // one step and its outputs per call
//   int exit_code = run.finish();      // final snapshot, summary.json, the console line
// or simply `run.run_to_end()`.
#include <chrono>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/directory_lock.hpp"
#include "solver/simulation.hpp"
#include "cutting/case.hpp"
#include "core/thread_tuner.hpp"
#include "io/checkpoint.hpp"
#include "io/progress.hpp"
#include "run/run_options.hpp"
#include "run/run_outputs.hpp"
#include "run/run_summary.hpp"

namespace mpmcut {

class CaseRun {
 public:
  // `root` is the (opened) result directory; `threads` the OpenMP threads already set.
  // Throws std::invalid_argument for a scene the solver cannot build.
  CaseRun(const Case& c, std::filesystem::path root, const RunOptions& options, int threads);

  // A new run: the outputs at t = 0 and the first output times.
  void start();
  // A resumed run: the result directory is cut back to what it was when `c` was written (CSV
  // lengths, snapshots, PVD index), then the state is restored.
  void resume(Checkpoint&& c, const std::filesystem::path& file);

  // One step and the outputs that fall due after it (history, snapshot, checkpoint). Returns false
  // when the run cannot go on: it reached its end, was stopped, or failed (see finish()).
  bool advance();
  // After the last advance(): the final checkpoint (when stopped) and snapshot, summary.json and the
  // console line. Returns the exit code (ExitCode).
  int finish();
  // Keeps the result directory's lock (io/directory_lock.hpp) until the run has finished.
  void hold(DirectoryLock lock) { lock_ = std::move(lock); }
  // advance() until it returns false, then finish(); the stop token's loop scope around both.
  int run_to_end();

  // Writes a checkpoint now (outputs flushed first); returns its file.
  std::filesystem::path write_checkpoint();

  bool finished() const;  // end time or step limit reached
  const Simulation& simulation() const { return sim_; }
  Simulation& simulation() { return sim_; }
  const std::filesystem::path& root() const { return root_; }
  int threads() const { return threads_; }
  StopToken& stop_token() { return *stop_; }
  // Asks the run to stop after its current step and says why in the summary ("stopped on request: <why> at step
  // ..."): the program driving the run knows the cause (a Python callback's exception), the token does not.
  void request_stop(std::string why) {
    stop_reason_ = std::move(why);
    stop_->request_stop();
  }
  void flush_outputs() { out_->flush(); }
  // The summary as it would be written now (status "running" while the run goes on).
  RunSummary summary() const;
  // Once finish() returned: the run's status and message, also where summary.json could not be written.
  const char* final_status() const { return status_; }
  const std::string& final_message() const { return message_; }

 private:
  DirectoryLock lock_;  // no other run writes into root_ while this one does
  using Clock = std::chrono::steady_clock;
  double session_wall_s() const { return std::chrono::duration<double>(Clock::now() - session_start_).count(); }
  bool checkpoint_due() const;
  void output_failed(const std::exception& e);  // an output error ends the run
  bool stopped(std::string_view how);  // a stop ends the run (`how`: what stopped it, for the message); false
  std::string stop_description() const;  // what the stop request was, for the message
  void begin();  // the console line and the progress display, before the first step
  void cut_back_outputs(const RunLoopState& loop) const;
  std::vector<FileLength> csv_lengths() const;

  std::filesystem::path root_;
  RunOptions options_;
  int threads_;
  StopToken own_stop_;  // when the options bring none
  StopToken* stop_;
  std::string stop_reason_;  // request_stop's why, empty for a plain request
  std::optional<ThreadTuner> tuner_;  // picks 1..threads_ by timing (busy machines); none = fixed
  Simulation sim_;
  std::optional<CuttingParameters> cutting_;  // the process of a cut (its outputs read it)
  std::uint64_t scene_hash_;
  CheckpointStore store_;
  std::optional<RunOutputs> out_;
  std::optional<Progress> progress_;
  double next_snapshot_ = 0.0;
  double next_history_ = 0.0;
  Clock::time_point session_start_ = Clock::now();
  Clock::time_point last_checkpoint_wall_ = Clock::now();
  double wall_before_s_ = 0.0;  // wall time of the sessions before a resume
  long last_checkpoint_step_ = -1;
  std::string last_checkpoint_;
  std::string resumed_from_;
  int synced_snapshots_ = 0;  // snapshots already made durable by a checkpoint
  // How the step loop ended: still going (status "complete" once finished), stopped, failed.
  const char* status_ = run_status::complete;
  std::string message_;
  int exit_code_ = kExitComplete;
  bool ended_ = false;  // advance() will not step again
};

}  // namespace mpmcut
