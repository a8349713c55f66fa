#pragma once
// The particles near a rigid body, with their signed distance from its outline: what particle-based
// contact detection, gap detection and heat transfer to rigid bodies look at.
#include <span>

#include "contact/rigid_polygon.hpp"
#include "core/grid.hpp"
#include "core/particles.hpp"
#include "core/shape_functions.hpp"

namespace mpmcut {

// Calls visit(p, x, shape, d, normal) for each particle p within two cells of the rigid body's bounding box,
// with its signed distance d from the body's outline (shifted by `shift`) and the outward normal there.
template <class Visit>
void for_each_particle_near(const Particles& P, const Grid& G, std::span<const ShapeFunction> body_shapes,
                            const RigidPolygon& geom, const Vec2& shift, Visit&& visit) {
  const Vec2 lo = geom.lower() + shift - Vec2::Constant(2.0 * G.h), hi = geom.upper() + shift + Vec2::Constant(2.0 * G.h);
  for (std::size_t p = 0; p < P.size(); ++p) {
    const Vec2 x = P.position[p];
    if (x.x() < lo.x() || x.x() > hi.x() || x.y() < lo.y() || x.y() > hi.y()) continue;
    Vec2 normal;
    const double d = geom.signed_distance(x - shift, normal);
    visit(p, x, body_shapes[P.body[p]], d, normal);
  }
}

}  // namespace mpmcut
