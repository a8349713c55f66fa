#include "io/scene_parser.hpp"

#include <cctype>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "contact/rigid_polygon.hpp"
#include "core/shape_functions.hpp"
#include "io/material_library.hpp"
#include "io/toml_reader.hpp"
#include "io/whole_file.hpp"
#include "solver/seeding.hpp"

namespace mpmcut {

namespace {

std::string vec_text(const Vec2& v) { return fmt::format("[{}, {}]", v.x(), v.y()); }

// The start-overlap and empty-body checks scan particle positions before the memory check: at most this many per
// check (a fraction of a second), so that a scene too large to run is still refused at once.
constexpr double kMaxSeedPointsScanned = 4e6;

// Physical ranges shared by several keys (docs/reliability.md, "Input ranges"). Wide enough for
// any 2D cutting or impact scene, narrow enough that sizes, step counts and output counts computed
// from them stay representable (the memory and step estimate then decides what fits this machine).
const Range kCoordinate = Range::closed(-1e3, 1e3, "m");
const Range kSpeedComponent = Range::closed(-1e4, 1e4, "m/s");
const Range kTime = Range::open_closed(0.0, 1000.0, "s");
const Range kOutputInterval = Range::closed(0.0, 1000.0, "s", "0 = first and last only / every step");
constexpr double kMaxTemperature = 1e4;  // K: above every melting point


// ---------------------------------------------------------------------------------------------
// --set overrides: edit the TOML tree before it is read, so that an overridden value is
// validated exactly like one written in the file (and an unknown key is reported as unknown).

struct PathStep {
  std::string key;
  std::optional<std::size_t> index;  // body[2] -> key "body", index 2
};

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return std::string(s.substr(first, s.find_last_not_of(" \t") - first + 1));
}

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

// "body[0].velocity" or "body.0.velocity" -> {body,0}, {velocity}
std::vector<PathStep> parse_key_path(const std::string& path, const std::string& error_prefix) {
  std::vector<PathStep> steps;
  auto bad = [&](std::string_view why) -> InputError {
    return InputError(fmt::format("{}invalid key path '{}': {}", error_prefix, path, why));
  };
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t dot = std::min(path.find('.', start), path.size());
    std::string segment = path.substr(start, dot - start);
    start = dot + 1;
    if (all_digits(segment)) {  // "body.0": an index into the previous key
      if (steps.empty() || steps.back().index) throw bad("an index must follow an array name");
      steps.back().index = std::stoul(segment);
      continue;
    }
    PathStep step;
    if (const auto open = segment.find('['); open != std::string::npos) {
      if (segment.back() != ']' || !all_digits(segment.substr(open + 1, segment.size() - open - 2)))
        throw bad("expected name[index]");
      step.index = std::stoul(segment.substr(open + 1, segment.size() - open - 2));
      segment.resize(open);
    }
    if (segment.empty()) throw bad("empty key");
    step.key = segment;
    steps.push_back(std::move(step));
  }
  return steps;
}

std::string canonical_path(const std::vector<PathStep>& steps) {
  std::string path;
  for (const auto& s : steps) {
    path += (path.empty() ? "" : ".") + s.key;
    if (s.index) path += fmt::format("[{}]", *s.index);
  }
  return path;
}

void apply_override(toml::table& root, const std::string& text, InputSource& source) {
  const std::string prefix = fmt::format("{}: --set '{}': ", source.name, text);
  const auto eq = text.find('=');
  if (eq == std::string::npos) {
    // `run --set KEY=V case.toml` gives the case file to --set (CLI11 takes every value up to the next option).
    const bool case_file = text.size() > 5 && text.compare(text.size() - 5, 5, ".toml") == 0;
    throw InputError(prefix + "expected key=value" +
                     (case_file ? " (is it the case file? Give the case file before --set: mpmcut run CASE.toml --set "
                                  "KEY=VALUE)"
                                : ""));
  }
  const std::vector<PathStep> steps = parse_key_path(trim(std::string_view(text).substr(0, eq)), prefix);
  const std::string value_text = trim(std::string_view(text).substr(eq + 1));
  source.overrides.push_back({canonical_path(steps), text});

  // The value as TOML ("0.3", "[1, 0]", "true", "\"usl\""), else a bare string ("usl").
  toml::table parsed;
  try {
    parsed = toml::parse(std::string_view("v = " + value_text), std::string_view("--set '" + text + "'"));
  } catch (const toml::parse_error&) {
  }
  toml::node* parsed_value = parsed.size() == 1 ? parsed.get("v") : nullptr;
  auto assign = [&](auto&& place) {
    if (parsed_value) parsed_value->visit([&](auto& v) { place(std::move(v)); });
    else place(toml::value<std::string>(value_text));
  };

  toml::table* table = &root;
  std::string walked;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const PathStep& step = steps[i];
    const bool last = i + 1 == steps.size();
    walked += (walked.empty() ? "" : ".") + step.key;
    toml::node* child = table->get(step.key);
    if (!step.index) {
      if (last) {
        assign([&](auto&& v) { table->insert_or_assign(step.key, std::move(v)); });
        // One quantity in two spellings (m/s or m/min): the override replaces whichever the file
        // used, so that `sweep --speeds` works on a case written in m/min.
        if (walked == "cutting.cutting_speed") table->erase("cutting_speed_m_per_min");
        if (walked == "cutting.cutting_speed_m_per_min") table->erase("cutting_speed");
        return;
      }
      // A missing table ([thermal], say) is created; a key outside the schema is then reported
      // as unknown when the scene is read.
      if (child == nullptr) child = &table->insert(step.key, toml::table{}).first->second;
      if (!child->is_table()) throw InputError(prefix + fmt::format("'{}' is not a table", walked));
      table = child->as_table();
      continue;
    }
    toml::array* array = child ? child->as_array() : nullptr;
    if (array == nullptr) {
      std::string hint;
      // A cut of a library set has no [[material]] to override: say how to make one.
      if (walked == "material")
        if (const toml::node* set = root.at_path("cutting.material").node(); set && set->is_string())
          hint = fmt::format("; this case cuts the library set \"{0}\": to change its keys, add to the case\n"
                             "  [[material]]\n  name = \"{0}\"\n  library = \"{0}\"\n"
                             "and set the key there or with --set 'material[0].KEY=VALUE'",
                             set->value_or(std::string()));
      throw InputError(prefix + fmt::format("'{}' is not an array in the case{}", walked, hint));
    }
    if (*step.index >= array->size())
      throw InputError(prefix + fmt::format("index {} is out of range: '{}' has {} entries", *step.index, walked,
                                            array->size()));
    walked += fmt::format("[{}]", *step.index);
    if (last) {
      assign([&](auto&& v) { array->replace(array->cbegin() + static_cast<std::ptrdiff_t>(*step.index), std::move(v)); });
      return;
    }
    table = array->get(*step.index)->as_table();
    if (table == nullptr) throw InputError(prefix + fmt::format("'{}' is not a table", walked));
  }
}

// ---------------------------------------------------------------------------------------------
// Geometry checks

double signed_area(const std::vector<Vec2>& v) {
  double a = 0.0;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) a += v[j].x() * v[i].y() - v[i].x() * v[j].y();
  return 0.5 * a;
}

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Closed segments pq and rs share a point (touching counts: the polygon would not be simple).
bool segments_intersect(const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s) {
  auto orient = [](const Vec2& a, const Vec2& b, const Vec2& c) {
    const double o = cross(b - a, c - a);
    return (o > 0.0) - (o < 0.0);
  };
  auto on_segment = [](const Vec2& a, const Vec2& b, const Vec2& c) {  // c collinear with ab
    return c.x() >= std::min(a.x(), b.x()) && c.x() <= std::max(a.x(), b.x()) && c.y() >= std::min(a.y(), b.y()) &&
           c.y() <= std::max(a.y(), b.y());
  };
  const int o1 = orient(p, q, r), o2 = orient(p, q, s), o3 = orient(r, s, p), o4 = orient(r, s, q);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && on_segment(p, q, r)) || (o2 == 0 && on_segment(p, q, s)) || (o3 == 0 && on_segment(r, s, p)) ||
         (o4 == 0 && on_segment(r, s, q));
}

// A polygon read from `key`, checked to be simple with non-zero area.
Polygon read_polygon(TableReader& t, std::string_view key) {
  std::vector<Vec2> v = t.points(key);
  for (const Vec2& p : v)
    if (!kCoordinate.contains(p.x()) || !kCoordinate.contains(p.y()))
      t.fail(key, fmt::format("every coordinate must be {}, got vertex {}", kCoordinate.text(), vec_text(p)));
  // Users often repeat the first vertex to close the outline; the closing edge is implicit.
  if (v.size() > 3 && v.front() == v.back()) v.pop_back();
  if (v.size() < 3) t.fail(key, fmt::format("a polygon needs at least 3 vertices, got {}", v.size()));
  Vec2 lo = v[0], hi = v[0];
  for (const auto& p : v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    if (v[i] == v[(i + 1) % n]) t.fail(key, fmt::format("degenerate polygon: vertex {} repeats vertex {}", (i + 1) % n, i));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
      if (segments_intersect(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n]))
        t.fail(key, fmt::format("polygon is not simple: edge {}-{} crosses edge {}-{}", i, (i + 1) % n, j, (j + 1) % n));
    }
  if (std::abs(signed_area(v)) <= 1e-12 * (hi - lo).squaredNorm())
    t.fail(key, "degenerate polygon: zero area (all vertices on one line)");
  return Polygon{std::move(v)};
}

// ---------------------------------------------------------------------------------------------
// Sections

GridSpec read_grid(TableReader t) {
  GridSpec g;
  t.require_key("cell_size", "background grid cell size h, m");
  t.require_key("min", "lower-left corner [x, y], m");
  t.require_key("max", "upper-right corner [x, y], m");
  g.cell_size = t.number("cell_size", 0.0, Range::closed(1e-9, 100.0, "m"));
  g.min = t.vec2("min", g.min, kCoordinate);
  g.max = t.vec2("max", g.max, kCoordinate);
  t.check("max", (g.max.array() > g.min.array()).all(), "greater than grid.min = " + vec_text(g.min) + " in x and y", 0.0);
  const Vec2 size = g.max - g.min;
  t.check("cell_size", g.cell_size <= size.minCoeff(),
          fmt::format("at most the domain size ({} x {})", size.x(), size.y()), g.cell_size);
  t.reject_unknown_keys();
  return g;
}

BoundaryKind read_boundary(TableReader& t, std::string_view side) {
  return t.choice<BoundaryKind>(
      side, {{"free", BoundaryKind::Free}, {"fixed", BoundaryKind::Fixed}, {"roller", BoundaryKind::Roller}},
      BoundaryKind::Free);
}

BoundarySpec read_boundaries(std::optional<TableReader> t) {
  BoundarySpec b;
  if (!t) return b;
  b.left = read_boundary(*t, "left");
  b.right = read_boundary(*t, "right");
  b.bottom = read_boundary(*t, "bottom");
  b.top = read_boundary(*t, "top");
  t->reject_unknown_keys();
  return b;
}

// `base`: the values a key takes when absent; end_time is required unless the base has one.
}  // namespace

SolverSpec read_solver(TableReader t, SolverSpec s) {
  s.shape_function = t.choice<ShapeFunctionKind>(
      "shape_function", {{"ugimp", ShapeFunctionKind::UGimp}, {"linear", ShapeFunctionKind::Linear}}, s.shape_function);
  s.scheme = t.choice<TimeScheme>("scheme", {{"musl", TimeScheme::MUSL}, {"usl", TimeScheme::USL}}, s.scheme);
  // Up to 1, though a free surface's GIMP particles, the bulk viscosity and the penalty springs lower the stable
  // Courant number of the lumped-mass update to about 0.87-0.96 each (eigenvalue checks of a 1D chain): capping it
  // lower refused the scene.toml of results run above it (resume, analyze, plot). Documented in docs/input.md.
  s.cfl = t.number("cfl", s.cfl, Range::open_closed(0.0, 1.0, "", "Courant number"));
  s.flip_fraction = t.number("flip_fraction", s.flip_fraction, Range::closed(0.0, 1.0, "", "1 = pure FLIP"));
  if (s.end_time <= 0.0) t.require_key("end_time", "simulated time, s");
  s.end_time = t.number("end_time", s.end_time, kTime);
  s.max_steps = t.integer("max_steps", s.max_steps, Range::closed(0.0, 1e12, "steps", "0 = unlimited"));
  s.fixed_time_step =
      t.number("fixed_time_step", s.fixed_time_step, Range::closed(0.0, 1.0, "s", "0 = from the CFL condition"));
  s.remove_escaping_particles = t.boolean("remove_escaping_particles", s.remove_escaping_particles);
  s.contact_distance_cells = t.number("contact_distance_cells", s.contact_distance_cells, Range::closed(0.0, 10.0, "cells"));
  s.mass_scaling_factor = t.number("mass_scaling_factor", s.mass_scaling_factor);
  t.check("mass_scaling_factor", s.mass_scaling_factor >= 1.0 && s.mass_scaling_factor <= kMaxMassScalingFactor,
          fmt::format("in [1, {:g}] (1 = no mass scaling)", kMaxMassScalingFactor), s.mass_scaling_factor);
  s.mass_scaling_target_time_step = t.number("mass_scaling_target_time_step", s.mass_scaling_target_time_step);
  t.check("mass_scaling_target_time_step",
          s.mass_scaling_target_time_step >= 0.0 && s.mass_scaling_target_time_step < 1.0,
          "in [0, 1) s (0 = no target)", s.mass_scaling_target_time_step);
  if (s.mass_scaling_target_time_step > 0.0 && t.has("mass_scaling_factor") && s.mass_scaling_factor > 1.0)
    t.fail("mass_scaling_target_time_step", "give either mass_scaling_factor or mass_scaling_target_time_step, not both");
  if (s.mass_scaling_target_time_step > 0.0 && s.fixed_time_step > 0.0)
    t.fail("mass_scaling_target_time_step", "has no meaning with a fixed_time_step; give one of them");
  s.contact_detection = t.choice<ContactDetection>(
      "contact_detection",
      {{"node", ContactDetection::Node}, {"particle", ContactDetection::Particle}, {"gap", ContactDetection::Gap},
       {"penalty", ContactDetection::Penalty}},
      s.contact_detection);
  s.penalty_stiffness = t.number("penalty_stiffness", s.penalty_stiffness,
                                 Range::closed(0.01, 2.0, "", "x m / dt_stable^2 per unit overlap; contact_detection = \"penalty\""));
  s.volumetric_average = t.choice<VolumetricAverage>(
      "volumetric_average", {{"off", VolumetricAverage::Off}, {"nodal", VolumetricAverage::Nodal}}, s.volumetric_average);
  t.reject_unknown_keys();
  return s;
}

OutputSpec read_output(std::optional<TableReader> t, OutputSpec o) {
  if (!t) return o;
  o.snapshot_interval =
      t->number("snapshot_interval", o.snapshot_interval, Range::closed(0.0, 1000.0, "s", "0 = first and last only"));
  o.history_interval = t->number("history_interval", o.history_interval, Range::closed(0.0, 1000.0, "s", "0 = every step"));
  o.vtu = t->boolean("vtu", o.vtu);
  t->reject_unknown_keys();
  return o;
}

namespace {

ThermalSpec read_thermal(std::optional<TableReader> t) {
  ThermalSpec th;
  if (!t) return th;
  th.conduction = t->boolean("conduction", th.conduction);
  for (auto [side, value] : {std::pair{"left", &th.left}, {"right", &th.right}, {"bottom", &th.bottom}, {"top", &th.top}}) {
    *value = t->optional_number(side);
    // Kept, not refused, without conduction: an expanded cutting scene run with --set thermal.conduction=false
    // (docs/results/conduction_off) keeps its far-field side for when conduction is on again.
    if (*value)
      t->check(side, **value, Range::open_closed(0.0, kMaxTemperature, "K", "absent for an insulated side"));
  }
  t->reject_unknown_keys();
  return th;
}

Shape read_shape(TableReader& t, const GridSpec& grid) {
  const int count = int(t.has("rectangle")) + int(t.has("disk")) + int(t.has("polygon"));
  if (count != 1)
    t.fail_table(fmt::format("needs exactly one shape (rectangle = {{min = [x, y], max = [x, y]}}, disk = {{center = "
                             "[x, y], radius = r}} or polygon = [[x, y], ...]), got {}",
                             count));
  Shape shape;
  std::string key;
  if (auto r = t.optional_table("rectangle")) {
    key = "rectangle";
    shape.kind = ShapeKind::Rectangle;
    r->require_key("min", "lower-left corner [x, y], m");
    r->require_key("max", "upper-right corner [x, y], m");
    shape.rectangle.min = r->vec2("min", Vec2::Zero(), kCoordinate);
    shape.rectangle.max = r->vec2("max", Vec2::Zero(), kCoordinate);
    r->check("max", (shape.rectangle.max.array() > shape.rectangle.min.array()).all(),
             "greater than min = " + vec_text(shape.rectangle.min) + " in x and y", 0.0);
    r->reject_unknown_keys();
  } else if (auto d = t.optional_table("disk")) {
    key = "disk";
    shape.kind = ShapeKind::Disk;
    d->require_key("center", "[x, y], m");
    d->require_key("radius", "m");
    shape.disk.center = d->vec2("center", Vec2::Zero(), kCoordinate);
    shape.disk.radius = d->number("radius", 0.0, Range::open_closed(0.0, 1e3, "m"));
    d->reject_unknown_keys();
  } else {
    key = "polygon";
    shape.kind = ShapeKind::Polygon;
    shape.polygon = read_polygon(t, "polygon");
  }
  // Particles outside the grid would be lost on the first step.
  Vec2 lo, hi;
  shape.bounds(lo, hi);
  const double tol = 1e-12 * (grid.max - grid.min).norm();
  if ((lo.array() < grid.min.array() - tol).any() || (hi.array() > grid.max.array() + tol).any())
    t.fail(key, fmt::format("the shape (bounding box {} to {}) must lie inside the grid domain {} to {}", vec_text(lo),
                            vec_text(hi), vec_text(grid.min), vec_text(grid.max)));
  return shape;
}

// The key that holds a body's shape (read_shape made sure there is exactly one).
std::string shape_key(TableReader& t) {
  for (const char* key : {"rectangle", "disk", "polygon"})
    if (t.has(key)) return key;
  return "rectangle";
}

std::string list_names(const std::vector<MaterialParameters>& materials) {
  std::string text;
  for (const auto& m : materials) text += (text.empty() ? "" : ", ") + ("\"" + m.name + "\"");
  return text.empty() ? "(none)" : text;
}

BodySpec read_body(TableReader t, const Scene& scene) {
  BodySpec b;
  t.require_key("name", "identifies the body in outputs");
  t.require_key("material", "name of a [[material]]");
  b.name = t.string("name", "");
  t.check("name", !b.name.empty(), "a non-empty string", 0.0);
  b.material = t.string("material", "");
  const int m = scene.material_index(b.material);
  if (m < 0)
    t.fail("material", fmt::format("no [[material]] named \"{}\"; defined materials: {}", b.material,
                                   list_names(scene.materials)));
  b.shape = read_shape(t, scene.grid);
  b.particles_per_cell =
      static_cast<int>(t.integer("particles_per_cell", b.particles_per_cell, Range::closed(1, 8, "per direction")));
  // A lattice turned by 90 deg is the unturned one again: one quarter turn either way spans every lattice.
  b.lattice_angle_deg = t.number("lattice_angle_deg", b.lattice_angle_deg, Range::closed(-90.0, 90.0, "deg"));
  if (t.has("lattice_origin")) b.lattice_origin = t.vec2("lattice_origin", Vec2::Zero(), kCoordinate);
  b.velocity = t.vec2("velocity", b.velocity, kSpeedComponent);
  // Starting at the material's reference temperature means no thermal softening at rest.
  b.temperature = t.number("temperature", scene.materials[m].room_temperature, temperature_range(scene.materials[m]));
  t.reject_unknown_keys();
  // A shape thinner than the particle spacing holds none of the sub-grid's points: the body would vanish silently.
  // (Beyond kMaxSeedPointsScanned in its box the search is left out: such a shape is no sliver, and the memory
  // check decides whether it runs at all.)
  bool seeded = seed_points_in_box(b, scene.grid.cell_size) > kMaxSeedPointsScanned;
  if (!seeded)
    for_each_seed_point(b, scene.grid.min, scene.grid.cell_size, [&](const Vec2&) {
      seeded = true;
      return false;
    });
  if (!seeded)
    t.fail(shape_key(t), fmt::format("body \"{}\" gets no particle: its shape holds none of the points of the particle "
                                     "sub-grid (spacing grid.cell_size / particles_per_cell = {:g} m); make the shape "
                                     "larger than that spacing, or give a smaller cell_size or more particles_per_cell",
                                     b.name, scene.grid.cell_size / b.particles_per_cell));
  return b;
}

// A seed point of `body` inside `inside`'s region (within the box [lo, hi]), if any. The scan runs before the
// memory check and must not turn a huge scene's instant refusal into minutes of scanning: beyond
// kMaxSeedPointsScanned points it steps over the sub-grid (an overlap narrower than the stride then passes).
template <class Inside>
std::optional<Vec2> first_point_inside(const BodySpec& body, const GridSpec& grid, const Vec2& lo, const Vec2& hi,
                                       Inside inside) {
  const double points = seed_points_in_box(body, grid.cell_size, lo, hi);
  const long stride = points > kMaxSeedPointsScanned
                          ? static_cast<long>(std::ceil(std::sqrt(points / kMaxSeedPointsScanned)))
                          : 1;
  std::optional<Vec2> found;
  for_each_seed_point(
      body, grid.min, grid.cell_size, lo, hi,
      [&](const Vec2& x) {
        if (inside(x)) found = x;
        return !found;
      },
      stride);
  return found;
}

// Two bodies may touch, not share area: the particles of both would sit there, twice the mass. Both ways round:
// with different particles_per_cell the coarser body may have no point inside the finer one. A point on the other
// body's outline touches it (shapes contain their outline; a shared sloped edge can even count its points in
// both polygons by round-off): only a point whose four neighbours a millionth of the spacing away are inside too
// is an overlap.
void check_body_overlaps(TableReader& t, const Scene& scene) {
  const BodySpec& body = scene.bodies.back();
  const auto point_of_in = [&](const BodySpec& a, const BodySpec& b) {
    Vec2 lo, hi;
    b.shape.bounds(lo, hi);
    const double e = 1e-6 * scene.grid.cell_size / a.particles_per_cell;
    return first_point_inside(a, scene.grid, lo, hi, [&](const Vec2& p) {
      return b.shape.contains(p) && b.shape.contains(p + Vec2(e, 0.0)) && b.shape.contains(p - Vec2(e, 0.0)) &&
             b.shape.contains(p + Vec2(0.0, e)) && b.shape.contains(p - Vec2(0.0, e));
    });
  };
  for (std::size_t i = 0; i + 1 < scene.bodies.size(); ++i) {
    const BodySpec& other = scene.bodies[i];
    if (const auto x = point_of_in(body, other))
      t.fail(shape_key(t), fmt::format("body \"{}\" overlaps body \"{}\" (its particle at {} lies inside \"{}\"): "
                                       "bodies may touch but not share area, where both would put their mass",
                                       body.name, other.name, vec_text(*x), other.name));
    if (const auto x = point_of_in(other, body))
      t.fail(shape_key(t), fmt::format("body \"{}\" overlaps body \"{}\" (a particle of \"{}\" at {} lies inside it): "
                                       "bodies may touch but not share area, where both would put their mass",
                                       body.name, other.name, other.name, vec_text(*x)));
  }
}

// A body that starts inside a rigid body is pushed out of it in one step, with a huge, unphysical impulse. With
// penalty contact the springs act where a particle's domain reaches into the rigid body, so a particle closer to the
// outline than its domain's half width is pushed out just the same (a block laid on a plate turned against the grid:
// its staircase of particles was shot off the plate at the first step, and the test saw no contact at all).
void check_rigid_overlaps(TableReader& t, const Scene& scene) {
  const RigidBodySpec& rigid = scene.rigid_bodies.back();
  const RigidPolygon outline(rigid.polygon, rigid.rounding_radius);  // its box includes the rounding
  const bool penalty = scene.solver.contact_detection == ContactDetection::Penalty;
  for (const BodySpec& body : scene.bodies) {
    // A particle on the outline touches it (a punch whose rounding reaches the body's first particle row exactly).
    const double spacing = scene.grid.cell_size / body.particles_per_cell, tolerance = 1e-6 * spacing;
    const double reach =
        penalty ? ShapeFunction(scene.solver.shape_function, scene.grid.cell_size, body.particles_per_cell).half_width()
                : 0.0;
    const Vec2 margin = Vec2::Constant(reach);
    Vec2 normal;
    double distance = 0.0;
    if (const auto x = first_point_inside(body, scene.grid, outline.lower() - margin, outline.upper() + margin,
                                          [&](const Vec2& p) {
                                            distance = outline.signed_distance(p, normal);
                                            return distance < reach - tolerance;
                                          })) {
      if (distance < -tolerance)
        t.fail("polygon", fmt::format("rigid body \"{}\" overlaps body \"{}\" at the start (the body's particle at {} "
                                      "lies inside it): place the rigid body outside the deformable bodies; it may "
                                      "touch them",
                                      rigid.name, body.name, vec_text(*x)));
      t.fail("polygon",
             fmt::format("rigid body \"{}\" reaches into the particle domains of body \"{}\" at the start (its particle at "
                         "{} is {:.3g} m from the outline, less than the domain's half width {:.3g} m): with "
                         "solver.contact_detection = \"penalty\" the springs would push such particles out within a "
                         "step; leave a gap of at least {:.3g} m between the body and the rigid outline, or use "
                         "contact_detection = \"node\"",
                         rigid.name, body.name, vec_text(*x), std::max(distance, 0.0), reach, reach));
    }
  }
}

// Frictional heat goes into the particles at the contact, whose temperature rises by heat / (m c).
// Only bodies the rigid body can reach count: the boxes they sweep over the run (at their initial velocities, the
// bodies also under the body force), two cells wide, must meet (a pad the punch never reaches was refused).
void check_friction_heat(TableReader& t, const Scene& scene) {
  const RigidBodySpec& rigid = scene.rigid_bodies.back();
  if (rigid.friction <= 0.0 || rigid.friction_heat_share <= 0.0) return;
  const double T = scene.solver.end_time, margin = 2.0 * scene.grid.cell_size;
  const RigidPolygon outline(rigid.polygon, rigid.rounding_radius);  // its box includes the rounding
  const Vec2 r_move = T * rigid.velocity, r_grow = Vec2::Constant(margin);
  const Vec2 r_lo = outline.lower().cwiseMin(outline.lower() + r_move) - r_grow;
  const Vec2 r_hi = outline.upper().cwiseMax(outline.upper() + r_move) + r_grow;
  // A body at rest can be pushed into the rigid body by another one: every body may travel as far as the fastest
  // body or rigid body of the scene in any direction, besides its own initial motion.
  double fastest = 0.0;
  for (const BodySpec& b : scene.bodies) fastest = std::max(fastest, b.velocity.norm());
  for (const RigidBodySpec& r : scene.rigid_bodies) fastest = std::max(fastest, r.velocity.norm());
  for (const BodySpec& body : scene.bodies) {
    const MaterialParameters& m = scene.materials[scene.material_index(body.material)];
    Vec2 lo, hi;
    body.shape.bounds(lo, hi);
    const Vec2 move = T * body.velocity;
    const Vec2 grow = Vec2::Constant(0.5 * scene.body_force.norm() * T * T + fastest * T + margin);
    lo = lo.cwiseMin(lo + move) - grow;
    hi = hi.cwiseMax(hi + move) + grow;
    const bool reachable = (lo.array() <= r_hi.array()).all() && (r_lo.array() <= hi.array()).all();
    if (reachable && m.specific_heat <= 0.0)
      t.fail("friction", fmt::format("= {:g} heats the bodies it rubs (friction_heat_share = {:g}), but material \"{}\" "
                                     "of body \"{}\" has no specific_heat (0 J/(kg K)): its temperature would become "
                                     "infinite; give the material a specific_heat, or friction_heat_share = 0",
                                     rigid.friction, rigid.friction_heat_share, m.name, body.name));
  }
}

// A conducting rigid body (conductivity > 0): its heat capacity and the outline's edges where it is held.
void read_body_conduction(TableReader& t, RigidBodySpec& r) {
  r.conductivity = t.number("conductivity", r.conductivity,
                            Range::closed(0.0, 1e4, "W/(m K)", "0 = the body stays at its temperature"));
  r.volumetric_heat_capacity = t.number("volumetric_heat_capacity", r.volumetric_heat_capacity,
                                        Range::closed(0.0, 1e9, "J/(m^3 K)", "rho c; 0 = a steady body"));
  r.heat_averaging_time = t.number("heat_averaging_time", r.heat_averaging_time,
                                   Range::closed(0.0, 1e6, "s", "a steady body follows its heat input averaged so"));
  const std::size_t edges = r.polygon.vertices.size();
  if (const toml::node* n = t.node("held_faces")) {
    const toml::array* list = n->as_array();
    if (!list) t.fail("held_faces", "must be a list of the outline's edge indices, e.g. [1, 2], got " + describe_value(*n));
    for (const toml::node& e : *list) {
      const auto k = e.value_exact<std::int64_t>();
      if (!k || *k < 0 || *k >= static_cast<std::int64_t>(edges))
        t.fail("held_faces", fmt::format("lists edges of the outline by index, integers in [0, {}] (edge k runs from "
                                         "polygon vertex k to k + 1), got {}",
                                         edges - 1, describe_value(e)));
      r.held_faces.push_back(static_cast<int>(*k));
    }
  }
  if (r.conductivity <= 0.0) {
    t.check("volumetric_heat_capacity", r.volumetric_heat_capacity == 0.0,
            "0 unless conductivity > 0 (only a conducting body stores heat)", r.volumetric_heat_capacity);
    t.check("heat_averaging_time", r.heat_averaging_time == 0.0,
            "0 unless conductivity > 0 (it belongs to a steady conducting body)", r.heat_averaging_time);
    if (!r.held_faces.empty())
      t.fail("held_faces", "holds the faces of a conducting body at its temperature: give conductivity > 0, or leave "
                           "held_faces out");
    return;
  }
  if (r.volumetric_heat_capacity > 0.0)
    t.check("heat_averaging_time", r.heat_averaging_time == 0.0,
            "0 for a transient body (volumetric_heat_capacity > 0); only a steady one averages its heat input",
            r.heat_averaging_time);
  else
    t.check("heat_averaging_time", r.heat_averaging_time > 0.0,
            "> 0 s for a steady conducting body (volumetric_heat_capacity = 0): its field follows the heat input "
            "averaged over this time",
            r.heat_averaging_time);
  t.check("conductivity", r.friction_heat_share == 1.0 || r.friction == 0.0,
          "0 unless friction_heat_share = 1 (a conducting body takes its part of the frictional heat by conduction "
          "from the material's surface)",
          r.conductivity);
  t.check("conductivity", r.heat_transfer_coefficient > 0.0,
          "0 unless heat_transfer_coefficient > 0 (heat enters a conducting body only through it)", r.conductivity);
  t.check("conductivity", !r.held_faces.empty(),
          "0 unless held_faces lists the faces where the body is held at its temperature (without one it would "
          "only heat up)",
          r.conductivity);
}

RigidBodySpec read_rigid_body(TableReader t, bool conduction) {
  RigidBodySpec r;
  t.require_key("name", "identifies the rigid body in outputs (forces)");
  t.require_key("polygon", "outline [[x, y], ...] at t = 0, m");
  r.name = t.string("name", "");
  t.check("name", !r.name.empty(), "a non-empty string", 0.0);
  r.polygon = read_polygon(t, "polygon");
  r.rounding_radius = t.number("rounding_radius", r.rounding_radius, Range::closed(0.0, 1.0, "m"));
  r.velocity = t.vec2("velocity", r.velocity, kSpeedComponent);
  r.friction = t.number("friction", r.friction, Range::closed(0.0, 2.0, "", "Coulomb coefficient"));
  r.friction_heat_share = t.number("friction_heat_share", r.friction_heat_share,
                                   Range::closed(0.0, 1.0, "", "share of the frictional heat into the deformable body"));
  r.heat_transfer_coefficient = t.number("heat_transfer_coefficient", r.heat_transfer_coefficient,
                                         Range::closed(0.0, 1e9, "W/(m^2 K)", "0 = adiabatic surface"));
  r.temperature = t.number("temperature", r.temperature, Range::open_closed(0.0, kMaxTemperature, "K"));
  if (r.heat_transfer_coefficient > 0.0)
    t.check("heat_transfer_coefficient", conduction,
            "0 unless thermal.conduction = true (the heat it takes is part of the conduction update)",
            r.heat_transfer_coefficient);
  read_body_conduction(t, r);
  t.reject_unknown_keys();
  return r;
}

}  // namespace

Range temperature_range(const MaterialParameters& m) {
  if (m.melting_temperature > 0.0) return Range::open(0.0, m.melting_temperature, "K", "below the melting temperature");
  return Range::open_closed(0.0, kMaxTemperature, "K");
}

Scene read_scene_tables(TableReader& top) {
  Scene scene;
  scene.title = top.string("title", "");
  scene.grid = read_grid(top.table("grid"));
  scene.boundaries = read_boundaries(top.optional_table("boundaries"));
  scene.solver = read_solver(top.table("solver"));
  scene.output = read_output(top.optional_table("output"));
  scene.thermal = read_thermal(top.optional_table("thermal"));
  scene.body_force = top.vec2("body_force", scene.body_force, Range::closed(-1e12, 1e12, "m/s^2"));

  // A set may start from a library set or from an earlier set of this file (`library = ...`).
  MaterialLibrary library = builtin_material_library();
  scene.materials = read_case_materials(top, library, [&](TableReader& t, const MaterialParameters& m) {
    // Conduction divides by the heat capacity m c of each node.
    if (scene.thermal.conduction)
      t.check("specific_heat", m.specific_heat > 0.0, "positive (J/(kg K)) when thermal.conduction = true",
              m.specific_heat);
  });

  // Bodies and rigid bodies share one namespace: outputs (forces, fields) are keyed by name.
  std::vector<std::string> names;
  auto claim_name = [&](TableReader& t, const std::string& name) {
    if (std::find(names.begin(), names.end(), name) != names.end())
      t.fail("name", fmt::format("duplicate body name \"{}\" (bodies and rigid bodies need distinct names)", name));
    names.push_back(name);
  };
  for (TableReader& t : top.array_of_tables("body")) {
    scene.bodies.push_back(read_body(t, scene));
    claim_name(t, scene.bodies.back().name);
    check_body_overlaps(t, scene);
  }
  if (scene.bodies.empty()) {
    if (top.has("body")) top.fail("body", "a scene needs at least one deformable body, got none");
    top.fail_table("no [[body]] entries: a scene needs at least one deformable body");
  }
  for (TableReader& t : top.array_of_tables("rigid_body")) {
    scene.rigid_bodies.push_back(read_rigid_body(t, scene.thermal.conduction));
    claim_name(t, scene.rigid_bodies.back().name);
    check_rigid_overlaps(t, scene);
    check_friction_heat(t, scene);
  }
  return scene;
}

CaseTree parse_case_tree(std::string_view toml_text, const std::string& source_name,
                         const std::vector<std::string>& overrides) {
  CaseTree tree{parse_toml(toml_text, source_name), std::make_shared<InputSource>(InputSource{source_name, {}})};
  for (const std::string& o : overrides) apply_override(tree.root, o, *tree.source);
  return tree;
}

std::string read_case_text(const std::filesystem::path& file) {
  std::error_code ec;
  // Not opened unless a regular file (a directory opens on Linux and reads as nothing).
  std::optional<std::string> text =
      std::filesystem::is_regular_file(file, ec) ? read_whole_file(file) : std::optional<std::string>();
  if (!text) throw InputError(fmt::format("{}: cannot read case file: {}", file.string(), unreadable_reason(file)));
  return std::move(*text);
}

}  // namespace mpmcut
