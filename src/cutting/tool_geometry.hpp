#pragma once
// The cutting tool as a rigid body: a wedge with rake angle, clearance angle and a rounded
// cutting edge of radius r, represented exactly as a core polygon grown by r.
#include <string>

#include "solver/scene.hpp"
#include "cutting/cutting_parameters.hpp"

namespace mpmcut {

struct ToolPlacement {
  double machined_surface_y = 0.0;  // lowest point of the cutting edge, m
  double uncut_surface_y = 0.0;     // the workpiece's top, m
  // x of the edge's leftmost point (at the height of the edge centre), m; for a negative rake, whose face leans
  // further left above the edge, of the tool's leftmost point between the machined and the uncut surface.
  double leading_x = 0.0;
};

// The directions of the tool's faces as the preset builds them (angles in degrees). The rake face: up it, away from
// the edge, and its outward normal towards the chip (rake 0: +y and -x). The flank: along it, away from the edge and
// rising at the clearance angle, and its outward normal towards the machined surface.
struct FaceDirections {
  Vec2 along, normal;
};
FaceDirections rake_face_directions(double rake_angle_deg);
FaceDirections flank_directions(double clearance_angle_deg);

// The tool's length (along the machined surface, from the cutting edge to its back) and height (up the rake face,
// from the edge to its top), m.
struct ToolSize {
  double length = 0.0, height = 0.0;
};

// cutting.tool_length and tool_height, or where 0 the automatic sizes: length max(3 t0, 0.3 mm), height max(4 t0,
// 0.4 mm), both at least 4 edge radii, grown where the rake angle, the clearance angle or the edge radius needs
// it for the outline to be a tool (tool_size_problem). The automatic sizes are a tool at every accepted angle
// and radius.
ToolSize tool_size(const CuttingParameters& c);

// Why a tool of this size cannot be built, and at which [cutting] key; an empty message when it can. The outline
// must be a simple polygon (the rake face must not lean past the back, the back must rise above the end of the
// flank), the rounded edge must leave a flat rake face and flank (the core polygon of the rounding keeps every
// edge), and the rake face must reach 2 t0 up, above the chip.
struct ToolSizeProblem {
  std::string key;
  std::string message;
};
ToolSizeProblem tool_size_problem(const CuttingParameters& c, const ToolSize& size);

// The tool's travel beyond its start (half a cell before the workpiece) before it meets the workpiece between the
// machined and the uncut surface, m: 0 unless the edge radius exceeds t0, then r - sqrt(r^2 - (r - t0)^2) where the
// arc below the uncut surface meets the workpiece's end first (at rake 0 and -20 deg alike: the rake face starts
// above it). 0 for a size that is no tool.
double tool_engagement_travel(const CuttingParameters& c);

// The tool moving at -cutting_speed along x, its rake face facing -x, placed so that its lowest
// point lies on the machined surface and its edge at leading_x.
// Throws std::invalid_argument with tool_size_problem's message when the size is not a tool.
RigidBodySpec make_cutting_tool(const CuttingParameters& c, const ToolPlacement& where, const ToolSize& size);

}  // namespace mpmcut
