#pragma once
// `mpmcut sweep CASE --speeds ... --feeds ...`: a grid of cutting runs, each a separate process of this
// same program (locally, or on an MPI task farm under mpirun/srun: studies/task_farm.hpp), then a table
// (sweep.csv, sweep.md) and plots (tools/plot_sweep.py).
#include <string>

#include <CLI/CLI.hpp>

#include "studies/case_runs.hpp"

namespace mpmcut {

// True if `app` (the top-level program) has a subcommand of this name.
bool has_subcommand(const CLI::App& app, const std::string& name);

void add_sweep_command(CLI::App& app);

}  // namespace mpmcut
