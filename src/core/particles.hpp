#pragma once
// Material points as a structure of arrays: one std::vector per field, accessed by name
// (p.velocity[i]), so the hot loops are plain array loops and the code says what it touches.
// The fields are declared in core/particle_fields.hpp; this file turns that list into the arrays,
// a one-particle record with the same member names, and a loop over the fields for everything
// that handles all of them (add, resize, permute, checkpoint, VTU).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/particle_fields.hpp"
#include "core/tensor.hpp"

namespace mpmcut {

// What one particle holds in a field; follows from the field's type.
enum class FieldKind {
  scalar,               // double
  vector2,              // Vec2
  tensor2x2,            // Mat2
  plane_strain_tensor,  // PlaneStrainTensor: symmetric, xx yy zz xy
  integer_id,           // std::int32_t
};

template <class T>
constexpr FieldKind field_kind_of();
template <> constexpr FieldKind field_kind_of<double>() { return FieldKind::scalar; }
template <> constexpr FieldKind field_kind_of<Vec2>() { return FieldKind::vector2; }
template <> constexpr FieldKind field_kind_of<Mat2>() { return FieldKind::tensor2x2; }
template <> constexpr FieldKind field_kind_of<PlaneStrainTensor>() { return FieldKind::plane_strain_tensor; }
template <> constexpr FieldKind field_kind_of<std::int32_t>() { return FieldKind::integer_id; }

// One entry of MPMCUT_PARTICLE_FIELDS, without its type.
struct ParticleFieldInfo {
  std::string_view name;     // member name; checkpoint section particles.<name>
  std::string_view unit;     // as in output names; "" dimensionless, "id" an index
  unsigned flags = 0;        // kCheckpoint, kVtu, kVtuRead, kVtuOptional
  std::string_view meaning;  // one line for the documentation
  FieldKind kind = FieldKind::scalar;

  bool has(unsigned flag) const { return (flags & flag) == flag; }
  // The name with its unit, as output files show it: temperature_K, plastic_strain, body_id.
  std::string output_name() const {
    std::string s(name);
    if (!unit.empty()) s.append("_").append(unit);
    return s;
  }
};

// One particle: a member of each field, same names as Particles, at the field's initial value.
struct ParticleRow {
#define MPMCUT_ROW_MEMBER(type, name, unit, initial, flags, meaning) type name = initial;
  MPMCUT_PARTICLE_FIELDS(MPMCUT_ROW_MEMBER)
#undef MPMCUT_ROW_MEMBER
};

struct Particles {
#define MPMCUT_ARRAY_MEMBER(type, name, unit, initial, flags, meaning) std::vector<type> name;
  MPMCUT_PARTICLE_FIELDS(MPMCUT_ARRAY_MEMBER)
#undef MPMCUT_ARRAY_MEMBER

  std::size_t size() const { return position.size(); }

  // Appends one particle at rest with zero stress; every array grows by one.
  std::size_t add(const Vec2& x, const Vec2& v, double mass_kg, double volume_m2,
                  double temperature_K, int body_id, int material_id);
  // Appends one particle with the values of `row`.
  std::size_t add(const ParticleRow& row);
  // Sets every array to n entries; new ones take their field's initial value.
  void resize(std::size_t n);
  // Reorders every array by `order` (new index k takes old index order[k]); an order shorter than
  // size() also drops the particles it does not name.
  void permute(const std::vector<std::size_t>& order);

  // Particle i as one record, and back.
  ParticleRow row(std::size_t i) const;
  void set_row(std::size_t i, const ParticleRow& row);
};

// A field with its type: `array` and `value` select it in Particles and in ParticleRow.
template <class T>
struct ParticleField {
  using value_type = T;
  ParticleFieldInfo info;
  std::vector<T> Particles::*array;
  T ParticleRow::*value;
};

// Calls fn(const ParticleField<T>&) for every field, in the order of MPMCUT_PARTICLE_FIELDS.
template <class Fn>
void for_each_particle_field(Fn&& fn) {
#define MPMCUT_VISIT_FIELD(type, name, unit, initial, flags, meaning) \
  fn(ParticleField<type>{{#name, unit, flags, meaning, field_kind_of<type>()}, &Particles::name, &ParticleRow::name});
  MPMCUT_PARTICLE_FIELDS(MPMCUT_VISIT_FIELD)
#undef MPMCUT_VISIT_FIELD
}

// One step of the particle's motion, velocity gradient L over dt: F <- (I + dt L) F, and the volume V <- det(I + dt L) V
// from the step's own volume change rather than det F V0. Where the flow keeps stretching a particle (a failed one
// drawn along the tool's edge), F's entries grow to ~1e7 and det F, a difference of two products of that size, loses
// every digit: J came out in steps of 0.25, then 0, with density and pressure infinite. det(I + dt L) is near 1 and
// exact to rounding; the two agree in exact arithmetic (det of a product).
void advance_deformation(Particles& particles, std::size_t i, const Mat2& L, double dt);

// The fields as a list (docs, tests, messages).
const std::vector<ParticleFieldInfo>& particle_field_infos();

// A member added to Particles by hand instead of through MPMCUT_PARTICLE_FIELDS would be missed by
// every loop over the fields (not sorted, not checkpointed): refuse it.
#define MPMCUT_COUNT_FIELD(type, name, unit, initial, flags, meaning) +1
inline constexpr std::size_t kParticleFieldCount = 0 MPMCUT_PARTICLE_FIELDS(MPMCUT_COUNT_FIELD);
#undef MPMCUT_COUNT_FIELD
static_assert(sizeof(Particles) == kParticleFieldCount * sizeof(std::vector<double>),
              "Particles has a member that is not in MPMCUT_PARTICLE_FIELDS (core/particle_fields.hpp)");

}  // namespace mpmcut
