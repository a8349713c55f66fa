#pragma once
// The step's guards: the run stops the moment a particle carries a NaN, leaves the grid domain or
// sinks more than a cell into a rigid body, with a message that names step, time, particle, body
// and field.
#include <stdexcept>
#include <vector>

#include "contact/rigid_body.hpp"
#include "contact/rigid_contact.hpp"
#include "core/grid.hpp"
#include "core/particles.hpp"
#include "solver/scene.hpp"

namespace mpmcut {

// Thrown by the guards: carries the where.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws SimulationError for the first offending particle (deterministically).
void check_guards(const Particles& particles, const Grid& grid, const Scene& scene, const RigidContact& contact,
                  const std::vector<RigidBodyState>& bodies, long step, double time, bool parallel);

}  // namespace mpmcut
