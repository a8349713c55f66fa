// The cut's resolution report (src/cutting/cutting_resolution.*): cells across t0 and across the edge
// radius, and a warning exactly where the convergence study found the forces still changing with the cell.
#include <gtest/gtest.h>

#include "cutting/cutting_resolution.hpp"

namespace mpmcut {
namespace {

CuttingParameters cut(double t0, double edge_radius, double cell) {
  CuttingParameters c;
  c.uncut_chip_thickness = t0;
  c.edge_radius = edge_radius;
  c.cell_size = cell;
  return c;
}

TEST(CuttingResolution, AResolvedCutHasNoWarning) {
  const CuttingResolution r = cutting_resolution(cut(0.1e-3, 40e-6, 10e-6), 0.0);
  EXPECT_DOUBLE_EQ(r.cell_size_m, 10e-6);
  EXPECT_NEAR(r.cells_per_uncut_chip, 10.0, 1e-12);
  EXPECT_NEAR(r.cells_per_edge_radius, 4.0, 1e-12);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_TRUE(console_lines(r).empty());
}

TEST(CuttingResolution, TheDefaultCellIsATenthOfTheUncutChip) {
  EXPECT_NEAR(cutting_resolution(cut(0.05e-3, 20e-6, 0.0), 0.0).cell_size_m, 5e-6, 1e-18);
}

TEST(CuttingResolution, AnEdgeOfFewerThanFourCellsIsFlagged) {
  const CuttingResolution r = cutting_resolution(cut(0.05e-3, 5e-6, 4e-6), 0.0);  // the default cut at t0/12.5
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("edge radius 5 um is 1.3 cells"), std::string::npos) << r.warnings[0];
  EXPECT_NE(r.warnings[0].find("1.25e-06 m"), std::string::npos) << r.warnings[0];
  EXPECT_EQ(to_json(r)["warnings"].size(), 1u);
}

TEST(CuttingResolution, ACoarseChipIsFlaggedAndASharpEdgeIsNot) {
  const CuttingResolution r = cutting_resolution(cut(0.1e-3, 0.0, 20e-6), 0.0);  // t0/5, edge 0
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("uncut chip thickness is 5 cells"), std::string::npos) << r.warnings[0];
}

// l_th = sqrt(kappa t0 / V): by hand for kappa = 6.8 / (4430 * 526.3) = 2.9166e-6 m^2/s, t0 = 0.1 mm:
// 381.3 m/min 6.774 um, 12.6 m/min 37.27 um. The fast cut at the matrix's 8.25 um cell (0.82 cells across l_th) is
// flagged, at t0/24 (1.63 cells) not; the slow cut at 7.875 um (4.7 cells) is not.
TEST(CuttingResolution, AnUnresolvedThermalLengthIsFlagged) {
  const double kappa = 6.8 / (4430.0 * 526.3);
  EXPECT_NEAR(thermal_length_m(kappa, 0.1e-3, 381.3 / 60.0), 6.774e-6, 0.001e-6);
  EXPECT_EQ(thermal_length_m(0.0, 0.1e-3, 1.0), 0.0);  // no conduction: no length, no check
  CuttingParameters fast = cut(0.1e-3, 33e-6, 8.25e-6);
  fast.cutting_speed = 381.3 / 60.0;
  CuttingResolution r = cutting_resolution(fast, kappa);
  EXPECT_NEAR(r.thermal_length_m, 6.774e-6, 0.001e-6);
  EXPECT_NEAR(r.cells_per_thermal_length, 6.774 / 8.25, 0.001);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("thermal length sqrt(kappa t0/V) = 6.77 um"), std::string::npos) << r.warnings[0];
  EXPECT_NE(r.warnings[0].find("is 0.82 cells"), std::string::npos) << r.warnings[0];
  EXPECT_NE(r.warnings[0].find("4.52e-06 m"), std::string::npos) << r.warnings[0];  // l_th / 1.5
  EXPECT_NEAR(to_json(r)["cells_per_thermal_length"].get<double>(), 6.774 / 8.25, 0.001);
  fast.cell_size = 0.1e-3 / 24;
  EXPECT_TRUE(cutting_resolution(fast, kappa).warnings.empty());
  CuttingParameters slow = cut(0.1e-3, 31.5e-6, 7.875e-6);
  slow.cutting_speed = 12.6 / 60.0;
  r = cutting_resolution(slow, kappa);
  EXPECT_NEAR(r.cells_per_thermal_length, 37.27 / 7.875, 0.002);
  EXPECT_TRUE(r.warnings.empty());
}

}  // namespace
}  // namespace mpmcut
