#include "contact/frictional_heating.hpp"

#include <algorithm>

#include "core/deterministic_sum.hpp"
#include "core/stencil.hpp"

namespace mpmcut {

double deposit_frictional_heat(Particles& P, const Grid& G, std::span<const ShapeFunction> body_shapes,
                               const std::vector<MaterialParameters>& materials, const NodeBox& heated,
                               std::vector<double>& deposited, bool parallel) {
  const std::size_t n = P.size();
  if (heated.empty()) return 0.0;  // no frictional heat this step
  // Only particles whose stencil can reach a heated node (2 cells around the heated box).
  const Vec2 lo = heated.lo - Vec2::Constant(2.0), hi = heated.hi + Vec2::Constant(2.0);
  deposited.assign(n, 0.0);
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t p = 0; p < n; ++p) {
    const Vec2 u = (P.position[p] - G.origin) / G.h;
    if (u.x() < lo.x() || u.x() > hi.x() || u.y() < lo.y() || u.y() > hi.y()) continue;
    double dT = 0.0;
    for_each_stencil_weight(G, particle_stencil(G, body_shapes, P, p), [&](int node, double w) {
      if (G.friction_heat[node] > 0.0) dT += w * G.friction_heat[node] / G.heat_capacity[node];
    });
    const MaterialParameters& mat = materials[P.material[p]];
    if (mat.melting_temperature > 0.0) dT = std::clamp(mat.melting_temperature - P.temperature[p], 0.0, dT);
    P.temperature[p] += dT;
    deposited[p] = P.mass[p] * mat.specific_heat * dT;
  }
  return deterministic_sum(n, [&](std::size_t p) { return deposited[p]; }, parallel);
}

}  // namespace mpmcut
