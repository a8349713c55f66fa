#include "cutting/tool_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace mpmcut {

FaceDirections rake_face_directions(double rake_angle_deg) {
  const double a = rake_angle_deg * (std::numbers::pi / 180.0);
  return {Vec2(std::sin(a), std::cos(a)), Vec2(-std::cos(a), std::sin(a))};
}

FaceDirections flank_directions(double clearance_angle_deg) {
  const double g = clearance_angle_deg * (std::numbers::pi / 180.0);
  return {Vec2(std::cos(g), std::sin(g)), Vec2(std::sin(g), -std::cos(g))};
}

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

// The sharp wedge with its cutting edge at the origin, counter-clockwise: edge, end of the flank (rising at the
// clearance angle), back corner, top of the rake face (leaning by the rake angle).
std::vector<Vec2> sharp_wedge(const CuttingParameters& c, const ToolSize& size) {
  const Vec2 rake_dir = rake_face_directions(c.rake_angle_deg).along;
  const Vec2 flank_dir = flank_directions(c.clearance_angle_deg).along;
  const Vec2 p_flank = (size.length / flank_dir.x()) * flank_dir;
  const Vec2 p_rake = (size.height / rake_dir.y()) * rake_dir;
  return {Vec2::Zero(), p_flank, Vec2(p_flank.x(), p_rake.y()), p_rake};
}

// The polygon whose r-neighbourhood is the wedge with its corners rounded by r.
std::vector<Vec2> rounding_core(const std::vector<Vec2>& wedge, double r) {
  return r > 0.0 ? offset_inward(wedge, r) : wedge;
}

// Every edge of the core keeps its direction (none shrank through zero length): the rounding fits the wedge.
bool core_keeps_every_edge(const std::vector<Vec2>& wedge, const std::vector<Vec2>& core) {
  const std::size_t n = wedge.size();
  for (std::size_t i = 0; i < n; ++i)
    if ((core[(i + 1) % n] - core[i]).dot(wedge[(i + 1) % n] - wedge[i]) <= 0.0) return false;
  return true;
}

// The two ways a wedge of the given size is not a simple polygon (wedge points as sharp_wedge orders them).
bool rake_leans_past_back(const std::vector<Vec2>& wedge) { return wedge[3].x() >= wedge[1].x(); }
bool flank_rises_above_top(const std::vector<Vec2>& wedge) { return wedge[2].y() <= wedge[1].y(); }

// Whether the outline of this size, with a radius r, is a tool (the checks of tool_size_problem but the 2 t0).
bool is_a_tool(const CuttingParameters& c, const ToolSize& size, double r) {
  const std::vector<Vec2> wedge = sharp_wedge(c, size);
  if (rake_leans_past_back(wedge) || flank_rises_above_top(wedge)) return false;
  return core_keeps_every_edge(wedge, rounding_core(wedge, r));
}

// The leftmost x at height y of the polygon `core` grown by r (the union of its edges' capsules), or +inf where
// the line misses it.
double leftmost_x_at(const std::vector<Vec2>& core, double r, double y) {
  double x = std::numeric_limits<double>::infinity();
  const std::size_t n = core.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = core[i], b = core[(i + 1) % n];
    if (std::abs(y - a.y()) <= r) x = std::min(x, a.x() - std::sqrt(r * r - (y - a.y()) * (y - a.y())));
    const Vec2 d = (b - a).normalized();
    for (const double side : {-1.0, 1.0}) {  // both offset lines of the capsule
      const Vec2 shift = side * r * Vec2(-d.y(), d.x());
      const Vec2 p = a + shift, q = b + shift;
      if (p.y() == q.y()) {
        if (y == p.y()) x = std::min({x, p.x(), q.x()});
      } else if ((y - p.y()) * (y - q.y()) <= 0.0) {
        x = std::min(x, p.x() + (y - p.y()) * (q.x() - p.x()) / (q.y() - p.y()));
      }
    }
  }
  return x;
}

// The leftmost x of the grown polygon between heights y0 < y1. Its left boundary is convex in y, so the minimum
// lies at y0, at y1, or at its leftmost point overall (a core vertex's, r to its left) where that is in between.
double leftmost_x_between(const std::vector<Vec2>& core, double r, double y0, double y1) {
  double x = std::min(leftmost_x_at(core, r, y0), leftmost_x_at(core, r, y1));
  const auto leftmost = std::min_element(core.begin(), core.end(), [](const Vec2& a, const Vec2& b) { return a.x() < b.x(); });
  if (leftmost->y() >= y0 && leftmost->y() <= y1) x = std::min(x, leftmost->x() - r);
  return x;
}

}  // namespace

ToolSize tool_size(const CuttingParameters& c) {
  const double t0 = c.uncut_chip_thickness, r = c.edge_radius;
  const bool auto_length = c.tool_length <= 0.0, auto_height = c.tool_height <= 0.0;
  ToolSize s{auto_length ? std::max({3.0 * t0, 0.3e-3, 4.0 * r}) : c.tool_length,
             auto_height ? std::max({4.0 * t0, 0.4e-3, 4.0 * r}) : c.tool_height};
  // The automatic sizes grow 10 % beyond what the rake and the clearance angle need (rake + clearance < 80 deg
  // makes this converge: the growth per round is 1.21 tan(rake) tan(clearance) < 0.85)...
  const double deg = std::numbers::pi / 180.0;
  const double tan_rake = std::tan(c.rake_angle_deg * deg), tan_clearance = std::tan(c.clearance_angle_deg * deg);
  for (int i = 0; i < 100; ++i) {
    const ToolSize before = s;
    if (auto_length) s.length = std::max(s.length, 1.1 * s.height * tan_rake);
    if (auto_height) s.height = std::max(s.height, 1.1 * s.length * tan_clearance);
    if (s.length == before.length && s.height == before.height) break;
  }
  // ... and by half while the rounded edge does not fit (a sharp wedge needs room for a large radius). Where that
  // does not make a tool (a given size is at fault), the sizes before it stand and tool_size_problem says why.
  ToolSize grown = s;
  for (int i = 0; i < 12 && (auto_length || auto_height) && !is_a_tool(c, grown, r); ++i) {
    if (auto_length) grown.length *= 1.5;
    if (auto_height) grown.height *= 1.5;
  }
  return is_a_tool(c, grown, r) ? grown : s;
}

ToolSizeProblem tool_size_problem(const CuttingParameters& c, const ToolSize& size) {
  const std::vector<Vec2> wedge = sharp_wedge(c, size);
  const double t0 = c.uncut_chip_thickness;
  const auto mm = [](double m) { return fmt::format("{:.4g} mm", m * 1e3); };
  const std::string sizes = fmt::format("tool_length {}{}, tool_height {}{}", mm(size.length),
                                        c.tool_length > 0.0 ? "" : " (automatic)", mm(size.height),
                                        c.tool_height > 0.0 ? "" : " (automatic)");
  if (rake_leans_past_back(wedge))
    return {"tool_length",
            fmt::format("the rake face (rake angle {:g} deg) leans past the tool's back: its top is {} beyond the edge "
                        "and the tool is {} long ({}); give tool_length > {} or a smaller tool_height",
                        c.rake_angle_deg, mm(wedge[3].x()), mm(size.length), sizes, mm(wedge[3].x()))};
  if (flank_rises_above_top(wedge))
    return {"tool_height",
            fmt::format("the flank (clearance angle {:g} deg) rises {} over the tool's length, above the tool's top "
                        "({}); give tool_height > {} or a shorter tool_length",
                        c.clearance_angle_deg, mm(wedge[1].y()), sizes, mm(wedge[1].y()))};
  if (size.height < 2.0 * t0)
    return {"tool_height",
            fmt::format("the rake face reaches {} up, less than 2 uncut chip thicknesses ({}): the chip, thicker than "
                        "t0, would flow over the tool's top ({}); give tool_height >= {}",
                        mm(size.height), mm(2.0 * t0), sizes, mm(2.0 * t0))};
  if (!core_keeps_every_edge(wedge, rounding_core(wedge, c.edge_radius))) {
    // The largest radius that fits, by bisection (the core shrinks monotonically with r).
    double lo = 0.0, hi = c.edge_radius;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (is_a_tool(c, size, mid) ? lo : hi) = mid;
    }
    return {"edge_radius",
            fmt::format("an edge radius of {} does not fit the tool ({}, rake {:g} deg, clearance {:g} deg): the "
                        "rounding would leave no flat rake face or flank; at most {} fits, or give a larger tool",
                        mm(c.edge_radius), sizes, c.rake_angle_deg, c.clearance_angle_deg, mm(lo))};
  }
  return {};
}

namespace {
// The tool's core polygon (to be grown by the edge radius) in its place.
std::vector<Vec2> placed_core(const CuttingParameters& c, const ToolPlacement& where, const ToolSize& size) {
  const double r = c.edge_radius;
  std::vector<Vec2> core = rounding_core(sharp_wedge(c, size), r);
  // Place it: the edge centre core[0] sits r above the machined surface (the lowest point of the arc on it), its
  // leftmost point (centre - r) at leading_x. A negative rake leans the rake face left of that above the edge: the
  // tool then moves right until its leftmost point between the two surfaces is at leading_x, so that it does not
  // start inside the workpiece (a -20 deg rake started 30 um inside). An edge radius > t0 meets the workpiece
  // right of leading_x and starts with a gap (r - sqrt(r^2 - (r - t0)^2) of travel); it is left so, since the
  // validation's thin-feed records (r_n = 34 um at h = 0.01 mm) were run with it.
  const Vec2 shift = Vec2(where.leading_x + r, where.machined_surface_y + r) - core[0];
  for (Vec2& p : core) p += shift;
  const double leftmost = leftmost_x_between(core, r, where.machined_surface_y, where.uncut_surface_y);
  if (leftmost < where.leading_x - 1e-9 * std::max(size.length, size.height))
    for (Vec2& p : core) p.x() += where.leading_x - leftmost;
  return core;
}
}  // namespace

double tool_engagement_travel(const CuttingParameters& c) {
  const ToolSize size = tool_size(c);
  if (!tool_size_problem(c, size).message.empty()) return 0.0;  // not a tool: reported at its key
  const ToolPlacement where{0.0, c.uncut_chip_thickness, 0.0};
  const std::vector<Vec2> core = placed_core(c, where, size);
  return std::max(0.0, leftmost_x_between(core, c.edge_radius, where.machined_surface_y, where.uncut_surface_y));
}

RigidBodySpec make_cutting_tool(const CuttingParameters& c, const ToolPlacement& where, const ToolSize& size) {
  if (const ToolSizeProblem problem = tool_size_problem(c, size); !problem.message.empty())
    throw std::invalid_argument("cutting tool: " + problem.message);
  const double r = c.edge_radius;
  const std::vector<Vec2> core = placed_core(c, where, size);
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
  if (c.tool_conductivity > 0.0) {
    tool.conductivity = c.tool_conductivity;
    tool.volumetric_heat_capacity = c.tool_volumetric_heat_capacity;
    // Held where the insert sits in its holder: the back (edge 1 of the outline) and the top (edge 2).
    tool.held_faces = {1, 2};
    if (c.tool_volumetric_heat_capacity <= 0.0)
      tool.heat_averaging_time = kSteadyToolAveragingFraction * c.cut_length / c.cutting_speed;
  }
  return tool;
}

}  // namespace mpmcut
