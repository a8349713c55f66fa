#pragma once
// Sums over particles that do not depend on the number of threads: fixed chunks, each summed in
// order, then the chunks in order. (An OpenMP reduction(+) combines in a varying order.)
#include <algorithm>
#include <cstddef>
#include <vector>

namespace mpmcut {

inline constexpr std::size_t kDeterministicSumChunk = 4096;  // particles per partial sum

// Sum of f(i) for i in [0, n); parallel = false runs it on one thread (same result).
template <class F>
double deterministic_sum(std::size_t n, F&& f, bool parallel) {
  const std::size_t chunks = (n + kDeterministicSumChunk - 1) / kDeterministicSumChunk;
  std::vector<double> partial(chunks, 0.0);
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t c = 0; c < chunks; ++c) {
    double s = 0.0;
    const std::size_t end = std::min(n, (c + 1) * kDeterministicSumChunk);
    for (std::size_t i = c * kDeterministicSumChunk; i < end; ++i) s += f(i);
    partial[c] = s;
  }
  double total = 0.0;
  for (double s : partial) total += s;
  return total;
}

}  // namespace mpmcut
