// summary.json through RunSummary (src/run/run_summary.hpp): what the run writes is what the studies
// read, key for key; the observers' sections are carried whole; the headline readers find the values
// the chip analysis and the cutting observer write.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "solver/simulation.hpp"
#include "run/case_loading.hpp"
#include "run/run_summary.hpp"

namespace mpmcut {
namespace {

Scene block() { return load_case(std::string(MPMCUT_TEST_DIR) + "/support/cases/elastic_block.toml").scene; }

// An energy balance that leaves more than 5 % unaccounted for carries a warning (a coarse, fast cut with -9.5 % ran
// "complete" without one); the residual of a resolved run (0.5-1 %) does not.
TEST(RunSummary, AnEnergyResidualBeyondFivePercentIsWarned) {
  RunSummary s;
  s.energy_relative_residual = -0.095;
  const nlohmann::json j = to_json(s);
  ASSERT_TRUE(j["energy_balance"].contains("warning"));
  EXPECT_NE(j["energy_balance"]["warning"].get<std::string>().find("-9.5 %"), std::string::npos);
  s.energy_relative_residual = 0.049;
  EXPECT_FALSE(to_json(s)["energy_balance"].contains("warning"));
  s.energy_relative_residual = 0.051;
  EXPECT_TRUE(to_json(s)["energy_balance"].contains("warning"));
}

TEST(RunSummary, WhatTheRunWritesReadsBackKeyForKey) {
  Simulation sim(block());
  for (int k = 0; k < 5; ++k) sim.step();
  const RunSummary s = summarize(sim, std::nullopt, run_status::complete, 2.0, "", 1);
  EXPECT_EQ(s.steps, 5);
  EXPECT_EQ(s.particles, sim.particles().size());
  EXPECT_DOUBLE_EQ(s.particle_steps_per_s, s.particles * 5 / 2.0);
  ASSERT_EQ(s.rigid_bodies.size(), 1u);
  EXPECT_EQ(s.rigid_bodies[0].name, "wall");
  EXPECT_EQ(s.rigid_bodies[0].displacement_m, sim.rigid_bodies()[0].displacement);
  EXPECT_EQ(s.energy_J_per_m.kinetic, sim.energy().kinetic);

  nlohmann::json j = to_json(s);
  EXPECT_FALSE(j.contains("message"));  // only when there is one
  EXPECT_FALSE(j.contains("mean_cutting_force_N_per_mm"));  // not a cutting run
  // Sections an observer adds travel through the struct unchanged.
  j["chip"] = {{"classification", "serrated"}, {"pitch_m", 4e-5}, {"segmentation_degree", 0.4}};
  j["temperature"] = {{"primary_shear_zone", {{"max_K", 900.0}}}, {"tool_chip_interface", {{"max_K", nullptr}}}};
  j["cutting"] = {{"material", "ti64"}};
  j["mean_cutting_force_N_per_mm"] = 123.5;
  j["mean_thrust_force_N_per_mm"] = nullptr;
  const RunSummary back = summary_from_json(j);
  EXPECT_EQ(to_json(back), j);
  EXPECT_EQ(back.rigid_bodies, s.rigid_bodies);
  EXPECT_EQ(back.energy_J_per_m, s.energy_J_per_m);
  EXPECT_EQ(back.mean_cutting_force_N_per_mm, 123.5);
  EXPECT_FALSE(back.mean_thrust_force_N_per_mm.has_value());

  const ChipHeadline chip = chip_headline(back);
  EXPECT_EQ(chip.classification, "serrated");
  EXPECT_EQ(chip.pitch_m, 4e-5);
  EXPECT_EQ(chip.segmentation_degree, 0.4);
  EXPECT_EQ(chip.shear_zone_max_K, 900.0);
  EXPECT_FALSE(chip.tool_chip_max_K.has_value());
  EXPECT_FALSE(chip.chip_thickness_ratio.has_value());
  EXPECT_EQ(mass_scaling_factor(back), 1.0);
}

// A conducting rigid body reports its hottest cell (rigid_bodies[].max_temperature_K), read back as written; the
// others carry no such key.
TEST(RunSummary, AConductingRigidBodyReportsItsHottestCell) {
  Simulation plain(block());
  EXPECT_FALSE(to_json(summarize(plain, std::nullopt, run_status::complete, 1.0, "", 1))["rigid_bodies"][0].contains(
      "max_temperature_K"));
  Scene scene = block();
  scene.thermal.conduction = true;
  for (auto& m : scene.materials) m.specific_heat = std::max(m.specific_heat, 1.0);
  RigidBodySpec& wall = scene.rigid_bodies.at(0);
  wall.heat_transfer_coefficient = 1e3;
  wall.conductivity = 10.0;
  wall.volumetric_heat_capacity = 1e6;
  wall.temperature = 350.0;
  wall.held_faces = {0};
  Simulation sim(scene);
  const RunSummary s = summarize(sim, std::nullopt, run_status::complete, 1.0, "", 1);
  ASSERT_TRUE(s.rigid_bodies.at(0).max_temperature_K.has_value());
  EXPECT_EQ(*s.rigid_bodies[0].max_temperature_K, 350.0);  // the start: every cell at the body's temperature
  EXPECT_EQ(summary_from_json(to_json(s)).rigid_bodies, s.rigid_bodies);
}

TEST(RunSummary, FileRoundTripAndWrongTypesAreNamed) {
  Simulation sim(block());
  RunSummary s = summarize(sim, std::nullopt, run_status::failed, 0.0, "it broke", 2);
  s.last_checkpoint = "checkpoints/checkpoint_000001.bin";
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                       ("mpmcut_test_run_summary_" + std::to_string(::getpid()) + ".json");
  write_summary(file, s);
  const RunSummary back = read_summary(file);
  EXPECT_EQ(back.status, "failed");
  EXPECT_EQ(back.message, "it broke");
  EXPECT_EQ(back.threads, 2);
  EXPECT_EQ(back.last_checkpoint, s.last_checkpoint);
  EXPECT_EQ(to_json(back), to_json(s));
  std::filesystem::remove(file);

  nlohmann::json j = to_json(s);
  j["max_temperature_K"] = "hot";
  EXPECT_THROW(
      {
        try {
          summary_from_json(j);
        } catch (const std::runtime_error& e) {
          EXPECT_NE(std::string(e.what()).find("max_temperature_K"), std::string::npos) << e.what();
          throw;
        }
      },
      std::runtime_error);
}

}  // namespace
}  // namespace mpmcut
