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
    Vec2 lo, hi;
    body.shape.bounds(lo, hi);
    const long k0 = static_cast<long>(std::floor((lo.x() - grid.domain_min.x()) / d));
    const long k1 = static_cast<long>(std::ceil((hi.x() - grid.domain_min.x()) / d));
    const long l0 = static_cast<long>(std::floor((lo.y() - grid.domain_min.y()) / d));
    const long l1 = static_cast<long>(std::ceil((hi.y() - grid.domain_min.y()) / d));
    const double rho = scene.materials[mat].density;
    for (long l = l0; l < l1; ++l)
      for (long k = k0; k < k1; ++k) {
        const Vec2 x = grid.domain_min + d * Vec2(k + 0.5, l + 0.5);
        if (!body.shape.contains(x)) continue;
        particles.add(x, body.velocity, rho * d * d, d * d, body.temperature, static_cast<int>(b), mat);
      }
  }
}

}  // namespace mpmcut
