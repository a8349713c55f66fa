#pragma once
// Everything besides the particle arrays that the next step depends on: with the particles it is
// what a checkpoint holds of the simulation (io/checkpoint.hpp), so that a restored run continues
// bit-identically. Plain data; Simulation::restart_state() and Simulation::restore().
#include <vector>

#include "contact/rigid_body.hpp"
#include "core/energy_totals.hpp"
#include "thermal/heat_conduction.hpp"

namespace mpmcut {

struct RestartState {
  double time = 0.0;     // s
  long step = 0;         // steps taken (the particle sort runs every 20, keyed on it)
  double last_dt = 0.0;  // s
  std::vector<RigidBodyState> rigid_bodies;  // in the scene's order
  EnergyTotals energy;
  long removed_particles = 0;  // left the domain (solver.remove_escaping_particles)
  double removed_mass = 0.0;   // kg per m
  ConductionSubcycle conduction;
};

}  // namespace mpmcut
