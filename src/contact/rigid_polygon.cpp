#include "contact/rigid_polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mpmcut {

RigidPolygon::RigidPolygon(const Polygon& outline, double rounding_radius)
    : v_(outline.vertices), radius_(rounding_radius) {
  if (v_.empty()) return;
  lo_ = hi_ = v_.front();
  for (const auto& p : v_) {
    lo_ = lo_.cwiseMin(p);
    hi_ = hi_.cwiseMax(p);
  }
  lo_ -= Vec2::Constant(radius_);
  hi_ += Vec2::Constant(radius_);
}

bool RigidPolygon::inside(const Vec2& x) const {
  if (radius_ > 0.0) {
    Vec2 n;
    return signed_distance(x, n) < 0.0;
  }
  return inside_core(x);
}

bool RigidPolygon::inside_core(const Vec2& x) const {
  bool in = false;
  for (std::size_t i = 0, j = v_.size() - 1; i < v_.size(); j = i++) {
    if ((v_[i].y() > x.y()) != (v_[j].y() > x.y())) {
      const double xc = v_[j].x() + (x.y() - v_[j].y()) * (v_[i].x() - v_[j].x()) / (v_[i].y() - v_[j].y());
      if (x.x() < xc) in = !in;
    }
  }
  return in;
}

double RigidPolygon::signed_distance(const Vec2& x, Vec2& normal) const {
  return polygon_distance(x, normal) - radius_;
}

double RigidPolygon::polygon_distance(const Vec2& x, Vec2& normal) const {
  double best = std::numeric_limits<double>::max();
  Vec2 closest = x;
  for (std::size_t i = 0, j = v_.size() - 1; i < v_.size(); j = i++) {
    const Vec2 a = v_[j], b = v_[i];
    const Vec2 ab = b - a;
    const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    const Vec2 c = a + t * ab;
    const double d2 = (x - c).squaredNorm();
    if (d2 < best) {
      best = d2;
      closest = c;
    }
  }
  const double d = std::sqrt(best);
  const bool in = inside_core(x);
  Vec2 dir = x - closest;
  if (d > 1e-14 * (hi_ - lo_).norm()) {
    normal = (in ? -dir : dir) / d;
  } else {
    // On the boundary: fall back to the normal of the nearest edge (outward).
    normal = Vec2::Zero();
    for (std::size_t i = 0, j = v_.size() - 1; i < v_.size(); j = i++) {
      const Vec2 ab = v_[i] - v_[j];
      const double t = std::clamp((x - v_[j]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      if ((x - (v_[j] + t * ab)).squaredNorm() <= best * (1 + 1e-12) + 1e-300) {
        Vec2 n(ab.y(), -ab.x());
        normal += n.normalized();
      }
    }
    const double s = area_sign_();
    normal = (s * normal).normalized();
  }
  return in ? -d : d;
}

double RigidPolygon::signed_area_() const {
  double a = 0.0;
  for (std::size_t i = 0, j = v_.size() - 1; i < v_.size(); j = i++)
    a += v_[j].x() * v_[i].y() - v_[i].x() * v_[j].y();
  return 0.5 * a;
}

double RigidPolygon::area() const { return std::abs(signed_area_()); }

}  // namespace mpmcut
