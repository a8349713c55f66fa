#pragma once
// Scatter from particles to the grid without atomics: particles are grouped by strips of grid
// rows, and strips are coloured even/odd; strips of one colour never share a node, so they run in
// parallel. Each node always receives its contributions in the same order, whatever the number of
// threads: bit-identical results.
#include <cstddef>
#include <span>
#include <vector>

#include "core/grid.hpp"
#include "core/particles.hpp"
#include "core/shape_functions.hpp"

namespace mpmcut {

class StripColouring {
 public:
  static constexpr int kStripRows = 4;  // grid rows per strip (>= 2 so even strips never share nodes)

  // Groups the particles by the strip of the lowest grid row their stencil reaches (counting sort,
  // stable in particle order). Valid until the particles move or are reordered.
  void bucket(const Particles& particles, const Grid& grid, std::span<const ShapeFunction> body_shapes);

  // Calls scatter(p) for every particle bucketed: the even strips in parallel, then the odd ones.
  template <class F>
  void for_each(bool parallel, F&& scatter) const {
    const int strips = static_cast<int>(strip_begin_.size()) - 1;
    for (int colour = 0; colour < 2; ++colour) {
#pragma omp parallel for schedule(dynamic, 1) if (parallel)
      for (int s = colour; s < strips; s += 2)
        for (std::size_t k = strip_begin_[s]; k < strip_begin_[s + 1]; ++k) scatter(strip_order_[k]);
    }
  }

 private:
  std::vector<std::size_t> strip_order_;  // particle indices grouped by strip
  std::vector<std::size_t> strip_begin_;  // strip s holds strip_order_[strip_begin_[s] .. strip_begin_[s+1])
};

}  // namespace mpmcut
