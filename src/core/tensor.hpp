#pragma once
// Small fixed-size algebra used everywhere: 2D vectors and matrices (Eigen), and the
// plane-strain stress/strain tensor that keeps the out-of-plane zz component.
#include <Eigen/Dense>
#include <cmath>

namespace mpmcut {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

// Symmetric tensor in plane strain: in-plane xx, yy, xy plus the out-of-plane zz.
// The zz component matters: under plastic flow s_zz != 0 although eps_zz = 0, and the
// von Mises stress and triaxiality are wrong without it.
struct PlaneStrainTensor {
  double xx = 0.0;
  double yy = 0.0;
  double zz = 0.0;
  double xy = 0.0;

  double trace() const { return xx + yy + zz; }
  double mean() const { return trace() / 3.0; }
  // Deviatoric part: this minus mean()*I (all three diagonal terms change).
  PlaneStrainTensor deviator() const {
    const double m = mean();
    return {xx - m, yy - m, zz - m, xy};
  }
  // Full double contraction a:a (the xy term counts twice, for xy and yx).
  double contract(const PlaneStrainTensor& o) const {
    return xx * o.xx + yy * o.yy + zz * o.zz + 2.0 * xy * o.xy;
  }
  // von Mises equivalent value sqrt(3/2 s:s), for a stress.
  double von_mises() const {
    const PlaneStrainTensor s = deviator();
    return std::sqrt(1.5 * s.contract(s));
  }
  PlaneStrainTensor operator+(const PlaneStrainTensor& o) const {
    return {xx + o.xx, yy + o.yy, zz + o.zz, xy + o.xy};
  }
  PlaneStrainTensor operator-(const PlaneStrainTensor& o) const {
    return {xx - o.xx, yy - o.yy, zz - o.zz, xy - o.xy};
  }
  PlaneStrainTensor operator*(double a) const { return {a * xx, a * yy, a * zz, a * xy}; }
  PlaneStrainTensor& operator+=(const PlaneStrainTensor& o) {
    xx += o.xx; yy += o.yy; zz += o.zz; xy += o.xy;
    return *this;
  }
  // Adds a*I (e.g. -p*I for a pressure p).
  PlaneStrainTensor plus_identity(double a) const { return {xx + a, yy + a, zz + a, xy}; }
  Mat2 in_plane() const {
    Mat2 m;
    m << xx, xy, xy, yy;
    return m;
  }
  static PlaneStrainTensor from_in_plane(const Mat2& m, double zz) {
    return {m(0, 0), m(1, 1), zz, 0.5 * (m(0, 1) + m(1, 0))};
  }
};

inline PlaneStrainTensor operator*(double a, const PlaneStrainTensor& t) { return t * a; }

}  // namespace mpmcut
