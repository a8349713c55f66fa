#include "core/particles.hpp"

namespace mpmcut {

std::size_t Particles::add(const Vec2& x, const Vec2& v, double mass_kg, double volume_m2,
                           double temperature_K, int body_id, int material_id) {
  position.push_back(x);
  velocity.push_back(v);
  velocity_gradient.push_back(Mat2::Zero());
  deformation_gradient.push_back(Mat2::Identity());
  mass.push_back(mass_kg);
  volume.push_back(volume_m2);
  initial_volume.push_back(volume_m2);
  stress.push_back({});
  effective_stress.push_back({});
  plastic_strain.push_back(0.0);
  plastic_strain_rate.push_back(0.0);
  temperature.push_back(temperature_K);
  damage_initiation.push_back(0.0);
  damage.push_back(0.0);
  plastic_displacement.push_back(0.0);
  initiation_yield_stress.push_back(0.0);
  fracture_energy.push_back(0.0);
  damage_dissipation.push_back(0.0);
  body.push_back(body_id);
  material.push_back(material_id);
  return position.size() - 1;
}

namespace {
template <class T>
void apply_order(std::vector<T>& a, const std::vector<std::size_t>& order) {
  std::vector<T> out(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) out[k] = a[order[k]];
  a.swap(out);
}
}  // namespace

void Particles::permute(const std::vector<std::size_t>& order) {
  apply_order(position, order);
  apply_order(velocity, order);
  apply_order(velocity_gradient, order);
  apply_order(deformation_gradient, order);
  apply_order(mass, order);
  apply_order(volume, order);
  apply_order(initial_volume, order);
  apply_order(stress, order);
  apply_order(effective_stress, order);
  apply_order(plastic_strain, order);
  apply_order(plastic_strain_rate, order);
  apply_order(temperature, order);
  apply_order(damage_initiation, order);
  apply_order(damage, order);
  apply_order(plastic_displacement, order);
  apply_order(initiation_yield_stress, order);
  apply_order(fracture_energy, order);
  apply_order(damage_dissipation, order);
  apply_order(body, order);
  apply_order(material, order);
}

}  // namespace mpmcut
