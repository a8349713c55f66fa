#pragma once
// Scene -> TOML case file: the generic tables. Every key is written explicitly (materials inlined
// with all their parameters, no library references), so the file documents the run completely and
// parses back to an equal Scene. The records that a layer above owns (the cutting process) are
// appended by run/case_loading.hpp's write_scene, which writes the expanded scene of each run.
#include <ostream>
#include <string>
#include <vector>

#include "solver/scene.hpp"

namespace mpmcut {

void write_scene_tables(const Scene& scene, std::ostream& out);

// Every contact detection as a case file spells it (solver.contact_detection), for options that pass one on.
std::vector<std::string> contact_detection_names();
// One of them.
std::string contact_detection_name(ContactDetection d);
// Likewise every solver.volumetric_average.
std::vector<std::string> volumetric_average_names();

// One [[material]] table with every parameter explicit (as in write_scene_tables).
void write_material(const MaterialParameters& m, std::ostream& out);

}  // namespace mpmcut
