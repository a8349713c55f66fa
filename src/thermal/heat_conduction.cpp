#include "thermal/heat_conduction.hpp"

#include <algorithm>
#include <limits>

#include "core/stencil.hpp"

namespace mpmcut {

SubcycledConduction::SubcycledConduction(bool enabled, const std::vector<MaterialParameters>& materials,
                                         double cell_size, double cfl)
    : enabled_(enabled), limit_(std::numeric_limits<double>::infinity()) {
  for (const auto& m : materials) {
    if (m.thermal_conductivity <= 0.0 || m.specific_heat <= 0.0) continue;
    const double alpha = m.thermal_conductivity / (m.density * m.specific_heat);
    limit_ = std::min(limit_, cfl * cell_size * cell_size / (4.0 * alpha));  // dt <= h^2/(4 alpha) in 2D
  }
}

std::optional<double> SubcycledConduction::end_step(ConductionSubcycle& s, double dt, bool due) const {
  if (!enabled_) return std::nullopt;
  s.elapsed += dt;
  if (!due) return std::nullopt;
  const double elapsed = s.elapsed;
  s.elapsed = 0.0;
  s.steps = 0;
  return elapsed;
}

void conduct_heat(Particles& P, Grid& G, std::span<const ShapeFunction> body_shapes,
                  const std::vector<MaterialParameters>& materials, const StripColouring& colouring, bool parallel,
                  double dt) {
  const std::size_t n = P.size();
  // Particle temperature gradient from the nodal temperatures, and its conductive flux scattered
  // back (the nodal temperatures are only read here, the heat rates only written).
  colouring.for_each(parallel, [&](std::size_t p) {
    const Stencil st = particle_stencil(G, body_shapes, P, p);
    Vec2 grad_T = Vec2::Zero();
    for_each_stencil_node(G, st, [&](int node, double, const Vec2& grad) { grad_T += G.temperature[node] * grad; });
    const double k = materials[P.material[p]].thermal_conductivity;
    const Vec2 flux = -k * grad_T;  // W/m^2
    // Conduct through the particle's solid only. Plastic flow keeps the volume, so V > V0 is crack
    // opening (the tensile cut-off after damage initiation; failed particles on a machined surface
    // reach V = 21 V0 at 1 um cells): void that does not conduct. With V instead, such a particle's
    // diffusivity is V/V0 times the material's, the explicit limit h^2/(4 alpha) no longer holds for
    // it, and its temperature oscillates without bound (test: OpenedParticlesConductByTheirSolid...).
    const double conducting_volume = std::min(P.volume[p], P.initial_volume[p]);
    for_each_stencil_node(G, st, [&](int node, double, const Vec2& grad) {
      G.heat_rate[node] += conducting_volume * flux.dot(grad);
    });
  });
  const std::size_t nn = G.node_count();
  std::vector<double>& dT = G.heat_rate;  // reused: becomes the nodal temperature increment
  const bool sinks = !G.sink_conductance.empty();
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t node = 0; node < nn; ++node) {
    if (G.heat_capacity[node] <= 0.0) {
      dT[node] = 0.0;
    } else if (G.fixed[node] & 4) {
      dT[node] = G.fixed_temperature[node] - G.temperature[node];
    } else if (sinks && G.sink_conductance[node] > 0.0) {
      // Heat flow g (T_sink - T) to a rigid body, implicit in T: stable for any g dt / C (the node
      // approaches the sink's temperature instead of overshooting it).
      const double g = G.sink_conductance[node];
      dT[node] = dt * (G.heat_rate[node] + g * (G.sink_temperature[node] - G.temperature[node])) /
                 (G.heat_capacity[node] + dt * g);
    } else {
      dT[node] = dt * G.heat_rate[node] / G.heat_capacity[node];
    }
  }
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t p = 0; p < n; ++p) {
    double inc = 0.0;
    for_each_stencil_weight(G, particle_stencil(G, body_shapes, P, p), [&](int node, double w) { inc += w * dT[node]; });
    P.temperature[p] += inc;
  }
}

}  // namespace mpmcut
