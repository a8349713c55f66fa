// Warnings on a cut's inputs in a wrong unit (src/cutting/input_plausibility.*): every library set that can
// be cut passes without one, and each usual slip (g/cm^3, GPa, MPa, kJ/(kg K), W/(cm K), C in percent,
// MPa sqrt(m), degrees Celsius)
// gives exactly its own warning, naming the key and the likely unit.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cutting/input_plausibility.hpp"
#include "io/material_library.hpp"

namespace mpmcut {
namespace {

MaterialParameters library_set(const std::string& name) {
  const MaterialParameters* m = builtin_material_library().find(name);
  EXPECT_NE(m, nullptr) << name;
  return m ? *m : MaterialParameters{};
}

// The one warning of `warnings`, which must contain every piece of `expected`.
void expect_one_warning(const std::vector<std::string>& warnings, const std::vector<std::string>& expected) {
  ASSERT_EQ(warnings.size(), 1u) << (warnings.empty() ? "none" : warnings.front() + " ... and more");
  for (const std::string& piece : expected) EXPECT_NE(warnings[0].find(piece), std::string::npos) << warnings[0];
}

TEST(InputPlausibility, EveryLibrarySetThatCanBeCutHasNoWarning) {
  int cut_sets = 0;
  for (const std::string& name : builtin_material_library().names()) {
    const MaterialParameters m = library_set(name);
    if (m.model != MaterialModel::JohnsonCook) continue;
    ++cut_sets;
    EXPECT_TRUE(input_plausibility_warnings(CuttingParameters{}, m).empty())
        << name << ": " << input_plausibility_warnings(CuttingParameters{}, m).front();
  }
  EXPECT_GE(cut_sets, 5);
}

TEST(InputPlausibility, TheLightestAndDensestMetalsAndTheirModuliPass) {
  MaterialParameters m = library_set("ti64-cutting");
  for (const double density : {1740.0, 22590.0}) {  // magnesium, osmium
    m.density = density;
    EXPECT_TRUE(input_plausibility_warnings(CuttingParameters{}, m).empty()) << density;
  }
  m = library_set("ti64-cutting");
  const double strength = m.jc_A + m.jc_B;
  for (const double e : {16e9, 411e9}) {  // lead, tungsten, at a flow stress of 0.5 % of E
    m.youngs_modulus = e;
    m.jc_A = 0.005 * e * m.jc_A / strength;
    m.jc_B = 0.005 * e - m.jc_A;
    EXPECT_TRUE(input_plausibility_warnings(CuttingParameters{}, m).empty()) << e;
  }
}

TEST(InputPlausibility, EachUnitSlipGivesItsOwnWarning) {
  const MaterialParameters ti = library_set("ti64-cutting");
  const CuttingParameters cut;
  MaterialParameters m = ti;
  m.density = 4.43;  // g/cm^3
  expect_one_warning(input_plausibility_warnings(cut, m), {"density = 4.43 kg/m^3", "g/cm^3"});
  m = ti;
  m.specific_heat = 0.5263;  // kJ/(kg K)
  expect_one_warning(input_plausibility_warnings(cut, m), {"specific_heat = 0.5263", "kJ/(kg K)"});
  m = ti;
  m.thermal_conductivity = 0.067;  // W/(cm K)
  expect_one_warning(input_plausibility_warnings(cut, m), {"thermal_conductivity = 0.067 W/(m K)", "W/(cm K)"});
  m.thermal_conductivity = 0.0;  // adiabatic: a model choice
  EXPECT_TRUE(input_plausibility_warnings(cut, m).empty());
  m.thermal_conductivity = 429.0;  // silver
  EXPECT_TRUE(input_plausibility_warnings(cut, m).empty());
  m = ti;
  m.jc_C = 100.0 * ti.jc_C;  // percent
  expect_one_warning(input_plausibility_warnings(cut, m), {"jc_C = ", "as a percentage"});
  m.jc_C = 0.06;  // Armco iron
  EXPECT_TRUE(input_plausibility_warnings(cut, m).empty());
  m = ti;
  m.jc_A *= 1e-6;  // MPa
  m.jc_B *= 1e-6;
  expect_one_warning(input_plausibility_warnings(cut, m), {"jc_A + jc_B", "MPa instead of Pa"});
  m = ti;
  m.fracture_energy = fracture_energy_from_toughness(65.0, m.youngs_modulus, m.poisson_ratio);  // MPa sqrt(m)
  m.fracture_energy_brittle = 0.0;
  m.fracture_transition_strain_rate = 0.0;
  expect_one_warning(input_plausibility_warnings(cut, m), {"fracture_energy = 3.28e-08", "K_IC = 65 Pa sqrt(m)",
                                                           "MPa sqrt(m)"});
  m = ti;
  m.fracture_energy_brittle = 0.5;  // kJ/m^2: G_b has no toughness key
  expect_one_warning(input_plausibility_warnings(cut, m), {"fracture_energy_brittle = 0.5 J/m^2 is below",
                                                           "kJ/m^2 instead of J/m^2"});
  EXPECT_EQ(input_plausibility_warnings(cut, m)[0].find("K_IC"), std::string::npos);
}

// One term in MPa beside the other in Pa leaves A + B plausible (A = 1000 Pa with B = 331 MPa): each term alone is
// checked too, and a set without A (OFHC copper-like A = 0) passes.
TEST(InputPlausibility, OneFlowStressTermInMegapascalsIsFlagged) {
  MaterialParameters m = library_set("ti64-johnson-1985");
  m.jc_A = 1000.0;
  expect_one_warning(input_plausibility_warnings(CuttingParameters{}, m), {"jc_A = 1000 Pa", "MPa instead of Pa"});
  m = library_set("ti64-johnson-1985");
  m.jc_B = 331.0;
  expect_one_warning(input_plausibility_warnings(CuttingParameters{}, m), {"jc_B = 331 Pa"});
  m = library_set("ti64-johnson-1985");
  m.jc_B += m.jc_A;
  m.jc_A = 0.0;
  EXPECT_TRUE(input_plausibility_warnings(CuttingParameters{}, m).empty());
}

TEST(InputPlausibility, AModulusInGigapascalsIsNamedBesideTheFlowStressItDistorts) {
  MaterialParameters m = library_set("ti64-cutting");
  m.youngs_modulus = 113.8;
  const std::vector<std::string> w = input_plausibility_warnings(CuttingParameters{}, m);
  ASSERT_GE(w.size(), 2u);
  EXPECT_NE(w[0].find("youngs_modulus = 113.8 Pa"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("GPa"), std::string::npos) << w[0];
  EXPECT_NE(w[1].find("jc_A + jc_B"), std::string::npos) << w[1];
}

TEST(InputPlausibility, TemperaturesInCelsiusAreFlagged) {
  MaterialParameters m = library_set("ti64-cutting");
  m.room_temperature = 25.0;
  m.melting_temperature = 1604.0;
  CuttingParameters cut;
  cut.initial_temperature = 25.0;
  cut.tool_temperature = 25.0;
  const std::vector<std::string> w = input_plausibility_warnings(cut, m);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NE(w[0].find("room_temperature = 25 K"), std::string::npos) << w[0];
  EXPECT_NE(w[1].find("cutting.initial_temperature = 25 K"), std::string::npos) << w[1];
  EXPECT_NE(w[1].find("degrees Celsius"), std::string::npos) << w[1];
  // Cryogenic machining (liquid nitrogen, 77 K) is no slip.
  cut.initial_temperature = 77.0;
  cut.tool_temperature = 77.0;
  m = library_set("ti64-cutting");
  EXPECT_TRUE(input_plausibility_warnings(cut, m).empty()) << input_plausibility_warnings(cut, m).front();
  cut.tool_heat_transfer_coefficient = 1e5;
  EXPECT_TRUE(input_plausibility_warnings(cut, m).empty());
  cut.tool_heat_transfer_coefficient = 0.0;
  cut.tool_temperature = 25.0;
  // The tool's temperature only where it acts: with a heat-transfer coefficient.
  cut.initial_temperature = 298.0;
  m = library_set("ti64-cutting");
  cut.tool_heat_transfer_coefficient = 1e5;
  expect_one_warning(input_plausibility_warnings(cut, m), {"cutting.tool_temperature = 25 K"});
}

// A conducting tool's conductivity in W/(cm K) (0.86 for carbide) and a specific heat given as rho c (230 J/(kg K)
// for carbide) are named; carbide's own values (86 W/(m K), 3e6 J/(m^3 K)) and diamond's (2000) pass.
TEST(InputPlausibility, AConductingToolInAnotherUnitIsNamed) {
  const MaterialParameters m = library_set("ti64-cutting");
  CuttingParameters cut;
  cut.material = m.name;
  cut.tool_heat_transfer_coefficient = 1e6;
  cut.tool_conductivity = 86.0;
  cut.tool_volumetric_heat_capacity = 3e6;
  EXPECT_TRUE(input_plausibility_warnings(cut, m).empty());
  cut.tool_conductivity = 2000.0;
  EXPECT_TRUE(input_plausibility_warnings(cut, m).empty());
  cut.tool_conductivity = 0.86;
  expect_one_warning(input_plausibility_warnings(cut, m), {"cutting.tool_conductivity = 0.86 W/(m K)", "W/(cm K)"});
  cut.tool_conductivity = 86.0;
  cut.tool_volumetric_heat_capacity = 230.0;
  expect_one_warning(input_plausibility_warnings(cut, m),
                     {"cutting.tool_volumetric_heat_capacity = 230 J/(m^3 K)", "multiply by the density"});
}

// A workpiece that starts near melting has almost no strength (1850 K: Fc 3.6 N/mm, a "continuous" chip); a
// preheated one (hot machining, 600 K) is no slip.
TEST(InputPlausibility, AWorkpieceStartingNearItsMeltingTemperatureIsNamed) {
  const MaterialParameters m = library_set("ti64-cutting");
  CuttingParameters cut;
  cut.initial_temperature = 1850.0;
  cut.tool_temperature = 1850.0;
  expect_one_warning(input_plausibility_warnings(cut, m),
                     {"cutting.initial_temperature = 1850 K", "98 % of the way", "melting"});
  cut.initial_temperature = cut.tool_temperature = 600.0;
  EXPECT_TRUE(input_plausibility_warnings(cut, m).empty());
}

TEST(InputPlausibility, ParametersThatActOnNothingAreNamed) {
  const MaterialParameters m = library_set("ti64-cutting");
  CuttingParameters cut;
  cut.tool_temperature = 600.0;  // an adiabatic tool (coefficient 0)
  expect_one_warning(input_plausibility_warnings(cut, m), {"tool_temperature = 600 K has no effect",
                                                           "tool_heat_transfer_coefficient"});
  MaterialParameters rate_independent = m;
  rate_independent.fracture_transition_strain_rate = 0.0;  // G_b without its transition
  expect_one_warning(input_plausibility_warnings(CuttingParameters{}, rate_independent),
                     {"fracture_energy_brittle", "has no effect", "fracture_transition_strain_rate > 0"});
}

}  // namespace
}  // namespace mpmcut
