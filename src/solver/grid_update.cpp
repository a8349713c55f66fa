#include "solver/grid_update.hpp"

namespace mpmcut {

void mark_boundary_nodes(const BoundarySpec& velocity, const ThermalSpec& temperature, Grid& grid) {
  const int il = Grid::kPadding, ir = grid.nx - 1 - Grid::kPadding;
  const int jb = Grid::kPadding, jt = grid.ny - 1 - Grid::kPadding;
  auto mark = [&](BoundaryKind kind, bool x_side, auto in_side) {
    if (kind == BoundaryKind::Free) return;
    const std::uint8_t bits = kind == BoundaryKind::Fixed ? 3 : (x_side ? 1 : 2);
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i)
        if (in_side(i, j)) grid.fixed[grid.index(i, j)] |= bits;
  };
  mark(velocity.left, true, [&](int i, int) { return i <= il; });
  mark(velocity.right, true, [&](int i, int) { return i >= ir; });
  mark(velocity.bottom, false, [&](int, int j) { return j <= jb; });
  mark(velocity.top, false, [&](int, int j) { return j >= jt; });
  auto mark_temperature = [&](const std::optional<double>& T, auto in_side) {
    if (!T) return;
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i)
        if (in_side(i, j)) {
          grid.fixed[grid.index(i, j)] |= 4;
          grid.fixed_temperature[grid.index(i, j)] = *T;
        }
  };
  mark_temperature(temperature.left, [&](int i, int) { return i <= il; });
  mark_temperature(temperature.right, [&](int i, int) { return i >= ir; });
  mark_temperature(temperature.bottom, [&](int, int j) { return j <= jb; });
  mark_temperature(temperature.top, [&](int, int j) { return j >= jt; });
}

void apply_velocity_boundary_conditions(BoundaryPhase phase, bool parallel, Grid& G) {
  const std::size_t nn = G.node_count();
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t n = 0; n < nn; ++n) {
    const std::uint8_t f = G.fixed[n];
    if ((f & 3) == 0) continue;
    for (int d = 0; d < 2; ++d) {
      if (!(f & (1 << d))) continue;
      if (phase == BoundaryPhase::AfterP2G) {
        G.velocity[n][d] = 0.0;
      } else {
        G.force[n][d] = 0.0;
        G.velocity_new[n][d] = 0.0;
      }
    }
  }
}

void update_grid_momentum(double dt, double node_mass_cutoff, bool parallel, Grid& G) {
  const std::size_t nn = G.node_count();
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t n = 0; n < nn; ++n) {
    const bool has_mass = G.mass[n] > node_mass_cutoff;
    G.velocity_new[n] = has_mass ? Vec2(G.velocity[n] + dt * G.force[n] / G.mass[n]) : G.velocity[n];
  }
  apply_velocity_boundary_conditions(BoundaryPhase::AfterUpdate, parallel, G);
}

}  // namespace mpmcut
