// Chip analysis on synthetic particle sets with known answers: which particles are the chip,
// classification (continuous / serrated / discontinuous), chip thickness ratio and the shear angle
// it implies (Merchant's geometry, Merchant 1945), temperatures by region (docs/analysis.md).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>

#include <nlohmann/json.hpp>

#include "analysis/chip_analysis.hpp"
#include "app/analyze_command.hpp"

namespace mpmcut {
namespace {

constexpr double kT0 = 100e-6, kH = 10e-6, kD = 5e-6;  // t0, cell, particle spacing (2 per cell)

// A 0 deg rake tool whose edge (sharp) sits at the origin, its rake face on x = 0, its body at x > 0;
// the machined surface is y = 0, the uncut surface y = t0.
ChipAnalysisSetup synthetic_setup() {
  ChipAnalysisSetup s;
  s.uncut_chip_thickness_m = kT0;
  s.cutting_speed_m_per_s = 20.0;
  s.rake_angle_deg = 0.0;
  s.cell_size_m = kH;
  s.particles_per_cell = 2;
  s.machined_surface_y_m = 0.0;
  s.tool_velocity_m_per_s = Vec2(-20.0, 0.0);
  s.tool = RigidPolygon(Polygon{{Vec2(0, 0), Vec2(300e-6, 30e-6), Vec2(300e-6, 1e-3), Vec2(0, 1e-3)}}, 0.0);
  s.max_damage = {0.999};
  return s;
}

// A chip against the rake face: particles at x < 0 from the machined surface up to `length`,
// thickness(y) wide, plastically strained (so they are chip); rows in `failed_rows` fully damaged.
Particles chip_particles_of(double length, const std::function<double(double)>& thickness,
                            const std::vector<int>& failed_rows = {}) {
  Particles p;
  for (int j = 0; (j + 0.5) * kD < length; ++j) {
    const double y = (j + 0.5) * kD;
    for (int i = 0; (i + 0.5) * kD < thickness(y); ++i) {
      const std::size_t k = p.add(Vec2(-(i + 0.5) * kD, y), Vec2(-20.0, 12.0), 1e-7, kD * kD, 400.0, 0, 0);
      p.plastic_strain[k] = 1.0;
      for (int r : failed_rows)
        if (r == j) p.damage[k] = 0.999;
    }
  }
  return p;
}

TEST(ChipAnalysis, ShearAngleFromChipRatioMatchesMerchantsGeometry) {
  // r = sin(phi)/cos(phi - alpha) inverted: tan(phi) = r cos(alpha) / (1 - r sin(alpha)).
  for (double alpha : {-10.0, 0.0, 6.0, 15.0})
    for (double phi : {15.0, 25.0, 35.0, 45.0}) {
      const double rad = std::numbers::pi / 180.0;
      const double r = std::sin(phi * rad) / std::cos((phi - alpha) * rad);
      EXPECT_NEAR(shear_angle_from_chip_ratio_deg(r, alpha), phi, 1e-10) << "alpha " << alpha;
    }
  EXPECT_NEAR(shear_angle_from_chip_ratio_deg(1.0, 0.0), 45.0, 1e-12);
}

TEST(ChipAnalysis, ChipIsTheMovedMaterialAboveTheMachinedSurface) {
  const ChipAnalysisSetup s = synthetic_setup();
  Particles p;
  p.add(Vec2(-50e-6, 50e-6), Vec2::Zero(), 1, 1, 300, 0, 0);   // uncut layer, no strain: not chip
  p.add(Vec2(-50e-6, 50e-6), Vec2::Zero(), 1, 1, 300, 0, 0);   // uncut layer, strained: chip
  p.plastic_strain[1] = 0.5;
  p.add(Vec2(-50e-6, 110e-6), Vec2::Zero(), 1, 1, 300, 0, 0);  // above the uncut surface: chip
  p.add(Vec2(-50e-6, -20e-6), Vec2::Zero(), 1, 1, 300, 0, 0);  // below the machined surface
  p.plastic_strain[3] = 2.0;
  p.add(Vec2(-50e-6, 110e-6), Vec2::Zero(), 1, 1, 300, 1, 0);  // another body
  EXPECT_EQ(chip_particles(p, s), (std::vector<char>{0, 1, 1, 0, 0}));
}

TEST(ChipAnalysis, StraightChipIsContinuousWithItsThicknessRatio) {
  const ChipAnalysisSetup s = synthetic_setup();
  const double tc = 150e-6;
  const ChipAnalysis a = analyze_chip(chip_particles_of(1e-3, [&](double) { return tc; }), s);
  EXPECT_EQ(a.classification, "continuous");
  EXPECT_EQ(a.classification_confidence, "clear");
  EXPECT_EQ(a.pieces, 1u);
  EXPECT_NEAR(*a.segmentation.mean_thickness_m, tc, 1e-12);
  EXPECT_EQ(*a.segmentation.degree, 0.0);
  EXPECT_NEAR(*a.chip_thickness_ratio, kT0 / tc, 1e-9);
  // A whole chip reads the same by area (within one particle row at the measured part's ends).
  EXPECT_NEAR(*a.area_mean_thickness_m, tc, 0.02 * tc);
  EXPECT_NEAR(chip_json(a)["chip_thickness_ratio_from_area"].get<double>(), kT0 / *a.area_mean_thickness_m, 1e-12);
  EXPECT_NEAR(*a.shear_angle_from_ratio_deg, std::atan(kT0 / tc) * 180.0 / std::numbers::pi, 1e-6);
  EXPECT_NEAR(*a.chip_velocity_m_per_s, 20.0 * kT0 / tc, 1e-9);
  EXPECT_NEAR(*a.chip_velocity_from_particles_m_per_s, 12.0, 1e-9);  // (v - v_tool) along the rake face
  EXPECT_FALSE(a.segmentation_frequency_Hz.has_value());
}

// t0/h = 10 cells is resolved (no note); the same chip analysed as if on a 6-cell grid gets the note.
TEST(ChipAnalysis, UnderResolvedChipCarriesANote) {
  ChipAnalysisSetup s = synthetic_setup();
  const auto chip = chip_particles_of(1e-3, [](double) { return 150e-6; });
  const ChipAnalysis fine = analyze_chip(chip, s);
  EXPECT_DOUBLE_EQ(fine.cells_per_feed, 10.0);
  EXPECT_TRUE(fine.resolution_note.empty());
  EXPECT_TRUE(chip_json(fine)["resolution_note"].is_null());
  s.cell_size_m = kT0 / 6.0;
  const ChipAnalysis coarse = analyze_chip(chip, s);
  EXPECT_NEAR(coarse.cells_per_feed, 6.0, 1e-12);
  EXPECT_NE(coarse.resolution_note.find("6.0 cells"), std::string::npos) << coarse.resolution_note;
  EXPECT_EQ(chip_json(coarse)["resolution_note"], coarse.resolution_note);
}

TEST(ChipAnalysis, SawtoothChipIsSerrated) {
  const ChipAnalysisSetup s = synthetic_setup();
  const double h = 80e-6, H = 160e-6, pitch = 100e-6;
  const ChipAnalysis a = analyze_chip(
      chip_particles_of(1e-3, [&](double y) { return h + (H - h) * std::fmod(y, pitch) / pitch; }), s);
  EXPECT_EQ(a.classification, "serrated");
  EXPECT_EQ(a.classification_confidence, "clear");
  EXPECT_EQ(a.pieces, 1u);
  // Ten teeth on the chip; the tail holding 3 t0^2 is taken as the entry chip and left out.
  EXPECT_GE(a.segmentation.segments, 6u);
  EXPECT_NEAR(*a.segmentation.degree, (H - h) / H, 0.06);
  EXPECT_NEAR(*a.segmentation.pitch_m, pitch, kD);
  const double vc = 20.0 * *a.chip_thickness_ratio;
  EXPECT_NEAR(*a.segmentation_frequency_Hz, vc / *a.segmentation.pitch_m, 1e-6);
}

// The chip's free end was cut while the tool entered the workpiece: in the simulated cuts it is thicker
// than the steady chip, then tapers to the workpiece's corner (docs/results/shear_localisation, 12.6 and
// 381.3 m/min at t0/24). Measured whole, a smooth chip with such an end shows one deep tooth (Gs 0.55)
// and a mean thickness above the steady one. The tail holding 3 t0^2 (the chip of 3 t0 of travel) is
// left out: the chip is flat, its thickness ratio the steady one.
TEST(ChipAnalysis, TheEntryChipAtTheFreeEndIsLeftOut) {
  const ChipAnalysisSetup s = synthetic_setup();
  const auto with_entry_end = [](double y) {
    const double u = y * 1e6;
    const double t = u < 820 ? 150 : u < 900 ? 150 + 50 * (u - 820) / 80 : u < 960 ? 200 - 140 * (u - 900) / 60 : 130;
    return t * 1e-6;
  };
  const ChipAnalysis a = analyze_chip(chip_particles_of(1e-3, with_entry_end), s);
  ASSERT_EQ(a.pieces, 1u);
  EXPECT_EQ(a.classification, "continuous");
  EXPECT_EQ(a.classification_confidence, "clear") << a.classification_note;
  EXPECT_EQ(*a.segmentation.degree, 0.0);
  EXPECT_NEAR(*a.segmentation.mean_thickness_m, 150e-6, 1e-12);
  // The measured part ends where the tail holds 3 t0^2 (27 000 um^2 from 820 um on): in the flat part,
  // about 20 um before the entry chip's thickening.
  const double end = a.profile.position_m(a.steady_samples - 1);
  EXPECT_GT(end, 790e-6);
  EXPECT_LT(end, 815e-6);
  EXPECT_TRUE(a.profile_note.empty());
  const nlohmann::json j = chip_json(a);
  EXPECT_EQ(j["profile"]["steady_samples"], a.steady_samples);
  ASSERT_EQ(j["profile"]["thickness_m"].size(), a.profile.thickness_m.size());  // the whole traced profile
  EXPECT_EQ(j["profile"]["thickness_m"].back().get<double>(), a.profile.thickness_m.back());
  EXPECT_LT(a.steady_samples, a.profile.thickness_m.size());
  // The whole profile still holds the entry's tooth: the thresholds alone would not remove it.
  const Segmentation whole = measure_segmentation(a.profile, a.prominence_m, a.min_pitch_m, a.narrow_width_m);
  EXPECT_GT(*whole.degree, 0.4);
}

// A chip that holds less than twice the entry's area (early in a cut, or a short cut) loses only its free
// half, and says so; a chip of a few samples is measured whole.
TEST(ChipAnalysis, AShortChipLosesOnlyItsFreeHalfWithANote) {
  const ChipAnalysisSetup s = synthetic_setup();
  // The profile runs from 150 to 300 um: 2.25 t0^2, less than twice 3 t0^2.
  const ChipAnalysis a = analyze_chip(chip_particles_of(300e-6, [](double) { return 150e-6; }), s);
  const double kept_area = static_cast<double>(a.steady_samples) * a.profile.spacing_m * 150e-6;
  EXPECT_NEAR(kept_area, 0.5 * profile_area(a.profile), 150e-6 * a.profile.spacing_m);
  EXPECT_NE(a.profile_note.find("short cut"), std::string::npos) << a.profile_note;
  EXPECT_EQ(chip_json(a)["profile"]["note"], a.profile_note);
  const ChipAnalysis tiny = analyze_chip(chip_particles_of(165e-6, [](double) { return 150e-6; }), s);
  ASSERT_GT(tiny.profile.thickness_m.size(), 0u);
  EXPECT_EQ(tiny.steady_samples, tiny.profile.thickness_m.size());
  EXPECT_NE(tiny.profile_note.find("measured whole"), std::string::npos) << tiny.profile_note;
}

// A short cut's serrated chip (the transition series cuts 4 t0): a 4.2 t0^2 profile with 60 um teeth. Leaving
// out the 3 t0^2 of the entry would keep about 85 um of chip, one tooth, and call it continuous; half the
// profile keeps about 150 um, more than two teeth.
TEST(ChipAnalysis, AShortCutsSawtoothChipIsStillSerrated) {
  const ChipAnalysisSetup s = synthetic_setup();
  const double h = 120e-6, H = 160e-6, pitch = 60e-6;
  const ChipAnalysis a = analyze_chip(
      chip_particles_of(450e-6, [&](double y) { return h + (H - h) * std::fmod(y, pitch) / pitch; }), s);
  ASSERT_EQ(a.pieces, 1u);
  EXPECT_EQ(a.classification, "serrated") << a.classification_note;
  EXPECT_GE(a.segmentation.segments, 2u);
  EXPECT_NEAR(*a.segmentation.pitch_m, pitch, kD);
  EXPECT_NEAR(*a.segmentation.degree, (H - h) / H, 0.08);
  EXPECT_NE(a.profile_note.find("short cut"), std::string::npos) << a.profile_note;
  // The whole entry area left out: fewer than two teeth remain.
  ChipProfile entry_rule = a.profile;
  entry_rule.thickness_m.resize(samples_before_tail_area(a.profile, 3.0 * kT0 * kT0));
  const Segmentation few = measure_segmentation(entry_rule, a.prominence_m, a.min_pitch_m, a.narrow_width_m);
  EXPECT_LT(few.segments, 2u);
}

TEST(ChipAnalysis, BlocksSeparatedByFailedRowsAreDiscontinuous) {
  const ChipAnalysisSetup s = synthetic_setup();
  // Rows 40 and 80 (y = 200 and 400 um) fully damaged: three pieces of 100 um x ~200 um.
  const ChipAnalysis a = analyze_chip(chip_particles_of(600e-6, [](double) { return 100e-6; }, {40, 80}), s);
  EXPECT_EQ(a.classification, "discontinuous");
  EXPECT_EQ(a.pieces, 3u);
  EXPECT_EQ(a.fragment_particles, 40u);  // the failed particles
}

TEST(ChipAnalysis, TemperaturePeaksByRegion) {
  const ChipAnalysisSetup s = synthetic_setup();
  Particles p = chip_particles_of(1e-3, [](double) { return 150e-6; });
  Particles extra;
  // Hot spots: one touching the rake face, one in the primary shear zone ahead of the edge, one in
  // the chip far from both (counts only for the overall maximum).
  auto hot = [&p](const Vec2& x, double T) {
    const std::size_t k = p.add(x, Vec2::Zero(), 1e-7, kD * kD, T, 0, 0);
    p.plastic_strain[k] = 1.0;
  };
  hot(Vec2(-0.5 * kD, 300e-6), 1400.0);
  hot(Vec2(-60e-6, 50e-6), 1100.0);
  hot(Vec2(-140e-6, 800e-6), 1500.0);
  const ChipAnalysis a = analyze_chip(p, s);
  EXPECT_EQ(*a.max_temperature_K, 1500.0);
  EXPECT_EQ(*a.tool_chip_interface.max_K, 1400.0);
  EXPECT_EQ(*a.primary_shear_zone.max_K, 1100.0);
  EXPECT_NEAR(a.primary_shear_zone.position_m->x(), -60e-6, 1e-15);
}

TEST(ChipAnalysis, NoChipAndJsonKeys) {
  const ChipAnalysisSetup s = synthetic_setup();
  const ChipAnalysis a = analyze_chip(Particles{}, s);
  EXPECT_EQ(a.classification, "none");
  const nlohmann::json j = chip_json(a);
  for (const char* key : {"classification", "segmentation_degree", "peak_height_m", "valley_height_m", "pitch_m",
                          "segmentation_frequency_Hz", "chip_thickness_ratio", "shear_angle_from_ratio_deg",
                          "shear_band_angle_deg", "pieces", "segments"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_TRUE(j["segmentation_degree"].is_null());
  EXPECT_TRUE(temperature_json(a)["primary_shear_zone"]["max_K"].is_null());
}

// A one-piece chip too short for a profile (still at the root): "continuous" only as one piece, marginal, with a
// note; it was "continuous, clear" with every chip measure empty.
TEST(ChipAnalysis, AChipWithoutAProfileIsAMarginalOnePieceChip) {
  const ChipAnalysisSetup s = synthetic_setup();
  const ChipAnalysis a = analyze_chip(chip_particles_of(40e-6, [](double) { return 150e-6; }), s);
  ASSERT_EQ(a.classification, "continuous");
  EXPECT_EQ(a.pieces, 1u);
  EXPECT_FALSE(a.segmentation.degree.has_value());
  EXPECT_FALSE(a.chip_thickness_ratio.has_value());
  EXPECT_EQ(a.classification_confidence, "marginal");
  EXPECT_NE(a.classification_note.find("could not be measured"), std::string::npos) << a.classification_note;
}

// A chip thinner than t0/2 is no steady chip (a short or under-resolved cut measured t0/tc 4.6, "clear"): marginal.
TEST(ChipAnalysis, AChipThinnerThanHalfTheUncutChipIsMarginal) {
  const ChipAnalysisSetup s = synthetic_setup();
  const ChipAnalysis thin = analyze_chip(chip_particles_of(1e-3, [](double) { return 40e-6; }), s);
  ASSERT_EQ(thin.classification, "continuous");
  EXPECT_NEAR(*thin.chip_thickness_ratio, 2.5, 0.1);
  EXPECT_EQ(thin.classification_confidence, "marginal");
  EXPECT_NE(thin.classification_note.find("not a steady chip"), std::string::npos) << thin.classification_note;
  const ChipAnalysis thick = analyze_chip(chip_particles_of(1e-3, [](double) { return 60e-6; }), s);  // t0/tc 1.7
  EXPECT_EQ(thick.classification_confidence, "clear");
}

TEST(ChipAnalysis, SetupNeedsTheWorkpieceAndTheTool) {
  Scene scene;
  EXPECT_THROW(chip_analysis_setup(scene, CuttingParameters{}, Vec2::Zero(), 0.0), std::invalid_argument);
}

TEST(ChipAnalysis, AnalyzeCommandRefusesWhatIsNotACuttingResult) {
  EXPECT_EQ(analyze_result_directory("/nonexistent/mpmcut_result", "last"), 2);
  EXPECT_EQ(analyze_result_directory(std::filesystem::temp_directory_path(), "last"), 2);
}

}  // namespace
}  // namespace mpmcut

namespace mpmcut {
namespace {

// A weakly toothed chip (Gs ~ 0.19, the default cut's at t0/12) is serrated but marginal: within the band
// of the threshold, where the type flips with the grid. Deeper teeth (Gs 0.5) are clear.
TEST(ChipAnalysis, WeakTeethAreAMarginalSerration) {
  const ChipAnalysisSetup s = synthetic_setup();
  const auto sawtooth = [&](double h, double H) {
    const double pitch = 100e-6;
    return analyze_chip(chip_particles_of(1e-3, [&](double y) { return h + (H - h) * std::fmod(y, pitch) / pitch; }), s);
  };
  const ChipAnalysis weak = sawtooth(130e-6, 160e-6);
  EXPECT_EQ(weak.classification, "serrated");
  EXPECT_EQ(weak.classification_confidence, "marginal");
  EXPECT_NE(weak.classification_note.find("within 0.1 of the serrated threshold"), std::string::npos)
      << weak.classification_note;
  EXPECT_EQ(chip_json(weak)["classification_confidence"], "marginal");
  const ChipAnalysis deep = sawtooth(80e-6, 160e-6);
  EXPECT_EQ(deep.classification_confidence, "clear");
}

// One deep tooth on a short chip: as deep as a serrated chip, but the rule needs two teeth, so it is
// "continuous" and marked marginal (its pitch may be longer than the chip).
TEST(ChipAnalysis, OneDeepToothIsAMarginalContinuousChip) {
  const ChipAnalysisSetup s = synthetic_setup();
  // Thickness along the chip, um: 150, down to a gullet of 90, up to one crest of 160, then 100 to the end.
  const auto profile = [](double y) {
    const double u = y * 1e6;
    const double t = u < 300 ? 150 : u < 350 ? 150 - 60 * (u - 300) / 50 : u < 600 ? 90 + 70 * (u - 350) / 250
                     : u < 650 ? 160 - 60 * (u - 600) / 50 : 100;
    return t * 1e-6;
  };
  const ChipAnalysis a = analyze_chip(chip_particles_of(1e-3, profile), s);
  ASSERT_LT(a.segmentation.segments, 2u);
  ASSERT_GE(a.segmentation.degree.value_or(0.0), 0.1);
  EXPECT_EQ(a.classification, "continuous");
  EXPECT_EQ(a.classification_confidence, "marginal");
  EXPECT_NE(a.classification_note.find("tooth"), std::string::npos) << a.classification_note;
}

}  // namespace
}  // namespace mpmcut
