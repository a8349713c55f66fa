#pragma once
// A whole run as the command line does it (`mpmcut run`, `mpmcut resume`): the checks before
// anything is written, the result directory, the run to its end (run/case_run.hpp) and the
// messages on stderr; returns the exit code. Also what a result directory holds for a scene
// (the studies' --keep-complete), and the continuation of a stopped run (docs/reliability.md).
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "cutting/case.hpp"
#include "run/case_run.hpp"
#include "run/run_options.hpp"

namespace mpmcut {

// Why a run could not be opened (nothing was stepped): the message for the user and the exit code.
struct RunOpenError : std::runtime_error {
  RunOpenError(const std::string& what, int code) : std::runtime_error(what), exit_code(code) {}
  int exit_code;
};

// A new run in options.out_dir, ready to step: the memory and step check, the result directory,
// scene.toml, a "running" summary.json and the outputs at t = 0. Throws RunOpenError.
std::unique_ptr<CaseRun> open_run(const Case& c, const RunOptions& options);

// The stopped run in options.out_dir, continued from its newest valid checkpoint (scene from its
// scene.toml; warnings about skipped checkpoints go to stderr). Throws RunOpenError.
std::unique_ptr<CaseRun> open_resumed_run(const RunOptions& options);

// Runs `c`; returns one of ExitCode. Messages go to stderr.
int run_case(const Case& c, const RunOptions& options);

// What a result directory holds for `scene` (studies rerun with `run --keep-complete`: a complete run
// of the same scene is kept, an unfinished one with a checkpoint is resumed, anything else is rerun).
// "The same scene" = its scene.toml is byte for byte what this scene writes. Outdated: a complete or
// resumable run of the same scene made by an older model of it (summary.json model_version below
// model_version(c.scene), solver/model_version.hpp); it is run again from the start.
enum class ExistingRun { None, Complete, Resumable, Outdated };
ExistingRun existing_run(const std::filesystem::path& dir, const Case& c);

// Why the run in `dir` is outdated for `c`: "made by model version N; since then: <the changes>"; empty
// when it is not (or has no readable summary).
std::string outdated_run_reason(const std::filesystem::path& dir, const Case& c);
// The same for the scene of the run's own scene.toml (a study reading its results back); empty also when that
// scene does not read.
std::string outdated_run_reason(const std::filesystem::path& dir);

// Continues the run in options.out_dir from its newest valid checkpoint (scene from its
// scene.toml); returns one of ExitCode.
int resume_case(const RunOptions& options);

// The most OpenMP threads a run may ask for (a larger team crashes the OpenMP runtime before it can say why).
inline constexpr int kMaxThreads = 1024;

// The OpenMP threads of a run: `requested`, or all cores (OMP_NUM_THREADS) when 0; set for the process.
// std::invalid_argument outside [0, kMaxThreads].
int set_threads(int requested);

}  // namespace mpmcut
