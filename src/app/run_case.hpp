#pragma once
// Runs a scene to its end time, writing everything into a result directory: the run loop
// with its observers (snapshots, histories, progress, summary), checkpoints, and the
// continuation of a stopped run from its last checkpoint (docs/reliability.md).
#include <filesystem>
#include <string>
#include <string_view>

#include "core/scene.hpp"

namespace mpmcut {

// How often a run writes a checkpoint: every N steps, or after N seconds of wall time.
// Parsed from the --checkpoint-every text (parse_checkpoint_interval).
struct CheckpointInterval {
  enum class Kind { Off, Steps, WallSeconds };
  Kind kind = Kind::WallSeconds;
  double value = 1800.0;  // steps or seconds; the default: every 30 min of wall time

  std::string text() const;  // e.g. "every 5000 steps", "every 600 s of wall time", "off"
};

// "5000" or "5000steps" -> every 5000 steps; "600s", "45sec", "10min", "2h" -> wall time;
// "off" or "0" -> never (a checkpoint is still written on SIGINT/SIGTERM). Whitespace between
// number and unit is allowed. Throws InputError with the accepted forms.
CheckpointInterval parse_checkpoint_interval(std::string_view text);

struct RunOptions {
  std::filesystem::path out_dir;  // result directory (for resume: the directory to continue)
  bool force = false;             // run: overwrite an existing result directory;
                                  // resume: continue a directory whose run is already complete
  int threads = 0;                // OpenMP threads; 0 = all cores
  bool tune_threads = true;       // use the fastest of 1..threads, re-timed every 10 s (core/thread_tuner.hpp)
  bool progress = true;           // progress bar / lines on stderr
  CheckpointInterval checkpoint_every;
  bool checkpoint_every_given = true;  // resume: false = keep the interrupted run's interval
};

// Exit codes of `mpmcut run` and `mpmcut resume`, also documented in docs/reliability.md.
enum ExitCode : int {
  kExitComplete = 0,
  kExitInputError = 2,         // bad case file or option; resume: nothing (valid) to resume
  kExitSimulationFailed = 3,
  kExitOutputError = 4,        // cannot write the result directory (unwritable, disk full, file too large)
  kExitInterrupted = 130,      // SIGINT/SIGTERM: checkpoint written, summary says "interrupted"
};

// Runs `scene`; returns one of ExitCode. Messages go to stderr.
int run_case(const Scene& scene, const RunOptions& options);

// What a result directory holds for `scene` (studies rerun with `run --keep-complete`: a complete run
// of the same scene is kept, an unfinished one with a checkpoint is resumed, anything else is rerun).
// "The same scene" = its scene.toml is byte for byte what this scene writes.
enum class ExistingRun { None, Complete, Resumable };
ExistingRun existing_run(const std::filesystem::path& dir, const Scene& scene);

// Continues the run in options.out_dir from its newest valid checkpoint (scene from its
// scene.toml); returns one of ExitCode.
int resume_case(const RunOptions& options);

}  // namespace mpmcut
