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
  const CuttingResolution r = cutting_resolution(cut(0.1e-3, 40e-6, 10e-6));
  EXPECT_DOUBLE_EQ(r.cell_size_m, 10e-6);
  EXPECT_NEAR(r.cells_per_uncut_chip, 10.0, 1e-12);
  EXPECT_NEAR(r.cells_per_edge_radius, 4.0, 1e-12);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_TRUE(console_lines(r).empty());
}

TEST(CuttingResolution, TheDefaultCellIsATenthOfTheUncutChip) {
  EXPECT_NEAR(cutting_resolution(cut(0.05e-3, 20e-6, 0.0)).cell_size_m, 5e-6, 1e-18);
}

TEST(CuttingResolution, AnEdgeOfFewerThanFourCellsIsFlagged) {
  const CuttingResolution r = cutting_resolution(cut(0.05e-3, 5e-6, 4e-6));  // the default cut at t0/12.5
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("edge radius 5 um is 1.3 cells"), std::string::npos) << r.warnings[0];
  EXPECT_NE(r.warnings[0].find("1.25e-06 m"), std::string::npos) << r.warnings[0];
  EXPECT_EQ(to_json(r)["warnings"].size(), 1u);
}

TEST(CuttingResolution, ACoarseChipIsFlaggedAndASharpEdgeIsNot) {
  const CuttingResolution r = cutting_resolution(cut(0.1e-3, 0.0, 20e-6));  // t0/5, edge 0
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("uncut chip thickness is 5 cells"), std::string::npos) << r.warnings[0];
}

}  // namespace
}  // namespace mpmcut
