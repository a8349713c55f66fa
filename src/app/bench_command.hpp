#pragma once
// `mpmcut bench`: particle-steps per second of the explicit step on three standard problems:
//   elastic  - an elastic Ti-6Al-4V-like block with a smooth velocity field (transfers + grid, cheap stress);
//   plastic  - a Ti-6Al-4V Johnson-Cook block (heating, damage) in sustained pure shear: every particle
//              flows plastically in the timed steps (the fraction is measured and printed);
//   cutting  - the default cut (cases/ti64_default.toml), timed after the chip has started to form.
// Each reports wall-clock and CPU-time rates (the CPU figure is less sensitive to a shared machine).
#include <string>
#include <vector>

namespace mpmcut {

struct BenchOptions {
  long particles = 100000;       // approximate, elastic and plastic blocks
  int steps = 200;               // timed steps, elastic and plastic blocks
  int cutting_steps = 300;       // timed steps of the cutting case (per thread count)
  std::vector<int> threads{1, 2};
  std::string which = "all";     // elastic | plastic | cutting | all
  bool background_load = false;  // keep one core busy with a spinning process while measuring
};

int run_benchmark(const BenchOptions& options);

}  // namespace mpmcut
