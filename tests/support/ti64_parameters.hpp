#pragma once
// Ti-6Al-4V parameters shared by the material tests, written out here (not taken from the
// library) so that a change to materials/*.toml cannot silently change what the tests check.
// Johnson 1985 flow stress: A 862 MPa, B 331 MPa, n 0.34, C 0.012, m 0.8, T_m 1878 K (as most
// cutting papers; docs/materials.md); elastic/thermal constants after Sandia Payette (E 113.8 GPa, nu 0.342, c 526.3 J/(kg K));
// damage D1..D5 = -0.09, 0.25, -0.5, 0.014, 3.87 (Johnson-Holmquist/Lesuer; docs/references.md).
#include "physics/material_parameters.hpp"

namespace mpmcut::testing {

inline MaterialParameters ti64_johnson_1985() {
  MaterialParameters m;
  m.name = "ti64-johnson-1985";
  m.model = MaterialModel::JohnsonCook;
  m.density = 4430.0;
  m.youngs_modulus = 113.8e9;
  m.poisson_ratio = 0.342;
  m.specific_heat = 526.3;
  m.taylor_quinney = 0.9;
  m.room_temperature = 298.0;
  m.melting_temperature = 1878.0;
  m.jc_A = 862e6;
  m.jc_B = 331e6;
  m.jc_n = 0.34;
  m.jc_C = 0.012;
  m.jc_m = 0.8;
  m.reference_strain_rate = 1.0;
  return m;
}

// `m` with the TANH softening of Sima & Oezel 2010, model 3: a = 2, b = 5, c = 2, d = 1, s = 0.05
// (docs/theory_materials.md 2.5, docs/materials.md).
inline MaterialParameters with_sima_ozel_softening(MaterialParameters m) {
  m.flow_softening = FlowSoftening::Tanh;
  m.tanh_a = 2.0;
  m.tanh_b = 5.0;
  m.tanh_c = 2.0;
  m.tanh_d = 1.0;
  m.tanh_s = 0.05;
  return m;
}

// Sima & Oezel 2010 model 3: the Lee & Lin 1998 set b (A 724.7 MPa, B 683.1 MPa, n 0.47, C 0.035, m 1) with
// their TANH softening; the other constants as ti64_johnson_1985.
inline MaterialParameters ti64_sima_ozel_2010() {
  MaterialParameters m = ti64_johnson_1985();
  m.name = "ti64-sima-ozel-2010";
  m.jc_A = 724.7e6;
  m.jc_B = 683.1e6;
  m.jc_n = 0.47;
  m.jc_C = 0.035;
  m.jc_m = 1.0;
  return with_sima_ozel_softening(m);
}

// `m` with Johnson-Cook damage initiation and Hillerborg evolution switched on.
inline MaterialParameters with_jc_damage(MaterialParameters m, DamageEvolution law = DamageEvolution::Linear,
                                         double G_f = 2.0e4) {
  m.damage_enabled = true;
  m.jc_D1 = -0.09;
  m.jc_D2 = 0.25;
  m.jc_D3 = -0.5;
  m.jc_D4 = 0.014;
  m.jc_D5 = 3.87;
  m.min_failure_strain = 0.01;
  m.damage_evolution = law;
  m.fracture_energy = G_f;
  m.max_damage = 0.999;
  return m;
}

}  // namespace mpmcut::testing
