#pragma once
// The cutting tool as a rigid body: a wedge with rake angle, clearance angle and a rounded
// cutting edge of radius r, represented exactly as a core polygon grown by r.
#include "solver/scene.hpp"
#include "cutting/cutting_parameters.hpp"

namespace mpmcut {

struct ToolPlacement {
  double machined_surface_y = 0.0;  // lowest point of the cutting edge, m
  double leading_x = 0.0;           // x of the edge's leftmost point at the height of the edge centre, m
};

// The tool moving at -cutting_speed along x, its rake face facing -x, placed so that its lowest
// point lies on the machined surface and its edge at leading_x.
RigidBodySpec make_cutting_tool(const CuttingParameters& c, const ToolPlacement& where, double tool_length,
                                double tool_height);

}  // namespace mpmcut
