// Chip free-surface profile: peak/valley detection with a prominence threshold, the segmentation
// degree Gs = (H - h)/H and the pitch on synthetic profiles with known answers (docs/analysis.md),
// and the walk along a chip (trace_chip_profile) on particle sets of known thickness.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <numbers>

#include "analysis/chip_profile.hpp"

namespace mpmcut {
namespace {

ChipProfile profile_of(std::vector<double> thickness, double spacing) {
  ChipProfile p;
  p.spacing_m = spacing;
  p.thickness_m = std::move(thickness);
  return p;
}

// Saw-tooth: rises linearly from h to H over `period` samples, then drops; ends on a valley sample.
std::vector<double> sawtooth(double h, double H, int period, int teeth) {
  std::vector<double> y;
  for (int k = 0; k < period * teeth; ++k) y.push_back(h + (H - h) * (k % period) / (period - 1));
  y.push_back(h);
  return y;
}

TEST(ChipProfile, SawtoothGivesExactHeightsPitchAndDegree) {
  const double spacing = 5e-6, h = 60e-6, H = 100e-6;
  const ChipProfile p = profile_of(sawtooth(h, H, 10, 5), spacing);
  const Segmentation s = measure_segmentation(p, 10e-6);
  ASSERT_EQ(s.extrema.peaks, (std::vector<std::size_t>{9, 19, 29, 39, 49}));
  // The first and last samples are the profile's ends, not valleys.
  ASSERT_EQ(s.extrema.valleys, (std::vector<std::size_t>{10, 20, 30, 40}));
  EXPECT_EQ(s.segments, 5u);
  EXPECT_DOUBLE_EQ(*s.peak_height_m, H);
  EXPECT_DOUBLE_EQ(*s.valley_height_m, h);
  EXPECT_DOUBLE_EQ(*s.degree, (H - h) / H);
  EXPECT_DOUBLE_EQ(*s.pitch_m, 10 * spacing);
}

TEST(ChipProfile, SineGivesExactHeightsPitchAndDegree) {
  const double spacing = 2e-6, mean = 80e-6, amplitude = 20e-6;
  std::vector<double> y;
  for (int k = 0; k <= 100; ++k) y.push_back(mean + amplitude * std::sin(2.0 * std::numbers::pi * k / 20.0));
  const Segmentation s = measure_segmentation(profile_of(y, spacing), 10e-6);
  ASSERT_EQ(s.extrema.peaks, (std::vector<std::size_t>{5, 25, 45, 65, 85}));
  ASSERT_EQ(s.extrema.valleys, (std::vector<std::size_t>{15, 35, 55, 75, 95}));
  EXPECT_NEAR(*s.peak_height_m, mean + amplitude, 1e-18);
  EXPECT_NEAR(*s.valley_height_m, mean - amplitude, 1e-18);
  EXPECT_NEAR(*s.degree, 2 * amplitude / (mean + amplitude), 1e-12);
  EXPECT_NEAR(*s.pitch_m, 20 * spacing, 1e-18);
}

TEST(ChipProfile, OneParticleNoiseIsNotASegment) {
  // Alternating +-1 particle spacing around a flat chip: below the prominence, so not a tooth.
  const double d = 5e-6;
  std::vector<double> y;
  for (int k = 0; k < 60; ++k) y.push_back(100e-6 + (k % 2 ? d : -d) * 0.5);
  const Segmentation s = measure_segmentation(profile_of(y, 5e-6), 1.5 * d);
  EXPECT_TRUE(s.extrema.peaks.empty());
  EXPECT_TRUE(s.extrema.valleys.empty());
  EXPECT_EQ(s.segments, 0u);
  EXPECT_EQ(*s.degree, 0.0);
  EXPECT_NEAR(*s.mean_thickness_m, 100e-6, 1e-12);
  EXPECT_FALSE(s.pitch_m.has_value());
}

// A saw-tooth whose crests and valleys flicker: where the cross-section jumps between including a
// tooth's tip or not, the thickness drops by more than the prominence for one sample and comes back
// (what the walk gives on fine particle clouds). The zig-zag alone counts every flicker as a tooth;
// merging teeth closer than the minimum pitch recovers the five teeth, their heights and their pitch.
std::vector<double> flickering_sawtooth(double h, double H, int period, int teeth, double flicker) {
  std::vector<double> y = sawtooth(h, H, period, teeth);
  for (int tooth = 0; tooth < teeth; ++tooth) {
    y[tooth * period + period - 3] -= flicker;          // a notch just below the crest
    if (tooth > 0) y[tooth * period + 2] += flicker;    // a spike just after the valley
  }
  return y;
}

TEST(ChipProfile, FlickerAtCrestsAndValleysIsMergedIntoItsTooth) {
  const double spacing = 2e-6, h = 30e-6, H = 110e-6, prominence = 10e-6;
  const int period = 40;  // pitch 80 um
  const ChipProfile p = profile_of(flickering_sawtooth(h, H, period, 5, 30e-6), spacing);

  const Segmentation raw = measure_segmentation(p, prominence);
  ASSERT_GT(raw.segments, 5u);  // without merging, the flicker counts: the test would catch its loss

  const double min_pitch = 25e-6;  // 0.25 t0 at t0 = 0.1 mm
  const Segmentation s = measure_segmentation(p, prominence, min_pitch);
  EXPECT_EQ(s.segments, 5u);
  EXPECT_EQ(s.extrema.peaks, (std::vector<std::size_t>{39, 79, 119, 159, 199}));
  EXPECT_EQ(s.extrema.valleys, (std::vector<std::size_t>{40, 80, 120, 160}));
  EXPECT_DOUBLE_EQ(*s.peak_height_m, H);
  EXPECT_DOUBLE_EQ(*s.valley_height_m, h);
  EXPECT_DOUBLE_EQ(*s.pitch_m, period * spacing);
  EXPECT_DOUBLE_EQ(*s.degree, (H - h) / H);
}

TEST(ChipProfile, TeethAtTheMinimumPitchAreKept) {
  // Real teeth exactly min_pitch apart are not merged; half a sample closer, they are.
  const double spacing = 2e-6;
  const ChipProfile p = profile_of(sawtooth(30e-6, 110e-6, 10, 6), spacing);  // pitch 20 um
  EXPECT_EQ(measure_segmentation(p, 10e-6, 20e-6).segments, 6u);
  EXPECT_NEAR(*measure_segmentation(p, 10e-6, 20e-6).pitch_m, 20e-6, 1e-18);
  EXPECT_LT(measure_segmentation(p, 10e-6, 21e-6).segments, 6u);
}

TEST(ChipProfile, MergingKeepsAlternationAndProminence) {
  // Random-looking profile: after merging, peaks and valleys alternate, neighbours of one kind are
  // min_spacing apart, and each extremum differs from its neighbours by at least the prominence.
  std::vector<double> y;
  for (int k = 0; k < 400; ++k)
    y.push_back(60e-6 + 25e-6 * std::sin(0.13 * k) + 18e-6 * std::sin(1.7 * k + 0.3) + 9e-6 * std::sin(4.1 * k));
  const double prominence = 10e-6;
  ProfileExtrema e = find_profile_extrema(y, prominence);
  ASSERT_GT(e.peaks.size(), 30u);
  merge_close_extrema(y, e, 12);
  std::vector<std::pair<std::size_t, bool>> seq;
  for (std::size_t k : e.peaks) seq.emplace_back(k, true);
  for (std::size_t k : e.valleys) seq.emplace_back(k, false);
  std::sort(seq.begin(), seq.end());
  ASSERT_GE(seq.size(), 4u);
  for (std::size_t j = 0; j + 1 < seq.size(); ++j) {
    EXPECT_NE(seq[j].second, seq[j + 1].second) << "at " << seq[j].first;
    EXPECT_GE(std::abs(y[seq[j].first] - y[seq[j + 1].first]), prominence) << "at " << seq[j].first;
    if (j + 2 < seq.size()) EXPECT_GE(seq[j + 2].first - seq[j].first, 12u) << "at " << seq[j].first;
  }
}

// The 12.6 m/min cut at t0/24 (docs/results/shear_localisation) measured a smooth chip ~200 um thick
// whose cross-section crossed a particle-row gap at two stations (21.7 and 30.9 um): each one-sample
// dip became a valley between two "peaks", and Gs came out 0.47. One cell (two samples at h/2) or
// narrower is not a tooth; the real valley of a saw-tooth, wider than that, stays.
TEST(ChipProfile, DipsNarrowerThanACellAreNotTeeth) {
  const double spacing = 2e-6, prominence = 10e-6;
  std::vector<double> smooth(60, 200e-6);
  for (int k = 0; k < 60; ++k) smooth[k] += 4e-6 * std::sin(0.3 * k);  // free-surface roughness below p
  std::vector<double> dipped = smooth;
  dipped[15] = 21.7e-6;                       // one sample
  dipped[40] = 30.9e-6, dipped[41] = 0.0;     // two samples (a gap)
  const Segmentation raw = measure_segmentation(profile_of(dipped, spacing), prominence);
  ASSERT_GE(raw.segments, 2u);                // without the cleaning: counted as teeth
  ASSERT_GT(*raw.degree, 0.5);
  const Segmentation clean = measure_segmentation(profile_of(dipped, spacing), prominence, 0.0, 2 * spacing);
  EXPECT_EQ(clean.segments, 0u);
  EXPECT_EQ(*clean.degree, 0.0);
  for (std::size_t k = 0; k < smooth.size(); ++k) EXPECT_NEAR(clean.thickness_m[k], smooth[k], 8e-6) << k;
  EXPECT_NEAR(*clean.mean_thickness_m, 200e-6, 1e-6);
  // Three samples are wider than the cell: a valley.
  std::vector<double> wide = smooth;
  wide[30] = wide[31] = wide[32] = 150e-6;
  const Segmentation kept = measure_segmentation(profile_of(wide, spacing), prominence, 0.0, 2 * spacing);
  ASSERT_EQ(kept.extrema.valleys.size(), 1u);
  EXPECT_NEAR(kept.thickness_m[kept.extrema.valleys[0]], 150e-6, 1e-12);
  // A saw-tooth's valley (one low sample, its right neighbour only just higher) is not an excursion.
  const ChipProfile saw = profile_of(sawtooth(60e-6, 100e-6, 10, 5), 5e-6);
  const Segmentation sawn = measure_segmentation(saw, 10e-6, 0.0, 10e-6);
  EXPECT_EQ(sawn.extrema.valleys, (std::vector<std::size_t>{10, 20, 30, 40}));
  EXPECT_DOUBLE_EQ(*sawn.degree, 0.4);
}

TEST(ChipProfile, NarrowExcursionsUpAndAtTheEnds) {
  std::vector<double> y{5, 50, 5, 5, 6, 60, 61, 7, 7, 80};  // spikes of one and two samples; a jump at the end
  remove_narrow_excursions(y, 10, 2);
  const std::vector<double> want{5, 5, 5, 5, 6, 6 + 1.0 / 3.0, 6 + 2.0 / 3.0, 7, 7, 80};
  ASSERT_EQ(y.size(), want.size());
  for (std::size_t k = 0; k < y.size(); ++k) EXPECT_NEAR(y[k], want[k], 1e-12) << k;
  // A steep saw-tooth's valley as a 5 um particle grid quantises it: its flank climbs p within two samples,
  // but it lies between a crest and a flank, not between two equal samples: kept.
  std::vector<double> steep{155, 155, 105, 115, 115, 120, 130, 130, 140, 150, 155, 155, 105, 115};
  const std::vector<double> steep_before = steep;
  remove_narrow_excursions(steep, 10, 2);
  EXPECT_EQ(steep, steep_before);
  std::vector<double> first{50, 5, 5};  // a first sample is the profile's cut end: kept
  remove_narrow_excursions(first, 10, 2);
  EXPECT_EQ(first, (std::vector<double>{50, 5, 5}));
}

TEST(ChipProfile, TailAreaCountsSamplesFromTheEnd) {
  const ChipProfile p = profile_of({1, 1, 2, 2, 4}, 0.5);  // areas 0.5 0.5 1 1 2
  EXPECT_EQ(samples_before_tail_area(p, 2.0), 4u);   // the last sample holds it
  EXPECT_EQ(samples_before_tail_area(p, 2.5), 3u);
  EXPECT_EQ(samples_before_tail_area(p, 4.0), 2u);
  EXPECT_EQ(samples_before_tail_area(p, 5.0), 0u);   // all of it
  EXPECT_EQ(samples_before_tail_area(p, 6.0), 0u);
  EXPECT_EQ(samples_before_tail_area(p, 0.0), 5u);
}

TEST(ChipProfile, EmptyProfileHasNoMetrics) {
  const Segmentation s = measure_segmentation(ChipProfile{}, 1e-6);
  EXPECT_FALSE(s.degree.has_value());
  EXPECT_FALSE(s.mean_thickness_m.has_value());
  EXPECT_EQ(s.segments, 0u);
}

// A straight chip of `rows` x `columns` particles of spacing d against a rake face x = 0 (it lies at x < 0).
std::vector<Vec2> straight_chip(int rows, int columns, double d) {
  std::vector<Vec2> x;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) x.emplace_back(-(i + 0.5) * d, (j + 0.5) * d);
  return x;
}

TEST(ChipProfile, TraceMeasuresAStraightChipExactly) {
  const double d = 5e-6;
  const std::vector<Vec2> x = straight_chip(200, 24, d);  // 120 um thick, 1 mm long
  const ChipProfile p = trace_chip_profile(x, Vec2(0.0, 10 * d), Vec2(0, 1), Vec2(-1, 0), 0.5 * 2 * d, d, 600e-6, 100e-6);
  ASSERT_GT(p.thickness_m.size(), 150u);
  for (std::size_t k = 0; k < p.thickness_m.size(); ++k)
    ASSERT_NEAR(p.thickness_m[k], 24 * d, 1e-12) << "sample " << k;
}

// A chip that curls away from the tool: an annulus arc of inner radius R, thickness T, over 150 degrees, particles
// of spacing d; its rake side is the outer rim, which touches the rake face x = 0 at y = 0.
std::vector<Vec2> curled_chip(double d, double R, double T) {
  const Vec2 centre(-R - T, 0.0);
  std::vector<Vec2> x;
  for (double r = R + 0.5 * d; r < R + T; r += d) {
    const double dtheta = d / r;
    for (double theta = -0.2; theta < 150.0 * std::numbers::pi / 180.0; theta += dtheta)
      x.push_back(centre + r * Vec2(std::cos(theta), std::sin(theta)));
  }
  return x;
}

TEST(ChipProfile, TraceFollowsACurledChip) {
  // A chip that curls away from the tool: an annulus arc of inner radius R (the rake side is the
  // outer rim), thickness T, over 150 degrees. The walk must measure T across it, not its projection.
  const double d = 5e-6, R = 200e-6, T = 100e-6;
  const std::vector<Vec2> x = curled_chip(d, R, T);
  const ChipProfile p = trace_chip_profile(x, Vec2(0.0, 0.0), Vec2(0, 1), Vec2(-1, 0), d, d, 600e-6, 100e-6);
  const double arc = (R + T) * 150.0 * std::numbers::pi / 180.0;
  ASSERT_GT(static_cast<double>(p.thickness_m.size()) * d, 0.8 * arc);
  // All but the last two stations, where the slab runs off the arc's end face.
  for (std::size_t k = 0; k + 2 < p.thickness_m.size(); ++k)
    ASSERT_NEAR(p.thickness_m[k], T, 1.5 * d) << "sample " << k;
}

TEST(ChipProfile, TraceOfASawtoothChipRecoversItsTeeth) {
  // Straight chip, outer edge a saw-tooth from 80 to 120 um with a 100 um pitch: heights and pitch
  // within the resolution of one particle spacing.
  const double d = 5e-6, h = 80e-6, H = 120e-6, pitch = 100e-6;
  std::vector<Vec2> x;
  for (int j = 0; j < 200; ++j) {
    const double y = (j + 0.5) * d;
    const double phase = std::fmod(y, pitch) / pitch;
    const double thickness = h + (H - h) * phase;
    for (int i = 0; (i + 0.5) * d < thickness; ++i) x.emplace_back(-(i + 0.5) * d, y);
  }
  const ChipProfile p = trace_chip_profile(x, Vec2(0.0, 0.0), Vec2(0, 1), Vec2(-1, 0), 0.5 * d, d, 600e-6, 100e-6);
  const Segmentation s = measure_segmentation(p, 10e-6);
  EXPECT_GE(s.segments, 8u);
  EXPECT_NEAR(*s.peak_height_m, H, 1.5 * d);
  EXPECT_NEAR(*s.valley_height_m, h, 1.5 * d);
  EXPECT_NEAR(*s.pitch_m, pitch, d);
  EXPECT_NEAR(*s.degree, (H - h) / H, 0.06);
}

// --- Thickness by area ------------------------------------------------------------------------

TEST(ChipProfile, AreaThicknessOfAStraightChipIsItsThickness) {
  const double d = 5e-6;
  const std::vector<Vec2> x = straight_chip(200, 24, d);  // 120 um thick
  // Stations between particle rows, so that each row belongs to exactly one station.
  const ChipProfile p = trace_chip_profile(x, Vec2(0.0, 10.2 * d), Vec2(0, 1), Vec2(-1, 0), d, d, 600e-6, 100e-6);
  ASSERT_GT(p.thickness_m.size(), 150u);
  // Not the last stations: the cloud ends inside the last one's slab.
  for (std::size_t samples : {std::size_t{20}, std::size_t{150}})
    EXPECT_NEAR(*area_mean_thickness(p, samples, x, d, 100e-6, Vec2(-1, 0)), 24 * d, 1e-9) << samples << " samples";
  EXPECT_FALSE(area_mean_thickness(p, 0, x, d, 100e-6, Vec2(-1, 0)));
}

TEST(ChipProfile, AreaThicknessCountsTheSegmentBeyondAnOpenCrack) {
  // A straight 120 um chip on the rake face x = 0 with open cracks every 100 um: slits 2.5 spacings wide at
  // 45 deg from the free surface down to 40 um from the rake face, as between the segments of a serrated chip.
  // A cross-section that meets a crack stops there (the ligament), so the profile's mean is too thin; the area
  // counts the segment beyond it and gives the cloud's area over the measured length.
  const double d = 5e-6, T = 120e-6, ligament = 40e-6, pitch = 100e-6, opening = 2.5 * d;
  std::vector<Vec2> x;
  for (int j = 0; j < 200; ++j)
    for (int i = 0; i < 24; ++i) {
      const Vec2 q(-(i + 0.5) * d, (j + 0.5) * d);
      const double depth = -q.x();  // from the rake face
      // Distance to the nearest crack line y = y_c + (depth - ligament) (45 deg), for depth > ligament.
      const double u = q.y() - (depth - ligament);
      const double to_crack = std::abs(u - pitch * std::round(u / pitch)) / std::sqrt(2.0);
      if (depth > ligament && to_crack < 0.5 * opening) continue;
      x.push_back(q);
    }
  const ChipProfile p = trace_chip_profile(x, Vec2(0.0, 100.2 * d), Vec2(0, -1), Vec2(-1, 0), d, d, 600e-6, 100e-6);
  const std::size_t n = 80;  // 400 um: four pitches, away from the cloud's ends
  ASSERT_GE(p.thickness_m.size(), n);
  std::size_t inside = 0;  // points in the 80 stations' rows: y from 100.2 d - 80 d + 0.5 d to 100.2 d + 0.5 d
  for (const Vec2& q : x)
    if (q.y() > (100.2 - 79.5) * d && q.y() < (100.2 + 0.5) * d) ++inside;
  const double expected = static_cast<double>(inside) * d * d / (n * d);
  const double by_area = *area_mean_thickness(p, n, x, d, 100e-6, Vec2(-1, 0));
  EXPECT_NEAR(by_area, expected, 0.01 * expected);
  EXPECT_GT(by_area, 0.85 * T);  // the cracks take little area (12 %) ...
  double profile_mean = 0.0;
  for (std::size_t k = 0; k < n; ++k) profile_mean += p.thickness_m[k] / n;
  EXPECT_LT(profile_mean, 0.85 * by_area);  // ... but stop many cross-sections at the ligament
}

TEST(ChipProfile, AreaThicknessOfACurledChipIsItsThicknessAcross) {
  // The curled chip of TraceFollowsACurledChip: thickness T across an arc whose inner (rake) side is the outer
  // rim. Its area over the rim's length is T (1 - T / (2 (R + T))) = 0.83 T; counted across the curl, T.
  const double d = 2.5e-6, R = 200e-6, T = 100e-6;
  const std::vector<Vec2> x = curled_chip(d, R, T);
  const ChipProfile p = trace_chip_profile(x, Vec2(0.0, 0.0), Vec2(0, 1), Vec2(-1, 0), d, d, 600e-6, 100e-6);
  ASSERT_GT(p.thickness_m.size(), 200u);
  const std::size_t n = p.thickness_m.size() - 20;  // not the arc's end face
  EXPECT_NEAR(*area_mean_thickness(p, n, x, d, 100e-6, Vec2(-1, 0)), T, 0.03 * T);
}

}  // namespace
}  // namespace mpmcut
