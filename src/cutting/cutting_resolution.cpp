#include "cutting/cutting_resolution.hpp"

#include <cmath>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "cutting/cutting_scene.hpp"

namespace mpmcut {

double thermal_length_m(double kappa, double t0, double speed) {
  return kappa > 0.0 && speed > 0.0 ? std::sqrt(kappa * t0 / speed) : 0.0;
}

double workpiece_thermal_diffusivity_m2_per_s(const CuttingParameters& c, const Scene& scene) {
  const int m = scene.material_index(c.material);
  return m < 0 ? 0.0 : scene.materials[m].thermal_diffusivity();
}

namespace {

// A warning where a length of the cut spans fewer than `resolved` cells: the finding, then the cell that resolves it.
void warn_if_unresolved(CuttingResolution& r, double length_m, double resolved, const std::string& finding,
                        std::string_view tail = "") {
  if (length_m > 0.0 && length_m / r.cell_size_m < resolved)
    r.warnings.push_back(
        fmt::format("{}; resolve it with cutting.cell_size <= {:.3g} m{}", finding, length_m / resolved, tail));
}

}  // namespace

CuttingResolution cutting_resolution(const CuttingParameters& c, double kappa) {
  CuttingResolution r;
  r.cell_size_m = cutting_cell_size(c);
  r.cells_per_uncut_chip = c.uncut_chip_thickness / r.cell_size_m;
  r.cells_per_edge_radius = c.edge_radius / r.cell_size_m;
  r.particles_per_cell = c.particles_per_cell;
  r.thermal_length_m = thermal_length_m(kappa, c.uncut_chip_thickness, c.cutting_speed);
  r.cells_per_thermal_length = r.thermal_length_m / r.cell_size_m;
  warn_if_unresolved(r, c.uncut_chip_thickness, kResolvedCellsPerFeed,
                     fmt::format("the uncut chip thickness is {:.3g} cells (cell {:.3g} um): below {:g} cells the "
                                 "forces still change with the cell by more than 5 % (docs/results/convergence)",
                                 r.cells_per_uncut_chip, r.cell_size_m * 1e6, kResolvedCellsPerFeed));
  warn_if_unresolved(r, c.edge_radius, kResolvedCellsPerEdgeRadius,
                     fmt::format("the edge radius {:.3g} um is {:.2g} cells: below {:g} cells the grid, not the edge, "
                                 "sets the ploughing and flank forces, and the thrust force falls as the cell shrinks "
                                 "(a 5 um edge at 1.2 cells: -22 % from t0/16 to t0/24, docs/results/convergence)",
                                 c.edge_radius * 1e6, r.cells_per_edge_radius, kResolvedCellsPerEdgeRadius),
                     ", or read Ft as an upper bound");
  warn_if_unresolved(r, r.thermal_length_m, kResolvedCellsPerThermalLength,
                     fmt::format("the thermal length sqrt(kappa t0/V) = {:.3g} um, the width scale of an adiabatic "
                                 "shear band at this speed, is {:.2g} cells: below {:g} cells a serrating cut's shear "
                                 "bands, chip and forces still change with the cell (at h = 0.1 mm, 381.3 m/min: Fc "
                                 "-8 % from 1.1 to 1.6 cells, -3.6 % from 1.6 to 2.2; docs/results/low_speed_chip)",
                                 r.thermal_length_m * 1e6, r.cells_per_thermal_length, kResolvedCellsPerThermalLength));
  return r;
}

nlohmann::json to_json(const CuttingResolution& r) {
  nlohmann::json j = {{"cell_size_m", r.cell_size_m},
                      {"cells_per_uncut_chip_thickness", r.cells_per_uncut_chip},
                      {"cells_per_edge_radius", r.cells_per_edge_radius},
                      {"thermal_length_m", r.thermal_length_m},
                      {"cells_per_thermal_length", r.cells_per_thermal_length},
                      {"particles_per_cell_per_direction", r.particles_per_cell}};
  j["warnings"] = r.warnings;
  return j;
}

std::string console_lines(const CuttingResolution& r) {
  std::string out;
  for (const std::string& w : r.warnings) out += "warning: " + w + "\n";
  return out;
}

}  // namespace mpmcut
