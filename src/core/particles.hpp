#pragma once
// Material points as a structure of arrays: one std::vector per field, accessed by name
// (p.velocity[i]), so the hot loops are plain array loops and the code says what it touches.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/tensor.hpp"

namespace mpmcut {

struct Particles {
  // Kinematics
  std::vector<Vec2> position;          // m
  std::vector<Vec2> velocity;          // m/s
  std::vector<Mat2> velocity_gradient; // 1/s, L = grad v of the last step
  std::vector<Mat2> deformation_gradient;  // F, in-plane (F_zz = 1 in plane strain)
  // Mass and volume
  std::vector<double> mass;            // kg per m of thickness
  std::vector<double> volume;          // m^2 (per m of thickness), current
  std::vector<double> initial_volume;  // m^2
  // Stress: `stress` is the Cauchy stress used for the internal force (damage applied);
  // `effective_stress` is the undamaged stress the return mapping works on.
  std::vector<PlaneStrainTensor> stress;            // Pa
  std::vector<PlaneStrainTensor> effective_stress;  // Pa
  // Constitutive state (unused fields stay zero for models that do not need them)
  std::vector<double> plastic_strain;       // equivalent plastic strain, -
  std::vector<double> plastic_strain_rate;  // smoothed equivalent plastic strain rate, 1/s
  std::vector<double> temperature;          // K
  std::vector<double> damage_initiation;    // omega, JC initiation indicator (>= 1: initiated), -
  std::vector<double> damage;               // D in [0, 1], -
  std::vector<double> plastic_displacement; // u_pl after initiation, m
  std::vector<double> initiation_yield_stress;  // sigma_y0 at initiation, Pa
  std::vector<double> fracture_energy;          // G_f fixed at initiation (rate-dependent), J/m^2
  // Damage dissipation of this particle since the start, J per m of thickness: divided by its
  // fracture_energy it is the crack length (per m of thickness) its softening stands for.
  std::vector<double> damage_dissipation;
  // Identity
  std::vector<std::int32_t> body;      // index into Scene::bodies
  std::vector<std::int32_t> material;  // index into the material list

  std::size_t size() const { return position.size(); }

  // Appends one particle at rest with zero stress; every array grows by one.
  std::size_t add(const Vec2& x, const Vec2& v, double mass_kg, double volume_m2,
                  double temperature_K, int body_id, int material_id);

  // Reorders every array by `order` (new index k takes old index order[k]).
  void permute(const std::vector<std::size_t>& order);
};

}  // namespace mpmcut
