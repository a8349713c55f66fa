#pragma once
// The material of the grid-level Hillerborg tests (tests/verification/test_hillerborg_*.cpp): Ti-6Al-4V's elastic
// constants with an elastic-perfectly plastic Johnson-Cook flow stress, no heating and a failure strain that is
// the same for every triaxiality, rate and temperature, so that the softening law alone sets the dissipation.
#include <algorithm>
#include <string>

#include "physics/material_parameters.hpp"

namespace mpmcut::testing::hillerborg {

constexpr double kE = 113.8e9, kNu = 0.342, kRho = 4430.0;  // Ti-6Al-4V elastic constants (Payette)
constexpr double kYield = 200e6;   // Pa: low, so that u_f/h stays below 1 on the finest grid with a G_f
                                   // large against the elastic release h Y
constexpr double kFractureEnergy = 500.0;  // J/m^2: u_f = 2 G_f/sigma_y = 5 um (linear law)

inline MaterialParameters layer_material(const std::string& name, DamageEvolution law, double failure_strain,
                                         double yield = kYield) {
  MaterialParameters m;
  m.name = name;
  m.model = MaterialModel::JohnsonCook;
  m.density = kRho;
  m.youngs_modulus = kE;
  m.poisson_ratio = kNu;
  m.specific_heat = 526.3;
  m.taylor_quinney = 0.0;  // no heating: T stays at T_r, so no thermal softening
  m.melting_temperature = 1878.0;
  m.jc_A = yield;
  m.jc_B = 0.0;  // perfectly plastic: sigma_y = sigma_y0 after initiation, so the linear law gives G_f exactly
  m.jc_C = 0.0;  // rate independent
  m.damage_enabled = true;
  m.jc_D1 = failure_strain;  // eps_f = D1 for every triaxiality, rate and temperature
  m.min_failure_strain = std::min(0.01, failure_strain);
  m.damage_evolution = law;
  m.fracture_energy = kFractureEnergy;
  m.max_damage = 0.999;
  return m;
}

}  // namespace mpmcut::testing::hillerborg
