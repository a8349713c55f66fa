#pragma once
// The particle fields, each declared once. Everything that handles "all the fields" comes from
// this list: the Particles arrays and ParticleRow (core/particles.hpp), add/resize/permute, the
// checkpoint's particle section (io/checkpoint.cpp), the VTU writer and reader (io/vtu_*.cpp) and
// the material-point record (physics/material_point_driver.hpp). Adding a field is one entry here
// plus its physics; README.md, "Adding a particle field", walks through it.
//
// It is an X-macro because C++ has no reflection: one entry must become both a named member
// (P.temperature[p], so hot loops stay plain array loops) and a name string for the files.
#include <cstdint>

#include "core/tensor.hpp"

namespace mpmcut {

// Where a field goes besides memory (the flags column).
inline constexpr unsigned kCheckpoint = 1u << 0;   // in restart files; a restart is bit-identical only
                                                   // if everything the step reads is checkpointed
inline constexpr unsigned kVtu = 1u << 1;          // in VTU snapshots as <name>_<unit> (position: the Points)
inline constexpr unsigned kVtuRead = 1u << 2;      // read back from snapshots (`mpmcut analyze`); needs kVtu
inline constexpr unsigned kVtuOptional = 1u << 3;  // snapshots from before the field existed lack it:
                                                   // it reads as its initial value there

// One entry per field: X(type, name, unit, initial, flags, meaning)
//   type     double, Vec2, Mat2, PlaneStrainTensor or std::int32_t (ids); the kind follows from it
//   name     the member name, also the checkpoint section particles.<name>
//   unit     as written in output names (m_per_s, J_per_m2; "" dimensionless, "id" an index): the VTU
//            array is <name>_<unit>
//   initial  the value of a new particle where Particles::add() does not set it
//   meaning  one line for the documentation
// Storage is per m of thickness (2D plane strain).
// clang-format off
#define MPMCUT_PARTICLE_FIELDS(X)                                                                                     \
  /* Kinematics */                                                                                                    \
  X(Vec2, position, "m", Vec2::Zero(), kCheckpoint | kVtu | kVtuRead, "position (the Points of a VTU snapshot)")    \
  X(Vec2, velocity, "m_per_s", Vec2::Zero(), kCheckpoint | kVtu | kVtuRead, "velocity")                             \
  X(Mat2, velocity_gradient, "per_s", Mat2::Zero(), kCheckpoint | kVtu | kVtuRead,                                  \
    "velocity gradient L = grad v of the last step, L_ij = dv_i/dx_j")                                                \
  X(Mat2, deformation_gradient, "", Mat2::Identity(), kCheckpoint,                                                    \
    "deformation gradient F, in-plane (F_zz = 1); snapshots hold J = V/V0 = det F")                                   \
  /* Mass and volume */                                                                                               \
  X(double, mass, "kg_per_m", 0.0, kCheckpoint | kVtu | kVtuRead, "mass per m of thickness")                          \
  X(double, volume, "m3_per_m", 0.0, kCheckpoint | kVtu | kVtuRead, "current volume per m of thickness (an area)")    \
  X(double, initial_volume, "m3_per_m", 0.0, kCheckpoint, "volume at the start, per m of thickness")                  \
  /* Stress: `stress` (damage applied) gives the internal force; the return mapping works on the undamaged one */    \
  X(PlaneStrainTensor, stress, "Pa", PlaneStrainTensor{}, kCheckpoint | kVtu | kVtuRead,                              \
    "Cauchy stress with damage applied")                                                                              \
  X(PlaneStrainTensor, effective_stress, "Pa", PlaneStrainTensor{}, kCheckpoint | kVtu | kVtuRead,                    \
    "undamaged stress of the return mapping")                                                                         \
  /* Constitutive state (fields a material does not use stay at their initial value) */                              \
  X(double, plastic_strain, "", 0.0, kCheckpoint | kVtu | kVtuRead, "equivalent plastic strain")                      \
  X(double, plastic_strain_rate, "per_s", 0.0, kCheckpoint | kVtu | kVtuRead,                                         \
    "smoothed equivalent plastic strain rate")                                                                        \
  X(double, temperature, "K", 0.0, kCheckpoint | kVtu | kVtuRead, "temperature")                                      \
  X(double, damage_initiation, "", 0.0, kCheckpoint | kVtu | kVtuRead,                                                \
    "Johnson-Cook initiation indicator omega (>= 1: initiated)")                                                      \
  X(double, damage, "", 0.0, kCheckpoint | kVtu | kVtuRead, "damage D in [0, 1]")                                     \
  X(double, plastic_displacement, "m", 0.0, kCheckpoint | kVtu | kVtuRead,                                            \
    "plastic displacement u_pl after damage initiation")                                                              \
  X(double, initiation_yield_stress, "Pa", 0.0, kCheckpoint, "yield stress sigma_y0 at damage initiation")            \
  X(double, fracture_energy, "J_per_m2", 0.0, kCheckpoint | kVtu | kVtuRead,                                          \
    "fracture energy G_f, fixed at damage initiation (rate-dependent; 0 before)")                                     \
  X(double, damage_dissipation, "J_per_m", 0.0, kCheckpoint | kVtu | kVtuRead | kVtuOptional,                         \
    "damage dissipation since the start, per m of thickness; divided by G_f the crack length it stands for")          \
  X(double, crack_opening, "", 0.0, kCheckpoint | kVtu | kVtuRead | kVtuOptional,                                    \
    "volumetric (log) strain of the open crack in the particle: the gap that compression closes at zero pressure")   \
  X(double, crack_opening_max, "", 0.0, kCheckpoint,                                                                  \
    "largest crack_opening so far: a closed gap reopens at zero stress up to it")                                     \
  /* Contact */                                                                                                       \
  X(Vec2, contact_friction_force, "N_per_m", Vec2::Zero(), kCheckpoint,                                               \
    "penalty contact: the friction force on the particle in its last step in contact (zero out of contact)")         \
  /* Identity */                                                                                                      \
  X(std::int32_t, body, "id", 0, kCheckpoint | kVtu | kVtuRead, "index of the body in the scene")                     \
  X(std::int32_t, material, "id", 0, kCheckpoint | kVtu | kVtuRead, "index of the material")
// clang-format on

}  // namespace mpmcut
