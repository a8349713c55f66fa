#pragma once
// `mpmcut bench`: particle-steps per second of the explicit step on a standard elastic block.
#include <vector>

namespace mpmcut {

struct BenchOptions {
  long particles = 100000;       // approximate
  int steps = 200;
  std::vector<int> threads{1, 2};
};

int run_benchmark(const BenchOptions& options);

}  // namespace mpmcut
