// Mass scaling changes the inertia and nothing else (docs/mass_scaling.md): the stable step grows
// by sqrt(f), heat conduction and the heat of plastic work are unchanged, and a target time step
// is reached by the factor it implies.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/scene_builders.hpp"
#include "../support/ti64_parameters.hpp"
#include "solver/simulation.hpp"

using namespace mpmcut;
using namespace mpmcut::testing;

namespace {

// The sub-cycled slab of test_heat_conduction.cpp: a stiff solid at rest (E = 1e7 Pa) whose left
// face is held at 400 K from t = 0 (support/scene_builders.hpp).
Scene slab(double mass_scaling_factor) {
  Scene s = heat_slab_scene(ShapeFunctionKind::UGimp, 100, 1e7);
  s.solver.mass_scaling_factor = mass_scaling_factor;
  return s;
}

struct SlabResult {
  double max_error_vs_erfc = 0.0;  // / (Ts - T0)
  double heat_content = 0.0;       // sum m c (T - T0), J/m
  long steps = 0;
  std::vector<double> temperature;
};

SlabResult run_slab(double f) {
  Simulation sim(slab(f));
  const double t_end = 0.02;
  while (sim.time() < t_end) sim.step(t_end - sim.time());
  SlabResult r;
  r.steps = sim.step_count();
  const auto& P = sim.particles();
  for (std::size_t p = 0; p < P.size(); ++p) {
    r.heat_content += P.mass[p] * 1.0 * (P.temperature[p] - 300.0);
    r.temperature.push_back(P.temperature[p]);
    const double x = P.position[p].x();
    if (x > 0.6) continue;
    const double exact = 300.0 + 100.0 * std::erfc(x / (2 * std::sqrt(sim.time())));
    r.max_error_vs_erfc = std::max(r.max_error_vs_erfc, std::abs(P.temperature[p] - exact) / 100.0);
  }
  return r;
}

// A Ti-6Al-4V block (0.2 x 0.2 mm, no damage) upset by 10 % between a fixed base and a rigid
// platen moving down at 2 m/s: plastic work, its heat and the platen force.
struct UpsetResult {
  double plastic_work = 0.0, heat = 0.0, mean_temperature_rise = 0.0, platen_force = 0.0;
  double factor = 1.0;
  long steps = 0;
};

UpsetResult upset(double f) {
  const double H = 0.2e-3, h = H / 16, v = 2.0, stroke = 0.1 * H;
  Scene s;
  s.grid = {h, Vec2(-4 * h, 0), Vec2(H + 4 * h, H + 4 * h)};
  s.boundaries.bottom = BoundaryKind::Roller;
  s.solver.mass_scaling_factor = f;
  s.materials.push_back(ti64_johnson_1985());
  s.bodies.push_back(rectangle_body("block", "ti64-johnson-1985", Vec2(0, 0), Vec2(H, H), 2));
  RigidBodySpec platen;
  platen.name = "platen";
  platen.polygon.vertices = {Vec2(-3 * h, H + 0.25 * h), Vec2(H + 3 * h, H + 0.25 * h), Vec2(H + 3 * h, H + 3.5 * h),
                             Vec2(-3 * h, H + 3.5 * h)};
  platen.velocity = Vec2(0, -v);
  s.rigid_bodies.push_back(platen);
  s.solver.end_time = (stroke + 0.25 * h) / v;
  Simulation sim(s);
  sim.set_parallel_min_particles(1u << 30);
  const double t_window = 0.7 * s.solver.end_time;
  Vec2 impulse_at_window = Vec2::Zero();
  double time_at_window = -1.0;
  while (sim.time() < s.solver.end_time * (1 - 1e-12)) {
    sim.step(s.solver.end_time - sim.time());
    if (time_at_window < 0.0 && sim.time() >= t_window) {
      time_at_window = sim.time();
      impulse_at_window = sim.rigid_bodies()[0].impulse;
    }
  }
  UpsetResult r;
  r.plastic_work = sim.energy().plastic_work;
  r.heat = sim.energy().heat;
  // Mass-weighted mean temperature rise, from the particles (not from the energy ledger).
  double m_total = 0.0;
  for (std::size_t p = 0; p < sim.particles().size(); ++p) {
    m_total += sim.particles().mass[p];
    r.mean_temperature_rise += sim.particles().mass[p] * (sim.particles().temperature[p] - 298.0);
  }
  r.mean_temperature_rise /= m_total;
  // Mean platen force over the last 30 % of the stroke, from the impulse history.
  r.platen_force = (sim.rigid_bodies()[0].impulse.y() - impulse_at_window.y()) / (sim.time() - time_at_window);
  r.factor = sim.mass_scaling_factor();
  r.steps = sim.step_count();
  return r;
}

}  // namespace

// Conduction sees the true heat capacity: with the inertia 64x (step 8x longer, now at the
// conduction limit) the slab still follows erfc within 2 %, holds the same heat within 0.5 %, and
// every particle's temperature agrees within 1 % of Ts - T0 with the unscaled run.
TEST(MassScaling, ConductionIsUnchanged) {
  const SlabResult plain = run_slab(1.0), scaled = run_slab(64.0);
  EXPECT_LT(plain.max_error_vs_erfc, 0.02);
  EXPECT_LT(scaled.max_error_vs_erfc, 0.02);
  EXPECT_LT(scaled.steps * 4, plain.steps) << "the step did not grow";
  EXPECT_NEAR(scaled.heat_content / plain.heat_content, 1.0, 5e-3);
  ASSERT_EQ(plain.temperature.size(), scaled.temperature.size());
  for (std::size_t p = 0; p < plain.temperature.size(); ++p)
    EXPECT_NEAR(scaled.temperature[p], plain.temperature[p], 1.0) << "particle " << p;
}

// Adiabatic heating sees the true mass: upsetting the block with the inertia 100x (equivalent
// inertia of a 20 m/s platen, inertia number 0.002) does the same plastic work and heat within
// 1 %, heats the block by the same mean temperature within 1 %, and the heat is still
// beta x plastic work (beta = 0.9). A heat capacity taken from the scaled mass would give a
// 100x smaller temperature rise.
TEST(MassScaling, PlasticWorkAndHeatAreUnchanged) {
  const UpsetResult plain = upset(1.0), scaled = upset(100.0);
  EXPECT_EQ(scaled.factor, 100.0);
  EXPECT_LT(scaled.steps * 5, plain.steps);
  ASSERT_GT(plain.plastic_work, 0.0);
  EXPECT_NEAR(scaled.plastic_work / plain.plastic_work, 1.0, 0.01);
  EXPECT_NEAR(scaled.heat / plain.heat, 1.0, 0.01);
  EXPECT_NEAR(scaled.heat / scaled.plastic_work, 0.9, 1e-3);
  // sigma eps_p beta / (rho c) ~ 900 MPa x 0.09 x 0.9 / (4430 x 526) ~ 30 K.
  ASSERT_GT(plain.mean_temperature_rise, 10.0);
  EXPECT_NEAR(scaled.mean_temperature_rise / plain.mean_temperature_rise, 1.0, 0.01);
  EXPECT_NEAR(scaled.platen_force / plain.platen_force, 1.0, 0.03);
}

// A target step sets f = (target / dt_cfl)^2: the step taken reaches the target, and the
// resolved factor is what the CFL condition implies.
TEST(MassScaling, TargetTimeStepSetsTheFactor) {
  Scene s = slab(1.0);
  s.thermal.conduction = false;
  const double dt0 = Simulation(s).stable_time_step();
  s.solver.mass_scaling_target_time_step = 10.0 * dt0;
  Simulation sim(s);
  EXPECT_NEAR(sim.mass_scaling_factor(), 100.0, 1e-6);
  EXPECT_NEAR(sim.stable_time_step() / (10.0 * dt0), 1.0, 1e-9);
  // A target below the CFL step needs no scaling.
  s.solver.mass_scaling_target_time_step = 0.5 * dt0;
  EXPECT_EQ(Simulation(s).mass_scaling_factor(), 1.0);
}

// The inertia that is integrated is the scaled one: momentum and kinetic energy carry f.
TEST(MassScaling, MomentumAndKineticEnergyCarryTheFactor) {
  Scene s = slab(1.0);
  s.bodies[0].velocity = Vec2(3.0, 0.0);
  s.thermal.conduction = false;
  Simulation plain(s);
  s.solver.mass_scaling_factor = 9.0;
  Simulation scaled(s);
  EXPECT_NEAR(scaled.total_momentum().x() / plain.total_momentum().x(), 9.0, 1e-12);
  EXPECT_NEAR(scaled.energy().kinetic / plain.energy().kinetic, 9.0, 1e-12);
}
