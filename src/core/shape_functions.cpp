#include "core/shape_functions.hpp"

#include <cmath>

namespace mpmcut {

ShapeFunction::ShapeFunction(ShapeFunctionKind kind, double cell_size, int particles_per_cell)
    : kind_(kind), h_(cell_size) {
  l_ = kind == ShapeFunctionKind::UGimp ? 0.5 / particles_per_cell : 0.0;
  lp_ = l_ * h_;
}

// Dimensionless forms with r = |xi|/h, l = lp/h (valid for l <= 1/2), from BK04 Eq. (40):
//   r < l:        S = 1 - (r^2 + l^2)/(2l)
//   l <= r < 1-l: S = 1 - r
//   1-l <= r < 1+l: S = (1 + l - r)^2 / (4l)
double ShapeFunction::weight_1d(double xi) const {
  const double r = std::abs(xi) / h_;
  if (kind_ == ShapeFunctionKind::Linear) return r < 1.0 ? 1.0 - r : 0.0;
  const double l = l_;
  if (r < l) return 1.0 - (r * r + l * l) / (2.0 * l);
  if (r < 1.0 - l) return 1.0 - r;
  if (r < 1.0 + l) {
    const double a = 1.0 + l - r;
    return a * a / (4.0 * l);
  }
  return 0.0;
}

double ShapeFunction::gradient_1d(double xi) const {
  const double r = std::abs(xi) / h_;
  const double sign = xi < 0.0 ? -1.0 : 1.0;
  if (kind_ == ShapeFunctionKind::Linear) return r < 1.0 ? -sign / h_ : 0.0;
  const double l = l_;
  if (r < l) return -(xi / h_) / (l * h_);
  if (r < 1.0 - l) return -sign / h_;
  if (r < 1.0 + l) return -sign * (1.0 + l - r) / (2.0 * l * h_);
  return 0.0;
}

}  // namespace mpmcut
