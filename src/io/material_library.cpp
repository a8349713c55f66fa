#include "io/material_library.hpp"

#include <cmath>

#include <fmt/format.h>

#include "io/embedded_text.hpp"

namespace mpmcut {

double fracture_energy_from_toughness(double toughness_Pa_sqrt_m, double youngs_modulus, double poisson_ratio) {
  return toughness_Pa_sqrt_m * toughness_Pa_sqrt_m * (1.0 - poisson_ratio * poisson_ratio) / youngs_modulus;
}

namespace {

std::string list_names(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names) text += (text.empty() ? "" : ", ") + ("\"" + n + "\"");
  return text.empty() ? "(none)" : text;
}

// Range checks after all keys are read, so that inherited (library) values are checked too.
void validate_material(TableReader& t, const MaterialParameters& m) {
  const bool jc = m.model == MaterialModel::JohnsonCook;
  t.check("density", m.density > 0.0, "a positive number (kg/m^3)", m.density);
  t.check("youngs_modulus", m.youngs_modulus > 0.0, "a positive number (Pa)", m.youngs_modulus);
  t.check("poisson_ratio", m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5, "in (-1, 0.5)", m.poisson_ratio);
  if (jc)
    t.check("specific_heat", m.specific_heat > 0.0, "a positive number (J/(kg K)) for johnson_cook (plastic heating)",
            m.specific_heat);
  else
    t.check("specific_heat", m.specific_heat >= 0.0, ">= 0 (J/(kg K))", m.specific_heat);
  t.check("thermal_conductivity", m.thermal_conductivity >= 0.0, ">= 0 (W/(m K))", m.thermal_conductivity);
  t.check("taylor_quinney", m.taylor_quinney >= 0.0 && m.taylor_quinney <= 1.0, "in [0, 1]", m.taylor_quinney);
  t.check("room_temperature", m.room_temperature > 0.0, "a positive temperature (K)", m.room_temperature);
  if (jc) {
    t.check("melting_temperature", m.melting_temperature > m.room_temperature,
            fmt::format("greater than room_temperature ({} K)", m.room_temperature), m.melting_temperature);
    t.check("jc_A", m.jc_A >= 0.0, ">= 0 (Pa)", m.jc_A);
    t.check("jc_B", m.jc_B >= 0.0, ">= 0 (Pa)", m.jc_B);
    t.check("jc_n", m.jc_n >= 0.0, ">= 0", m.jc_n);
    t.check("jc_C", m.jc_C >= 0.0, ">= 0", m.jc_C);
    t.check("jc_m", m.jc_m > 0.0, "> 0", m.jc_m);
    t.check("reference_strain_rate", m.reference_strain_rate > 0.0, "> 0 (1/s)", m.reference_strain_rate);
  }
  t.check("strain_rate_smoothing_time", m.strain_rate_smoothing_time >= 0.0, ">= 0 (s)",
          m.strain_rate_smoothing_time);
  if (m.eos == EquationOfState::MieGruneisen) {
    t.check("mg_c0", m.mg_c0 > 0.0, "> 0 (m/s) with eos = \"mie_gruneisen\"", m.mg_c0);
    t.check("mg_s", m.mg_s >= 0.0, ">= 0", m.mg_s);
    t.check("mg_gamma0", m.mg_gamma0 >= 0.0, ">= 0", m.mg_gamma0);
  }
  t.check("bulk_viscosity_linear", m.bulk_viscosity_linear >= 0.0, ">= 0", m.bulk_viscosity_linear);
  t.check("bulk_viscosity_quadratic", m.bulk_viscosity_quadratic >= 0.0, ">= 0", m.bulk_viscosity_quadratic);
  if (m.damage_enabled) {
    // Damage is driven by plastic strain, which an elastic material never has.
    t.check("damage", jc, "false unless model = \"johnson_cook\"", 1.0);
    t.check("min_failure_strain", m.min_failure_strain > 0.0, "> 0 (eps_f clamp; with D1 < 0 eps_f can reach 0)",
            m.min_failure_strain);
    // G_f = 0 is Abaqus' "instantaneous failure", which it warns causes dynamic instabilities.
    t.check("fracture_energy", m.fracture_energy > 0.0, "> 0 (J/m^2) when damage = true", m.fracture_energy);
  }
  t.check("fracture_energy", m.fracture_energy >= 0.0, ">= 0 (J/m^2)", m.fracture_energy);
  t.check("fracture_transition_strain_rate", m.fracture_transition_strain_rate >= 0.0,
          ">= 0 (1/s; 0 = fracture energy independent of rate)", m.fracture_transition_strain_rate);
  if (m.fracture_transition_strain_rate > 0.0) {
    t.check("fracture_energy_brittle", m.fracture_energy_brittle > 0.0,
            "> 0 (J/m^2, the high-rate fracture energy) when fracture_transition_strain_rate > 0",
            m.fracture_energy_brittle);
    t.check("fracture_transition_exponent", m.fracture_transition_exponent > 0.0, "> 0", m.fracture_transition_exponent);
  }
  t.check("max_damage", m.max_damage > 0.0 && m.max_damage <= 1.0, "in (0, 1]", m.max_damage);
}

}  // namespace

MaterialParameters read_material(TableReader& t, const MaterialLibrary& library) {
  MaterialParameters m;
  t.require_key("name", "the name bodies use to refer to this material");
  const bool from_library = t.has("library");
  if (from_library) {
    const std::string set = t.string("library", "");
    const MaterialParameters* base = library.find(set);
    if (base == nullptr)
      t.fail("library", fmt::format("no material set \"{}\"; available sets: {}", set, list_names(library.names())));
    m = *base;
  }
  m.name = t.string("name", "");
  t.check("name", !m.name.empty(), "a non-empty string", 0.0);
  m.citation = t.string("citation", m.citation);
  m.model = t.choice<MaterialModel>("model", {{"elastic", MaterialModel::Elastic}, {"johnson_cook", MaterialModel::JohnsonCook}},
                                    m.model);
  if (!from_library) {
    t.require_key("density", "kg/m^3");
    t.require_key("youngs_modulus", "Pa");
    t.require_key("poisson_ratio", "-");
    if (m.model == MaterialModel::JohnsonCook) {
      for (const char* key : {"jc_A", "jc_B", "jc_n", "jc_C", "jc_m", "melting_temperature", "specific_heat"})
        t.require_key(key, "needed by model = \"johnson_cook\"");
    }
  }
  m.density = t.number("density", m.density);
  m.youngs_modulus = t.number("youngs_modulus", m.youngs_modulus);
  m.poisson_ratio = t.number("poisson_ratio", m.poisson_ratio);
  m.specific_heat = t.number("specific_heat", m.specific_heat);
  m.thermal_conductivity = t.number("thermal_conductivity", m.thermal_conductivity);
  m.taylor_quinney = t.number("taylor_quinney", m.taylor_quinney);
  m.room_temperature = t.number("room_temperature", m.room_temperature);
  m.melting_temperature = t.number("melting_temperature", m.melting_temperature);
  m.jc_A = t.number("jc_A", m.jc_A);
  m.jc_B = t.number("jc_B", m.jc_B);
  m.jc_n = t.number("jc_n", m.jc_n);
  m.jc_C = t.number("jc_C", m.jc_C);
  m.jc_m = t.number("jc_m", m.jc_m);
  m.reference_strain_rate = t.number("reference_strain_rate", m.reference_strain_rate);
  m.strain_rate_smoothing_time = t.number("strain_rate_smoothing_time", m.strain_rate_smoothing_time);
  m.eos = t.choice<EquationOfState>(
      "eos", {{"linear", EquationOfState::Linear}, {"mie_gruneisen", EquationOfState::MieGruneisen}}, m.eos);
  m.mg_c0 = t.number("mg_c0", m.mg_c0);
  m.mg_s = t.number("mg_s", m.mg_s);
  m.mg_gamma0 = t.number("mg_gamma0", m.mg_gamma0);
  m.bulk_viscosity_linear = t.number("bulk_viscosity_linear", m.bulk_viscosity_linear);
  m.bulk_viscosity_quadratic = t.number("bulk_viscosity_quadratic", m.bulk_viscosity_quadratic);
  m.damage_enabled = t.boolean("damage", m.damage_enabled);
  m.jc_D1 = t.number("jc_D1", m.jc_D1);
  m.jc_D2 = t.number("jc_D2", m.jc_D2);
  m.jc_D3 = t.number("jc_D3", m.jc_D3);
  m.jc_D4 = t.number("jc_D4", m.jc_D4);
  m.jc_D5 = t.number("jc_D5", m.jc_D5);
  m.min_failure_strain = t.number("min_failure_strain", m.min_failure_strain);
  m.damage_triaxiality_cutoff = t.number("damage_triaxiality_cutoff", m.damage_triaxiality_cutoff);
  m.damage_evolution = t.choice<DamageEvolution>(
      "damage_evolution", {{"linear", DamageEvolution::Linear}, {"exponential", DamageEvolution::Exponential}},
      m.damage_evolution);
  m.fracture_energy = t.number("fracture_energy", m.fracture_energy);
  m.fracture_energy_brittle = t.number("fracture_energy_brittle", m.fracture_energy_brittle);
  m.fracture_transition_strain_rate = t.number("fracture_transition_strain_rate", m.fracture_transition_strain_rate);
  m.fracture_transition_exponent = t.number("fracture_transition_exponent", m.fracture_transition_exponent);
  m.max_damage = t.number("max_damage", m.max_damage);
  // Toughness is what handbooks give; the damage law needs the energy. Converted with the final
  // E and nu of this material (after library overrides).
  if (auto toughness = t.optional_number("fracture_toughness")) {
    if (t.has("fracture_energy")) t.fail("fracture_toughness", "give fracture_energy or fracture_toughness, not both");
    t.check("fracture_toughness", *toughness > 0.0, "a positive number (Pa sqrt(m))", *toughness);
    m.fracture_energy = fracture_energy_from_toughness(*toughness, m.youngs_modulus, m.poisson_ratio);
  }
  validate_material(t, m);
  t.reject_unknown_keys();
  return m;
}

void MaterialLibrary::add_file(std::string_view toml_text, const std::string& source_name) {
  toml::table root = parse_toml(toml_text, source_name);
  auto source = std::make_shared<InputSource>(InputSource{source_name, {}});
  TableReader file(root, "", source);
  for (TableReader& t : file.array_of_tables("material")) {
    MaterialParameters m = read_material(t, *this);
    if (find(m.name) != nullptr) t.fail("name", fmt::format("duplicate material set \"{}\"", m.name));
    sets_.push_back(std::move(m));
  }
  file.reject_unknown_keys();
}

const MaterialParameters* MaterialLibrary::find(std::string_view set_name) const {
  for (const auto& m : sets_)
    if (m.name == set_name) return &m;
  return nullptr;
}

std::vector<std::string> MaterialLibrary::names() const {
  std::vector<std::string> result;
  for (const auto& m : sets_) result.push_back(m.name);
  return result;
}

const MaterialLibrary& builtin_material_library() {
  static const MaterialLibrary library = [] {
    MaterialLibrary lib;
    for (const EmbeddedText& file : embedded_texts())
      if (file.path.starts_with("materials/")) lib.add_file(file.text, std::string(file.path));
    return lib;
  }();
  return library;
}

}  // namespace mpmcut
