#include "io/scene_writer.hpp"

#include "io/material_keys.hpp"
#include "io/toml_reader.hpp"

#include <fmt/format.h>

namespace mpmcut {

namespace {

std::string num(double x) { return toml_float(x); }

// A TOML basic string: double quotes, with quotes, backslashes and control characters escaped.
std::string str(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) out += fmt::format("\\u{:04X}", static_cast<unsigned>(c));
        else out += c;
    }
  }
  return out + "\"";
}

std::string vec(const Vec2& v) { return fmt::format("[{}, {}]", num(v.x()), num(v.y())); }

std::string points(const std::vector<Vec2>& pts) {
  std::string s = "[";
  for (std::size_t i = 0; i < pts.size(); ++i) s += (i ? ", " : "") + vec(pts[i]);
  return s + "]";
}

const char* name(BoundaryKind b) {
  switch (b) {
    case BoundaryKind::Free: return "free";
    case BoundaryKind::Fixed: return "fixed";
    case BoundaryKind::Roller: return "roller";
  }
  return "?";
}

// The names read_solver accepts (the SceneWriter.RoundTripsEveryContactDetection test keeps them equal).
const char* name(ContactDetection d) {
  switch (d) {
    case ContactDetection::Node: return "node";
    case ContactDetection::Particle: return "particle";
    case ContactDetection::Gap: return "gap";
    case ContactDetection::Penalty: return "penalty";
  }
  return "?";
}
constexpr ContactDetection kContactDetections[] = {ContactDetection::Node, ContactDetection::Particle,
                                                   ContactDetection::Gap, ContactDetection::Penalty};

std::string shape_line(const Shape& s) {
  switch (s.kind) {
    case ShapeKind::Rectangle:
      return "rectangle = { min = " + vec(s.rectangle.min) + ", max = " + vec(s.rectangle.max) + " }";
    case ShapeKind::Disk:
      return "disk = { center = " + vec(s.disk.center) + ", radius = " + num(s.disk.radius) + " }";
    case ShapeKind::Polygon:
      return "polygon = " + points(s.polygon.vertices);
  }
  return "";
}

}  // namespace

void write_material(const MaterialParameters& m, std::ostream& out) {
  out << "\n[[material]]\n";
  out << "name = " << str(m.name) << "\n";
  out << "citation = " << str(m.citation) << "\n";
  write_material_keys(m, out);
}

void write_scene_tables(const Scene& s, std::ostream& out) {
  out << "# Complete mpmcut case: every key explicit (docs/input.md).\n";
  out << "title = " << str(s.title) << "\n";
  out << "body_force = " << vec(s.body_force) << "\n";

  out << "\n[grid]\n";
  out << "cell_size = " << num(s.grid.cell_size) << "\n";
  out << "min = " << vec(s.grid.min) << "\n";
  out << "max = " << vec(s.grid.max) << "\n";

  out << "\n[boundaries]\n";
  out << "left = \"" << name(s.boundaries.left) << "\"\n";
  out << "right = \"" << name(s.boundaries.right) << "\"\n";
  out << "bottom = \"" << name(s.boundaries.bottom) << "\"\n";
  out << "top = \"" << name(s.boundaries.top) << "\"\n";

  out << "\n[solver]\n";
  out << "shape_function = \"" << (s.solver.shape_function == ShapeFunctionKind::UGimp ? "ugimp" : "linear") << "\"\n";
  out << "scheme = \"" << (s.solver.scheme == TimeScheme::MUSL ? "musl" : "usl") << "\"\n";
  out << "cfl = " << num(s.solver.cfl) << "\n";
  out << "flip_fraction = " << num(s.solver.flip_fraction) << "\n";
  out << "end_time = " << num(s.solver.end_time) << "\n";
  out << "max_steps = " << s.solver.max_steps << "\n";
  out << "fixed_time_step = " << num(s.solver.fixed_time_step) << "\n";
  out << "remove_escaping_particles = " << (s.solver.remove_escaping_particles ? "true" : "false") << "\n";
  out << "contact_distance_cells = " << num(s.solver.contact_distance_cells) << "\n";
  out << "mass_scaling_factor = " << num(s.solver.mass_scaling_factor) << "\n";
  out << "mass_scaling_target_time_step = " << num(s.solver.mass_scaling_target_time_step) << "\n";
  out << "contact_detection = \"" << name(s.solver.contact_detection) << "\"\n";
  // Only where it acts: scenes of the other detections stay as they were written before the key
  // existed, so committed run records (validate --records) still match their conditions.
  if (s.solver.contact_detection == ContactDetection::Penalty)
    out << "penalty_stiffness = " << num(s.solver.penalty_stiffness) << "\n";
  // Likewise only when on.
  if (s.solver.volumetric_average == VolumetricAverage::Nodal) out << "volumetric_average = \"nodal\"\n";

  out << "\n[output]\n";
  out << "snapshot_interval = " << num(s.output.snapshot_interval) << "\n";
  out << "history_interval = " << num(s.output.history_interval) << "\n";
  out << "vtu = " << (s.output.vtu ? "true" : "false") << "\n";

  out << "\n[thermal]\n";
  out << "conduction = " << (s.thermal.conduction ? "true" : "false") << "\n";
  for (auto [side, value] : {std::pair{"left", &s.thermal.left}, {"right", &s.thermal.right},
                             {"bottom", &s.thermal.bottom}, {"top", &s.thermal.top}}) {
    if (*value) out << side << " = " << num(**value) << "\n";
    else out << "# " << side << ": insulated\n";
  }

  for (const auto& m : s.materials) write_material(m, out);

  for (const auto& b : s.bodies) {
    out << "\n[[body]]\n";
    out << "name = " << str(b.name) << "\n";
    out << "material = " << str(b.material) << "\n";
    out << shape_line(b.shape) << "\n";
    out << "particles_per_cell = " << b.particles_per_cell << "\n";
    // Written only where set, so that scenes written before the keys existed stay as they were.
    if (b.lattice_angle_deg != 0.0) out << "lattice_angle_deg = " << num(b.lattice_angle_deg) << "\n";
    if (b.lattice_origin) out << "lattice_origin = " << vec(*b.lattice_origin) << "\n";
    out << "velocity = " << vec(b.velocity) << "\n";
    out << "temperature = " << num(b.temperature) << "\n";
  }
  for (const auto& r : s.rigid_bodies) {
    out << "\n[[rigid_body]]\n";
    out << "name = " << str(r.name) << "\n";
    out << "polygon = " << points(r.polygon.vertices) << "\n";
    out << "rounding_radius = " << num(r.rounding_radius) << "\n";
    out << "velocity = " << vec(r.velocity) << "\n";
    out << "friction = " << num(r.friction) << "\n";
    // Written only where it is not the default, so that scenes written before the key existed stay
    // byte-identical (run records are matched by their scene text).
    if (r.friction_heat_share != 1.0) out << "friction_heat_share = " << num(r.friction_heat_share) << "\n";
    if (r.heat_transfer_coefficient != 0.0)
      out << "heat_transfer_coefficient = " << num(r.heat_transfer_coefficient) << "\n";
    if (r.temperature != RigidBodySpec{}.temperature) out << "temperature = " << num(r.temperature) << "\n";
    if (r.conductivity != 0.0) {
      out << "conductivity = " << num(r.conductivity) << "\n";
      out << "volumetric_heat_capacity = " << num(r.volumetric_heat_capacity) << "\n";
      if (r.heat_averaging_time != 0.0) out << "heat_averaging_time = " << num(r.heat_averaging_time) << "\n";
      out << "held_faces = [";
      for (std::size_t k = 0; k < r.held_faces.size(); ++k) out << (k ? ", " : "") << r.held_faces[k];
      out << "]\n";
    }
  }
}

std::vector<std::string> contact_detection_names() {
  std::vector<std::string> names;
  for (ContactDetection d : kContactDetections) names.emplace_back(name(d));
  return names;
}

std::string contact_detection_name(ContactDetection d) { return name(d); }

std::vector<std::string> volumetric_average_names() { return {"off", "nodal"}; }

}  // namespace mpmcut
