#pragma once
// Many runs beyond one machine: an MPI task farm for the studies (sweep, validate, calibrate).
//
// Started under mpirun or srun with more than one rank, a study command runs its own logic on rank 0
// only; rank 0 hands the cases out one at a time to the other ranks, each of which runs its case exactly
// as the local pool does (a separate `mpmcut run` process, studies/case_runs.hpp) and sends back the exit
// status. The cases write into the study's result directory, which must therefore be on a file system
// that all nodes see (as the home and scratch file systems of a cluster are). A failed case is reported
// like a failed local case; it does not stop the farm.
//
// Started without MPI (no launcher variables in the environment), nothing of MPI is initialised and the
// cases run as local processes, at most --jobs at a time. Each case is the same command either way, so
// that the results are identical run by run.
#include <functional>
#include <string>
#include <vector>

#include "studies/case_runs.hpp"

namespace mpmcut {

// True if this process was started by an MPI launcher: OpenMPI's mpirun sets OMPI_COMM_WORLD_SIZE,
// Slurm's srun (PMI-2 or PMIx) sets PMI_SIZE or PMIX_RANK.
bool launched_under_mpi();

// Runs a study command's `body`. Under an MPI launcher with more than one rank: MPI is initialised,
// rank 0 runs `body` (whose run_cases() calls go to the farm) and then releases the workers; the other
// ranks serve cases until released and return 0. Otherwise `body` runs as it is. Returns the exit code
// of this process. Exceptions from `body` propagate after the workers have been released.
int run_study(const std::function<int()>& body);

// Runs the cases of a study: on the farm's worker ranks inside run_study under MPI, else locally (at most
// `jobs` processes at a time, run_children). Returns false if interrupted (SIGINT/SIGTERM).
bool run_cases(std::vector<ChildRun>& runs, int jobs, bool print_progress,
               double progress_interval_s = kDefaultProgressIntervalS);

// "at most N at a time" (local) or "on M MPI ranks" (farm), for a study's opening line.
std::string concurrency_text(int jobs);

// Ranks that run cases when the farm is active (MPI world size - 1), else 0.
int farm_worker_count();

}  // namespace mpmcut
