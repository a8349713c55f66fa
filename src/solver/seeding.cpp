#include "solver/seeding.hpp"

#include <cmath>
#include <stdexcept>

namespace mpmcut {

void seed_particles(const Scene& scene, const Grid& grid, Particles& particles) {
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const BodySpec& body = scene.bodies[b];
    const int mat = scene.material_index(body.material);
    if (mat < 0) throw std::invalid_argument("body '" + body.name + "' uses unknown material '" + body.material + "'");
    const double d = grid.h / body.particles_per_cell;
    const double rho = scene.materials[mat].density;
    for_each_seed_point(body, grid.domain_min, grid.h, [&](const Vec2& x) {
      particles.add(x, body.velocity, rho * d * d, d * d, body.temperature, static_cast<int>(b), mat);
      return true;
    });
  }
}

double seed_points_in_box(const BodySpec& body, double cell_size, const Vec2& lo, const Vec2& hi) {
  const SeedLattice lattice(body, Vec2::Zero(), cell_size);
  Vec2 body_lo, body_hi;
  body.shape.bounds(body_lo, body_hi);
  const Vec2 extent = body_hi.cwiseMin(hi) - body_lo.cwiseMax(lo);
  if ((extent.array() < 0.0).any()) return 0.0;
  const double c = std::abs(lattice.cos_angle), s = std::abs(lattice.sin_angle);
  const double along_k = c * extent.x() + s * extent.y(), along_l = s * extent.x() + c * extent.y();
  return (along_k / lattice.spacing + 1.0) * (along_l / lattice.spacing + 1.0);
}

}  // namespace mpmcut
