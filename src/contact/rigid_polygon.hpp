#pragma once
// Exact geometry of a rigid body: a simple polygon with its signed distance and outward
// normal. Curved features (a cutting edge radius) are represented by fine arcs of vertices;
// the distance to that polygon is exact.
#include <vector>

#include "core/scene.hpp"
#include "core/tensor.hpp"

namespace mpmcut {

class RigidPolygon {
 public:
  RigidPolygon() = default;
  explicit RigidPolygon(const Polygon& outline);

  // Signed distance from x to the outline (m): negative inside, positive outside.
  // `normal` receives the unit outward normal at the closest boundary point.
  double signed_distance(const Vec2& x, Vec2& normal) const;
  bool inside(const Vec2& x) const;
  const Vec2& lower() const { return lo_; }
  const Vec2& upper() const { return hi_; }
  // Polygon area (m^2), positive.
  double area() const;
  const std::vector<Vec2>& vertices() const { return v_; }

 private:
  double signed_area_() const;  // > 0 for counter-clockwise vertices
  double area_sign_() const { return signed_area_() >= 0.0 ? 1.0 : -1.0; }
  std::vector<Vec2> v_;
  Vec2 lo_ = Vec2::Zero(), hi_ = Vec2::Zero();
};

}  // namespace mpmcut
