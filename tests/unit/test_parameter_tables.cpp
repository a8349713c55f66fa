// The physics models' parameter tables (src/physics/*_parameters.hpp) are the one rule set for a
// material: every value the input reader refuses at a model limit, the physics constructors refuse
// too, and the other way round; caps of plausibility bind the reader only. The writer writes every
// key the reader reads.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "io/input_error.hpp"
#include "io/material_keys.hpp"
#include "io/material_library.hpp"
#include "io/scene_writer.hpp"
#include "physics/material.hpp"
#include "../support/ti64_parameters.hpp"

namespace mpmcut {
namespace {

// Every switch on (Johnson-Cook, TANH softening, Mie-Grueneisen, damage, a rate-dependent G_f): every
// parameter in use.
MaterialParameters everything_on() {
  MaterialParameters m = testing::with_jc_damage(testing::with_sima_ozel_softening(testing::ti64_johnson_1985()));
  m.eos = EquationOfState::MieGruneisen;
  m.mg_c0 = 5130.0;
  m.mg_s = 1.028;
  m.mg_gamma0 = 1.23;
  m.fracture_transition_strain_rate = 2e6;
  m.fracture_energy_brittle = 5e3;
  m.crack_friction = 0.5;
  return m;
}

// The reader's message for `m` written as a library file ("" if it reads).
std::string reader_error(const MaterialParameters& m) {
  std::ostringstream text;
  write_material(m, text);
  try {
    MaterialLibrary().add_file(text.str(), "m.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool physics_refuses_key(const MaterialParameters& m, std::string_view key) {
  for (const ParameterProblem& p : parameter_problems(m, Check::ModelLimits))
    if (p.key == key) return true;
  return false;
}

TEST(ParameterTables, ReaderAndPhysicsRefuseTheSameValuesAtEveryModelLimit) {
  const MaterialParameters base = everything_on();
  ASSERT_EQ(reader_error(base), "");
  ASSERT_NO_THROW(make_material(base));
  int limits = 0, caps = 0;
  for_each_parameter_table([&]<class P>(const ParameterTable<P>& table) {
    for (const Parameter<P>& row : table.parameters) {
      if (row.kind != Parameter<P>::Kind::Number) continue;
      const Range r = row.range_at(base);
      // Just outside each end of the range.
      for (const bool lower : {true, false}) {
        const double end = lower ? r.min : r.max;
        const bool open = lower ? r.min_open : r.max_open;
        const double outside = open ? end : std::nextafter(end, lower ? -1e300 : 1e300);
        MaterialParameters m = base;
        static_cast<P&>(m).*row.number = outside;
        SCOPED_TRACE(std::string(row.key) + (lower ? " below " : " above ") + std::to_string(outside));
        const std::string message = reader_error(m);
        // A key written only if set is not written at its default (0): the reader then misses it.
        const bool left_out = row.written_only_if_set && outside == P{}.*row.number;
        const std::string expected = left_out ? "missing required key '" + std::string(row.key) + "'"
                                              : "key 'material[0]." + std::string(row.key) + "': must be " + r.text();
        EXPECT_NE(message.find(expected), std::string::npos) << message;
        if (lower ? row.min_is_cap : row.max_is_cap) {
          ++caps;
          EXPECT_FALSE(physics_refuses_key(m, row.key));
        } else {
          ++limits;
          EXPECT_TRUE(physics_refuses_key(m, row.key));
          EXPECT_THROW(make_material(m), std::invalid_argument);
        }
      }
    }
  });
  EXPECT_GT(limits, 20);
  EXPECT_GT(caps, 20);
}

// Rules that no single range expresses, and switches, are refused by both too.
TEST(ParameterTables, RulesAndSwitchesBindReaderAndPhysicsAlike) {
  MaterialParameters no_yield = everything_on();
  no_yield.jc_A = no_yield.jc_B = 0.0;
  EXPECT_NE(reader_error(no_yield).find("key 'material[0].jc_B': must be positive when jc_A = 0"), std::string::npos);
  EXPECT_THROW(make_material(no_yield), std::invalid_argument);

  MaterialParameters elastic_with_damage = everything_on();
  elastic_with_damage.model = MaterialModel::Elastic;
  EXPECT_NE(reader_error(elastic_with_damage).find("key 'material[0].damage': must be false unless model = "
                                                   "\"johnson_cook\""),
            std::string::npos);
  EXPECT_THROW(make_material(elastic_with_damage), std::invalid_argument);

  // A key its switch leaves unused may hold 0, its default: an elastic material with jc_m = 0.
  MaterialParameters elastic = testing::ti64_johnson_1985();
  elastic.model = MaterialModel::Elastic;
  elastic.jc_m = 0.0;
  elastic.specific_heat = 0.0;
  EXPECT_EQ(reader_error(elastic), "");
  EXPECT_NO_THROW(make_material(elastic));
}

// What the writer writes, the reader reads back to an equal material: every table key is written.
// The unit of a key as the reference table gives it: what a calibration's evaluations.csv names its columns with.
TEST(ParameterTables, KeyUnitIsTheTablesUnit) {
  EXPECT_EQ(material_key_unit("jc_A"), "Pa");
  EXPECT_EQ(material_key_unit("fracture_energy"), "J/m^2");
  EXPECT_EQ(material_key_unit("reference_strain_rate"), "1/s");
  EXPECT_EQ(material_key_unit("melting_temperature"), "K");
  EXPECT_EQ(material_key_unit("jc_C"), "");  // a ratio
  EXPECT_EQ(material_key_unit("model"), "");  // not a number
  EXPECT_EQ(material_key_unit("no_such_key"), "");
}

TEST(ParameterTables, WriterWritesEveryKeyTheReaderReads) {
  const MaterialParameters m = everything_on();
  std::ostringstream text;
  write_material(m, text);
  MaterialLibrary lib;
  lib.add_file(text.str(), "m.toml");
  ASSERT_NE(lib.find(m.name), nullptr);
  EXPECT_TRUE(*lib.find(m.name) == m);
  int keys = 0;
  for_each_parameter_table([&](const auto& table) {
    for (const auto& row : table.parameters) {
      ++keys;
      EXPECT_NE(text.str().find("\n" + std::string(row.key) + " = "), std::string::npos) << row.key;
    }
  });
  EXPECT_GT(keys, 30);
}

// Keys added after run records were made are written only when set, so that the expanded scene of a
// material without them reads as before and its records still match (studies/run_records.cpp); reading the
// shorter text back gives the same material.
TEST(ParameterTables, KeysWrittenOnlyIfSetAreLeftOutAtTheirDefault) {
  const MaterialParameters m = testing::with_jc_damage(testing::ti64_johnson_1985());
  std::ostringstream text;
  write_material(m, text);
  for (const char* key : {"flow_softening", "tanh_a", "tanh_b", "tanh_c", "tanh_d", "tanh_s", "crack_friction"})
    EXPECT_EQ(text.str().find(std::string("\n") + key + " = "), std::string::npos) << key;
  MaterialLibrary lib;
  lib.add_file(text.str(), "m.toml");
  ASSERT_NE(lib.find(m.name), nullptr);
  EXPECT_TRUE(*lib.find(m.name) == m);
}

// The TANH constants are required once the switch is on, and refused out of range, at the key.
TEST(ParameterTables, TanhSofteningNeedsItsConstants) {
  const std::string base = "[[material]]\nname = \"t\"\nlibrary = \"ti64-johnson-1985\"\nflow_softening = \"tanh\"\n";
  auto error = [](const std::string& text) -> std::string {
    try {
      MaterialLibrary lib = builtin_material_library();
      lib.add_file(text, "t.toml");
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const std::string all = "tanh_a = 2.0\ntanh_b = 5.0\ntanh_c = 2.0\ntanh_d = 1.0\ntanh_s = 0.05\n";
  EXPECT_EQ(error(base + all), "");
  EXPECT_NE(error(base + "tanh_a = 2.0\n").find("tanh_b"), std::string::npos) << error(base + "tanh_a = 2.0\n");
  const std::string negative = base + "tanh_a = -1.0\ntanh_b = 5.0\ntanh_c = 2.0\ntanh_d = 1.0\ntanh_s = 0.05\n";
  EXPECT_NE(error(negative).find("tanh_a"), std::string::npos) << error(negative);
  const std::string unknown = "[[material]]\nname = \"t\"\nlibrary = \"ti64-johnson-1985\"\nflow_softening = \"x\"\n";
  EXPECT_NE(error(unknown).find("flow_softening"), std::string::npos) << error(unknown);
}

}  // namespace
}  // namespace mpmcut
