#pragma once
// Warnings on a cut's inputs that the keys' ranges accept but that no machined metal has: most often a
// number given in another unit than its key's (a density in g/cm^3, a yield stress in MPa, a temperature
// in degrees Celsius, a toughness in MPa sqrt(m)). Such a cut runs to "complete" with numbers that are
// wrong by orders of magnitude, so the run says so: on the console at its start, in summary.json
// (`input_warnings`) and in a study's message. They are warnings, not errors: a model material may mean
// them. Each names the key, its value with the unit, what is usual, and the likely slip.
#include <string>
#include <vector>

#include "cutting/cutting_parameters.hpp"
#include "physics/material_parameters.hpp"
#include "solver/scene.hpp"

namespace mpmcut {

// Bounds of what a machined metal has (with a margin), each from handbook values (docs/references.md:
// ASM Handbook Vol. 2, CRC Handbook): the lightest structural metal is magnesium (1740 kg/m^3), the densest
// osmium (22 590); Young's moduli run from lead (16 GPa) to tungsten (411 GPa); specific heats from lead
// (129 J/(kg K)) to magnesium (1020); Johnson-Cook A + B, the flow stress at a plastic strain of 1, lies at
// 0.3-2 % of E (OFHC copper 382 MPa / 124 GPa, 4340 steel 1302 MPa / 200 GPa); the Johnson-Cook strain-rate
// coefficient C of metals' sets is 0.001-0.06 (Johnson and Cook 1983: OFHC copper 0.025, Armco iron 0.06, 4340
// steel 0.014); thermal conductivities run from Ti-6Al-4V (about 7 W/(m K)) and manganese (7.8) to silver (429);
// the fracture energy of a metal is 1e3-1e5 J/m^2, of glass about 10.
struct MetalPlausibility {
  double min_density_kg_m3 = 1000.0;
  double max_density_kg_m3 = 25000.0;
  double min_youngs_modulus_Pa = 5e9;
  double max_youngs_modulus_Pa = 1.2e12;
  double min_specific_heat_J_kgK = 50.0;
  double max_specific_heat_J_kgK = 5000.0;
  double min_flow_stress_over_E = 1e-4;  // (A + B) / E
  double max_flow_stress_over_E = 0.1;
  // A or B alone, where given (> 0): a term in MPa beside the other in Pa leaves A + B plausible. The softest
  // terms of metals' sets are some 2e-4 E (OFHC copper's A = 90 MPa at E = 124 GPa); a slip is 1e-6 of its value.
  double min_flow_stress_term_over_E = 1e-5;
  // C as a percentage (1.4 for 0.014) is 100 times too large; no metal's set comes near 0.5.
  double max_jc_C = 0.5;
  // A conductivity in W/(cm K) is 100 times too small. 0 is allowed without a word: an adiabatic workpiece is a
  // model choice (docs/materials.md says an own set's conductivity defaults to 0).
  double min_thermal_conductivity_W_mK = 1.0;
  double max_thermal_conductivity_W_mK = 1000.0;
  double min_fracture_energy_J_m2 = 1.0;
  // A conducting tool: tool materials conduct from about 20-30 W/(m K) (alumina) to 2100 (diamond), the WC phase of
  // carbide 121 ([MitsubishiToolMaterials]), a carbide tool 86 ([SciRep2021Ti64Tool]); solids store rho c of a few
  // 1e6 J/(m^3 K) (about 3 R per mole of atoms: iron 7874 kg/m^3 x 449 J/(kg K) = 3.5e6, [CRC2016]), so a specific
  // heat in J/(kg K) given as rho c is a thousand times too small.
  double min_tool_conductivity_W_mK = 5.0;
  double max_tool_conductivity_W_mK = 2500.0;
  double min_tool_volumetric_heat_capacity = 5e5;
  double max_tool_volumetric_heat_capacity = 1e7;
  // Below: a temperature in degrees Celsius? (Room temperature in degrees C is 20-25; cryogenic machining with
  // liquid nitrogen, 77 K, is real practice and passes.)
  double min_temperature_K = 60.0;
  // A workpiece that starts this close to melting, T* = (T0 - T_room) / (T_melt - T_room), has almost no strength
  // (Johnson-Cook: the flow stress times 1 - T*^m): a Johnson-Cook set is not fitted there.
  double max_initial_homologous_temperature = 0.75;
};

std::vector<std::string> input_plausibility_warnings(const CuttingParameters& c, const MaterialParameters& workpiece,
                                                     const MetalPlausibility& bounds = {});

// The same for the workpiece of a scene built from `c` (none if the scene has no such material).
std::vector<std::string> input_plausibility_warnings(const CuttingParameters& c, const Scene& scene);

}  // namespace mpmcut
