#pragma once
// How well a cut's grid resolves the chip and the cutting edge, with warnings where the grid
// convergence study (docs/results/convergence) found the answer still changing with the cell.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cutting/cutting_parameters.hpp"
#include "solver/scene.hpp"

namespace mpmcut {

// Below these the forces were found to depend on the cell (docs/results/convergence):
// with r_n = 34 um Fc and Ft change < 2 % from t0/16 to t0/24 and are within 6 % at t0/8; with a
// 5 um edge at 0.4-1.2 cells the edge and flank forces fall in proportion to the cell (Ft -22 %
// from t0/16 to t0/24). mpmcut validate uses cells <= min(t0/10, r_n/4).
inline constexpr double kResolvedCellsPerFeed = 8.0;
inline constexpr double kResolvedCellsPerEdgeRadius = 4.0;
// Cells across the thermal length sqrt(kappa t0 / V), the width scale of an adiabatic shear band: at h = 0.1 mm,
// 381.3 m/min (l_th = 6.8 um) Fc moved -8 % from 1.1 to 1.6 cells and -3.6 % from 1.6 to 2.2 (TANH set), -5.2 and
// -2.6 % (the speed-ends set); at 100 m/min 1.5 cells were within 1.4 % of 3.2 (docs/results/low_speed_chip,
// docs/results/shear_localisation).
inline constexpr double kResolvedCellsPerThermalLength = 1.5;

// The thermal length of a cut, m: sqrt(kappa t0 / V), how far heat diffuses (kappa = k / (rho c), m^2/s) in the time
// t0 / V the material takes to cross the primary shear zone. 37 um at 12.6 m/min and 6.8 um at 381.3 m/min for
// Ti-6Al-4V at t0 = 0.1 mm.
double thermal_length_m(double thermal_diffusivity_m2_per_s, double uncut_chip_thickness_m, double speed_m_per_s);

struct CuttingResolution {
  double cell_size_m = 0.0;
  double cells_per_uncut_chip = 0.0;  // t0 / h
  double cells_per_edge_radius = 0.0; // r_n / h (0 for a sharp edge)
  double thermal_length_m = 0.0;        // sqrt(kappa t0 / V) (0: the workpiece conducts no heat)
  double cells_per_thermal_length = 0.0;
  int particles_per_cell = 0;         // per direction
  std::vector<std::string> warnings;
};

// `workpiece_thermal_diffusivity` k / (rho c) of the workpiece material, m^2/s (0: no thermal-length check).
CuttingResolution cutting_resolution(const CuttingParameters& c, double workpiece_thermal_diffusivity_m2_per_s);
// The workpiece material's thermal diffusivity in a scene built from `c` (0 if the scene has no such material).
double workpiece_thermal_diffusivity_m2_per_s(const CuttingParameters& c, const Scene& scene);
nlohmann::json to_json(const CuttingResolution& r);
// "warning: ..." lines for the console; empty when the grid resolves the cut.
std::string console_lines(const CuttingResolution& r);

}  // namespace mpmcut
