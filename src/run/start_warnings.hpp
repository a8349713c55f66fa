#pragma once
// The warnings a cut gives before it steps: a grid too coarse for the chip, the edge or the shear bands
// (cutting/cutting_resolution.hpp), a cut too short for its force window (cutting/cutting_scene.hpp) and inputs in
// a wrong unit (cutting/input_plausibility.hpp). One source for the start of `mpmcut run` / `resume` and for
// `mpmcut run --check`, which says what a run would. (The mass scaling's line needs the built simulation.)
#include <string>

#include "cutting/cutting_parameters.hpp"
#include "solver/scene.hpp"

namespace mpmcut {

// "warning: ...\n" lines; empty when there is nothing to say.
std::string cut_start_warning_lines(const CuttingParameters& c, const Scene& scene);

}  // namespace mpmcut
