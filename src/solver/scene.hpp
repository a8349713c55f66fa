#pragma once
// The scene: plain data that fully describes a run. Parsing (TOML) produces it, the cutting preset
// produces it, the solver consumes it. The solver never sees TOML, nor the cutting process a scene
// may stand for (cutting/case.hpp pairs the two).
// All quantities SI unless the name says otherwise.
#include <optional>
#include <string>
#include <vector>

#include "core/scene_specs.hpp"
#include "physics/material_parameters.hpp"

namespace mpmcut {

struct Scene {
  std::string title;
  std::string source_file;  // where it came from, for messages
  GridSpec grid;
  BoundarySpec boundaries;
  ThermalSpec thermal;
  SolverSpec solver;
  OutputSpec output;
  Vec2 body_force = Vec2::Zero();  // gravity-like acceleration, m/s^2
  std::vector<MaterialParameters> materials;
  std::vector<BodySpec> bodies;
  std::vector<RigidBodySpec> rigid_bodies;

  // Index of the material called `name`, or -1.
  int material_index(const std::string& name) const;

  bool operator==(const Scene&) const = default;  // field-wise, for round-trip tests
};

}  // namespace mpmcut
