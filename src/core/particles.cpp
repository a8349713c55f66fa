#include "core/particles.hpp"

namespace mpmcut {

std::size_t Particles::add(const Vec2& x, const Vec2& v, double mass_kg, double volume_m2,
                           double temperature_K, int body_id, int material_id) {
  ParticleRow r;
  r.position = x;
  r.velocity = v;
  r.mass = mass_kg;
  r.volume = volume_m2;
  r.initial_volume = volume_m2;
  r.temperature = temperature_K;
  r.body = body_id;
  r.material = material_id;
  return add(r);
}

std::size_t Particles::add(const ParticleRow& row) {
  for_each_particle_field([&](const auto& f) { (this->*f.array).push_back(row.*f.value); });
  return size() - 1;
}

void Particles::resize(std::size_t n) {
  const ParticleRow initial;
  for_each_particle_field([&](const auto& f) { (this->*f.array).resize(n, initial.*f.value); });
}

void advance_deformation(Particles& P, std::size_t i, const Mat2& L, double dt) {
  const Mat2 increment = Mat2::Identity() + dt * L;
  P.deformation_gradient[i] = increment * P.deformation_gradient[i];
  P.volume[i] *= increment.determinant();
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
  for_each_particle_field([&](const auto& f) { apply_order(this->*f.array, order); });
}

ParticleRow Particles::row(std::size_t i) const {
  ParticleRow r;
  for_each_particle_field([&](const auto& f) { r.*f.value = (this->*f.array)[i]; });
  return r;
}

void Particles::set_row(std::size_t i, const ParticleRow& row) {
  for_each_particle_field([&](const auto& f) { (this->*f.array)[i] = row.*f.value; });
}

const std::vector<ParticleFieldInfo>& particle_field_infos() {
  static const std::vector<ParticleFieldInfo> infos = [] {
    std::vector<ParticleFieldInfo> v;
    for_each_particle_field([&](const auto& f) { v.push_back(f.info); });
    return v;
  }();
  return infos;
}

}  // namespace mpmcut
