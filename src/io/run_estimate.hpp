#pragma once
// What a scene will cost before anything is allocated: particles, grid nodes, memory, steps.
// A run that cannot fit in this machine's memory, or whose step count no machine can finish,
// is refused as an input error before the first large allocation (docs/reliability.md).
#include <string>

#include "solver/scene.hpp"

namespace mpmcut {

struct RunEstimate {
  double particles = 0.0;   // from the bodies' areas and particles per cell
  double grid_nodes = 0.0;  // including the padding
  double bytes = 0.0;       // particles, grid and per-step scratch
  double steps = 0.0;       // end_time over the smallest step: CFL, conduction, output intervals
  double snapshots = 0.0;   // VTU snapshots the output schedule asks for
};

// Bytes per particle and per grid node, including the per-step scratch arrays (position_new,
// constitutive increments, strip buckets, the sort's key and order, a permutation copy). Measured
// sizes of Particles/Grid plus the scratch; kept a little generous on purpose.
inline constexpr double kBytesPerParticle = 520.0;
inline constexpr double kBytesPerGridNode = 150.0;
// No run of this program can finish more steps than this (at >= 1 microsecond per step it would take
// more than a quarter of an hour per 1e9 steps even for a single particle).
inline constexpr double kMaxSteps = 1e9;
inline constexpr double kMaxSnapshots = 1e5;

RunEstimate estimate_run(const Scene& scene);

// Memory this process can use: MemAvailable of /proc/meminfo (sysconf's free pages where that is
// missing), capped by a cgroup memory limit where one is set. Bytes; 0 if nothing can be read.
double available_memory_bytes();

// The case keys that set a run's size and step count, named in check_run_fits' messages: a generic
// scene's by default; a case built by the cutting preset names its own (cutting/cutting_case.hpp).
struct RunSizeKeys {
  std::string size = "grid.cell_size, grid.min/max, the bodies' shapes and particles_per_cell";
  std::string simulated_time = "solver.end_time";
  std::string cell_size = "grid.cell_size";
};

// Throws InputError when the estimate does not fit (memory, steps, snapshots); the message says
// how much the run needs, what the machine has and which keys to change.
void check_run_fits(const Scene& scene, const RunEstimate& estimate, double available_bytes,
                    const RunSizeKeys& keys = {});
inline void check_run_fits(const Scene& scene, const RunSizeKeys& keys = {}) {
  check_run_fits(scene, estimate_run(scene), available_memory_bytes(), keys);
}

std::string format_bytes(double bytes);

}  // namespace mpmcut
