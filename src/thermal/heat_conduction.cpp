#include "thermal/heat_conduction.hpp"

#include <algorithm>
#include <limits>

#include "core/deterministic_sum.hpp"
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

double conduct_heat(Particles& P, Grid& G, std::span<const ShapeFunction> body_shapes,
                    const std::vector<MaterialParameters>& materials, const StripColouring& colouring, bool parallel,
                    double dt, ConductionScratch& scratch) {
  const std::size_t n = P.size();
  const std::size_t nn = G.node_count();
  // The range of the old particle temperatures at each node (for the bound below).
  std::vector<double>& range_lo = scratch.node_low;
  std::vector<double>& range_hi = scratch.node_high;
  range_lo.assign(nn, std::numeric_limits<double>::infinity());
  range_hi.assign(nn, -std::numeric_limits<double>::infinity());
  // A fixed-temperature node at a face sees particles on one side only: its P2G temperature is the
  // field's mean about 3/8 of a cell inside (GIMP, 2 particles per cell), not the face's value. Resetting
  // that mean to the face's value made it the fixed point of the FLIP increments, which lifts the field of
  // the first cell by ~3/8 h |grad T| past the face's temperature (16-19 % of the step at 50 cells: the
  // maximum principle broken). Instead the gradient sees the face's value at the node, and the node's
  // mean is brought to that of the field through it: T_fixed + grad T . (x_mean - x_node), both from
  // the node's particles.
  std::vector<Vec2>& offset = scratch.face_offset;
  std::vector<Vec2>& gradient = scratch.face_gradient;
  bool any_fixed = false;
  for (std::size_t node = 0; node < nn && !any_fixed; ++node)
    any_fixed = (G.fixed[node] & 4) && G.heat_capacity[node] > 0.0;
  if (any_fixed) {
    offset.assign(nn, Vec2::Zero());
    gradient.assign(nn, Vec2::Zero());
  }
  // The value a node's field takes: its P2G temperature, the face's at a fixed node.
  const auto field_at = [&](int node) {
    return any_fixed && (G.fixed[node] & 4) ? G.fixed_temperature[node] : G.temperature[node];
  };
  // Particle temperature gradient from the nodal temperatures, and its conductive flux scattered
  // back (the nodal temperatures are only read here, the heat rates only written).
  colouring.for_each(parallel, [&](std::size_t p) {
    const Stencil st = particle_stencil(G, body_shapes, P, p);
    Vec2 grad_T = Vec2::Zero();
    // A node that no particle weighs (heat capacity 0) has no temperature (0 in the array): with linear shape
    // functions a particle exactly on a grid line still has a gradient there, and 0 K read as a flux of k T / h.
    // Such a node takes the particle's own value, which adds nothing (the gradients sum to zero).
    for_each_stencil_node(G, st, [&](int node, double, const Vec2& grad) {
      grad_T += (G.heat_capacity[node] > 0.0 ? field_at(node) : P.temperature[p]) * grad;
    });
    const double k = materials[P.material[p]].thermal_conductivity;
    const Vec2 flux = -k * grad_T;  // W/m^2
    // Conduct through the particle's solid only. Plastic flow keeps the volume, so V > V0 is crack
    // opening (the tensile cut-off after damage initiation; failed particles on a machined surface
    // reach V = 21 V0 at 1 um cells): void that does not conduct. With V instead, such a particle's
    // diffusivity is V/V0 times the material's, the explicit limit h^2/(4 alpha) no longer holds for
    // it, and its temperature oscillates without bound (test: OpenedParticlesConductByTheirSolid...).
    const double conducting_volume = std::min(P.volume[p], P.initial_volume[p]);
    const double mc = P.mass[p] * materials[P.material[p]].specific_heat;
    for_each_stencil_node(G, st, [&](int node, double w, const Vec2& grad) {
      G.heat_rate[node] += conducting_volume * flux.dot(grad);
      if (w <= 0.0) return;
      if (any_fixed && (G.fixed[node] & 4)) {
        offset[node] += w * mc * (P.position[p] - G.node_position(node % G.nx, node / G.nx));
        gradient[node] += w * mc * grad_T;
      }
      range_lo[node] = std::min(range_lo[node], P.temperature[p]);
      range_hi[node] = std::max(range_hi[node], P.temperature[p]);
    });
  });
  std::vector<double>& dT = G.heat_rate;  // reused: becomes the nodal temperature increment
  const bool sinks = !G.sink_conductance.empty();
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t node = 0; node < nn; ++node) {
    if (G.heat_capacity[node] <= 0.0) {
      dT[node] = 0.0;
    } else if (G.fixed[node] & 4) {
      const double C = G.heat_capacity[node];
      double target = G.fixed_temperature[node] + (gradient[node] / C).dot(offset[node] / C);
      // Within the fixed value and the node's particles (a gradient across a crack is no field's slope).
      target = std::clamp(target, std::min(G.fixed_temperature[node], range_lo[node]),
                          std::max(G.fixed_temperature[node], range_hi[node]));
      dT[node] = target - G.temperature[node];
    } else if (sinks && G.sink_conductance[node] > 0.0) {
      range_lo[node] = std::min(range_lo[node], G.sink_temperature[node]);
      range_hi[node] = std::max(range_hi[node], G.sink_temperature[node]);
      // Heat flow g (T_sink - T) to a rigid body, implicit in T: stable for any g dt / C (the node
      // approaches the sink's temperature instead of overshooting it).
      const double g = G.sink_conductance[node];
      dT[node] = dt * (G.heat_rate[node] + g * (G.sink_temperature[node] - G.temperature[node])) /
                 (G.heat_capacity[node] + dt * g);
    } else {
      dT[node] = dt * G.heat_rate[node] / G.heat_capacity[node];
    }
  }
  // Back to the particles, as increments: a particle keeps its deviation from the nodal field (the
  // field is not smeared). Alone, that lets a particle left cold among hot ones (arriving under the
  // tool edge) take its nodes' whole cooling and fall below every temperature around it (-505 K at
  // 1 um cells), and a hot one rise above them (above the melting cap). Conduction cannot leave the
  // range of the temperatures it started from: a particle's new temperature is bounded by the old
  // ones of the particles sharing its nodes, by its nodes' new temperatures (the grid moves heat a
  // cell further than that: a front advances) and by their sink temperatures (discrete maximum
  // principle). The heat a bound cuts, C_p (T_p - T_flip), is taken back from the particles that
  // share its nodes and were not cut, in proportion to w C (from all of them where none is left),
  // so the update still conserves heat (test: ColdParticlesAmongHotOnesStayInRange). Particles at a
  // fixed-temperature node are not bounded: heat enters there from outside the body (the face holds
  // its value), so their increment may leave the range of the old temperatures around them; bounding
  // it holds the first cell back as the face heats it (erfc test at 100 cells: 0.016 -> 1.5 %).
  // Heat into the sinks: at a sink node C dT = dt (heat rate + g (T_sink - T - dT)), and the heat rates sum to
  // zero, so the particles lose sum g (T + dT - T_sink) dt to the sinks (less the bound's cut shares, below).
  double sink_heat = 0.0;
  if (sinks) {
    G.sink_heat.resize(nn);
#pragma omp parallel for schedule(static) if (parallel)
    for (std::size_t node = 0; node < nn; ++node) {
      const double g = G.sink_conductance[node];
      G.sink_heat[node] = g > 0.0 && G.heat_capacity[node] > 0.0 && !(G.fixed[node] & 4)
                              ? g * (G.temperature[node] + dT[node] - G.sink_temperature[node]) * dt
                              : 0.0;
    }
    sink_heat = deterministic_sum(nn, [&](std::size_t node) { return G.sink_heat[node]; }, parallel);
  }
  std::vector<double>& cut_heat = scratch.cut_heat;  // heat added by the bound, J per particle (per unit depth)
  cut_heat.assign(n, 0.0);
  int any_cut = 0;
#pragma omp parallel for schedule(static) if (parallel) reduction(| : any_cut)
  for (std::size_t p = 0; p < n; ++p) {
    double inc = 0.0;
    double lo = P.temperature[p], hi = P.temperature[p];
    bool prescribed = false;
    for_each_stencil_weight(G, particle_stencil(G, body_shapes, P, p), [&](int node, double w) {
      inc += w * dT[node];
      prescribed = prescribed || (G.fixed[node] & 4);
      const double node_new = G.temperature[node] + dT[node];  // carries heat the grid moved in
      lo = std::min({lo, range_lo[node], node_new});
      hi = std::max({hi, range_hi[node], node_new});
    });
    const double flip = P.temperature[p] + inc;
    P.temperature[p] = prescribed ? flip : std::clamp(flip, lo, hi);
    if (P.temperature[p] != flip) {
      cut_heat[p] = P.mass[p] * materials[P.material[p]].specific_heat * (P.temperature[p] - flip);
      any_cut = 1;
    }
  }
  if (!any_cut) return sink_heat;
  // Nodal shares of the heat cut, and the heat capacity of the particles not cut (strips: no races).
  std::vector<double>& node_cut = range_lo;  // reused
  std::vector<double>& uncut_capacity = range_hi;
  std::fill(node_cut.begin(), node_cut.end(), 0.0);
  std::fill(uncut_capacity.begin(), uncut_capacity.end(), 0.0);
  std::vector<double>& sink_cut = scratch.sink_cut;
  if (sinks) sink_cut.assign(nn, 0.0);
  colouring.for_each(parallel, [&](std::size_t p) {
    const double mc = P.mass[p] * materials[P.material[p]].specific_heat;
    for_each_stencil_weight(G, particle_stencil(G, body_shapes, P, p), [&](int node, double w) {
      if (cut_heat[p] != 0.0) {
        // At a sink node the tool took or gave that heat: it does so that much less.
        if (sinks && G.sink_conductance[node] > 0.0)
          sink_cut[node] += w * cut_heat[p];
        else
          node_cut[node] += w * cut_heat[p];
      } else
        uncut_capacity[node] += w * mc;
    });
  });
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t p = 0; p < n; ++p) {
    const bool cut = cut_heat[p] != 0.0;
    double dTp = 0.0;
    for_each_stencil_weight(G, particle_stencil(G, body_shapes, P, p), [&](int node, double w) {
      if (node_cut[node] == 0.0) return;
      if (uncut_capacity[node] > 0.0) {
        if (!cut) dTp -= w * node_cut[node] / uncut_capacity[node];
      } else {
        dTp -= w * node_cut[node] / G.heat_capacity[node];
      }
    });
    P.temperature[p] += dTp;
  }
  if (sinks) {
    sink_heat -= deterministic_sum(nn, [&](std::size_t node) { return sink_cut[node]; }, parallel);
    for (std::size_t node = 0; node < nn; ++node) G.sink_heat[node] -= sink_cut[node];
  }
  return sink_heat;
}

}  // namespace mpmcut
