#include "cutting/tool_geometry.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mpmcut {

namespace {

// Intersection of the lines a + s da and b + t db.
Vec2 intersect(const Vec2& a, const Vec2& da, const Vec2& b, const Vec2& db) {
  const double det = da.x() * db.y() - da.y() * db.x();
  const Vec2 ab = b - a;
  const double s = (ab.x() * db.y() - ab.y() * db.x()) / det;
  return a + s * da;
}

// Moves every edge of a convex counter-clockwise polygon inward by r and intersects the
// neighbours: the core whose r-neighbourhood is the polygon with rounded corners.
std::vector<Vec2> offset_inward(const std::vector<Vec2>& v, double r) {
  const std::size_t n = v.size();
  std::vector<Vec2> point(n), dir(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 d = (v[(i + 1) % n] - v[i]).normalized();
    const Vec2 inward(-d.y(), d.x());  // left of the edge = inside for counter-clockwise order
    point[i] = v[i] + r * inward;
    dir[i] = d;
  }
  std::vector<Vec2> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t prev = (i + n - 1) % n;
    out[i] = intersect(point[prev], dir[prev], point[i], dir[i]);
  }
  return out;
}

}  // namespace

RigidBodySpec make_cutting_tool(const CuttingParameters& c, const ToolPlacement& where, double tool_length,
                                double tool_height) {
  const double deg = std::numbers::pi / 180.0;
  const double alpha = c.rake_angle_deg * deg, gamma = c.clearance_angle_deg * deg;
  // Sharp wedge with its cutting edge at the origin, counter-clockwise: edge, end of the flank
  // (rising at the clearance angle), back corner, top of the rake face (leaning by the rake angle).
  const Vec2 rake_dir(std::sin(alpha), std::cos(alpha));
  const Vec2 flank_dir(std::cos(gamma), std::sin(gamma));
  const Vec2 p_flank = (tool_length / flank_dir.x()) * flank_dir;
  const Vec2 p_rake = (tool_height / rake_dir.y()) * rake_dir;
  std::vector<Vec2> wedge{Vec2::Zero(), p_flank, Vec2(p_flank.x(), p_rake.y()), p_rake};
  if (p_rake.x() >= p_flank.x()) throw std::invalid_argument("cutting tool: rake face leans past the tool's back");
  const double r = c.edge_radius;
  std::vector<Vec2> core = r > 0.0 ? offset_inward(wedge, r) : wedge;
  // Place it: the edge centre core[0] sits r above the machined surface; its leftmost point
  // (centre - r in x) at leading_x.
  const Vec2 shift = Vec2(where.leading_x + r, where.machined_surface_y + r) - core[0];
  for (Vec2& p : core) p += shift;
  RigidBodySpec tool;
  tool.name = "tool";
  tool.polygon.vertices = core;
  tool.rounding_radius = r;
  tool.velocity = Vec2(-c.cutting_speed, 0.0);
  tool.friction = c.friction;
  tool.friction_heat_share = c.friction_heat_share;
  tool.heat_transfer_coefficient = c.tool_heat_transfer_coefficient;
  // Its temperature matters only where it exchanges heat (and an adiabatic tool's scene stays the
  // text it was before the tool had one).
  if (c.tool_heat_transfer_coefficient > 0.0) tool.temperature = c.tool_temperature;
  return tool;
}

}  // namespace mpmcut
