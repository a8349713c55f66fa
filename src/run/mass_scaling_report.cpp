#include "run/mass_scaling_report.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "cutting/mass_scaling.hpp"

namespace mpmcut {

MassScalingReport mass_scaling_report(const Simulation& sim, const std::optional<CuttingParameters>& cutting) {
  const Scene& s = sim.scene();
  MassScalingReport r;
  r.factor = sim.mass_scaling_factor();
  r.target_time_step_s = s.solver.mass_scaling_target_time_step;
  if (cutting) {
    r.reference_speed_m_per_s = cutting->cutting_speed;
  } else {
    for (const auto& b : s.rigid_bodies) r.reference_speed_m_per_s = std::max(r.reference_speed_m_per_s, b.velocity.norm());
    for (const auto& b : s.bodies) r.reference_speed_m_per_s = std::max(r.reference_speed_m_per_s, b.velocity.norm());
  }
  for (const auto& b : s.bodies) {
    const int m = s.material_index(b.material);
    if (m < 0) continue;
    const MaterialParameters& mat = s.materials[m];
    r.unscaled_inertia_number = std::max(r.unscaled_inertia_number, inertia_number(mat, 1.0, r.reference_speed_m_per_s));
    r.inertia_number = std::max(r.inertia_number, inertia_number(mat, r.factor, r.reference_speed_m_per_s));
  }
  const EnergyTotals& e = sim.energy();
  const double internal = e.elastic + e.plastic_work + e.damage_dissipation;
  r.kinetic_to_internal = internal > 0.0 ? e.kinetic / internal : 0.0;
  if (r.factor > 1.0 && r.inertia_number > kInertiaNumberWarning)
    r.warning = fmt::format(
        "mass scaling factor {:.4g} raises the inertia number rho f V^2 / sigma to {:.3g} (above {:g}): the scaled "
        "inertia may change forces and chip shape; lower the factor (or the target time step)",
        r.factor, r.inertia_number, kInertiaNumberWarning);
  return r;
}

nlohmann::json to_json(const MassScalingReport& r) {
  nlohmann::json j = {{"factor", r.factor},
                      {"target_time_step_s", r.target_time_step_s},
                      {"reference_speed_m_per_s", r.reference_speed_m_per_s},
                      {"equivalent_speed_m_per_s", r.reference_speed_m_per_s * std::sqrt(r.factor)},
                      {"inertia_number", r.inertia_number},
                      {"unscaled_inertia_number", r.unscaled_inertia_number},
                      {"kinetic_to_internal_energy", r.kinetic_to_internal}};
  if (r.warning) j["warning"] = *r.warning;
  return j;
}

std::string console_line(const MassScalingReport& r) {
  std::string line;
  if (r.factor > 1.0)
    line = fmt::format(
        "mass scaling: inertia x {:.4g} (time step x {:.3g}); inertia number rho f V^2 / sigma = {:.2g} at V = {:.4g} m/s "
        "(as inertial as an unscaled cut at {:.4g} m/s)\n",
        r.factor, std::sqrt(r.factor), r.inertia_number, r.reference_speed_m_per_s,
        r.reference_speed_m_per_s * std::sqrt(r.factor));
  if (r.warning) line += "warning: " + *r.warning + "\n";
  return line;
}

}  // namespace mpmcut
