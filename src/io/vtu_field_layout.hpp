#pragma once
// How a particle field (core/particle_fields.hpp) appears in a VTU snapshot: its array name and
// VTK's components for each kind of value, and the way back. Shared by io/vtu_writer.cpp and
// io/vtu_reader.cpp so that what one writes the other reads bit-exactly.
//
// VTK has no 2D types: a vector gets z = 0 (3 components), a 2x2 tensor becomes the row-major 3x3
// (9), the plane-strain tensor the symmetric 6 in VTK's order xx yy zz xy yz xz with yz = xz = 0.
// Ids are Int32 with one component; everything else is Float64.
#include <cstdint>
#include <string>

#include "core/particles.hpp"

namespace mpmcut {

constexpr int vtu_components(FieldKind kind) {
  switch (kind) {
    case FieldKind::scalar: return 1;
    case FieldKind::vector2: return 3;
    case FieldKind::tensor2x2: return 9;
    case FieldKind::plane_strain_tensor: return 6;
    case FieldKind::integer_id: return 1;
  }
  return 1;
}

// The array of a field in a snapshot: the position is the geometry (Points), every other field
// is point data named with its unit.
inline std::string vtu_array_name(const ParticleFieldInfo& field) {
  return field.name == "position" ? std::string("Points") : field.output_name();
}

// Written as point data (the position is written as the Points instead).
inline bool vtu_point_data(const ParticleFieldInfo& field) {
  return field.has(kVtu) && field.name != "position";
}

inline void to_vtk(double v, double* out) { out[0] = v; }
inline void to_vtk(const Vec2& v, double* out) {
  out[0] = v.x(); out[1] = v.y(); out[2] = 0.0;
}
inline void to_vtk(const Mat2& m, double* out) {
  out[0] = m(0, 0); out[1] = m(0, 1); out[2] = 0.0;
  out[3] = m(1, 0); out[4] = m(1, 1); out[5] = 0.0;
  out[6] = 0.0;     out[7] = 0.0;     out[8] = 0.0;
}
inline void to_vtk(const PlaneStrainTensor& t, double* out) {
  out[0] = t.xx; out[1] = t.yy; out[2] = t.zz; out[3] = t.xy; out[4] = 0.0; out[5] = 0.0;
}

inline void from_vtk(const double* in, double& v) { v = in[0]; }
inline void from_vtk(const double* in, Vec2& v) { v = Vec2(in[0], in[1]); }
inline void from_vtk(const double* in, Mat2& m) { m << in[0], in[1], in[3], in[4]; }
inline void from_vtk(const double* in, PlaneStrainTensor& t) { t = {in[0], in[1], in[2], in[3]}; }

}  // namespace mpmcut
