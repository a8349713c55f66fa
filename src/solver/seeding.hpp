#pragma once
// The particles a scene starts with.
#include <cmath>
#include <limits>

#include "core/grid.hpp"
#include "core/particles.hpp"
#include "solver/scene.hpp"

namespace mpmcut {

// Fills each body with particles on a regular sub-grid aligned with the background grid:
// particles_per_cell per direction per cell, each owning a square of side h/ppc (its uGIMP
// domain), at the body's velocity and temperature. Throws std::invalid_argument for a body whose
// material the scene does not have.
void seed_particles(const Scene& scene, const Grid& grid, Particles& particles);

// Calls visit(x) for each position where seed_particles puts a particle of `body`, restricted to the box
// [lo, hi], until visit returns false; with `stride` > 1 only every stride-th point in each direction. `domain_min`
// and `cell_size` are the grid's. For the checks of a scene before it is run (a body that gets no particle, bodies
// that overlap at the start), so they see exactly the seeded points.
template <class Visit>
void for_each_seed_point(const BodySpec& body, const Vec2& domain_min, double cell_size, const Vec2& lo,
                         const Vec2& hi, Visit visit, long stride = 1);

// The same over the whole body.
template <class Visit>
void for_each_seed_point(const BodySpec& body, const Vec2& domain_min, double cell_size, Visit visit) {
  const Vec2 everywhere = Vec2::Constant(std::numeric_limits<double>::infinity());
  for_each_seed_point(body, domain_min, cell_size, -everywhere, everywhere, visit);
}

// How many sub-grid points of `body` its bounding box, cut to [lo, hi], spans (what for_each_seed_point visits
// at stride 1, at most): a check can bound its cost before it starts.
double seed_points_in_box(const BodySpec& body, double cell_size, const Vec2& lo, const Vec2& hi);
// The same over the whole body's bounding box.
inline double seed_points_in_box(const BodySpec& body, double cell_size) {
  const Vec2 everywhere = Vec2::Constant(std::numeric_limits<double>::infinity());
  return seed_points_in_box(body, cell_size, -everywhere, everywhere);
}

template <class Visit>
void for_each_seed_point(const BodySpec& body, const Vec2& domain_min, double cell_size, const Vec2& lo,
                         const Vec2& hi, Visit visit, long stride) {
  const double d = cell_size / body.particles_per_cell;
  Vec2 body_lo, body_hi;
  body.shape.bounds(body_lo, body_hi);
  const Vec2 from = body_lo.cwiseMax(lo), to = body_hi.cwiseMin(hi);
  if ((from.array() > to.array()).any()) return;
  const long k0 = static_cast<long>(std::floor((from.x() - domain_min.x()) / d));
  const long k1 = static_cast<long>(std::ceil((to.x() - domain_min.x()) / d));
  const long l0 = static_cast<long>(std::floor((from.y() - domain_min.y()) / d));
  const long l1 = static_cast<long>(std::ceil((to.y() - domain_min.y()) / d));
  for (long l = l0; l < l1; l += stride)
    for (long k = k0; k < k1; k += stride) {
      const Vec2 x = domain_min + d * Vec2(k + 0.5, l + 0.5);
      if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any() || !body.shape.contains(x)) continue;
      if (!visit(x)) return;
    }
}

}  // namespace mpmcut
