#include "core/scene_specs.hpp"

#include <algorithm>
#include <cmath>

namespace mpmcut {

namespace {
// Even-odd rule: a point is inside a simple polygon if a ray crosses its edges an odd number of times.
bool polygon_contains(const Polygon& poly, const Vec2& x) {
  bool inside = false;
  const auto& v = poly.vertices;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    if ((v[i].y() > x.y()) != (v[j].y() > x.y())) {
      const double xc = v[j].x() + (x.y() - v[j].y()) * (v[i].x() - v[j].x()) / (v[i].y() - v[j].y());
      if (x.x() < xc) inside = !inside;
    }
  }
  return inside;
}
}  // namespace

bool Shape::contains(const Vec2& x) const {
  switch (kind) {
    case ShapeKind::Rectangle:
      return x.x() >= rectangle.min.x() && x.x() <= rectangle.max.x() && x.y() >= rectangle.min.y() &&
             x.y() <= rectangle.max.y();
    case ShapeKind::Disk:
      return (x - disk.center).squaredNorm() <= disk.radius * disk.radius;
    case ShapeKind::Polygon:
      return polygon_contains(polygon, x);
  }
  return false;
}

void Shape::bounds(Vec2& lo, Vec2& hi) const {
  switch (kind) {
    case ShapeKind::Rectangle:
      lo = rectangle.min;
      hi = rectangle.max;
      return;
    case ShapeKind::Disk:
      lo = disk.center - Vec2::Constant(disk.radius);
      hi = disk.center + Vec2::Constant(disk.radius);
      return;
    case ShapeKind::Polygon:
      lo = hi = polygon.vertices.empty() ? Vec2::Zero() : polygon.vertices.front();
      for (const auto& v : polygon.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
      return;
  }
}

}  // namespace mpmcut
