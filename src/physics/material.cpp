#include "physics/material.hpp"

#include <stdexcept>

#include "physics/elastic.hpp"
#include "physics/johnson_cook.hpp"

namespace mpmcut {

double Material::wave_speed(const Particles&, std::size_t) const { return p_wave_speed_; }

double Material::elastic_energy(const Particles& p, std::size_t i) const {
  // Complementary energy of a linear isotropic solid: p^2/(2K) + s:s/(4G), per unit volume.
  const PlaneStrainTensor& s = p.stress[i];
  const double pressure = -s.mean();
  const PlaneStrainTensor dev = s.deviator();
  return p.volume[i] *
         (pressure * pressure / (2.0 * params_.bulk_modulus()) + dev.contract(dev) / (4.0 * params_.shear_modulus()));
}

PlaneStrainTensor jaumann_rotate(const PlaneStrainTensor& sigma, const Mat2& L, double dt) {
  const double w = 0.5 * (L(1, 0) - L(0, 1));  // spin W = [[0, -w], [w, 0]]
  // (W s - s W) for in-plane s: xx: -2 w sxy, yy: +2 w sxy, xy: w (sxx - syy)
  PlaneStrainTensor r = sigma;
  r.xx -= 2.0 * dt * w * sigma.xy;
  r.yy += 2.0 * dt * w * sigma.xy;
  r.xy += dt * w * (sigma.xx - sigma.yy);
  return r;
}

std::unique_ptr<Material> make_material(const MaterialParameters& params) {
  switch (params.model) {
    case MaterialModel::Elastic:
      return std::make_unique<LinearElastic>(params);
    case MaterialModel::JohnsonCook:
      return std::make_unique<JohnsonCookMaterial>(params);
  }
  throw std::invalid_argument("unknown material model for material '" + params.name + "'");
}

}  // namespace mpmcut
