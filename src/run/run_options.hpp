#pragma once
// How a run is carried out (not what is simulated: that is the Scene), and the exit codes of the
// command line's `run` and `resume`, which the library's run functions return.
#include <filesystem>

#include "run/checkpoint_interval.hpp"
#include "run/stop_token.hpp"

namespace mpmcut {

struct RunOptions {
  std::filesystem::path out_dir;  // result directory (for resume: the directory to continue)
  bool force = false;             // run: overwrite an existing result directory;
                                  // resume: continue a directory whose run is already complete
  int threads = 0;                // OpenMP threads; 0 = all cores
  bool tune_threads = true;       // use the fastest of 1..threads, re-timed every 10 s (core/thread_tuner.hpp)
  bool progress = true;           // progress bar / lines on stderr
  CheckpointInterval checkpoint_every;
  bool checkpoint_every_given = true;  // resume: false = keep the interrupted run's interval
  StopToken* stop = nullptr;      // asks the run to stop after a step (none: it runs to its end)
};

// Exit codes of `mpmcut run` and `mpmcut resume`, also documented in docs/reliability.md.
enum ExitCode : int {
  kExitComplete = 0,
  kExitInputError = 2,         // bad case file or option; resume: nothing (valid) to resume
  kExitSimulationFailed = 3,
  kExitOutputError = 4,        // cannot write the result directory (unwritable, disk full, file too large)
  kExitInterrupted = 130,      // stopped (SIGINT/SIGTERM, a StopToken): checkpoint written, summary "interrupted"
};

}  // namespace mpmcut
