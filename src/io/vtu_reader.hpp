#pragma once
// Reads the particle snapshots that write_particles_vtu() wrote back into Particles, so that the
// analysis (analysis/chip_analysis.hpp, `mpmcut analyze`) also works on finished or old runs.
//
// This is a reader for OUR files, not a general VTK reader: it expects the layout of
// io/vtu_writer.cpp (UnstructuredGrid, LittleEndian, header_type UInt64, one raw <AppendedData>
// block, the arrays of vtu_point_fields()). Anything else (another writer, compression, base64,
// a truncated or corrupt file, a missing array) is a std::runtime_error naming the file and
// what was wrong.
//
// What comes back: every field flagged kVtuRead in core/particle_fields.hpp, from its array
// (io/vtu_field_layout.hpp), bit-exact; a kVtuOptional one that an older snapshot lacks reads as
// its initial value. Not stored in the file, so reconstructed:
//   deformation_gradient = sqrt(J) I (only J = det F is stored; det F round-trips, F itself does not)
//   initial_volume = volume / J;  the other fields without kVtuRead: their initial value.
// Derived arrays (von_mises_stress_Pa, pressure_Pa, density_kg_per_m3) are not read.
#include <filesystem>

#include "core/particles.hpp"

namespace mpmcut {

struct VtuSnapshot {
  Particles particles;
  double time_s = 0.0;  // FieldData TimeValue
};

VtuSnapshot read_particles_vtu(const std::filesystem::path& file);

}  // namespace mpmcut
