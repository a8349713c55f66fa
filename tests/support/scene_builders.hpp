#pragma once
// Small helpers to build scenes in code for tests (the same Scene the input parser produces).
#include <string>

#include "core/scene.hpp"

namespace mpmcut::testing {

inline MaterialParameters elastic_material(const std::string& name, double E, double nu, double rho) {
  MaterialParameters m;
  m.name = name;
  m.model = MaterialModel::Elastic;
  m.youngs_modulus = E;
  m.poisson_ratio = nu;
  m.density = rho;
  m.specific_heat = 500.0;
  m.thermal_conductivity = 10.0;
  return m;
}

inline BodySpec rectangle_body(const std::string& name, const std::string& material, Vec2 lo, Vec2 hi, int ppc,
                               Vec2 velocity = Vec2::Zero()) {
  BodySpec b;
  b.name = name;
  b.material = material;
  b.shape.kind = ShapeKind::Rectangle;
  b.shape.rectangle = {lo, hi};
  b.particles_per_cell = ppc;
  b.velocity = velocity;
  return b;
}

inline BodySpec disk_body(const std::string& name, const std::string& material, Vec2 center, double radius, int ppc,
                          Vec2 velocity) {
  BodySpec b;
  b.name = name;
  b.material = material;
  b.shape.kind = ShapeKind::Disk;
  b.shape.disk = {center, radius};
  b.particles_per_cell = ppc;
  b.velocity = velocity;
  return b;
}

}  // namespace mpmcut::testing
