#pragma once
// A single material point driven by a prescribed velocity gradient, without a grid: the
// constitutive-driver used by the verification tests (theory_materials.md §2-§6). Each step does what
// the solver does for one particle: F <- (I + L dt) F, V = det(F) V0, then Material::update.
// Optionally one component of L (L_yy) is solved for so that a stress condition holds
// (sigma_yy = 0, or a prescribed triaxiality), which gives mixed-control paths in plane strain.
#include <vector>

#include "physics/material.hpp"

namespace mpmcut {

// The state after a step (or the initial state) and the energies of that step. The particle's
// fields are the ParticleRow members (same names as the Particles arrays: stress, plastic_strain,
// damage, ...; velocity_gradient is the L applied in this step, after any control).
struct MaterialPointRecord : ParticleRow {
  long step = 0;
  double time = 0.0;                  // s
  double density = 0.0;               // mass / volume, kg/m^3
  ConstitutiveIncrement increment;    // this step's energies, J per m
  ConstitutiveIncrement cumulative;   // sums since the start, J per m
  double elastic_energy = 0.0;        // Material::elastic_energy after the step, J per m
};

class MaterialPointDriver {
 public:
  // One particle of volume V0 = 1 m^2 and mass density*V0 at temperature_K; cell_size_m is the
  // Hillerborg length passed in the StepContext. The material must outlive the driver.
  MaterialPointDriver(const Material& material, double temperature_K, double cell_size_m);

  // The particle (index 0), e.g. to preset a state before driving.
  Particles& particles() { return particles_; }
  const Particles& particles() const { return particles_; }

  // One step with the given L; returns the new state (a copy of history().back()).
  MaterialPointRecord step(const Mat2& L, double dt);
  // One step where L_yy is solved for so that sigma_yy = 0 (L_yy of the argument is the first guess).
  MaterialPointRecord step_free_yy(const Mat2& L, double dt);
  // One step where L_yy is solved for so that the triaxiality -p/q of the stress equals eta.
  MaterialPointRecord step_with_triaxiality(const Mat2& L, double dt, double eta);
  // n steps with a constant L; returns the whole history.
  const std::vector<MaterialPointRecord>& run(const Mat2& L, double dt, long steps);

  // history()[0] is the initial state, history()[k] the state after step k.
  // (References into the history are invalidated by the next step; the step functions return copies.)
  const std::vector<MaterialPointRecord>& history() const { return history_; }
  const MaterialPointRecord& last() const { return history_.back(); }

 private:
  template <class Residual>
  MaterialPointRecord step_controlled(const Mat2& L, double dt, Residual residual, double tolerance);
  // Advances a copy of the particle state; returns the increment.
  ConstitutiveIncrement advance(Particles& p, const Mat2& L, double dt) const;
  const MaterialPointRecord& record(const Mat2& L, double dt, const ConstitutiveIncrement& inc);

  const Material& material_;
  Particles particles_;
  double cell_size_;
  double controlled_lyy_ = 0.0;  // last solved L_yy, the next step's first guess
  bool have_controlled_lyy_ = false;
  std::vector<MaterialPointRecord> history_;
};

}  // namespace mpmcut
