// The built-in material library (materials/*.toml, compiled in): every set is present with the
// published numbers (docs/materials.md, docs/references.md), the toughness -> fracture energy conversion
// (plane-strain LEFM), and library files are validated like case files.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

#include "io/input_error.hpp"
#include "io/material_library.hpp"
#include "../support/ti64_parameters.hpp"

namespace mpmcut {
namespace {

struct JcSet {
  const char* name;
  double A_MPa, B_MPa, n, C, m, melting_K, room_K;
};

// docs/materials.md (and the choices documented in materials/ti6al4v.toml).
const JcSet kTi64Sets[] = {
    {"ti64-johnson-1985", 862.0, 331.0, 0.34, 0.012, 0.8, 1878.0, 298.0},
    {"ti64-lee-lin-1998", 782.7, 498.4, 0.28, 0.028, 1.0, 1878.0, 298.0},
    {"ti64-lee-lin-1998-sima", 724.7, 683.1, 0.47, 0.035, 1.0, 1878.0, 298.0},
    {"ti64-seo-2005", 997.9, 653.1, 0.45, 0.0198, 0.7, 1873.0, 293.0},
    {"ti64-lesuer-2000", 1098.0, 1092.0, 0.93, 0.014, 1.1, 1905.15, 293.15},
};

TEST(MaterialLibrary, HasTheTi64JohnsonCookSetsWithPublishedConstants) {
  const MaterialLibrary& lib = builtin_material_library();
  for (const JcSet& s : kTi64Sets) {
    SCOPED_TRACE(s.name);
    const MaterialParameters* m = lib.find(s.name);
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->model, MaterialModel::JohnsonCook);
    EXPECT_FALSE(m->citation.empty());
    EXPECT_DOUBLE_EQ(m->jc_A, s.A_MPa * 1e6);
    EXPECT_DOUBLE_EQ(m->jc_B, s.B_MPa * 1e6);
    EXPECT_DOUBLE_EQ(m->jc_n, s.n);
    EXPECT_DOUBLE_EQ(m->jc_C, s.C);
    EXPECT_DOUBLE_EQ(m->jc_m, s.m);
    EXPECT_DOUBLE_EQ(m->melting_temperature, s.melting_K);
    EXPECT_DOUBLE_EQ(m->room_temperature, s.room_K);
    EXPECT_DOUBLE_EQ(m->reference_strain_rate, 1.0);
    // Johnson–Holmquist / Lesuer damage constants (Abaqus VUMAT deck [V]).
    EXPECT_TRUE(m->damage_enabled);
    EXPECT_DOUBLE_EQ(m->jc_D1, -0.09);
    EXPECT_DOUBLE_EQ(m->jc_D2, 0.25);
    EXPECT_DOUBLE_EQ(m->jc_D3, -0.5);
    EXPECT_DOUBLE_EQ(m->jc_D4, 0.014);
    EXPECT_DOUBLE_EQ(m->jc_D5, 3.87);
    // Elastic and thermal constants of docs/materials.md; P-wave speed 6313 m/s (computed).
    EXPECT_DOUBLE_EQ(m->density, 4430.0);
    EXPECT_NEAR(m->p_wave_speed(), 6313.0, 5.0);
    EXPECT_GT(m->specific_heat, 0.0);
    // G_f from K_IC = 65 MPa sqrt(m): 32.8 kJ/m^2 (computed).
    EXPECT_NEAR(m->fracture_energy, 32.8e3, 0.1e3);
  }
}

// The cutting calibration (docs/materials.md): the Johnson 1985 set with G_f 15 -> 5 kJ/m^2 around 2e6 1/s,
// nothing else changed.
// Library set `name` is set `base` with only what `change` sets changed (and its own name and citation).
void expect_derived_set(const char* name, const char* base, const std::function<void(MaterialParameters&)>& change) {
  const MaterialLibrary& lib = builtin_material_library();
  const MaterialParameters* set = lib.find(name);
  ASSERT_NE(set, nullptr) << name;
  MaterialParameters expected = *lib.find(base);
  expected.name = set->name;
  expected.citation = set->citation;
  change(expected);
  EXPECT_TRUE(*set == expected) << name;
}

TEST(MaterialLibrary, CuttingSetIsJohnson1985WithTheRateDependentFractureEnergy) {
  expect_derived_set("ti64-cutting", "ti64-johnson-1985", [](MaterialParameters& m) {
    m.fracture_energy = 15e3;
    m.fracture_energy_brittle = 5e3;
    m.fracture_transition_strain_rate = 2e6;
    m.fracture_transition_exponent = 4.0;
  });
}

// The set identified by `mpmcut calibrate` (docs/results/calibration): ti64-cutting with the fitted A and m,
// nothing else changed; the same values as the calibration's best_material.toml.
TEST(MaterialLibrary, KlippelCalibratedSetIsTheCuttingSetWithTheFittedAAndM) {
  expect_derived_set("ti64-klippel-2speed", "ti64-cutting", [](MaterialParameters& m) {
    m.jc_A = 889.482e6;
    m.jc_m = 1.14036;
  });
  EXPECT_NE(builtin_material_library().find("ti64-klippel-2speed")->citation.find("Klippel"), std::string::npos);
}

// The set identified with crack friction and a conducting tool (docs/results/calibration_crack_friction): ti64-cutting
// with the fitted B, the fixed speed-ends n and m and crack friction, nothing else changed; the values of the
// calibration's best_material.toml to six digits.
TEST(MaterialLibrary, CrackFrictionCalibratedSetIsTheCuttingSetWithItsFittedAndFixedKeys) {
  expect_derived_set("ti64-klippel-crack-friction", "ti64-cutting", [](MaterialParameters& m) {
    m.jc_B = 442.495e6;
    m.jc_n = 0.273163;
    m.jc_m = 1.027186;
    m.crack_friction = 0.5;
  });
  const std::string citation = builtin_material_library().find("ti64-klippel-crack-friction")->citation;
  EXPECT_NE(citation.find("Klippel"), std::string::npos);
  EXPECT_NE(citation.find("friction = 0.356"), std::string::npos);
}

// Sima & Oezel 2010 model 3: the Lee & Lin set b with the TANH softening switched on, nothing else changed.
TEST(MaterialLibrary, SimaOzelSetIsLeeLinBWithTheTanhSoftening) {
  expect_derived_set("ti64-sima-ozel-2010", "ti64-lee-lin-1998-sima",
                     [](MaterialParameters& m) { m = testing::with_sima_ozel_softening(m); });
}

TEST(MaterialLibrary, HasGenericElasticSets) {
  const MaterialLibrary& lib = builtin_material_library();
  for (const char* name : {"elastic-unit", "elastic-steel", "elastic-aluminium", "elastic-tungsten-carbide"}) {
    SCOPED_TRACE(name);
    const MaterialParameters* m = lib.find(name);
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->model, MaterialModel::Elastic);
    EXPECT_GT(m->p_wave_speed(), 0.0);
  }
  const MaterialParameters& unit = *lib.find("elastic-unit");
  EXPECT_DOUBLE_EQ(unit.youngs_modulus, 1000.0);
  EXPECT_DOUBLE_EQ(unit.poisson_ratio, 0.3);
  EXPECT_DOUBLE_EQ(unit.density, 1000.0);
  EXPECT_EQ(lib.find("no-such-set"), nullptr);
}

TEST(MaterialLibrary, NamesListsEverySetOnce) {
  const auto names = builtin_material_library().names();
  EXPECT_EQ(names.size(), builtin_material_library().sets().size());
  for (const auto& n : names) EXPECT_EQ(std::count(names.begin(), names.end(), n), 1) << n;
  EXPECT_NE(std::find(names.begin(), names.end(), "ti64-seo-2005"), names.end());
}

// Plane-strain LEFM: G_f = K_IC^2 (1 - nu^2) / E; E = 113.8 GPa, nu = 0.342:
// K_IC = 55 -> 23.5, 75 -> 43.6, 100 -> 78 kJ/m^2 (computed).
TEST(MaterialLibrary, FractureToughnessToEnergyPlaneStrain) {
  EXPECT_NEAR(fracture_energy_from_toughness(55e6, 113.8e9, 0.342), 23.5e3, 0.1e3);
  EXPECT_NEAR(fracture_energy_from_toughness(75e6, 113.8e9, 0.342), 43.6e3, 0.1e3);
  EXPECT_NEAR(fracture_energy_from_toughness(100e6, 113.8e9, 0.342), 78e3, 0.5e3);
  EXPECT_DOUBLE_EQ(fracture_energy_from_toughness(2.0, 4.0, 0.0), 1.0);
}

TEST(MaterialLibrary, FileMayDeriveASetFromAnEarlierOne) {
  MaterialLibrary lib;
  lib.add_file(R"(
[[material]]
name = "base"
density = 1.0
youngs_modulus = 10.0
poisson_ratio = 0.25

[[material]]
name = "stiffer"
library = "base"
youngs_modulus = 20.0
)",
               "lib.toml");
  ASSERT_NE(lib.find("stiffer"), nullptr);
  EXPECT_DOUBLE_EQ(lib.find("stiffer")->youngs_modulus, 20.0);
  EXPECT_DOUBLE_EQ(lib.find("stiffer")->poisson_ratio, 0.25);
  EXPECT_EQ(lib.names(), (std::vector<std::string>{"base", "stiffer"}));
}

TEST(MaterialLibrary, DuplicateAndInvalidSetsAreInputErrors) {
  MaterialLibrary lib;
  const char* twice = R"([[material]]
name = "a"
density = 1.0
youngs_modulus = 1.0
poisson_ratio = 0.0
[[material]]
name = "a"
density = 1.0
youngs_modulus = 1.0
poisson_ratio = 0.0
)";
  try {
    lib.add_file(twice, "lib.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lib.toml:7:8: key 'material[1].name': duplicate material set \"a\""),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(MaterialLibrary().add_file("[[material]]\nname = \"x\"\ndensity = -1.0\n", "bad.toml"), InputError);
}

// The rate-dependent fracture energy keys: read, and a transition without a brittle G_f is an error that
// names the key.
TEST(MaterialLibrary, RateDependentFractureEnergyKeys) {
  const std::string base = R"([[material]]
name = "ti"
library = "ti64-lesuer-2000"
fracture_energy = 15e3
fracture_transition_strain_rate = 1.2e6
)";
  MaterialLibrary lib = builtin_material_library();
  lib.add_file(base + "fracture_energy_brittle = 5e3\nfracture_transition_exponent = 3.0\n", "ok.toml");
  const MaterialParameters* m = lib.find("ti");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->fracture_transition_strain_rate, 1.2e6);
  EXPECT_EQ(m->fracture_energy_brittle, 5e3);
  EXPECT_EQ(m->fracture_transition_exponent, 3.0);
  try {
    MaterialLibrary copy = builtin_material_library();
    copy.add_file(base, "bad.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fracture_energy_brittle"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mpmcut
