#pragma once
// Scene -> TOML case file: the generic tables. Every key is written explicitly (materials inlined
// with all their parameters, no library references), so the file documents the run completely and
// parses back to an equal Scene. The records that a layer above owns (the cutting process) are
// appended by run/case_loading.hpp's write_scene, which writes the expanded scene of each run.
#include <ostream>

#include "solver/scene.hpp"

namespace mpmcut {

void write_scene_tables(const Scene& scene, std::ostream& out);

// One [[material]] table with every parameter explicit (as in write_scene_tables).
void write_material(const MaterialParameters& m, std::ostream& out);

}  // namespace mpmcut
