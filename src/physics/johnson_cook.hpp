#pragma once
#include "physics/material.hpp"

namespace mpmcut {

// Johnson-Cook thermo-visco-plasticity with JC damage initiation and Hillerborg evolution.
// (Being implemented: see issue 3.)
class JohnsonCookMaterial final : public Material {
 public:
  using Material::Material;
  ConstitutiveIncrement update(Particles& p, std::size_t i, const Mat2& L,
                               const StepContext& ctx) const override;
};

}  // namespace mpmcut
