#pragma once
// How well a cut's grid resolves the chip and the cutting edge, with warnings where the grid
// convergence study (docs/results/convergence) found the answer still changing with the cell.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cutting/cutting_parameters.hpp"

namespace mpmcut {

// Below these the forces were found to depend on the cell (docs/results/convergence):
// with r_n = 34 um Fc and Ft change < 2 % from t0/16 to t0/24 and are within 6 % at t0/8; with a
// 5 um edge at 0.4-1.2 cells the edge and flank forces fall in proportion to the cell (Ft -22 %
// from t0/16 to t0/24). mpmcut validate uses cells <= min(t0/10, r_n/4).
inline constexpr double kResolvedCellsPerFeed = 8.0;
inline constexpr double kResolvedCellsPerEdgeRadius = 4.0;

struct CuttingResolution {
  double cell_size_m = 0.0;
  double cells_per_uncut_chip = 0.0;  // t0 / h
  double cells_per_edge_radius = 0.0; // r_n / h (0 for a sharp edge)
  int particles_per_cell = 0;         // per direction
  std::vector<std::string> warnings;
};

CuttingResolution cutting_resolution(const CuttingParameters& c);
nlohmann::json to_json(const CuttingResolution& r);
// "warning: ..." lines for the console; empty when the grid resolves the cut.
std::string console_lines(const CuttingResolution& r);

}  // namespace mpmcut
