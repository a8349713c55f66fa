#include "core/strip_colouring.hpp"

#include <algorithm>
#include <cmath>

namespace mpmcut {

void StripColouring::bucket(const Particles& particles, const Grid& grid, std::span<const ShapeFunction> body_shapes) {
  const std::size_t n = particles.size();
  const int strips = grid.ny / kStripRows + 1;
  std::vector<int> strip_of(n);
  strip_begin_.assign(strips + 1, 0);
  for (std::size_t p = 0; p < n; ++p) {
    const double lp_cells = body_shapes[particles.body[p]].half_width() / grid.h;
    const int j0 = static_cast<int>(std::floor(((particles.position[p] - grid.origin) / grid.h).y() - lp_cells));
    strip_of[p] = std::clamp(j0, 0, grid.ny - 1) / kStripRows;
    ++strip_begin_[strip_of[p] + 1];
  }
  for (int s = 0; s < strips; ++s) strip_begin_[s + 1] += strip_begin_[s];
  strip_order_.resize(n);
  std::vector<std::size_t> fill(strip_begin_.begin(), strip_begin_.end() - 1);
  for (std::size_t p = 0; p < n; ++p) strip_order_[fill[strip_of[p]]++] = p;
}

}  // namespace mpmcut
