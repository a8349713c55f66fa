#include "solver/model_version.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace mpmcut {

namespace {

bool penalty_contact_with_friction(const Scene& s) {
  return s.solver.contact_detection == ContactDetection::Penalty &&
         std::any_of(s.rigid_bodies.begin(), s.rigid_bodies.end(), [](const RigidBodySpec& r) { return r.friction > 0; });
}

}  // namespace

const std::vector<ModelChange>& model_changes() {
  static const std::vector<ModelChange> changes{
      {1, "08f9ca5",
       "penalty contact: the friction spring's slip is the grid's velocity at the particle, not the particle's own "
       "(docs/cutting.md, \"The slip is the grid's\")",
       penalty_contact_with_friction},
  };
  return changes;
}

int model_version(const Scene& scene) {
  int version = 0;
  for (const ModelChange& c : model_changes())
    if (c.applies(scene)) version = std::max(version, c.version);
  return version;
}

std::string model_changes_since(int recorded, const Scene& scene) {
  std::string text;
  for (const ModelChange& c : model_changes()) {
    if (c.version <= recorded || !c.applies(scene)) continue;
    if (!text.empty()) text += "; ";
    text += fmt::format("version {} ({}): {}", c.version, c.revision, c.what);
  }
  return text;
}

}  // namespace mpmcut
