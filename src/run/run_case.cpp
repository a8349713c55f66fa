#include "run/run_case.hpp"

#include <omp.h>

#include <csignal>
#include <fstream>
#include <iostream>
#include <iterator>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "io/run_estimate.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/input_error.hpp"
#include "io/result_directory.hpp"
#include "io/whole_file.hpp"
#include "cutting/cutting_case.hpp"
#include "run/case_loading.hpp"
#include "run/case_run.hpp"
#include "run/run_summary.hpp"
#include "solver/model_version.hpp"

namespace mpmcut {

namespace fs = std::filesystem;

namespace {

// SIGXFSZ is ignored during a run so that a file-size limit surfaces as an EFBIG write error with a
// message instead of killing the process. (SIGINT/SIGTERM are the caller's: options.stop.)
struct IgnoreFileSizeSignal {
  struct sigaction old_xfsz {};
  IgnoreFileSizeSignal() {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGXFSZ, &ignore, &old_xfsz);
  }
  ~IgnoreFileSizeSignal() { sigaction(SIGXFSZ, &old_xfsz, nullptr); }
};

// Writes the expanded scene; a failure is an output error.
void write_expanded_scene(const Case& c, const fs::path& root) {
  write_file_atomically(root / "scene.toml", [&](std::ostream& out) { write_scene(c, out); });
}

// A scene the solver refused once its result directory existed: the summary says so (status "failed", the
// reason), not "running". Best effort: the error itself is reported by the caller either way.
void mark_failed_before_stepping(const Case& c, const fs::path& root, int threads, const std::string& why) {
  RunSummary s = summary_before_setup(c.scene.title, c.scene.source_file, threads);
  s.status = run_status::failed;
  s.message = why;
  try {
    write_summary(root / "summary.json", s);
  } catch (const std::exception&) {
  }
}

}  // namespace

int set_threads(int requested) {
  if (requested < 0 || requested > kMaxThreads)
    throw std::invalid_argument(
        fmt::format("threads = {}: expected 1 to {} (0: all cores)", requested, kMaxThreads));
  const int threads = requested > 0 ? requested : omp_get_max_threads();  // OMP_NUM_THREADS or all cores
  omp_set_num_threads(threads);
  return threads;
}

// ---------------------------------------------------------------------------------------------

std::unique_ptr<CaseRun> open_run(const Case& c, const RunOptions& options) {
  // Before the result directory and the first large allocation: a run that cannot fit in memory
  // or cannot finish is the user's input error, not a crash or a hang later.
  try {
    check_run_fits(c.scene, run_size_keys(c));
  } catch (const InputError& e) {
    throw RunOpenError(e.what(), kExitInputError);
  }
  int threads = 0;
  try {
    threads = set_threads(options.threads);
  } catch (const std::invalid_argument& e) {
    throw RunOpenError(e.what(), kExitInputError);
  }
  fs::path root;
  DirectoryLock lock;
  try {
    ResultDirectory directory = ResultDirectory::open(options.out_dir, options.force);
    root = directory.root();
    lock = directory.take_lock();
    write_summary(root / "summary.json", summary_before_setup(c.scene.title, c.scene.source_file, threads));
    write_expanded_scene(c, root);
  } catch (const std::exception& e) {
    throw RunOpenError(e.what(), kExitOutputError);
  }
  std::unique_ptr<CaseRun> run;
  try {
    run = std::make_unique<CaseRun>(c, root, options, threads);
    run->hold(std::move(lock));
    write_summary(root / "summary.json", summarize(run->simulation(), c.cutting, run_status::running, 0.0, "", threads));
    run->start();
  } catch (const std::invalid_argument& e) {  // a scene the solver cannot build
    mark_failed_before_stepping(c, root, threads, e.what());
    throw RunOpenError(e.what(), kExitInputError);
  } catch (const std::exception& e) {
    // The first snapshot or history row could not be written: the directory must not read "running".
    const std::string message = std::string("output error: ") + e.what();
    mark_failed_before_stepping(c, root, threads, message);
    throw RunOpenError(message, kExitOutputError);
  }
  return run;
}

int run_case(const Case& c, const RunOptions& options) {
  IgnoreFileSizeSignal file_size_signal;
  std::unique_ptr<CaseRun> run;
  try {
    run = open_run(c, options);
  } catch (const RunOpenError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return e.exit_code;
  }
  return run->run_to_end();
}

ExistingRun existing_run(const fs::path& dir, const Case& c) {
  std::error_code ec;
  if (!fs::exists(dir / "scene.toml", ec) || !fs::exists(dir / "summary.json", ec)) return ExistingRun::None;
  std::ostringstream expected;
  write_scene(c, expected);
  if (read_whole_file(dir / "scene.toml") != expected.str()) return ExistingRun::None;
  RunSummary summary;
  try {
    summary = read_summary(dir / "summary.json");
  } catch (const std::exception&) {
    return ExistingRun::None;
  }
  const bool complete = summary.status == run_status::complete;
  if (!complete && !fs::exists(dir / "checkpoints" / "latest", ec)) return ExistingRun::None;
  if (summary.model_version < model_version(c.scene)) return ExistingRun::Outdated;
  return complete ? ExistingRun::Complete : ExistingRun::Resumable;
}

std::string outdated_run_reason(const fs::path& dir, const Case& c) {
  int recorded = 0;
  try {
    recorded = read_summary(dir / "summary.json").model_version;
  } catch (const std::exception&) {
    return "";
  }
  const std::string changes = model_changes_since(recorded, c.scene);
  return changes.empty() ? "" : fmt::format("made by model version {} of this scene; since then: {}", recorded, changes);
}

std::string outdated_run_reason(const fs::path& dir) {
  try {
    return outdated_run_reason(dir, load_case(dir / "scene.toml"));
  } catch (const std::exception&) {
    return "";  // a scene this program cannot read is reported by whoever runs it
  }
}

std::unique_ptr<CaseRun> open_resumed_run(const RunOptions& options) {
  const fs::path root = options.out_dir;
  const auto refuse = [&](const std::string& why) {
    return RunOpenError("cannot resume '" + root.string() + "': " + why, kExitInputError);
  };
  std::error_code ec;
  if (!fs::is_directory(root, ec)) throw refuse("no such result directory");
  DirectoryLock lock;
  try {
    lock = DirectoryLock::acquire(root);
  } catch (const std::runtime_error& e) {
    // Another run writing there is an output error, as for `run` (docs/reliability.md, exit codes).
    throw RunOpenError("cannot resume '" + root.string() + "': " + e.what(), kExitOutputError);
  }
  for (const char* file : {"summary.json", "scene.toml"})
    if (!fs::exists(root / file))
      throw refuse(fmt::format("it has no {}, so it is not the result directory of a run that started stepping",
                               file));
  std::string status;
  int recorded_model_version = 0;
  try {
    const RunSummary summary = read_summary(root / "summary.json");
    status = summary.status;
    recorded_model_version = summary.model_version;
  } catch (const std::exception& e) {
    throw refuse(e.what());
  }
  if (status == run_status::complete && !options.force) {
    std::error_code ec;
    throw refuse(fs::exists(root / "checkpoints" / "latest", ec)
                     ? "its run is complete (summary.json status \"complete\"); there is nothing to resume. Use "
                       "--force to recompute from its last checkpoint to the end"
                     : "its run is complete (summary.json status \"complete\") and kept no checkpoint; there is "
                       "nothing to resume (run the case again for new results)");
  }
  if (status == run_status::failed)
    std::cerr << "note: the run had failed (see summary.json \"message\"); continuing from its last checkpoint\n";

  Case resumed_case;
  try {
    resumed_case = load_case(root / "scene.toml");
  } catch (const InputError& e) {
    throw refuse(e.what());
  }
  // A continuation by another model of the scene would be neither model's run.
  if (const std::string changes = model_changes_since(recorded_model_version, resumed_case.scene); !changes.empty())
    throw refuse(fmt::format("it was made by model version {} of its scene, and the physics of that scene has changed "
                             "since ({}); a continuation would mix the two models. Run it again from the start: "
                             "mpmcut run {} --out {} --force",
                             recorded_model_version, changes, (root / "scene.toml").string(), root.string()));
  CheckpointStore store(root);
  std::optional<CheckpointStore::Loaded> loaded;
  try {
    loaded = store.load_newest_valid();
  } catch (const CheckpointError& e) {
    throw refuse(e.what());
  }
  for (const std::string& r : loaded->rejected) std::cerr << "warning: " << r << "\n";
  if (!loaded->rejected.empty())
    std::cerr << "warning: falling back to the previous valid checkpoint '" << loaded->file.string() << "'\n";
  Checkpoint& c = loaded->checkpoint;
  if (c.scene_hash != scene_hash(resumed_case)) {
    throw refuse(fmt::format("scene.toml differs from the scene that checkpoint '{}' was written with, so this "
                              "would not continue the same run. Restore the original scene.toml or start a new run",
                              loaded->file.string()));
  }
  resumed_case.scene.source_file = c.loop.case_file;
  try {
    check_run_fits(resumed_case.scene, run_size_keys(resumed_case));  // the machine resuming may have less memory than the one that started
  } catch (const InputError& e) {
    throw refuse(e.what());
  }
  if (c.loop.mpmcut_version != MPMCUT_VERSION)
    std::cerr << "warning: the checkpoint was written by mpmcut " << c.loop.mpmcut_version << ", this is "
              << MPMCUT_VERSION << "; the continuation may differ from an uninterrupted run\n";
  int threads = 0;
  try {
    threads = set_threads(options.threads > 0 ? options.threads : c.loop.threads);
  } catch (const std::invalid_argument& e) {
    throw refuse(e.what());
  }
  RunOptions resumed = options;
  if (!options.checkpoint_every_given && c.loop.checkpoint_kind >= 0 && c.loop.checkpoint_kind <= 2)
    resumed.checkpoint_every = {static_cast<CheckpointInterval::Kind>(c.loop.checkpoint_kind), c.loop.checkpoint_value};

  std::unique_ptr<CaseRun> run;
  try {
    run = std::make_unique<CaseRun>(resumed_case, root, resumed, threads);
    run->hold(std::move(lock));
    run->resume(std::move(c), loaded->file);
    write_summary(root / "summary.json",
                  summarize(run->simulation(), resumed_case.cutting, run_status::running, 0.0, "", threads));
  } catch (const CheckpointError& e) {
    throw refuse(e.what());
  } catch (const std::invalid_argument& e) {
    throw refuse(e.what());
  } catch (const std::exception& e) {
    throw RunOpenError(std::string("output error: ") + e.what(), kExitOutputError);
  }
  std::cerr << fmt::format("resuming '{}' from {} (step {}, t = {:.6g} s)\n", root.string(),
                           loaded->file.filename().string(), run->simulation().step_count(),
                           run->simulation().time());
  return run;
}

int resume_case(const RunOptions& options) {
  IgnoreFileSizeSignal file_size_signal;
  std::unique_ptr<CaseRun> run;
  try {
    run = open_resumed_run(options);
  } catch (const RunOpenError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return e.exit_code;
  }
  return run->run_to_end();
}

}  // namespace mpmcut
