#include "run/run_summary.hpp"
#include "run/source_revision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "cutting/cutting_forces.hpp"
#include "cutting/cutting_resolution.hpp"
#include "cutting/input_plausibility.hpp"
#include "run/mass_scaling_report.hpp"
#include "solver/model_version.hpp"
#include "solver/simulation.hpp"

namespace mpmcut {

namespace {

using json = nlohmann::json;

// The typed keys, each written and read once below; everything else goes to `sections`.
constexpr const char* kTypedKeys[] = {
    "status", "message", "mpmcut_version", "source_revision", "model_version", "title", "case_file", "particles",
    "grid_nodes", "cell_size_m", "steps",
    "simulated_time_s", "end_time_s", "wall_time_s", "threads", "particle_steps_per_s", "energy_J_per_m",
    "energy_balance", "max_temperature_K", "rigid_bodies", "removed_particles", "removed_mass_kg_per_m",
    "last_checkpoint", "resumed_from", "mean_cutting_force_N_per_mm", "mean_thrust_force_N_per_mm"};

// The energy terms by their summary.json names.
template <class Energy, class F>
void for_each_energy_term(Energy& e, F&& f) {
  f("kinetic", e.kinetic);
  f("elastic", e.elastic);
  f("plastic_work", e.plastic_work);
  f("heat", e.heat);
  f("damage_dissipation", e.damage_dissipation);
  f("friction_work", e.friction_work);
  f("viscous_dissipation", e.viscous_dissipation);
  f("external_work", e.external_work);
  f("transfer_dissipation", e.transfer_dissipation);
  f("contact_safeguard", e.contact_safeguard);
  f("removed_energy", e.removed_energy);
  f("initial", e.initial);
}

json vec_json(const Vec2& v) { return {v.x(), v.y()}; }

// A number, or NaN where summary.json has null (write_json_atomically writes NaN and infinity as null).
double number(const json& j, const char* key) {
  const json& v = j.at(key);
  if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!v.is_number()) throw std::runtime_error(fmt::format("summary.json: \"{}\" is not a number", key));
  return v.get<double>();
}

std::optional<double> optional_number(const json& j, const char* key) {
  if (!j.contains(key) || j[key].is_null()) return std::nullopt;
  return number(j, key);
}

std::string text(const json& j, const char* key) {
  if (!j.contains(key)) return {};
  if (!j[key].is_string()) throw std::runtime_error(fmt::format("summary.json: \"{}\" is not a string", key));
  return j[key].get<std::string>();
}

Vec2 vec(const json& j, const char* key) {
  const json& v = j.at(key);
  if (!v.is_array() || v.size() != 2) throw std::runtime_error(fmt::format("summary.json: \"{}\" is not [x, y]", key));
  return {v[0].is_null() ? std::nan("") : v[0].get<double>(), v[1].is_null() ? std::nan("") : v[1].get<double>()};
}

// A number inside a section, if the section and the key are there.
std::optional<double> section_number(const json& sections, const char* section, const char* key) {
  if (!sections.contains(section) || !sections[section].is_object()) return std::nullopt;
  const json& s = sections[section];
  if (!s.contains(key) || !s[key].is_number()) return std::nullopt;
  return s[key].get<double>();
}

}  // namespace

RunSummary summary_before_setup(const std::string& title, const std::string& case_file, int threads) {
  RunSummary s;
  s.status = run_status::running;
  s.message = "setting up the simulation (a stop now leaves no checkpoint: run it again)";
  s.mpmcut_version = MPMCUT_VERSION;
  s.source_revision = source_revision();
  s.title = title;
  s.case_file = case_file;
  s.threads = threads;
  return s;
}

RunSummary summarize(const Simulation& sim, const std::optional<CuttingParameters>& cutting, const std::string& status,
                     double wall_s, const std::string& message, int threads) {
  RunSummary s;
  s.status = status;
  s.message = message;
  s.mpmcut_version = MPMCUT_VERSION;
  s.source_revision = source_revision();
  s.model_version = model_version(sim.scene());
  s.title = sim.scene().title;
  s.case_file = sim.scene().source_file;
  s.particles = sim.particles().size();
  s.grid_nodes = sim.grid().node_count();
  s.cell_size_m = sim.grid().h;
  s.steps = sim.step_count();
  s.simulated_time_s = sim.time();
  s.end_time_s = sim.scene().solver.end_time;
  s.wall_time_s = wall_s;
  s.threads = threads;
  s.particle_steps_per_s = wall_s > 0 ? static_cast<double>(sim.particles().size()) * sim.step_count() / wall_s : 0.0;
  const EnergyTotals& e = sim.energy();
  s.energy_J_per_m = {e.initial,  e.kinetic, e.elastic,       e.plastic_work,         e.heat,
                      e.damage_dissipation, e.friction, e.viscous, e.external_work, e.transfer_dissipation,
                      e.contact_safeguard, e.removed_energy};
  // initial energy + external work = the rest, term by term (docs/cutting.md, "Energy balance");
  // the residual is what no term accounts for, relative to the energy that came in.
  s.energy_residual_J_per_m = energy_balance_residual(e);
  s.energy_relative_residual =
      s.energy_residual_J_per_m / std::max(std::abs(e.initial) + std::abs(e.external_work), 1e-300);
  s.max_temperature_K = sim.max_temperature();
  s.sections["mass_scaling"] = to_json(mass_scaling_report(sim, cutting));
  if (cutting) {
    s.sections["cutting_resolution"] =
        to_json(cutting_resolution(*cutting, workpiece_thermal_diffusivity_m2_per_s(*cutting, sim.scene())));
    s.sections["input_warnings"] = input_plausibility_warnings(*cutting, sim.scene());
  }
  for (const auto& r : sim.rigid_bodies()) {
    s.rigid_bodies.push_back({r.name, r.force, r.impulse, r.displacement, r.work, std::nullopt});
    if (!r.temperature_field.empty())
      s.rigid_bodies.back().max_temperature_K = *std::max_element(r.temperature_field.begin(), r.temperature_field.end());
  }
  if (sim.removed_particles() > 0) {
    s.removed_particles = sim.removed_particles();
    s.removed_mass_kg_per_m = sim.removed_mass();
  }
  return s;
}

std::string energy_residual_warning(double relative_residual) {
  if (!(std::abs(relative_residual) > kEnergyResidualWarning)) return "";
  return fmt::format("the energy balance leaves {:+.1f} % of the energy in unaccounted for (normally 0.5-1 %, warned "
                     "beyond {:g} %): the run is not resolved well enough for its numbers to be trusted (too few "
                     "cells or particles across the chip or the body, a speed or a time step at its limits); refine it",
                     100.0 * relative_residual, 100.0 * kEnergyResidualWarning);
}

json to_json(const RunSummary& s) {
  json j = s.sections;
  j["status"] = s.status;
  if (!s.message.empty()) j["message"] = s.message;
  j["mpmcut_version"] = s.mpmcut_version;
  j["source_revision"] = s.source_revision;
  j["model_version"] = s.model_version;
  j["title"] = s.title;
  j["case_file"] = s.case_file;
  j["particles"] = s.particles;
  j["grid_nodes"] = s.grid_nodes;
  j["cell_size_m"] = s.cell_size_m;
  j["steps"] = s.steps;
  j["simulated_time_s"] = s.simulated_time_s;
  j["end_time_s"] = s.end_time_s;
  j["wall_time_s"] = s.wall_time_s;
  j["threads"] = s.threads;
  j["particle_steps_per_s"] = s.particle_steps_per_s;
  json energy = json::object();
  for_each_energy_term(s.energy_J_per_m, [&](const char* key, double v) { energy[key] = v; });
  j["energy_J_per_m"] = energy;
  j["energy_balance"] = {{"residual_J_per_m", s.energy_residual_J_per_m},
                         {"relative_residual", s.energy_relative_residual}};
  if (const std::string w = energy_residual_warning(s.energy_relative_residual); !w.empty())
    j["energy_balance"]["warning"] = w;
  j["max_temperature_K"] = s.max_temperature_K;
  json rigid = json::array();
  for (const auto& r : s.rigid_bodies) {
    rigid.push_back({{"name", r.name},
                     {"force_N_per_m", vec_json(r.force_N_per_m)},
                     {"impulse_N_s_per_m", vec_json(r.impulse_N_s_per_m)},
                     {"displacement_m", vec_json(r.displacement_m)},
                     {"work_J_per_m", r.work_J_per_m}});
    if (r.max_temperature_K) rigid.back()["max_temperature_K"] = *r.max_temperature_K;
  }
  j["rigid_bodies"] = rigid;
  if (s.removed_particles) j["removed_particles"] = *s.removed_particles;
  if (s.removed_mass_kg_per_m) j["removed_mass_kg_per_m"] = *s.removed_mass_kg_per_m;
  if (!s.last_checkpoint.empty()) j["last_checkpoint"] = s.last_checkpoint;
  if (!s.resumed_from.empty()) j["resumed_from"] = s.resumed_from;
  // A cutting run always has the keys: null when the run ended before its steady window.
  const auto force = [&](const char* key, const std::optional<double>& v) {
    if (v) j[key] = *v;
    else if (s.is_cutting_run()) j[key] = nullptr;
  };
  force("mean_cutting_force_N_per_mm", s.mean_cutting_force_N_per_mm);
  force("mean_thrust_force_N_per_mm", s.mean_thrust_force_N_per_mm);
  return j;
}

RunSummary summary_from_json(const json& j) {
  if (!j.is_object()) throw std::runtime_error("summary.json: not a JSON object");
  RunSummary s;
  s.status = text(j, "status");
  s.message = text(j, "message");
  s.mpmcut_version = text(j, "mpmcut_version");
  s.source_revision = text(j, "source_revision");
  s.title = text(j, "title");
  s.case_file = text(j, "case_file");
  // A summary written at the start of a run has all of these; one from an older version may lack some.
  if (j.contains("particles")) s.particles = j["particles"].get<std::uint64_t>();
  if (j.contains("grid_nodes")) s.grid_nodes = j["grid_nodes"].get<std::uint64_t>();
  if (j.contains("steps")) s.steps = j["steps"].get<long>();
  if (j.contains("threads")) s.threads = j["threads"].get<int>();
  if (j.contains("model_version")) s.model_version = j["model_version"].get<int>();
  for (auto [key, value] : {std::pair{"cell_size_m", &s.cell_size_m}, {"simulated_time_s", &s.simulated_time_s},
                            {"end_time_s", &s.end_time_s}, {"wall_time_s", &s.wall_time_s},
                            {"particle_steps_per_s", &s.particle_steps_per_s},
                            {"max_temperature_K", &s.max_temperature_K}})
    if (j.contains(key)) *value = number(j, key);
  if (j.contains("energy_J_per_m"))
    for_each_energy_term(s.energy_J_per_m, [&](const char* key, double& v) {
      if (j["energy_J_per_m"].contains(key)) v = number(j["energy_J_per_m"], key);
    });
  if (j.contains("energy_balance")) {
    s.energy_residual_J_per_m = number(j["energy_balance"], "residual_J_per_m");
    s.energy_relative_residual = number(j["energy_balance"], "relative_residual");
  }
  if (j.contains("rigid_bodies"))
    for (const json& r : j["rigid_bodies"])
      s.rigid_bodies.push_back({text(r, "name"), vec(r, "force_N_per_m"), vec(r, "impulse_N_s_per_m"),
                                vec(r, "displacement_m"), number(r, "work_J_per_m"),
                                optional_number(r, "max_temperature_K")});
  if (j.contains("removed_particles")) s.removed_particles = j["removed_particles"].get<std::uint64_t>();
  s.removed_mass_kg_per_m = optional_number(j, "removed_mass_kg_per_m");
  s.last_checkpoint = text(j, "last_checkpoint");
  s.resumed_from = text(j, "resumed_from");
  s.mean_cutting_force_N_per_mm = optional_number(j, "mean_cutting_force_N_per_mm");
  s.mean_thrust_force_N_per_mm = optional_number(j, "mean_thrust_force_N_per_mm");
  for (const auto& [key, value] : j.items())
    if (std::find_if(std::begin(kTypedKeys), std::end(kTypedKeys), [&](const char* k) { return key == k; }) ==
        std::end(kTypedKeys))
      s.sections[key] = value;
  return s;
}

void write_summary(const std::filesystem::path& file, const RunSummary& s) { write_json_atomically(file, to_json(s)); }

RunSummary read_summary(const std::filesystem::path& file) {
  try {
    return summary_from_json(read_json(file));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(fmt::format("{}: {}", file.string(), e.what()));
  }
}

ChipHeadline chip_headline(const RunSummary& s) {
  ChipHeadline h;
  const json& sec = s.sections;
  if (sec.contains("chip") && sec["chip"].is_object() && sec["chip"].contains("classification") &&
      sec["chip"]["classification"].is_string())
    h.classification = sec["chip"]["classification"].get<std::string>();
  if (sec.contains("chip") && sec["chip"].is_object() && sec["chip"].contains("classification_confidence") &&
      sec["chip"]["classification_confidence"].is_string())
    h.classification_confidence = sec["chip"]["classification_confidence"].get<std::string>();
  h.segmentation_degree = section_number(sec, "chip", "segmentation_degree");
  h.pitch_m = section_number(sec, "chip", "pitch_m");
  h.segmentation_frequency_Hz = section_number(sec, "chip", "segmentation_frequency_Hz");
  h.chip_thickness_ratio = section_number(sec, "chip", "chip_thickness_ratio");
  h.chip_thickness_ratio_from_area = section_number(sec, "chip", "chip_thickness_ratio_from_area");
  if (sec.contains("chip_over_time") && sec["chip_over_time"].is_object()) {
    h.segmentation_degree_mean = section_number(sec["chip_over_time"], "segmentation_degree", "mean");
    h.segmentation_degree_min = section_number(sec["chip_over_time"], "segmentation_degree", "min");
    h.segmentation_degree_max = section_number(sec["chip_over_time"], "segmentation_degree", "max");
  }
  if (sec.contains("temperature") && sec["temperature"].is_object()) {
    h.shear_zone_max_K = section_number(sec["temperature"], "primary_shear_zone", "max_K");
    h.tool_chip_max_K = section_number(sec["temperature"], "tool_chip_interface", "max_K");
  }
  return h;
}

std::optional<double> mass_scaling_factor(const RunSummary& s) { return section_number(s.sections, "mass_scaling", "factor"); }

std::optional<double> tool_heat_share(const RunSummary& s) {
  return section_number(s.sections, "tool_heat", "steady_window_share_of_tool_work");
}

ToolForceSplit tool_force_split(const RunSummary& s) {
  ToolForceSplit t;
  t.rake_normal_N_per_mm = section_number(s.sections, "rake_face", "normal_force_N_per_mm");
  t.rake_friction_N_per_mm = section_number(s.sections, "rake_face", "friction_force_N_per_mm");
  t.rake_friction_work_N_per_mm = section_number(s.sections, "rake_face", "friction_work_per_travel_N_per_mm");
  t.edge_flank_friction_work_N_per_mm =
      section_number(s.sections, "edge_and_flank", "friction_work_per_travel_N_per_mm");
  t.rake_slip_speed_m_per_s = section_number(s.sections, "rake_face", "mean_slip_speed_m_per_s");
  if (s.sections.contains("edge_and_flank") && s.sections["edge_and_flank"].is_object()) {
    const json& ef = s.sections["edge_and_flank"];
    const auto thrust = [&](const char* region, const char* part) {
      return ef.contains(region) && ef[region].is_object() ? section_number(ef[region], part, "thrust_force_N_per_mm")
                                                           : std::nullopt;
    };
    t.edge_arc_normal_thrust_N_per_mm = thrust("edge_arc", "normal_part");
    t.edge_arc_friction_thrust_N_per_mm = thrust("edge_arc", "friction_part");
    t.flank_normal_thrust_N_per_mm = thrust("flank", "normal_part");
    t.flank_friction_thrust_N_per_mm = thrust("flank", "friction_part");
  }
  const std::optional<double> rake_angle = section_number(s.sections, "cutting", "rake_angle_deg");
  if (t.rake_normal_N_per_mm && t.rake_friction_N_per_mm && rake_angle && s.mean_cutting_force_N_per_mm &&
      s.mean_thrust_force_N_per_mm) {
    const Vec2 rake = rake_face_force_on_tool(*t.rake_normal_N_per_mm, *t.rake_friction_N_per_mm, *rake_angle);
    t.edge_flank_cutting_N_per_mm = *s.mean_cutting_force_N_per_mm - rake.x();
    t.edge_flank_thrust_N_per_mm = *s.mean_thrust_force_N_per_mm - rake.y();
  }
  return t;
}

std::optional<double> steady_drift_percent(const RunSummary& s, const char* force) {
  if (!s.sections.contains("steady_window") || !s.sections["steady_window"].is_object()) return std::nullopt;
  const std::string key = std::string(force) + "_force_percent";
  return section_number(s.sections["steady_window"], "drift", key.c_str());
}

}  // namespace mpmcut
