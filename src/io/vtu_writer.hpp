#pragma once
// Particle snapshots as VTK XML UnstructuredGrid (.vtu) files for ParaView and meshio.
//
// One VTK_VERTEX cell per particle; points are (x, y, 0) in m. Arrays are stored as raw
// little-endian binary in one <AppendedData> block (header_type UInt64), which is several
// times faster to write and read than ASCII and needs no base64 pass. The file is written
// to a temporary and renamed, so a snapshot on disk is always complete.
//
// The point data are every particle field flagged kVtu in core/particle_fields.hpp, named
// <name>_<unit> (io/vtu_field_layout.hpp), then a few derived arrays (von Mises stress, pressure,
// density, det F); see vtu_point_fields(). Names without a unit suffix are dimensionless. Tensors
// use VTK's component order: a symmetric tensor has 6 components xx yy zz xy yz xz, a full tensor
// 9 components in row-major order.
// FieldData holds the snapshot time twice: "TimeValue" (the name ParaView looks for, in s)
// and "time_s".
#include <filesystem>
#include <string>
#include <vector>

#include "core/particles.hpp"

namespace mpmcut {

struct VtuFieldInfo {
  std::string name;     // array name, unit included
  int components;       // 1 scalar, 3 vector, 6 symmetric tensor, 9 full tensor
  bool integer;         // Int32 (ids) rather than Float64
  std::string meaning;  // one line for docs/outputs.md and --help texts
};

// The point-data arrays every snapshot contains, in file order.
const std::vector<VtuFieldInfo>& vtu_point_fields();

// Writes all particles of `p` to `file` (atomically); `time_s` goes into FieldData.
void write_particles_vtu(const Particles& p, const std::filesystem::path& file, double time_s);

}  // namespace mpmcut
