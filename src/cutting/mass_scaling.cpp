#include "cutting/mass_scaling.hpp"

#include <algorithm>

namespace mpmcut {

double reference_flow_stress(const MaterialParameters& m) {
  if (m.model == MaterialModel::JohnsonCook && m.jc_A > 0.0) return m.jc_A;
  return 1e-3 * m.youngs_modulus;
}

double inertia_number(const MaterialParameters& m, double mass_scaling_factor, double speed) {
  return m.density * mass_scaling_factor * speed * speed / reference_flow_stress(m);
}

double cutting_mass_scaling_factor(const CuttingParameters& c, const MaterialParameters& m) {
  if (c.mass_scaling > 0.0) return c.mass_scaling;
  const double unscaled = inertia_number(m, 1.0, c.cutting_speed);
  return std::max(1.0, c.mass_scaling_inertia_number / unscaled);
}

}  // namespace mpmcut
