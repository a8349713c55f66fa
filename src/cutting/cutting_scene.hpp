#pragma once
// The cutting preset: process parameters -> a general Scene (workpiece, tool, grid, boundary
// conditions, outputs). The result is written next to the results as scene.toml, so a user
// can see and edit exactly what ran. The process itself travels beside the scene (cutting/case.hpp).
#include <stdexcept>
#include <string>
#include <utility>

#include "solver/scene.hpp"
#include "cutting/cutting_parameters.hpp"

namespace mpmcut {

// A combination of [cutting] keys that cannot be built, with the key at fault (for the error's file and line).
struct CuttingKeyError : std::invalid_argument {
  CuttingKeyError(std::string key_name, const std::string& message)
      : std::invalid_argument(message), key(std::move(key_name)) {}
  std::string key;  // in [cutting], e.g. "workpiece_length"
};

// The tool contact of every scene the preset builds; a case's [solver] contact_detection picks another. Penalty
// contact: its forces do not depend on where the tool sits in its cell (Fc's cell-period noise 2-3 % against node
// detection's 11-13 %), its frictional work is the one its forces do and converges under refinement (docs/cutting.md,
// "Which contact a cut uses"). Node detection until 2026-12-07.
inline constexpr ContactDetection kCuttingPresetContact = ContactDetection::Penalty;

// `material` is the resolved workpiece material. Throws CuttingKeyError naming the parameter when the
// combination cannot be built (e.g. a cell larger than the chip), std::invalid_argument for the tool's shape.
Scene build_cutting_scene(const CuttingParameters& c, const MaterialParameters& material);

// The grid's cell size: cutting.cell_size, or t0 / 10 when it is not given, m.
double cutting_cell_size(const CuttingParameters& c);

// The workpiece height the preset uses: `workpiece_height` rounded up to t0 + a whole number of
// cells, so that the machined surface (y = H - t0, the tool's lowest point) lies on a row of grid
// nodes (the grid starts at y = 0), m.
double machined_surface_on_node_row(double workpiece_height, double uncut_chip_thickness, double cell_size);

// The tool travel after which the chip is taken as formed (start of the steady window), m.
double steady_window_start_travel(const CuttingParameters& c);
// The rule of steady_window_start_travel in words, for summary.json: "from max(...) to the end".
std::string steady_window_rule_text();
// A warning when less than half of the force window lies after the chip has formed (kEntryTravelT0 t0 of travel;
// cut_length below 3.75 t0 with the default window): the means are then mostly the entry transient's. Empty otherwise.
std::string steady_window_warning(const CuttingParameters& c);

}  // namespace mpmcut
