// Fracture accounting (docs/analysis.md, "Fracture accounting"): the crack length the damage dissipation
// stands for (sum of dissipation / G_f per particle), the real new surface from the chip analysis
// (gullet depths, piece separations), the boundary of a particle cloud and the energy partition, on
// inputs with known answers. The grid-level check (a band that fails along a known line) is in
// tests/verification/test_hillerborg_bar.cpp.
#include <gtest/gtest.h>

#include "analysis/fracture_accounting.hpp"

#include <nlohmann/json.hpp>

namespace mpmcut {
namespace {

TEST(FractureAccounting, EquivalentCrackLengthUsesEachParticlesFractureEnergy) {
  Particles p;
  for (int i = 0; i < 3; ++i) p.add(Vec2(i, 0), Vec2::Zero(), 1.0, 1.0, 300.0, 0, 0);
  p.damage_dissipation = {1.5, 0.5, 0.2};       // J/m
  p.fracture_energy = {15e3, 5e3, 0.0};         // J/m^2; G_f = 0 (failure at initiation) adds nothing
  EXPECT_DOUBLE_EQ(equivalent_crack_length_m(p), 1.5 / 15e3 + 0.5 / 5e3);
}

TEST(FractureAccounting, GulletDepthsAndPieceSeparations) {
  ChipAnalysis a;
  a.profile.spacing_m = 5e-6;
  a.profile.thickness_m = {80e-6, 100e-6, 60e-6, 120e-6, 70e-6, 110e-6, 90e-6};
  // The gullets are sought on the whole profile (the entry chip's included): peaks 1, 3, 5, valleys 2, 4.
  a.prominence_m = 10e-6;
  a.steady_samples = 2;  // what the segmentation metrics measured does not limit the new surface
  a.pieces = 3;
  std::vector<double> seg, sep;
  chip_crack_lengths(a, 100e-6, seg, sep);
  ASSERT_EQ(seg.size(), 2u);
  EXPECT_NEAR(seg[0], 0.5 * (100e-6 + 120e-6) - 60e-6, 1e-15);  // mean of the peaks beside it - valley
  EXPECT_NEAR(seg[1], 0.5 * (120e-6 + 110e-6) - 70e-6, 1e-15);
  ASSERT_EQ(sep.size(), 2u);  // 3 pieces: 2 separations, each as long as the chip is thick (peak height)
  EXPECT_DOUBLE_EQ(sep[0], 110e-6);
  // A flat chip in one piece has no crack of its own.
  ChipAnalysis flat;
  flat.profile.thickness_m = {1e-4, 1e-4};
  flat.pieces = 1;
  flat.prominence_m = 10e-6;
  chip_crack_lengths(flat, 100e-6, seg, sep);
  EXPECT_TRUE(seg.empty());
  EXPECT_TRUE(sep.empty());
}

// The chip's damage is set against the chip's own cracks, the workpiece's against the machined surface.
TEST(FractureAccounting, SurfaceBalanceSplitsChipFromWorkpiece) {
  FractureAccounting f;
  f.regions = {{"workpiece", ""}, {"chip_free_surface_layer", ""}, {"chip_interior", ""}, {"chip_fragments", ""}};
  f.regions[0].crack_length_m = 0.1e-3;
  f.regions[1].crack_length_m = 0.3e-3;
  f.regions[2].crack_length_m = 0.2e-3;
  f.regions[3].crack_length_m = 0.05e-3;
  f.removed_crack_length_m = 0.05e-3;
  f.machined_surface_length_m = 0.4e-3;
  f.segment_crack_lengths_m = {20e-6, 30e-6};
  f.piece_separation_lengths_m = {50e-6};
  const SurfaceBalance b = surface_balance(f);
  EXPECT_NEAR(b.chip_equivalent_crack_length_m, 0.6e-3, 1e-15);
  EXPECT_NEAR(b.chip_crack_length_m, 0.1e-3, 1e-15);
  EXPECT_NEAR(b.workpiece_equivalent_crack_length_m, 0.1e-3, 1e-15);
  EXPECT_NEAR(b.machined_surface_length_m, 0.4e-3, 1e-15);
  const nlohmann::json j = fracture_json(f, EnergyPartition{});
  EXPECT_NEAR(j["chip"]["crack_length_ratio"].get<double>(), 6.0, 1e-12);
  EXPECT_NEAR(j["workpiece"]["crack_length_ratio"].get<double>(), 0.25, 1e-12);
  f.segment_crack_lengths_m.clear();
  f.piece_separation_lengths_m.clear();
  EXPECT_TRUE(fracture_json(f, EnergyPartition{})["chip"]["crack_length_ratio"].is_null());  // no crack: no ratio
}

TEST(FractureAccounting, BoundaryOfALatticeIsItsOuterRing) {
  const double d = 1e-6;
  const int nx = 12, ny = 8;
  std::vector<Vec2> x;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) x.emplace_back(i * d, j * d);
  const std::vector<char> b = boundary_particles(x, d);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      // Neighbours within 2 d (exclusive) are the 8 lattice neighbours: on a face their mean offset
      // is 0.6 d, inside 0.
      const bool outer = i == 0 || j == 0 || i == nx - 1 || j == ny - 1;
      EXPECT_EQ(static_cast<bool>(b[i * ny + j]), outer) << i << ", " << j;
    }
}

TEST(FractureAccounting, EnergyPartitionSumsToOne) {
  const EnergyPartition e = energy_partition(10.0, 4.0, 3.0, 1.0, 0.5, 0.5, 0.0);
  EXPECT_DOUBLE_EQ(e.plastic, 0.4);
  EXPECT_DOUBLE_EQ(e.damage, 0.3);
  EXPECT_NEAR(e.remainder, 0.1, 1e-15);
  EXPECT_EQ(energy_partition(0.0, 1, 1, 1, 1, 1, 1).plastic, 0.0);
}

}  // namespace
}  // namespace mpmcut
