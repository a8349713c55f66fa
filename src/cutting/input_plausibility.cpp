#include "cutting/input_plausibility.hpp"

#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace mpmcut {

namespace {

// A material key as the warnings name it: "material 'ti64': density".
std::string material_key(const MaterialParameters& m, const char* key) { return fmt::format("material '{}': {}", m.name, key); }

// The toughness K_IC = sqrt(G E / (1 - nu^2)) that gives this fracture energy: handbooks quote K_IC, so a slip
// of MPa sqrt(m) for Pa sqrt(m) shows as a G_f 12 orders too small.
double toughness_of(double fracture_energy, const MaterialParameters& m) {
  return std::sqrt(fracture_energy * m.youngs_modulus / (1.0 - m.poisson_ratio * m.poisson_ratio));
}

// `from_toughness`: the key may come from fracture_toughness (G_f does; the high-rate G_b has only its energy key).
void check_fracture_energy(std::vector<std::string>& out, const MaterialParameters& m, const char* key, double g,
                           bool from_toughness, const MetalPlausibility& b) {
  if (g >= b.min_fracture_energy_J_m2) return;
  const std::string slip =
      from_toughness ? fmt::format("(the toughness K_IC = {:.3g} Pa sqrt(m) with this E and nu) ", toughness_of(g, m))
                     : std::string();
  out.push_back(fmt::format("{} = {:.3g} J/m^2 {}is below {:g} J/m^2, less than glass's (about 10); a metal's is "
                            "1e3-1e5 J/m^2: {}",
                            material_key(m, key), g, slip, b.min_fracture_energy_J_m2,
                            from_toughness ? "a fracture_toughness in MPa sqrt(m) instead of Pa sqrt(m)?"
                                           : "an energy in kJ/m^2 instead of J/m^2?"));
}

void check_temperature(std::vector<std::string>& out, const std::string& key, double t, const MetalPlausibility& b) {
  if (t >= b.min_temperature_K) return;
  out.push_back(fmt::format("{} = {:g} K is below {:g} K: a temperature in degrees Celsius instead of kelvin "
                            "(K = degrees C + 273.15)?",
                            key, t, b.min_temperature_K));
}

}  // namespace

std::vector<std::string> input_plausibility_warnings(const CuttingParameters& c, const MaterialParameters& m,
                                                     const MetalPlausibility& b) {
  std::vector<std::string> out;
  if (m.density < b.min_density_kg_m3 || m.density > b.max_density_kg_m3)
    out.push_back(fmt::format("{} = {:g} kg/m^3 is outside {:g}-{:g} kg/m^3, where every machined metal lies "
                              "(magnesium 1740, osmium 22 590): a density in g/cm^3 (x 1000 for kg/m^3)?",
                              material_key(m, "density"), m.density, b.min_density_kg_m3, b.max_density_kg_m3));
  if (m.youngs_modulus < b.min_youngs_modulus_Pa || m.youngs_modulus > b.max_youngs_modulus_Pa)
    out.push_back(fmt::format("{} = {:.4g} Pa is outside {:.3g}-{:.3g} Pa (a metal's is 16 GPa for lead to 411 GPa "
                              "for tungsten): a modulus in GPa or MPa instead of Pa?",
                              material_key(m, "youngs_modulus"), m.youngs_modulus, b.min_youngs_modulus_Pa,
                              b.max_youngs_modulus_Pa));
  if (m.specific_heat < b.min_specific_heat_J_kgK || m.specific_heat > b.max_specific_heat_J_kgK)
    out.push_back(fmt::format("{} = {:g} J/(kg K) is outside {:g}-{:g} J/(kg K) (a metal's is 129 for lead to "
                              "1020 for magnesium): a value in kJ/(kg K) instead of J/(kg K)?",
                              material_key(m, "specific_heat"), m.specific_heat, b.min_specific_heat_J_kgK,
                              b.max_specific_heat_J_kgK));
  if (m.thermal_conductivity > 0.0 &&
      (m.thermal_conductivity < b.min_thermal_conductivity_W_mK || m.thermal_conductivity > b.max_thermal_conductivity_W_mK))
    out.push_back(fmt::format("{} = {:g} W/(m K) is outside {:g}-{:g} W/(m K) (a metal's is about 7 for Ti-6Al-4V to 429 "
                              "for silver): a value in W/(cm K) (x 100 for W/(m K)) or in another unit?",
                              material_key(m, "thermal_conductivity"), m.thermal_conductivity,
                              b.min_thermal_conductivity_W_mK, b.max_thermal_conductivity_W_mK));
  if (m.model == MaterialModel::JohnsonCook && m.jc_C > b.max_jc_C)
    out.push_back(fmt::format("{} = {:g} is above {:g} (metals' sets: 0.001-0.06, e.g. 0.014 for 4340 steel): the "
                              "strain-rate coefficient as a percentage (/ 100)?",
                              material_key(m, "jc_C"), m.jc_C, b.max_jc_C));
  if (m.model == MaterialModel::JohnsonCook && m.youngs_modulus > 0.0) {
    // A + B, the flow stress at a plastic strain of 1, against E: unit-free, so it holds for every metal.
    const double ratio = (m.jc_A + m.jc_B) / m.youngs_modulus;
    if (ratio < b.min_flow_stress_over_E || ratio > b.max_flow_stress_over_E)
      out.push_back(fmt::format(
          "{} + jc_B = {:.4g} Pa, the flow stress at a plastic strain of 1, is {:.3g} of E = {:.4g} Pa, outside "
          "{:g}-{:g} (metals: 0.003-0.02): A and B in MPa instead of Pa, or E in another unit than A and B?",
          material_key(m, "jc_A"), m.jc_A + m.jc_B, ratio, m.youngs_modulus, b.min_flow_stress_over_E,
          b.max_flow_stress_over_E));
    for (const auto& [key, term] : {std::pair{"jc_A", m.jc_A}, std::pair{"jc_B", m.jc_B}})
      if (term > 0.0 && term < b.min_flow_stress_term_over_E * m.youngs_modulus && ratio >= b.min_flow_stress_over_E)
        out.push_back(fmt::format("{} = {:.4g} Pa is {:.3g} of E = {:.4g} Pa, below {:g} (the softest metal sets: "
                                  "2e-4): a value in MPa instead of Pa, beside the other term in Pa?",
                                  material_key(m, key), term, term / m.youngs_modulus, m.youngs_modulus,
                                  b.min_flow_stress_term_over_E));
    check_temperature(out, material_key(m, "room_temperature"), m.room_temperature, b);
  }
  if (m.damage_enabled) {
    check_fracture_energy(out, m, "fracture_energy", m.fracture_energy, true, b);
    if (m.fracture_transition_strain_rate > 0.0)
      check_fracture_energy(out, m, "fracture_energy_brittle", m.fracture_energy_brittle, false, b);
  }
  if (m.fracture_energy_brittle > 0.0 && !(m.damage_enabled && m.fracture_transition_strain_rate > 0.0))
    out.push_back(fmt::format("{} = {:g} J/m^2 has no effect: it is the high-rate fracture energy of a rate-dependent "
                              "G_f, used only with damage = true and fracture_transition_strain_rate > 0",
                              material_key(m, "fracture_energy_brittle"), m.fracture_energy_brittle));
  check_temperature(out, "cutting.initial_temperature", c.initial_temperature, b);
  if (m.model == MaterialModel::JohnsonCook && m.melting_temperature > m.room_temperature) {
    const double homologous = (c.initial_temperature - m.room_temperature) / (m.melting_temperature - m.room_temperature);
    if (homologous >= b.max_initial_homologous_temperature)
      out.push_back(fmt::format(
          "cutting.initial_temperature = {:g} K is {:.0f} % of the way from the material's room to its melting "
          "temperature ({:g}-{:g} K): the Johnson-Cook flow stress starts at {:.2g} of its room-temperature value "
          "(1 - T*^m), a range no Johnson-Cook set is fitted to; is it meant?",
          c.initial_temperature, 100.0 * homologous, m.room_temperature, m.melting_temperature,
          homologous < 1.0 ? 1.0 - std::pow(homologous, m.jc_m) : 0.0));
  }
  if (c.tool_heat_transfer_coefficient > 0.0)
    check_temperature(out, "cutting.tool_temperature", c.tool_temperature, b);
  else if (c.tool_temperature != c.initial_temperature)
    out.push_back(fmt::format("cutting.tool_temperature = {:g} K has no effect: cutting.tool_heat_transfer_coefficient "
                              "is 0 (the tool's surface is adiabatic); give the coefficient for the tool to exchange "
                              "heat with the chip",
                              c.tool_temperature));
  if (c.tool_conductivity > 0.0 &&
      (c.tool_conductivity < b.min_tool_conductivity_W_mK || c.tool_conductivity > b.max_tool_conductivity_W_mK))
    out.push_back(fmt::format("cutting.tool_conductivity = {:g} W/(m K) is outside {:g}-{:g} W/(m K) (tool materials: "
                              "about 30 for alumina, 86 for a carbide tool, 2100 for diamond): a value in W/(cm K) or in "
                              "another unit?",
                              c.tool_conductivity, b.min_tool_conductivity_W_mK, b.max_tool_conductivity_W_mK));
  if (c.tool_volumetric_heat_capacity > 0.0 && (c.tool_volumetric_heat_capacity < b.min_tool_volumetric_heat_capacity ||
                                                c.tool_volumetric_heat_capacity > b.max_tool_volumetric_heat_capacity))
    out.push_back(fmt::format("cutting.tool_volumetric_heat_capacity = {:g} J/(m^3 K) is outside {:g}-{:g} J/(m^3 K) "
                              "(solids: a few 1e6, e.g. 3.5e6 for iron): the specific heat in "
                              "J/(kg K) instead of rho c (multiply by the density)?",
                              c.tool_volumetric_heat_capacity, b.min_tool_volumetric_heat_capacity,
                              b.max_tool_volumetric_heat_capacity));
  return out;
}

std::vector<std::string> input_plausibility_warnings(const CuttingParameters& c, const Scene& scene) {
  const int m = scene.material_index(c.material);
  if (m < 0) return {};
  return input_plausibility_warnings(c, scene.materials[m]);
}

}  // namespace mpmcut
