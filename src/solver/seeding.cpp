#include "solver/seeding.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace mpmcut {

void seed_particles(const Scene& scene, const Grid& grid, Particles& particles) {
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const BodySpec& body = scene.bodies[b];
    const int mat = scene.material_index(body.material);
    if (mat < 0) throw std::invalid_argument("body '" + body.name + "' uses unknown material '" + body.material + "'");
    const double d = grid.h / body.particles_per_cell;
    const double rho = scene.materials[mat].density;
    const Vec2 everywhere = Vec2::Constant(std::numeric_limits<double>::infinity());
    for_each_seed_point(body, grid.domain_min, grid.h, -everywhere, everywhere, [&](const Vec2& x) {
      particles.add(x, body.velocity, rho * d * d, d * d, body.temperature, static_cast<int>(b), mat);
      return true;
    });
  }
}

}  // namespace mpmcut
