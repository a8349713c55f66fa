#include "core/grid.hpp"

#include <algorithm>
#include <cmath>

namespace mpmcut {

void Grid::build(const GridSpec& spec) {
  h = spec.cell_size;
  const Vec2 extent = spec.max - spec.min;
  const int cx = std::max(1, static_cast<int>(std::ceil(extent.x() / h - 1e-9)));
  const int cy = std::max(1, static_cast<int>(std::ceil(extent.y() / h - 1e-9)));
  domain_min = spec.min;
  domain_max = spec.min + h * Vec2(cx, cy);
  origin = spec.min - kPadding * h * Vec2::Ones();
  nx = cx + 2 * kPadding + 1;
  ny = cy + 2 * kPadding + 1;
  const std::size_t n = static_cast<std::size_t>(nx) * ny;
  mass.assign(n, 0.0);
  momentum.assign(n, Vec2::Zero());
  force.assign(n, Vec2::Zero());
  velocity.assign(n, Vec2::Zero());
  velocity_new.assign(n, Vec2::Zero());
  mass_position.assign(n, Vec2::Zero());
  friction_heat.assign(n, 0.0);
  heat_capacity.assign(n, 0.0);
  temperature.assign(n, 0.0);
  heat_rate.assign(n, 0.0);
  in_contact.assign(n, 0);
  fixed.assign(n, 0);
  fixed_temperature.assign(n, 0.0);
}

void Grid::reset() {
  std::fill(mass.begin(), mass.end(), 0.0);
  std::fill(momentum.begin(), momentum.end(), Vec2::Zero());
  std::fill(force.begin(), force.end(), Vec2::Zero());
  std::fill(mass_position.begin(), mass_position.end(), Vec2::Zero());
  std::fill(friction_heat.begin(), friction_heat.end(), 0.0);
  std::fill(heat_capacity.begin(), heat_capacity.end(), 0.0);
  std::fill(temperature.begin(), temperature.end(), 0.0);
  std::fill(heat_rate.begin(), heat_rate.end(), 0.0);
}

}  // namespace mpmcut
