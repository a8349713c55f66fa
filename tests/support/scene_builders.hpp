#pragma once
// Small helpers to build scenes in code for tests (the same Scene the input parser produces).
#include <cmath>
#include <string>

#include "solver/scene.hpp"

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

// A strip n0 <= n <= n1 across a layer and 0 <= s <= L along it, in the layer's frame: origin o, the layer's
// direction at theta (rad) to the grid's x axis (so a layer can be turned against the grid).
inline BodySpec inclined_strip(const std::string& name, const std::string& material, double n0, double n1, double L,
                               double theta, const Vec2& o, Vec2 velocity) {
  const Vec2 s(std::cos(theta), std::sin(theta)), n(-std::sin(theta), std::cos(theta));
  BodySpec b;
  b.name = name;
  b.material = material;
  b.shape.kind = ShapeKind::Polygon;
  b.shape.polygon.vertices = {o + n0 * n, o + L * s + n0 * n, o + L * s + n1 * n, o + n1 * n};
  b.particles_per_cell = 2;
  b.velocity = velocity;
  return b;
}

// Every body of the scene seeded on the particle lattice turned by angle_deg about `origin` (docs/input.md,
// [[body]] lattice_angle_deg): strips built with inclined_strip at that angle about that origin, with their sides a
// whole number of spacings from it, then have their sides half a spacing outside their outer rows, as unturned.
inline void seed_on_turned_lattice(Scene& scene, double angle_deg, const Vec2& origin) {
  for (BodySpec& b : scene.bodies) {
    b.lattice_angle_deg = angle_deg;
    b.lattice_origin = origin;
  }
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

// A column of length L in uniaxial strain (one cell high, roller top and bottom) moving at -v0
// into a fixed wall at x = 0, with `cells` cells along it: the set-up of the wave tests.
inline Scene uniaxial_strain_impact(const MaterialParameters& material, double L, int cells, double v0) {
  const double h = L / cells;
  Scene s;
  s.grid = {h, Vec2(0, 0), Vec2(L + 4 * h, h)};
  s.boundaries.left = BoundaryKind::Fixed;
  s.boundaries.bottom = BoundaryKind::Roller;
  s.boundaries.top = BoundaryKind::Roller;
  s.solver.cfl = 0.3;
  s.materials.push_back(material);
  s.bodies.push_back(rectangle_body("column", material.name, Vec2(0, 0), Vec2(L, h), 2, Vec2(-v0, 0)));
  return s;
}

// A slab [0, 1] x [0, 1/cells] m at 300 K whose left face is held at 400 K from t = 0, with
// rho = c = k = 1 (alpha = 1 m^2/s): the semi-infinite solution is
// T = 300 + 100 erfc(x / (2 sqrt(t))) away from the insulated right end. A soft solid at rest
// (E = youngs_modulus) so the mechanics stays still; a stiff one makes the step sub-cycle conduction.
inline Scene heat_slab_scene(ShapeFunctionKind kind, int cells, double youngs_modulus = 1.0) {
  const double L = 1.0, h = L / cells;
  Scene s;
  s.grid = {h, Vec2(0, 0), Vec2(L, h)};
  s.solver.shape_function = kind;
  s.solver.cfl = 0.4;
  s.thermal.conduction = true;
  s.thermal.left = 400.0;
  MaterialParameters m = elastic_material("slab", youngs_modulus, 0.0, 1.0);
  m.specific_heat = 1.0;
  m.thermal_conductivity = 1.0;
  s.materials.push_back(m);
  BodySpec b = rectangle_body("slab", "slab", Vec2(0, 0), Vec2(L, h), 2);
  b.temperature = 300.0;
  s.bodies.push_back(b);
  return s;
}

}  // namespace mpmcut::testing
