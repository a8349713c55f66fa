#include "io/material_library.hpp"

#include <cmath>
#include <algorithm>

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
  // Upper bounds: beyond every engineering material by an order of magnitude (docs/reliability.md);
  // they keep wave speeds, time steps and energies representable.
  const bool jc = m.model == MaterialModel::JohnsonCook;
  const Range dimensionless = Range::closed(0.0, 10.0);
  t.check("density", m.density, Range::open_closed(0.0, 1e5, "kg/m^3"));
  t.check("youngs_modulus", m.youngs_modulus, Range::open_closed(0.0, 1e13, "Pa"));
  t.check("poisson_ratio", m.poisson_ratio, Range::open(-1.0, 0.5));
  if (jc)
    t.check("specific_heat", m.specific_heat,
            Range::open_closed(0.0, 1e5, "J/(kg K)", "positive for johnson_cook: plastic heating"));
  else
    t.check("specific_heat", m.specific_heat, Range::closed(0.0, 1e5, "J/(kg K)"));
  t.check("thermal_conductivity", m.thermal_conductivity, Range::closed(0.0, 1e4, "W/(m K)"));
  t.check("taylor_quinney", m.taylor_quinney, Range::closed(0.0, 1.0));
  t.check("room_temperature", m.room_temperature, Range::open(0.0, 1e4, "K"));
  // A key the model uses is checked against its range; one it does not use is still checked, so
  // that a wrong value does not hide until the model is switched on, against the same range
  // widened to admit 0 (its default, which the expanded scene.toml writes back).
  const auto check_model_key = [&](const char* key, double value, bool used, Range range) {
    if (!used) range.min = std::min(range.min, 0.0), range.min_open = false, range.note = "";
    t.check(key, value, range);
  };
  check_model_key("melting_temperature", m.melting_temperature, jc,
                  Range::open_closed(m.room_temperature, 1e4, "K", "above room_temperature"));
  check_model_key("jc_A", m.jc_A, jc, Range::closed(0.0, 1e11, "Pa"));
  check_model_key("jc_B", m.jc_B, jc, Range::closed(0.0, 1e11, "Pa"));
  check_model_key("jc_n", m.jc_n, jc, dimensionless);
  check_model_key("jc_C", m.jc_C, jc, dimensionless);
  check_model_key("jc_m", m.jc_m, jc, Range::open_closed(0.0, 10.0));
  check_model_key("reference_strain_rate", m.reference_strain_rate, jc, Range::open_closed(0.0, 1e12, "1/s"));
  t.check("strain_rate_smoothing_time", m.strain_rate_smoothing_time, Range::closed(0.0, 1.0, "s"));
  const bool mg = m.eos == EquationOfState::MieGruneisen;
  check_model_key("mg_c0", m.mg_c0, mg, Range::open_closed(0.0, 1e5, "m/s", "with eos = \"mie_gruneisen\""));
  check_model_key("mg_s", m.mg_s, mg, dimensionless);
  check_model_key("mg_gamma0", m.mg_gamma0, mg, dimensionless);
  t.check("bulk_viscosity_linear", m.bulk_viscosity_linear, dimensionless);
  t.check("bulk_viscosity_quadratic", m.bulk_viscosity_quadratic, dimensionless);
  for (const auto& [key, value] : {std::pair{"jc_D1", m.jc_D1}, {"jc_D2", m.jc_D2}, {"jc_D3", m.jc_D3},
                                   {"jc_D4", m.jc_D4}, {"jc_D5", m.jc_D5}})
    t.check(key, value, Range::closed(-100.0, 100.0));
  t.check("damage_triaxiality_cutoff", m.damage_triaxiality_cutoff, Range::closed(-100.0, 100.0));
  if (!m.damage_enabled) check_model_key("min_failure_strain", m.min_failure_strain, false, Range::open_closed(0.0, 100.0));
  if (m.damage_enabled) {
    // Damage is driven by plastic strain, which an elastic material never has.
    t.check("damage", jc, "false unless model = \"johnson_cook\"", 1.0);
    t.check("min_failure_strain", m.min_failure_strain,
            Range::open_closed(0.0, 100.0, "", "eps_f clamp; with D1 < 0 eps_f can reach 0"));
    // G_f = 0 is Abaqus' "instantaneous failure", which it warns causes dynamic instabilities.
    t.check("fracture_energy", m.fracture_energy, Range::open_closed(0.0, 1e8, "J/m^2", "positive when damage = true"));
  }
  t.check("fracture_energy", m.fracture_energy, Range::closed(0.0, 1e8, "J/m^2"));
  t.check("fracture_transition_strain_rate", m.fracture_transition_strain_rate,
          Range::closed(0.0, 1e12, "1/s", "0 = fracture energy independent of rate"));
  const bool rate_dependent = m.fracture_transition_strain_rate > 0.0;
  check_model_key("fracture_energy_brittle", m.fracture_energy_brittle, rate_dependent,
                  Range::open_closed(0.0, 1e8, "J/m^2", "the high-rate fracture energy, when fracture_transition_strain_rate > 0"));
  check_model_key("fracture_transition_exponent", m.fracture_transition_exponent, rate_dependent,
                  Range::open_closed(0.0, 100.0));
  t.check("max_damage", m.max_damage, Range::open_closed(0.0, 1.0));
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
    t.check("fracture_toughness", *toughness, Range::open_closed(0.0, 1e10, "Pa sqrt(m)"));
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
