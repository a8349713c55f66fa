#include "solver/guards.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace mpmcut {

void check_guards(const Particles& P, const Grid& grid, const Scene& scene, const RigidContact& contact,
                  const std::vector<RigidBodyState>& bodies, long step, double time, bool parallel) {
  const std::size_t n = P.size();
  const Vec2 lo = grid.domain_min, hi = grid.domain_max;
  long bad = -1;
#pragma omp parallel for schedule(static) reduction(max : bad) if (parallel)
  for (std::size_t p = 0; p < n; ++p) {
    const PlaneStrainTensor& s = P.stress[p];
    const bool finite = std::isfinite(P.position[p].x()) && std::isfinite(P.position[p].y()) &&
                        std::isfinite(P.velocity[p].x()) && std::isfinite(P.velocity[p].y()) &&
                        std::isfinite(s.xx + s.yy + s.zz + s.xy) && std::isfinite(P.temperature[p]) &&
                        std::isfinite(P.volume[p]);
    const Vec2 x = P.position[p];
    const bool inside = x.x() >= lo.x() && x.x() <= hi.x() && x.y() >= lo.y() && x.y() <= hi.y();
    // T <= 0 K is finite but no physics makes it: a broken heat update, not a result to write. Nor is V <= 0: a
    // particle turned inside out within a step.
    const bool above_zero = P.temperature[p] > 0.0 && P.volume[p] > 0.0;
    if (!finite || !inside || !above_zero) bad = std::max(bad, static_cast<long>(p));
  }
  const auto where = [&](std::size_t p) {
    return fmt::format("step {}, time {:.6g} s, particle {} of body '{}' at ({:.6g}, {:.6g}) m", step, time, p,
                       scene.bodies[P.body[p]].name, P.position[p].x(), P.position[p].y());
  };
  if (bad >= 0) {
    // Report the first offending particle, deterministically.
    for (std::size_t p = 0; p < n; ++p) {
      // First, as it is the cause of what follows (density and pressure infinite or negative): a volume at or below
      // zero (a NaN one is reported below, with the other non-finite fields).
      if (P.volume[p] <= 0.0)
        throw SimulationError(fmt::format(
            "particle volume {:.6g} m^3/m (J = V/V0 = {:.6g}), not positive, at {}: the velocity gradient turned it "
            "inside out within a step (an unstable step: a smaller solver.cfl, or finer cells where the flow is this "
            "fast)",
            P.volume[p], P.volume[p] / P.initial_volume[p], where(p)));
      const PlaneStrainTensor& s = P.stress[p];
      const char* field = nullptr;
      if (!std::isfinite(P.position[p].x()) || !std::isfinite(P.position[p].y())) field = "position";
      else if (!std::isfinite(P.velocity[p].x()) || !std::isfinite(P.velocity[p].y())) field = "velocity";
      else if (!std::isfinite(s.xx + s.yy + s.zz + s.xy)) field = "stress";
      else if (!std::isfinite(P.temperature[p])) field = "temperature";
      else if (!std::isfinite(P.volume[p])) field = "volume";
      if (field) throw SimulationError(fmt::format("non-finite {} at {}", field, where(p)));
      if (P.temperature[p] <= 0.0)
        throw SimulationError(fmt::format("temperature {:.6g} K, at or below absolute zero, at {}", P.temperature[p], where(p)));
      const Vec2 x = P.position[p];
      if (x.x() < lo.x() || x.x() > hi.x() || x.y() < lo.y() || x.y() > hi.y())
        throw SimulationError(fmt::format("particle left the grid domain [{:.6g}, {:.6g}] x [{:.6g}, {:.6g}] m at {}",
                                          lo.x(), hi.x(), lo.y(), hi.y(), where(p)));
    }
  }
  for (std::size_t r = 0; r < bodies.size(); ++r) {
    const RigidPolygon& geom = contact.geometry(r);
    const Vec2 shift = bodies[r].displacement;
    const Vec2 blo = geom.lower() + shift, bhi = geom.upper() + shift;
    for (std::size_t p = 0; p < n; ++p) {
      const Vec2 x = P.position[p];
      if (x.x() < blo.x() || x.x() > bhi.x() || x.y() < blo.y() || x.y() > bhi.y()) continue;
      Vec2 normal;
      const double d = geom.signed_distance(x - shift, normal);
      if (d < -grid.h)
        throw SimulationError(fmt::format("particle penetrated rigid body '{}' by {:.3g} m (more than a cell) at {}",
                                          bodies[r].name, -d, where(p)));
    }
  }
}

}  // namespace mpmcut
