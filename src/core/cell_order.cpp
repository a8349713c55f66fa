#include "core/cell_order.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace mpmcut {

void sort_particles_by_cell(Particles& particles, const Grid& grid) {
  const std::size_t n = particles.size();
  std::vector<long> key(n);
  for (std::size_t p = 0; p < n; ++p) {
    const Vec2 u = (particles.position[p] - grid.origin) / grid.h;
    key[p] = static_cast<long>(std::floor(u.y())) * grid.nx + static_cast<long>(std::floor(u.x()));
  }
  std::vector<std::size_t> order(n);
  for (std::size_t p = 0; p < n; ++p) order[p] = p;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  particles.permute(order);
}

}  // namespace mpmcut
