#pragma once
// What mass scaling did to a run, for summary.json and the console (docs/mass_scaling.md).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "solver/simulation.hpp"
#include "cutting/cutting_parameters.hpp"

namespace mpmcut {

struct MassScalingReport {
  double factor = 1.0;                 // f, -
  double target_time_step_s = 0.0;     // 0 = a fixed factor
  double reference_speed_m_per_s = 0;  // cutting speed, else the fastest rigid body or initial velocity
  double inertia_number = 0.0;         // rho f V^2 / sigma_ref of the worst body, -
  double unscaled_inertia_number = 0.0;// rho V^2 / sigma_ref, -
  double kinetic_to_internal = 0.0;    // (scaled) kinetic over elastic + plastic + damage energy, -
  std::optional<std::string> warning;  // when the scaled inertia may change the answer
};

// `cutting`: the process of a cut, whose cutting speed is the reference speed.
MassScalingReport mass_scaling_report(const Simulation& sim, const std::optional<CuttingParameters>& cutting);
nlohmann::json to_json(const MassScalingReport& r);
// One console line ("mass scaling: ..."); empty when the run has no mass scaling and no warning.
std::string console_line(const MassScalingReport& r);

}  // namespace mpmcut
