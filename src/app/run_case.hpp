#pragma once
// Runs a scene to its end time, writing everything into a result directory: the run loop
// with its observers (snapshots, histories, progress, summary).
#include <filesystem>
#include <string>

#include "core/scene.hpp"

namespace mpmcut {

struct RunOptions {
  std::filesystem::path out_dir;  // result directory
  bool force = false;             // overwrite an existing result directory
  int threads = 0;                // OpenMP threads; 0 = all cores
  bool progress = true;           // progress bar / lines on stderr
};

// Exit codes of `mpmcut run`, also documented in the README.
enum ExitCode : int {
  kExitComplete = 0,
  kExitInputError = 2,
  kExitSimulationFailed = 3,
  kExitOutputError = 4,
  kExitInterrupted = 130,
};

// Runs `scene`; returns one of ExitCode. Messages go to stderr.
int run_case(const Scene& scene, const RunOptions& options);

}  // namespace mpmcut
