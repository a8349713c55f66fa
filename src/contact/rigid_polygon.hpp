#pragma once
// Exact geometry of a rigid body: a simple polygon grown by a rounding radius r (the set of
// points within r of the polygon), with its signed distance and outward normal. The distance
// to the grown shape is the polygon's distance minus r, so a rounded cutting edge is exact.
#include <vector>

#include "core/scene_specs.hpp"
#include "core/tensor.hpp"

namespace mpmcut {

class RigidPolygon {
 public:
  RigidPolygon() = default;
  explicit RigidPolygon(const Polygon& outline, double rounding_radius = 0.0);

  // Signed distance from x to the outline (m): negative inside, positive outside.
  // `normal` receives the unit outward normal at the closest boundary point.
  double signed_distance(const Vec2& x, Vec2& normal) const;
  bool inside(const Vec2& x) const;
  double rounding_radius() const { return radius_; }
  const Vec2& lower() const { return lo_; }
  const Vec2& upper() const { return hi_; }
  // Area of the core polygon (m^2), positive.
  double area() const;
  const std::vector<Vec2>& vertices() const { return v_; }

 private:
  double signed_area_() const;  // > 0 for counter-clockwise vertices
  double area_sign_() const { return signed_area_() >= 0.0 ? 1.0 : -1.0; }
  double polygon_distance(const Vec2& x, Vec2& normal) const;  // to the core polygon
  bool inside_core(const Vec2& x) const;
  std::vector<Vec2> v_;
  double radius_ = 0.0;
  Vec2 lo_ = Vec2::Zero(), hi_ = Vec2::Zero();
};

}  // namespace mpmcut
