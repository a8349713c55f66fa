// The cutting preset's geometry (src/cutting/cutting_scene.*): the machined surface, where the tool's
// lowest point runs, lies on a row of grid nodes on every grid, so that no result depends on where the
// tip happens to sit within its cell (docs/cutting.md, "Grid phase of the tool tip").
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cutting/cutting_scene.hpp"
#include "physics/material_parameters.hpp"

namespace mpmcut {
namespace {

double rows_below_machined_surface(const Scene& s, double t0) {
  const double H = s.bodies[0].shape.rectangle.max.y();
  return (H - t0 - s.grid.min.y()) / s.grid.cell_size;
}

TEST(CuttingScene, MachinedSurfaceLiesOnANodeRowOnEveryGrid) {
  MaterialParameters m;
  m.name = "ti";
  // The validation's rule cell = min(t0/10, r_n/4) gives cells that do not divide the depth
  // t0 + max(3 t0, 2 r_n) - t0: 9.825 um cells put the tip mid-cell in 300 um.
  for (double cell : {10e-6, 9.825e-6, 8.6e-6, 7.35e-6, 6.25e-6}) {
    for (double height : {0.0, 0.4e-3, 0.4e-3 + 0.3 * cell}) {
      SCOPED_TRACE(::testing::Message() << "cell " << cell << " m, workpiece_height " << height << " m");
      CuttingParameters c;
      c.cutting_speed = 2.0;
      c.uncut_chip_thickness = 0.1e-3;
      c.cut_length = 0.2e-3;
      c.cell_size = cell;
      c.workpiece_height = height;
      const Scene s = build_cutting_scene(c, m);
      const double rows = rows_below_machined_surface(s, c.uncut_chip_thickness);
      EXPECT_NEAR(rows, std::round(rows), 1e-6);
      // Rounded up, by less than a cell: never shallower than asked.
      const double asked = height > 0.0 ? height : 4.0 * c.uncut_chip_thickness;
      const double H = s.bodies[0].shape.rectangle.max.y();
      EXPECT_GE(H, asked - 1e-12);
      EXPECT_LT(H, asked + cell);
    }
  }
  // An aligned height stays exactly as it is (300 um / 10 um is 29.999... in floating point).
  EXPECT_EQ(machined_surface_on_node_row(0.4e-3, 0.1e-3, 10e-6), 0.4e-3);
  EXPECT_EQ(machined_surface_on_node_row(0.4e-3, 0.1e-3, 0.1e-3 / 24.0), 0.4e-3);
}

// The tool of the preset carries the process's friction, frictional-heat share and heat transfer.
TEST(CuttingScene, ToolCarriesFrictionAndHeatTransfer) {
  MaterialParameters m;
  m.name = "ti";
  CuttingParameters c;
  c.cutting_speed = 2.0;
  c.uncut_chip_thickness = 0.1e-3;
  c.cut_length = 0.2e-3;
  c.friction = 0.2;
  c.friction_heat_share = 0.4;
  c.tool_heat_transfer_coefficient = 1e6;
  c.tool_temperature = 500.0;
  const Scene s = build_cutting_scene(c, m);
  ASSERT_EQ(s.rigid_bodies.size(), 1u);
  EXPECT_EQ(s.rigid_bodies[0].friction, 0.2);
  EXPECT_EQ(s.rigid_bodies[0].friction_heat_share, 0.4);
  EXPECT_EQ(s.rigid_bodies[0].heat_transfer_coefficient, 1e6);
  EXPECT_EQ(s.rigid_bodies[0].temperature, 500.0);
  c.friction_heat_share = CuttingParameters{}.friction_heat_share;  // the default: all of it
  EXPECT_EQ(build_cutting_scene(c, m).rigid_bodies[0].friction_heat_share, 1.0);
}

// The force window of a short cut is its last 40 %; a cut whose window lies mostly within the 3 t0 of travel that the
// chip takes to form is flagged, with the shortest cut that is not: 3 t0 / (0.5 + 0.5 * 0.6) = 3.75 t0.
TEST(CuttingScene, ShortCutWhoseForceWindowPrecedesTheFormedChipIsFlagged) {
  CuttingParameters c;
  c.uncut_chip_thickness = 0.1e-3;
  c.cut_length = 0.08e-3;  // window 0.048-0.08 mm, all before 0.3 mm
  const std::string w = steady_window_warning(c);
  EXPECT_NE(w.find("too short"), std::string::npos) << w;
  EXPECT_NE(w.find("0.000375 m"), std::string::npos) << w;
  c.cut_length = 0.37e-3;  // window 0.222-0.37 mm: 0.07 of its 0.148 mm after 0.3 mm
  EXPECT_FALSE(steady_window_warning(c).empty());
  c.cut_length = 0.38e-3;  // window 0.228-0.38 mm: 0.08 of 0.152 mm after
  EXPECT_TRUE(steady_window_warning(c).empty());
  c.cut_length = 0.4e-3;  // the default cut
  EXPECT_TRUE(steady_window_warning(c).empty());
  c.cut_length = 1e-3;  // the window starts at 0.4 mm, after the chip has formed
  EXPECT_TRUE(steady_window_warning(c).empty());
  EXPECT_DOUBLE_EQ(steady_window_start_travel(c), 0.4e-3);
}

}  // namespace
}  // namespace mpmcut
