#include "cutting/cutting_input.hpp"

#include <fmt/format.h>

#include "cutting/tool_heat_settings.hpp"
#include "solver/scene.hpp"

namespace mpmcut {

CuttingParameters read_cutting_parameters(TableReader& t) {
  CuttingParameters c;
  t.require_key("material", "the workpiece material: a [[material]] name or a library set, e.g. \"ti64-johnson-1985\"");
  c.material = t.string("material", "");
  // Speed in SI, or in the machinist's m/min when the key says so; not both.
  const bool si = t.has("cutting_speed"), per_min = t.has("cutting_speed_m_per_min");
  if (si && per_min) t.fail("cutting_speed_m_per_min", "give either cutting_speed (m/s) or cutting_speed_m_per_min, not both");
  if (!si && !per_min) t.require_key("cutting_speed", "cutting speed V, m/s (or cutting_speed_m_per_min)");
  if (si) {
    c.cutting_speed = t.number("cutting_speed", 0.0, Range::open_closed(0.0, 1000.0, "m/s"));
  } else {
    const double v = t.number("cutting_speed_m_per_min", 0.0, Range::open_closed(0.0, 60000.0, "m/min"));
    c.cutting_speed = v / 60.0;
  }
  t.require_key("uncut_chip_thickness", "uncut chip thickness (feed) t0, m");
  c.uncut_chip_thickness =
      t.number("uncut_chip_thickness", 0.0, Range::open(0.0, 0.1, "m", "e.g. 0.1e-3 for 0.1 mm"));
  t.require_key("cut_length", "tool travel, m");
  // A cut of a metre is far beyond any MPM cutting study; the memory and step estimate then
  // decides whether the grid it needs fits this machine.
  c.cut_length = t.number("cut_length", 0.0, Range::open_closed(0.0, 1.0, "m"));
  c.width_of_cut = t.number("width_of_cut", c.width_of_cut, Range::open_closed(0.0, 10.0, "m"));
  c.workpiece_length = t.number("workpiece_length", c.workpiece_length, Range::closed(0.0, 2.0, "m", "0 = automatic"));
  c.workpiece_height = t.number("workpiece_height", c.workpiece_height, Range::closed(0.0, 1.0, "m", "0 = automatic"));
  c.rake_angle_deg = t.number("rake_angle_deg", c.rake_angle_deg, Range::open(-45.0, 45.0, "degrees"));
  c.clearance_angle_deg = t.number("clearance_angle_deg", c.clearance_angle_deg, Range::open(0.0, 45.0, "degrees"));
  t.check("rake_angle_deg", c.rake_angle_deg + c.clearance_angle_deg < 80.0,
          "such that rake + clearance < 80 degrees (the tool wedge needs a positive angle)", c.rake_angle_deg);
  // Bounded by the uncut chip thickness read above, so one message states the whole allowed range.
  c.edge_radius = t.number("edge_radius", c.edge_radius);
  t.check("edge_radius", c.edge_radius >= 0.0 && c.edge_radius < c.uncut_chip_thickness * 10.0,
          fmt::format("a length >= 0 m and below 10 uncut chip thicknesses ({:.4g} m)", 10.0 * c.uncut_chip_thickness),
          c.edge_radius);
  c.tool_length = t.number("tool_length", c.tool_length, Range::closed(0.0, 1.0, "m", "0 = automatic"));
  c.tool_height = t.number("tool_height", c.tool_height, Range::closed(0.0, 1.0, "m", "0 = automatic"));
  c.friction = t.number("friction", c.friction, Range::closed(0.0, 2.0, "", "Coulomb coefficient"));
  c.friction_heat_share = t.number(kFrictionHeatShare.key, c.friction_heat_share, kFrictionHeatShare.range);
  // Also below the workpiece material's melting point: checked once the material is known.
  c.initial_temperature = t.number("initial_temperature", c.initial_temperature, Range::open(0.0, 1e4, "K"));
  c.cell_size = t.number("cell_size", c.cell_size);
  // Not below grid.cell_size's 1 nm: the expanded scene must read back (1e-300 was taken, and its scene refused).
  t.check("cell_size", c.cell_size == 0.0 || (c.cell_size >= 1e-9 && c.cell_size <= 0.5 * c.uncut_chip_thickness),
          fmt::format("0 (= t0/10) or a length in [1e-9, uncut_chip_thickness/2 = {:.4g}] m", 0.5 * c.uncut_chip_thickness),
          c.cell_size);
  if (c.cell_size == 0.0 && c.uncut_chip_thickness / 10.0 < 1e-9)
    t.fail("cell_size", fmt::format("is 0, i.e. t0/10 = {:g} m, below the grid's 1 nm: give a cell_size of at least "
                                    "1e-9 m",
                                    c.uncut_chip_thickness / 10.0));
  c.particles_per_cell =
      static_cast<int>(t.integer("particles_per_cell", c.particles_per_cell, Range::closed(1, 4, "per direction")));
  c.conduction = t.boolean("conduction", c.conduction);
  c.tool_heat_transfer_coefficient =
      t.number(kToolHeatTransferCoefficient.key, c.tool_heat_transfer_coefficient, kToolHeatTransferCoefficient.range);
  // The tool starts, and stays, at the workpiece's initial temperature unless told otherwise.
  c.tool_temperature = t.number(kToolTemperature.key, c.initial_temperature, kToolTemperature.range);
  c.tool_conductivity = t.number(kToolConductivity.key, c.tool_conductivity, kToolConductivity.range);
  c.tool_volumetric_heat_capacity =
      t.number(kToolVolumetricHeatCapacity.key, c.tool_volumetric_heat_capacity, kToolVolumetricHeatCapacity.range);
  if (const auto conflict = tool_heat_conflict({c.friction_heat_share, c.tool_heat_transfer_coefficient,
                                                c.tool_conductivity, c.tool_volumetric_heat_capacity, c.conduction},
                                               "cutting."))
    t.check(conflict->key, false, conflict->allowed, conflict->value);
  c.chip_room = t.number("chip_room", c.chip_room, Range::closed(0.0, 1.0, "m", "0 = automatic"));
  c.snapshots = static_cast<int>(t.integer("snapshots", c.snapshots, Range::closed(1, 10000)));
  if (const toml::node* n = t.node("mass_scaling")) {
    if (auto word = n->value_exact<std::string>()) {
      if (*word == "auto") c.mass_scaling = 0.0;
      else if (*word == "off") c.mass_scaling = 1.0;
      else t.fail("mass_scaling", "must be \"auto\", \"off\" or a factor in [1, 1e6], got \"" + *word + "\"");
    } else {
      c.mass_scaling = t.number("mass_scaling", 0.0);
      t.check("mass_scaling", c.mass_scaling >= 1.0 && c.mass_scaling <= kMaxMassScalingFactor,
              "\"auto\", \"off\" or a factor in [1, 1e6]", c.mass_scaling);
    }
  }
  c.mass_scaling_inertia_number = t.number("mass_scaling_inertia_number", c.mass_scaling_inertia_number);
  t.check("mass_scaling_inertia_number", c.mass_scaling_inertia_number > 0.0 && c.mass_scaling_inertia_number <= 0.1,
          "in (0, 0.1] (rho f V^2 / A; 2e-3 keeps inertia forces near 0.2 % of the flow stress)",
          c.mass_scaling_inertia_number);
  c.steady_start_fraction = t.number("steady_start_fraction", c.steady_start_fraction, Range::closed_open(0.0, 1.0));
  t.reject_unknown_keys();
  return c;
}

void write_cutting_parameters(const CuttingParameters& c, std::ostream& out, std::string_view table_name) {
  const auto num = [](double x) { return fmt::format("{}", x); };
  out << "\n[" << table_name << "]\n";
  out << "material = \"" << c.material << "\"\n";
  out << "cutting_speed = " << num(c.cutting_speed) << "  # m/s\n";
  out << "uncut_chip_thickness = " << num(c.uncut_chip_thickness) << "  # m\n";
  out << "width_of_cut = " << num(c.width_of_cut) << "  # m\n";
  out << "cut_length = " << num(c.cut_length) << "  # m\n";
  out << "workpiece_length = " << num(c.workpiece_length) << "  # m (0 = automatic)\n";
  out << "workpiece_height = " << num(c.workpiece_height) << "  # m (0 = automatic)\n";
  out << "rake_angle_deg = " << num(c.rake_angle_deg) << "\n";
  out << "clearance_angle_deg = " << num(c.clearance_angle_deg) << "\n";
  out << "edge_radius = " << num(c.edge_radius) << "  # m\n";
  out << "tool_length = " << num(c.tool_length) << "  # m (0 = automatic)\n";
  out << "tool_height = " << num(c.tool_height) << "  # m (0 = automatic)\n";
  out << "friction = " << num(c.friction) << "\n";
  // Only where it is not the default: case files written before the key stay byte-identical.
  if (c.friction_heat_share != 1.0) out << "friction_heat_share = " << num(c.friction_heat_share) << "\n";
  out << "initial_temperature = " << num(c.initial_temperature) << "  # K\n";
  out << "cell_size = " << num(c.cell_size) << "  # m (0 = t0/10)\n";
  out << "particles_per_cell = " << c.particles_per_cell << "\n";
  out << "conduction = " << (c.conduction ? "true" : "false") << "\n";
  // Only where they are not the defaults: case files written before the keys stay byte-identical.
  if (c.tool_heat_transfer_coefficient != 0.0)
    out << "tool_heat_transfer_coefficient = " << num(c.tool_heat_transfer_coefficient) << "  # W/(m^2 K)\n";
  if (c.tool_temperature != c.initial_temperature) out << "tool_temperature = " << num(c.tool_temperature) << "  # K\n";
  if (c.tool_conductivity != 0.0) out << "tool_conductivity = " << num(c.tool_conductivity) << "  # W/(m K)\n";
  if (c.tool_volumetric_heat_capacity != 0.0)
    out << "tool_volumetric_heat_capacity = " << num(c.tool_volumetric_heat_capacity) << "  # J/(m^3 K)\n";
  out << "chip_room = " << num(c.chip_room) << "  # m (0 = automatic)\n";
  out << "snapshots = " << c.snapshots << "\n";
  if (c.mass_scaling == 0.0) out << "mass_scaling = \"auto\"\n";
  else out << "mass_scaling = " << num(c.mass_scaling) << "\n";
  out << "mass_scaling_inertia_number = " << num(c.mass_scaling_inertia_number) << "\n";
  out << "steady_start_fraction = " << num(c.steady_start_fraction) << "\n";
}

}  // namespace mpmcut
