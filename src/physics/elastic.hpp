#pragma once
#include "physics/material.hpp"

namespace mpmcut {

// Hypoelastic isotropic linear elasticity with the Jaumann stress rate, plane strain
// (D_zz = 0, sigma_zz evolves through lambda tr D).
class LinearElastic final : public Material {
 public:
  using Material::Material;
  ConstitutiveIncrement update(Particles& p, std::size_t i, const Mat2& L,
                               const StepContext& ctx) const override;
};

}  // namespace mpmcut
