#include "cutting/cutting_scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "cutting/mass_scaling.hpp"
#include "cutting/tool_geometry.hpp"

namespace mpmcut {

namespace {
// Short cuts still get the last 40 % of their travel as the force window.
constexpr double kShortCutWindowStart = 0.6;
}  // namespace

// The chip needs about three uncut chip thicknesses of travel to form, from where the tool meets the workpiece.
double steady_window_start_travel(const CuttingParameters& c) {
  return std::max(c.steady_start_fraction * c.cut_length,
                  std::min(tool_engagement_travel(c) + kEntryTravelT0 * c.uncut_chip_thickness,
                           kShortCutWindowStart * c.cut_length));
}

std::string steady_window_rule_text() {
  return fmt::format("from max(steady_start_fraction * cut_length, min(e + {:g} t0, {:g} cut_length)) to the end, e the "
                     "travel before the edge meets the workpiece (0 unless the edge radius exceeds t0)",
                     kEntryTravelT0, kShortCutWindowStart);
}

std::string steady_window_warning(const CuttingParameters& c) {
  const double engagement = tool_engagement_travel(c);
  const double formed = engagement + kEntryTravelT0 * c.uncut_chip_thickness;
  const double start = steady_window_start_travel(c);
  // Half the window after the chip has formed: L - formed >= (L - start) / 2.
  if (c.cut_length - formed >= 0.5 * (c.cut_length - start)) return "";
  // The warning arises only where the window starts at a fixed share q of the cut (q L < formed), so
  // L - formed >= (1 - q) L / 2 gives the shortest steady cut.
  const double q = std::max(c.steady_start_fraction, kShortCutWindowStart);
  const double needed = formed / (0.5 + 0.5 * q);
  const std::string edge =
      engagement > 0.0 ? fmt::format(" after the edge (radius {:.3g} m) meets the workpiece at {:.3g} m of travel",
                                     c.edge_radius, engagement)
                       : std::string();
  return fmt::format(
      "cutting.cut_length = {:.3g} m is too short: less than half of the force window ({:.3g} to {:.3g} m of travel) "
      "lies beyond the {:.3g} m the chip needs to form ({:g} t0{}), so the mean forces and the chip are mostly those "
      "of the entry transient; a steady mean needs cut_length >= {:.3g} m",
      c.cut_length, start, c.cut_length, formed, kEntryTravelT0, edge, needed);
}

double cutting_cell_size(const CuttingParameters& c) {
  return c.cell_size > 0.0 ? c.cell_size : c.uncut_chip_thickness / 10.0;
}

double machined_surface_on_node_row(double workpiece_height, double uncut_chip_thickness, double cell_size) {
  const double rows = (workpiece_height - uncut_chip_thickness) / cell_size;
  // A height that is aligned up to round-off stays exactly as given (the same scene as before).
  if (std::abs(rows - std::round(rows)) < 1e-6) return workpiece_height;
  return uncut_chip_thickness + std::ceil(rows) * cell_size;
}

Scene build_cutting_scene(const CuttingParameters& c, const MaterialParameters& material) {
  const double t0 = c.uncut_chip_thickness;
  const double h = cutting_cell_size(c);
  if (h > 0.5 * t0)
    throw CuttingKeyError(
        c.cell_size > 0.0 ? "cell_size" : "uncut_chip_thickness",
        fmt::format("cutting.cell_size = {:.3g} m is more than half the uncut chip thickness {:.3g} m: the chip would "
                    "be one or two cells thick",
                    h, t0));
  const double workpiece_length = c.workpiece_length > 0.0 ? c.workpiece_length : c.cut_length + 4.0 * t0 + 10.0 * h;
  const double workpiece_height = c.workpiece_height > 0.0 ? c.workpiece_height : 4.0 * t0;
  if (workpiece_length < c.cut_length + 2.0 * h)
    throw CuttingKeyError("workpiece_length",
                          fmt::format("cutting.workpiece_length = {:.4g} m must be at least cut_length + 2 cells = {:.4g} m "
                                      "(cut_length {:.4g} m, cell {:.4g} m), or 0 for cut_length + 4 t0 + 10 cells",
                                      workpiece_length, c.cut_length + 2.0 * h, c.cut_length, h));
  if (workpiece_height <= t0 + 2.0 * h)
    throw CuttingKeyError("workpiece_height",
                          fmt::format("cutting.workpiece_height = {:.4g} m must exceed uncut_chip_thickness + 2 cells = "
                                      "{:.4g} m (t0 {:.4g} m, cell {:.4g} m), or be 0 for 4 t0",
                                      workpiece_height, t0 + 2.0 * h, t0, h));
  const ToolSize tool = tool_size(c);
  if (const ToolSizeProblem problem = tool_size_problem(c, tool); !problem.message.empty())
    throw CuttingKeyError(problem.key, "cutting tool: " + problem.message);
  // An edge radius above t0 meets the workpiece only after some travel: a cut shorter than that never cuts (it ran
  // to "complete" with zero forces).
  if (const double engagement = tool_engagement_travel(c); engagement > 0.0 && c.cut_length <= engagement + h)
    throw CuttingKeyError("cut_length",
                          fmt::format("cutting.cut_length = {:.3g} m: the edge (radius {:.3g} m, above the uncut chip "
                                      "thickness {:.3g} m) meets the workpiece only after {:.3g} m of travel, so the "
                                      "tool would not cut; give more than {:.3g} m (the chip then needs {:g} t0 more "
                                      "to form)",
                                      c.cut_length, c.edge_radius, t0, engagement, engagement + h, kEntryTravelT0));
  const double chip_room = c.chip_room > 0.0 ? c.chip_room : std::max(0.6 * c.cut_length + 2.0 * t0, 5.0 * t0);

  Scene s;
  s.title = fmt::format("Orthogonal cut of {}: V = {:.4g} m/s, t0 = {:.4g} mm, rake {:.3g} deg, r = {:.3g} um",
                        material.name, c.cutting_speed, t0 * 1e3, c.rake_angle_deg, c.edge_radius * 1e6);
  // Workpiece [0, L] x [0, H], clamped at its left end and its base; the tool starts half a
  // cell beyond its right end (its leftmost point between the machined and the uncut surface) and moves left. H is rounded up to t0 + a whole number of cells, so
  // that the machined surface, where the tool's lowest point runs, lies on a row of nodes on every
  // grid: where the tip sits within its cell changed the thrust force by -33 % to +11 % at t0/10
  // with a 34 um edge (docs/cutting.md, "Grid phase of the tool tip").
  const double L = workpiece_length, H = machined_surface_on_node_row(workpiece_height, t0, h);
  const double tool_start = L + 0.5 * h;
  s.grid.cell_size = h;
  s.grid.min = Vec2(0.0, 0.0);
  s.grid.max = Vec2(tool_start + tool.length + 2.0 * h, H + chip_room);
  s.boundaries.left = BoundaryKind::Fixed;
  s.boundaries.bottom = BoundaryKind::Fixed;
  s.thermal.conduction = c.conduction;
  s.thermal.bottom = c.initial_temperature;  // the far field stays at the initial temperature

  MaterialParameters m = material;
  s.materials.push_back(m);
  BodySpec wp;
  wp.name = "workpiece";
  wp.material = m.name;
  wp.particles_per_cell = c.particles_per_cell;
  wp.temperature = c.initial_temperature;
  wp.shape.kind = ShapeKind::Rectangle;
  wp.shape.rectangle = {Vec2(0.0, 0.0), Vec2(L, H)};
  s.bodies.push_back(wp);

  ToolPlacement where;
  where.machined_surface_y = H - t0;
  where.uncut_surface_y = H;
  where.leading_x = tool_start;
  s.rigid_bodies.push_back(make_cutting_tool(c, where, tool));
  // A tool placed further right than its length says (a negative rake, a large edge radius) keeps a cell of grid
  // behind it.
  double tool_right = s.grid.max.x();
  for (const Vec2& p : s.rigid_bodies.back().polygon.vertices)
    tool_right = std::max(tool_right, p.x() + c.edge_radius + h);
  s.grid.max.x() = tool_right;

  s.solver.shape_function = ShapeFunctionKind::UGimp;
  s.solver.scheme = TimeScheme::MUSL;
  s.solver.cfl = 0.4;
  s.solver.flip_fraction = 0.99;
  s.solver.end_time = c.cut_length / c.cutting_speed;
  s.solver.remove_escaping_particles = true;
  s.solver.mass_scaling_factor = cutting_mass_scaling_factor(c, material);
  s.solver.contact_detection = kCuttingPresetContact;
  s.output.snapshot_interval = s.solver.end_time / std::max(1, c.snapshots);
  // Force rows every quarter cell of tool travel: fine enough to resolve chip segmentation.
  s.output.history_interval = 0.25 * h / c.cutting_speed;
  return s;
}

}  // namespace mpmcut
