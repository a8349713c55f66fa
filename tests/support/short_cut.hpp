#pragma once
// A short orthogonal cut of Ti-6Al-4V on a coarse grid through the cutting preset, run in-process:
// mean forces over the preset's steady window, penetration, chip rise, energy balance and the
// chip thickness ratio of the chip analysis at the end.
#include <algorithm>
#include <cmath>
#include <optional>

#include "analysis/chip_analysis.hpp"
#include "contact/rigid_polygon.hpp"
#include "solver/simulation.hpp"
#include "cutting/cutting_scene.hpp"
#include "io/material_library.hpp"

namespace mpmcut::testing {

inline CuttingParameters coarse_cut(double speed, double cut_length) {
  CuttingParameters c;
  c.material = "ti64-johnson-1985";
  c.cutting_speed = speed;
  c.uncut_chip_thickness = 0.1e-3;
  c.cut_length = cut_length;
  c.rake_angle_deg = 0.0;
  c.clearance_angle_deg = 11.0;
  c.edge_radius = 5e-6;
  c.friction = 0.35;
  c.cell_size = 20e-6;  // t0/5: coarse, enough for the global balance and force level
  c.particles_per_cell = 2;
  return c;
}

inline const MaterialParameters& ti64() { return *builtin_material_library().find("ti64-johnson-1985"); }

struct CutResult {
  double mean_cutting_force_N_per_m = 0.0;
  double mean_thrust_force_N_per_m = 0.0;
  double deepest_penetration_m = 0.0;  // most negative signed distance of a particle to the tool
  double chip_rise_m = 0.0;            // highest particle above the workpiece's top surface
  double balance_error = 0.0;          // (material side - tool work) / tool work
  double balance_error_without_algorithmic = 0.0;
  // t0 / t_c from the chip analysis, the mean over eight instants evenly spread over the steady
  // window (one instant's profile carries particle-scale noise of a few %)
  std::optional<double> chip_thickness_ratio;
  double mass_scaling_factor = 1.0;
  long steps = 0;
  bool finite = true;
};

// `detection`: the tool contact; none: the preset's (penalty contact).
inline CutResult run_cut(const CuttingParameters& c, const MaterialParameters& material = ti64(),
                         std::optional<ContactDetection> detection = std::nullopt) {
  Scene scene = build_cutting_scene(c, material);
  if (detection) scene.solver.contact_detection = *detection;
  Simulation sim(scene);
  const RigidBodySpec& tool_spec = scene.rigid_bodies[0];
  const RigidPolygon tool(tool_spec.polygon, tool_spec.rounding_radius);
  const double top = scene.bodies[0].shape.rectangle.max.y();
  const double steady_start = steady_window_start_travel(c) / c.cutting_speed;
  CutResult r;
  Vec2 impulse_at_start = Vec2::Zero();
  double t_start = -1.0;
  constexpr int kChipSamples = 8;
  const double sample_dt = (scene.solver.end_time - steady_start) / kChipSamples;
  double next_sample = steady_start + sample_dt, ratio_sum = 0.0;
  int ratio_count = 0;
  while (sim.time() < scene.solver.end_time * (1 - 1e-12)) {
    sim.step(std::min(scene.solver.end_time, next_sample) - sim.time());
    if (t_start < 0 && sim.time() >= steady_start) {
      t_start = sim.time();
      impulse_at_start = sim.rigid_bodies()[0].impulse;
    }
    if (sim.time() >= next_sample * (1 - 1e-12)) {
      const ChipAnalysisSetup setup = chip_analysis_setup(scene, c, sim.rigid_bodies()[0].displacement, sim.time());
      if (auto r = analyze_chip(sim.particles(), setup).chip_thickness_ratio) {
        ratio_sum += *r;
        ++ratio_count;
      }
      next_sample += sample_dt;
    }
    const Vec2 shift = sim.rigid_bodies()[0].displacement;
    for (const Vec2& x : sim.particles().position) {
      Vec2 n;
      r.deepest_penetration_m = std::min(r.deepest_penetration_m, tool.signed_distance(x - shift, n));
      r.chip_rise_m = std::max(r.chip_rise_m, x.y() - top);
    }
    r.finite = r.finite && std::isfinite(sim.rigid_bodies()[0].force.norm());
  }
  const Vec2 mean = (sim.rigid_bodies()[0].impulse - impulse_at_start) / (sim.time() - t_start);
  r.mean_cutting_force_N_per_m = mean.x();
  r.mean_thrust_force_N_per_m = mean.y();
  sim.refresh_energy();
  const EnergyTotals& e = sim.energy();
  // Every term of the ledger, the algorithmic ones included (FLIP/PIC blend, contact safeguard,
  // removed particles): the residual is what no term accounts for.
  r.balance_error = energy_balance_residual(e) / e.external_work;
  r.balance_error_without_algorithmic =
      (energy_balance_residual(e) - e.transfer_dissipation - e.contact_safeguard - e.removed_energy) / e.external_work;
  if (ratio_count > 0) r.chip_thickness_ratio = ratio_sum / ratio_count;
  r.mass_scaling_factor = sim.mass_scaling_factor();
  r.steps = sim.step_count();
  return r;
}

}  // namespace mpmcut::testing
