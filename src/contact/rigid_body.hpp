#pragma once
// A rigid body's motion and the force the deformable bodies exert on it through contact.
#include <string>
#include <vector>

#include "core/tensor.hpp"

namespace mpmcut {

struct RigidBodyState {
  std::string name;
  Vec2 velocity = Vec2::Zero();      // m/s (prescribed)
  Vec2 displacement = Vec2::Zero();  // m since t = 0
  Vec2 force = Vec2::Zero();         // N per m of thickness, on the rigid body, last step
  Vec2 impulse = Vec2::Zero();       // N s per m, accumulated
  Vec2 step_impulse = Vec2::Zero();  // N s per m, this step (both contact passes and the safeguard)
  double work = 0.0;                 // J per m: work done BY the rigid body on the material
  // A conducting body's temperature per cell (solver/rigid_body_heat), K, and for a steady one the heat input per
  // cell averaged over its heat_averaging_time, W/m; empty for the others.
  std::vector<double> temperature_field;
  std::vector<double> heat_input_average;
};

}  // namespace mpmcut
