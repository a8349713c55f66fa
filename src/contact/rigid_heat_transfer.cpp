#include "contact/rigid_heat_transfer.hpp"

#include <algorithm>
#include <cmath>

namespace mpmcut {

bool any_heat_transfer(const std::vector<RigidBodySpec>& bodies) {
  return std::any_of(bodies.begin(), bodies.end(), [](const RigidBodySpec& r) { return r.heat_transfer_coefficient > 0.0; });
}

void mark_heat_sinks(Grid& G, const std::vector<RigidBodySpec>& specs, const RigidContact& contact,
                     const std::vector<RigidBodyState>& bodies, const SurfaceTemperature& surface_temperature) {
  G.sink_conductance.assign(G.node_count(), 0.0);
  G.sink_temperature.assign(G.node_count(), 0.0);
  for (std::size_t r = 0; r < specs.size(); ++r) {
    if (specs[r].heat_transfer_coefficient <= 0.0) continue;
    // A conducting body's temperature is its surface cell's, half a cell (h/2) inside its outline: that half
    // cell's resistance h / (2 k) is in series with the contact's.
    const double h_c = specs[r].conductivity > 0.0
                           ? 1.0 / (1.0 / specs[r].heat_transfer_coefficient + 0.5 * G.h / specs[r].conductivity)
                           : specs[r].heat_transfer_coefficient;
    const RigidPolygon& geom = contact.geometry(r);
    const Vec2 shift = bodies[r].displacement;
    const auto [i0, i1, j0, j1] = nodes_near_body(geom, shift, G);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const int n = G.index(i, j);
        if (G.heat_capacity[n] <= 0.0) continue;  // no material at the node
        Vec2 normal;
        const Vec2 x_body = G.node_position(i, j) - shift;
        const double d = geom.signed_distance(x_body, normal);
        const double w = 1.0 - std::abs(d) / G.h;
        if (w <= 0.0) continue;
        // Two bodies at one node: one sink at their conductance-weighted temperature.
        const double g_body = w * h_c * G.h, g = G.sink_conductance[n] + g_body;
        const double T_body = surface_temperature && specs[r].conductivity > 0.0
                                  ? surface_temperature(r, n, x_body, d, normal, g_body)
                                  : specs[r].temperature;
        G.sink_temperature[n] = (G.sink_conductance[n] * G.sink_temperature[n] + g_body * T_body) / g;
        G.sink_conductance[n] = g;
      }
    }
  }
}

}  // namespace mpmcut
