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
// domain), at the body's velocity and temperature. A body with a lattice_angle_deg has the sub-grid turned by that
// angle about its lattice_origin (the grid's min corner by default): the particles sit at the centres of the turned
// squares, each with the square's volume; their uGIMP domains stay grid-aligned squares of the same area. Throws
// std::invalid_argument for a body whose material the scene does not have.
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

// How many sub-grid points of `body` its bounding box, cut to [lo, hi], spans (about what for_each_seed_point visits
// at stride 1; on a turned lattice the box's extent along the lattice's axes): a check can bound its cost before it
// starts.
double seed_points_in_box(const BodySpec& body, double cell_size, const Vec2& lo, const Vec2& hi);
// The same over the whole body's bounding box.
inline double seed_points_in_box(const BodySpec& body, double cell_size) {
  const Vec2 everywhere = Vec2::Constant(std::numeric_limits<double>::infinity());
  return seed_points_in_box(body, cell_size, -everywhere, everywhere);
}

// The lattice a body's particles are seeded on: squares of side `spacing`, turned by the body's lattice angle
// about its origin. Lattice coordinates (k, l) count squares along the turned axes; a particle sits at (k + ½, l + ½).
// Unturned, the positions are exactly origin + spacing (k + ½, l + ½).
struct SeedLattice {
  Vec2 origin;
  double spacing, cos_angle, sin_angle;
  SeedLattice(const BodySpec& body, const Vec2& domain_min, double cell_size)
      : origin(body.lattice_origin.value_or(domain_min)), spacing(cell_size / body.particles_per_cell) {
    const double turn = body.lattice_angle_deg * (std::acos(-1.0) / 180.0);
    cos_angle = std::cos(turn);  // exactly 1 and 0 unturned
    sin_angle = std::sin(turn);
  }
  Vec2 position(double k, double l) const {
    return origin + spacing * Vec2(cos_angle * k - sin_angle * l, sin_angle * k + cos_angle * l);
  }
  Vec2 coordinates(const Vec2& x) const {
    const Vec2 r = x - origin;
    return Vec2(cos_angle * r.x() + sin_angle * r.y(), -sin_angle * r.x() + cos_angle * r.y()) / spacing;
  }
};

template <class Visit>
void for_each_seed_point(const BodySpec& body, const Vec2& domain_min, double cell_size, const Vec2& lo,
                         const Vec2& hi, Visit visit, long stride) {
  const SeedLattice lattice(body, domain_min, cell_size);
  Vec2 body_lo, body_hi;
  body.shape.bounds(body_lo, body_hi);
  const Vec2 from = body_lo.cwiseMax(lo), to = body_hi.cwiseMin(hi);
  if ((from.array() > to.array()).any()) return;
  // The lattice squares that can hold a point of the box: the box's corners in lattice coordinates, bounded.
  Vec2 c_lo = Vec2::Constant(std::numeric_limits<double>::infinity()), c_hi = -c_lo;
  for (const Vec2& corner : {from, to, Vec2(from.x(), to.y()), Vec2(to.x(), from.y())}) {
    const Vec2 c = lattice.coordinates(corner);
    c_lo = c_lo.cwiseMin(c);
    c_hi = c_hi.cwiseMax(c);
  }
  const long k0 = static_cast<long>(std::floor(c_lo.x())), k1 = static_cast<long>(std::ceil(c_hi.x()));
  const long l0 = static_cast<long>(std::floor(c_lo.y())), l1 = static_cast<long>(std::ceil(c_hi.y()));
  for (long l = l0; l < l1; l += stride)
    for (long k = k0; k < k1; k += stride) {
      const Vec2 x = lattice.position(k + 0.5, l + 0.5);
      if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any() || !body.shape.contains(x)) continue;
      if (!visit(x)) return;
    }
}

}  // namespace mpmcut
