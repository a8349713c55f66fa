// The chip analysis over time (analysis/chip_over_time.hpp): when samples are due, their statistics, and their
// exact round trip through a checkpoint.
#include <gtest/gtest.h>

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "analysis/chip_over_time.hpp"

namespace mpmcut {
namespace {

ChipSample sample(double travel, const char* type, std::optional<double> gs, std::optional<double> tc,
                  std::optional<double> ta, bool steady = true) {
  ChipSample s;
  s.steady = steady;
  s.time_s = travel / 2.0;
  s.tool_travel_m = travel;
  s.classification = type;
  s.segmentation_degree = gs;
  s.mean_thickness_m = tc;
  s.area_mean_thickness_m = ta;
  return s;
}

TEST(ChipOverTime, SamplesAreDueOnAFixedGridOfTravelFromTheSteadyWindow) {
  const ChipSampling sampling{300e-6, 50e-6};
  std::vector<ChipSample> taken;
  EXPECT_FALSE(sampling.due(299e-6, taken));  // before the steady window
  EXPECT_TRUE(sampling.due(302e-6, taken));   // the first history row inside it
  taken.push_back(sample(302e-6, "serrated", 0.3, 120e-6, 125e-6));
  EXPECT_FALSE(sampling.due(349e-6, taken));
  EXPECT_TRUE(sampling.due(350e-6, taken));   // at 300 + 50 um, not 302 + 50: no drift with the history rows
  taken.push_back(sample(351e-6, "serrated", 0.3, 120e-6, 125e-6));
  EXPECT_FALSE(sampling.due(399e-6, taken));
  EXPECT_TRUE(sampling.due(400e-6, taken));
}

// A state whose t_A was left out (a tightly curled chip) is still a steady state: its note went into the profile's
// note, which marks an entry chip not left out, and every such state dropped out of the statistics.
TEST(ChipOverTime, AStateWithoutItsAreaThicknessIsStillSteady) {
  ChipAnalysis a;
  a.steady_samples = 40;
  a.area_mean_thickness_note = "the thickness by area exceeds the thickest cross-section: t_A is left out";
  EXPECT_TRUE(chip_sample(a).steady);
  a.profile_note = "the chip holds little more than the chip of the tool's entry";
  EXPECT_FALSE(chip_sample(a).steady);
}

TEST(ChipOverTime, StatisticsOverTheSteadySamplesThatHaveEachQuantity) {
  // The first state still measured part of the entry chip: listed, not averaged.
  const std::vector<ChipSample> samples{sample(250e-6, "continuous", 0.9, 150e-6, 160e-6, false),
                                        sample(300e-6, "serrated", 0.56, 113e-6, 118e-6),
                                        sample(350e-6, "serrated", 0.19, 117e-6, 119e-6),
                                        sample(400e-6, "continuous", std::nullopt, 121e-6, std::nullopt)};
  const nlohmann::json j = chip_over_time_json(samples, ChipSampling{300e-6, 50e-6});
  EXPECT_EQ(j["samples"].size(), 4u);
  EXPECT_EQ(j["steady_samples"], 3);
  EXPECT_FALSE(j["samples"][0]["steady"].get<bool>());
  EXPECT_TRUE(j["note"].is_null());
  EXPECT_EQ(j["classifications"].size(), 2u);
  EXPECT_EQ(j["classifications"]["serrated"], 2);
  EXPECT_EQ(j["classifications"]["continuous"], 1);
  EXPECT_NEAR(j["segmentation_degree"]["mean"].get<double>(), 0.375, 1e-12);
  EXPECT_EQ(j["segmentation_degree"]["min"].get<double>(), 0.19);
  EXPECT_EQ(j["segmentation_degree"]["max"].get<double>(), 0.56);
  EXPECT_EQ(j["segmentation_degree"]["samples"], 2);
  EXPECT_NEAR(j["mean_thickness_m"]["mean"].get<double>(), 117e-6, 1e-15);
  EXPECT_EQ(j["mean_thickness_m"]["samples"], 3);
  EXPECT_TRUE(j["pitch_m"]["mean"].is_null());
  EXPECT_EQ(j["tool_travel_interval_m"].get<double>(), 50e-6);
  const std::string text = chip_over_time_text(j);
  EXPECT_NE(text.find("3 states past the entry chip"), std::string::npos) << text;
  EXPECT_NE(text.find("Gs 0.38 (0.19-0.56)"), std::string::npos) << text;
  EXPECT_NE(text.find("thickness 117.0 um (113.0-121.0)"), std::string::npos) << text;
  EXPECT_TRUE(chip_over_time_text(chip_over_time_json({}, ChipSampling{})).empty());
  // A cut too short for any steady state: no statistics, a note, and the terminal says so.
  const nlohmann::json short_cut = chip_over_time_json({samples[0]}, ChipSampling{300e-6, 50e-6});
  EXPECT_EQ(short_cut["steady_samples"], 0);
  EXPECT_TRUE(short_cut["segmentation_degree"]["mean"].is_null());
  EXPECT_NE(short_cut["note"].get<std::string>().find("too short"), std::string::npos);
  EXPECT_NE(chip_over_time_text(short_cut).find("no statistics"), std::string::npos);
}

TEST(ChipOverTime, SamplesRoundTripExactlyThroughACheckpoint) {
  const std::vector<ChipSample> samples{sample(0.1 + 0.2, "serrated", 1.0 / 3.0, 113e-6 / 7.0, std::nullopt),
                                        sample(350e-6, "none", std::nullopt, std::nullopt, 119e-6, false)};
  const std::vector<ChipSample> back = chip_samples_from_text(chip_samples_text(samples));
  ASSERT_EQ(back.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(back[k].time_s, samples[k].time_s);
    EXPECT_EQ(back[k].tool_travel_m, samples[k].tool_travel_m);
    EXPECT_EQ(back[k].classification, samples[k].classification);
    EXPECT_EQ(back[k].steady, samples[k].steady);
    EXPECT_EQ(back[k].segmentation_degree, samples[k].segmentation_degree);
    EXPECT_EQ(back[k].mean_thickness_m, samples[k].mean_thickness_m);
    EXPECT_EQ(back[k].area_mean_thickness_m, samples[k].area_mean_thickness_m);
  }
  EXPECT_TRUE(chip_samples_from_text("").empty());  // a checkpoint from before the samples were kept
  EXPECT_THROW(chip_samples_from_text("{\"a\": 1}"), std::runtime_error);
  EXPECT_THROW(chip_samples_from_text("[{\"time_s\": 1}]"), std::runtime_error);
}

}  // namespace
}  // namespace mpmcut
