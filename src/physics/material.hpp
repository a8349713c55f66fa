#pragma once
// The material interface: something that turns a velocity gradient and a particle's state
// into a new stress and state. New models plug in by name through make_material().
#include <cstddef>
#include <memory>

#include "core/particles.hpp"
#include "physics/material_parameters.hpp"

namespace mpmcut {

// Energy increments of one particle over one step, J per m of thickness.
struct ConstitutiveIncrement {
  double plastic_work = 0.0;        // sigma_y * d(eps_p) * V
  double heat = 0.0;                // Taylor-Quinney part of the plastic work turned into heat
  double damage_dissipation = 0.0;  // energy released by damage softening
  double viscous_dissipation = 0.0; // work of the artificial bulk viscosity (>= 0)
};

// Everything a stress update needs besides the particle itself.
struct StepContext {
  double dt = 0.0;         // s
  double cell_size = 0.0;  // h, m: the Hillerborg characteristic length
  // Mass scaling factor f of the inertia (>= 1): the artificial bulk viscosity damps the scaled
  // dynamics, so it sees the scaled density f rho and wave speed c / sqrt(f).
  double inertia_factor = 1.0;  // -
};

class Material {
 public:
  // Throws std::invalid_argument when the parameters break a rule of their tables (require_valid).
  explicit Material(const MaterialParameters& params) : params_(params), p_wave_speed_(params.p_wave_speed()) {
    require_valid(params);
  }
  virtual ~Material() = default;
  const MaterialParameters& parameters() const { return params_; }

  // Advances stress and state of particle i over one step with velocity gradient L (1/s).
  // Called after the solver updated F and the volume. Must be thread-safe for distinct i.
  virtual ConstitutiveIncrement update(Particles& p, std::size_t i, const Mat2& L,
                                       const StepContext& ctx) const = 0;

  // Current P-wave speed of particle i for the CFL condition, m/s.
  virtual double wave_speed(const Particles& p, std::size_t i) const;

  // Recoverable elastic energy stored in particle i, J per m of thickness.
  virtual double elastic_energy(const Particles& p, std::size_t i) const;

 protected:
  MaterialParameters params_;
  double p_wave_speed_;  // elastic, m/s: cached, it is asked for every particle every step
};

// Builds the model named in params.model; throws std::invalid_argument if unknown.
std::unique_ptr<Material> make_material(const MaterialParameters& params);

// Jaumann co-rotational update of a stress: sigma + dt (W sigma - sigma W), with W = skew(L).
// zz is unchanged by an in-plane spin.
PlaneStrainTensor jaumann_rotate(const PlaneStrainTensor& sigma, const Mat2& L, double dt);

}  // namespace mpmcut
