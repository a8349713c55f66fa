#pragma once
// Heat flow between the deformable material and rigid bodies with a heat transfer coefficient
// ([[rigid_body]] heat_transfer_coefficient, [cutting] tool_heat_transfer_coefficient): each rigid
// body is a heat sink at its own constant temperature, acting on the grid nodes at its surface in
// the conduction update (thermal/heat_conduction). docs/cutting.md, "Contact", item 6.
#include <functional>
#include <vector>

#include "contact/rigid_body.hpp"
#include "contact/rigid_contact.hpp"
#include "core/grid.hpp"
#include "core/scene_specs.hpp"

namespace mpmcut {

bool any_heat_transfer(const std::vector<RigidBodySpec>& bodies);

// Before a conduction update (needs this step's P2G mass and heat capacity): fills
// grid.sink_conductance and grid.sink_temperature. A node at signed distance d_n from a body's outline
// (positive outside the body) gets the conductance h_c h (1 - |d_n|/h) (zero beyond one cell), W/(K m):
// these hat weights sum to one over the nodes of any line across the surface whatever its position in
// the cells, so each cell of surface carries h_c h. Only nodes with material count.
// A conducting body (RigidBodySpec::conductivity > 0) has a surface temperature of its own at each node:
// `surface_temperature` gives it, from the body's index, the node's index, its position in the body's frame at
// t = 0, its signed distance, the outward normal there and the conductance the node gets from that body. That
// temperature is the one half a cell inside the outline: the half cell's resistance h / (2 k) adds to 1 / h_c.
using SurfaceTemperature = std::function<double(std::size_t body, int node, const Vec2& x_body, double distance,
                                                const Vec2& normal, double conductance)>;
void mark_heat_sinks(Grid& grid, const std::vector<RigidBodySpec>& specs, const RigidContact& contact,
                     const std::vector<RigidBodyState>& bodies, const SurfaceTemperature& surface_temperature = {});

}  // namespace mpmcut
