#pragma once
// Scene -> TOML case file. Every key is written explicitly (materials inlined with all their
// parameters, no library references), so the file documents the run completely and parses back
// to an equal Scene. Used for the expanded scene in each result directory.
#include <ostream>

#include "core/scene.hpp"

namespace mpmcut {

void write_scene(const Scene& scene, std::ostream& out);

// One [[material]] table with every parameter explicit (as in write_scene).
void write_material(const MaterialParameters& m, std::ostream& out);

}  // namespace mpmcut
