// The cutting preset's geometry (src/cutting/cutting_scene.*): the machined surface, where the tool's
// lowest point runs, lies on a row of grid nodes on every grid, so that no result depends on where the
// tip happens to sit within its cell (docs/cutting.md, "Grid phase of the tool tip").
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "solver/rigid_body_heat.hpp"
#include "contact/rigid_polygon.hpp"
#include "cutting/cutting_scene.hpp"
#include "cutting/tool_geometry.hpp"
#include "io/material_library.hpp"
#include "physics/material_parameters.hpp"
#include "run/case_loading.hpp"

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

CuttingParameters tool_test_cut() {
  CuttingParameters c;
  c.cutting_speed = 2.0;
  c.uncut_chip_thickness = 0.1e-3;
  c.cut_length = 0.2e-3;
  c.cell_size = 10e-6;
  return c;
}

// Every accepted rake, clearance and edge radius gives a tool with the automatic sizes: a simple outline whose
// lowest point runs on the machined surface and whose leftmost point between the machined and the uncut surface
// starts half a cell beyond the workpiece (an edge radius > t0 a gap further), so that no workpiece particle
// starts inside it. Before, a rake from 38 deg
// was refused ("leans past the tool's back"), a radius of 1.5 t0 made a pill without faces and 5 t0 an inverted
// outline that removed every particle, and a rake of -20 deg started with its rake face 30 um inside the workpiece.
TEST(CuttingScene, AutomaticToolFitsEveryAcceptedAngleAndRadius) {
  MaterialParameters m;
  m.name = "ti";
  for (const double rake : {-44.9, -20.0, 0.0, 20.0, 38.0, 44.9})
    for (const double clearance : {0.5, 11.0, 35.0})
      for (const double radius_t0 : {0.0, 0.05, 0.5, 1.5, 5.0, 9.9}) {
        if (rake + clearance >= 80.0) continue;
        SCOPED_TRACE(::testing::Message() << "rake " << rake << ", clearance " << clearance << ", r " << radius_t0 << " t0");
        CuttingParameters c = tool_test_cut();
        c.rake_angle_deg = rake;
        c.clearance_angle_deg = clearance;
        c.edge_radius = radius_t0 * c.uncut_chip_thickness;
        c.cut_length += tool_engagement_travel(c);  // a large radius meets the workpiece late: the cut must reach it
        const ToolSize size = tool_size(c);
        EXPECT_EQ(tool_size_problem(c, size).message, "");
        Scene s;
        ASSERT_NO_THROW(s = build_cutting_scene(c, m));
        const RigidBodySpec& tool = s.rigid_bodies.at(0);
        const RigidPolygon shape(tool.polygon, tool.rounding_radius);
        const double H = s.bodies[0].shape.rectangle.max.y(), L = s.bodies[0].shape.rectangle.max.x();
        const double surface = H - c.uncut_chip_thickness, h = s.grid.cell_size;
        // The outline keeps its counter-clockwise order (an inverted core turns it round).
        double area2 = 0.0;
        const auto& v = tool.polygon.vertices;
        for (std::size_t i = 0; i < v.size(); ++i) area2 += v[i].x() * v[(i + 1) % v.size()].y() - v[(i + 1) % v.size()].x() * v[i].y();
        EXPECT_GT(area2, 0.0);
        // Lowest point on the machined surface; leftmost point within the cut's depth at L + h/2.
        double lowest = std::numeric_limits<double>::infinity(), leftmost = lowest;
        Vec2 normal;
        for (int i = 0; i <= 40; ++i) {  // the first x inside the tool at each height: a scan, then bisection
          const double y = surface + c.uncut_chip_thickness * i / 40.0, step = h / 8.0;
          double x = L - 2e-3;
          while (x < L + 2e-3 && shape.signed_distance(Vec2(x, y), normal) > 0.0) x += step;
          double lo = x - step, hi = x;
          for (int k = 0; k < 60; ++k) ((shape.signed_distance(Vec2(0.5 * (lo + hi), y), normal) > 0.0) ? lo : hi) = 0.5 * (lo + hi);
          leftmost = std::min(leftmost, hi);
        }
        for (const Vec2& p : v) lowest = std::min(lowest, p.y() - tool.rounding_radius);
        EXPECT_NEAR(lowest, surface, 1e-12);
        // Sampled at 41 heights t0/40 apart: a sharp edge's point is seen one sample up its rake face.
        const double sampling = 0.01 * h + (c.uncut_chip_thickness / 40.0) * std::max(0.0, std::tan(rake * M_PI / 180.0));
        // An edge radius > t0 meets the workpiece right of its own leftmost point, after a gap of travel; a negative
        // rake's face meets it at L + h/2 where the edge's leftmost point would have put it inside, else within r.
        const double r = c.edge_radius, t0 = c.uncut_chip_thickness;
        if (rake >= 0.0) {
          const double gap = r > t0 ? r - std::sqrt(r * r - (r - t0) * (r - t0)) : 0.0;
          EXPECT_NEAR(leftmost, L + 0.5 * h + gap, sampling + 0.01 * h);
        } else {
          EXPECT_LE(leftmost, L + 0.5 * h + r + 0.01 * h);
          if (r == 0.0) EXPECT_NEAR(leftmost, L + 0.5 * h, 0.01 * h);  // the sharp face leans left of the edge
        }
        EXPECT_GE(leftmost, L + 0.5 * h - 1e-9);
        EXPECT_LE(shape.upper().x(), s.grid.max.x());
      }
}

// The preset's contact is the penalty contact, whose springs act wherever a particle's domain reaches into the tool:
// every tool the preset accepts must start clear of the workpiece's particle domains, or a run's own scene.toml would
// not read back (resume, analyze) and the first step would shoot those particles off. The complete scene of each
// angle, radius and particle count parses back (scene_parser.cpp's check_rigid_overlaps), and a case's [solver]
// contact_detection still chooses another.
TEST(CuttingScene, PenaltyContactIsThePresetsAndEveryToolStartsClearOfTheParticleDomains) {
  const MaterialParameters& m = *builtin_material_library().find("ti64-cutting");
  for (const double rake : {-44.9, -20.0, 0.0, 38.0})
    for (const double clearance : {0.5, 11.0})
      for (const double radius_t0 : {0.0, 0.34, 1.5, 5.0})
        for (const int ppc : {1, 2, 4}) {
          SCOPED_TRACE(::testing::Message() << "rake " << rake << ", clearance " << clearance << ", r " << radius_t0
                                            << " t0, " << ppc << " particles per cell");
          CuttingParameters c = tool_test_cut();
          c.rake_angle_deg = rake;
          c.clearance_angle_deg = clearance;
          c.edge_radius = radius_t0 * c.uncut_chip_thickness;
          c.cut_length += tool_engagement_travel(c);
          c.particles_per_cell = ppc;
          c.material = m.name;
          const Case built{build_cutting_scene(c, m), c};
          EXPECT_EQ(built.scene.solver.contact_detection, ContactDetection::Penalty);
          EXPECT_NO_THROW(parse_case(scene_text(built), "scene.toml"));
        }
  const std::string cut = "[cutting]\nmaterial = \"ti64-cutting\"\ncutting_speed = 2.0\nuncut_chip_thickness = 0.1e-3\n"
                          "cut_length = 0.2e-3\n";
  EXPECT_EQ(parse_case(cut, "cut.toml").scene.solver.contact_detection, ContactDetection::Penalty);
  EXPECT_EQ(parse_case(cut + "[solver]\ncontact_detection = \"node\"\n", "cut.toml").scene.solver.contact_detection,
            ContactDetection::Node);
}

// Sizes given that cannot make a tool are refused at their key, saying what would fit.
TEST(CuttingScene, GivenToolSizesThatMakeNoToolAreRefusedAtTheirKey) {
  MaterialParameters m;
  m.name = "ti";
  const auto refusal = [&](CuttingParameters c) -> std::pair<std::string, std::string> {
    try {
      build_cutting_scene(c, m);
    } catch (const CuttingKeyError& e) {
      return {e.key, e.what()};
    }
    return {"", ""};
  };
  CuttingParameters c = tool_test_cut();
  c.tool_height = 50e-6;  // below the flank's rise over 0.3 mm at 11 deg (58 um): a self-crossing outline
  EXPECT_EQ(refusal(c).first, "tool_height");
  EXPECT_NE(refusal(c).second.find("give tool_height > 0.05831 mm"), std::string::npos) << refusal(c).second;
  c = tool_test_cut();
  c.tool_height = 0.15e-3;  // a simple outline, but the chip would flow over its top
  EXPECT_EQ(refusal(c).first, "tool_height");
  EXPECT_NE(refusal(c).second.find("tool_height >= 0.2 mm"), std::string::npos) << refusal(c).second;
  c = tool_test_cut();
  c.rake_angle_deg = 40.0;
  c.tool_length = 0.3e-3;  // the rake face's top is 0.336 mm out
  EXPECT_EQ(refusal(c).first, "tool_length");
  EXPECT_NE(refusal(c).second.find("give tool_length > 0.3356 mm"), std::string::npos) << refusal(c).second;
  c = tool_test_cut();
  c.edge_radius = 0.5e-3;
  c.tool_length = 0.3e-3;
  EXPECT_EQ(refusal(c).first, "edge_radius");
  EXPECT_NE(refusal(c).second.find("at most 0.15 mm fits"), std::string::npos) << refusal(c).second;
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

// A conducting tool (tool_conductivity > 0) is held on its back and top (edges 1 and 2 of the outline, the faces
// away from the chip: every held cell lies at least 0.2 mm from the cutting edge's centre); steady unless given a
// heat capacity, then averaging its heat input over 5 % of the cut.
TEST(CuttingScene, ConductingToolIsHeldOnItsBackAndTop) {
  MaterialParameters m;
  m.name = "ti";
  CuttingParameters c;
  c.cutting_speed = 2.0;
  c.uncut_chip_thickness = 0.1e-3;
  c.cut_length = 0.6e-3;
  c.tool_heat_transfer_coefficient = 1e6;
  c.tool_conductivity = 86.0;
  const Scene s = build_cutting_scene(c, m);
  const RigidBodySpec& tool = s.rigid_bodies.at(0);
  EXPECT_EQ(tool.conductivity, 86.0);
  EXPECT_EQ(tool.volumetric_heat_capacity, 0.0);
  EXPECT_DOUBLE_EQ(tool.heat_averaging_time, 0.05 * 0.6e-3 / 2.0);
  EXPECT_EQ(tool.held_faces, (std::vector<int>{1, 2}));
  const BodyConduction cells = make_body_conduction(tool, s.grid.cell_size);
  const Vec2 edge_centre = tool.polygon.vertices[0];
  int held = 0, conducting = 0;
  for (int k = 0; k < cells.cell_count(); ++k) {
    if (cells.kind(k) == BodyCell::Held) {
      ++held;
      EXPECT_GT((cells.cell_centre(k) - edge_centre).norm(), 0.2e-3) << "held cell " << k;
    } else if (cells.kind(k) == BodyCell::Conducting) {
      ++conducting;
    }
  }
  EXPECT_GT(held, 50);
  EXPECT_GT(conducting, 10 * held);
  c.tool_volumetric_heat_capacity = 3e6;
  const RigidBodySpec transient = build_cutting_scene(c, m).rigid_bodies.at(0);
  EXPECT_EQ(transient.volumetric_heat_capacity, 3e6);
  EXPECT_EQ(transient.heat_averaging_time, 0.0);
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

// An edge radius r > t0 meets the workpiece after e = r - sqrt(r^2 - (r - t0)^2) of travel (0.2 mm at r = 0.5 mm,
// t0 = 0.1 mm): a cut no longer than that is refused at cut_length (a 0.9 mm edge over 0.15 mm ran to "complete" with
// zero forces), and the force window and its warning count e in. r <= t0 meets it at once; the rake does not matter.
TEST(CuttingScene, ToolThatMeetsTheWorkpieceLateNeedsTheTravel) {
  CuttingParameters c;
  c.uncut_chip_thickness = 0.1e-3;
  c.edge_radius = 0.5e-3;
  EXPECT_NEAR(tool_engagement_travel(c), 0.5e-3 - std::sqrt(0.25e-6 - 0.16e-6), 1e-12);
  c.cut_length = 1e-3;  // window from max(0.4 mm, min(0.2 + 0.3 mm, 0.6 mm))
  EXPECT_NEAR(steady_window_start_travel(c), 0.5e-3, 1e-12);
  c.cut_length = 0.6e-3;  // window 0.36-0.6 mm: 0.1 mm of it after the 0.5 mm the chip needs
  EXPECT_NE(steady_window_warning(c).find("meets the workpiece at 0.0002 m"), std::string::npos)
      << steady_window_warning(c);
  MaterialParameters m;
  m.name = "ti";
  c.cut_length = 0.15e-3;
  try {
    build_cutting_scene(c, m);
    ADD_FAILURE() << "a tool that never reaches the workpiece was accepted";
  } catch (const CuttingKeyError& e) {
    EXPECT_EQ(e.key, "cut_length");
    EXPECT_NE(std::string(e.what()).find("meets the workpiece only after 0.0002 m"), std::string::npos) << e.what();
  }
  c.edge_radius = 0.1e-3;
  EXPECT_EQ(tool_engagement_travel(c), 0.0);
  c.edge_radius = 0.2e-3;
  const double at_rake_0 = tool_engagement_travel(c);
  EXPECT_NEAR(at_rake_0, 0.2e-3 - std::sqrt(0.04e-6 - 0.01e-6), 1e-12);
  c.rake_angle_deg = -20.0;  // the face leans over the edge above the uncut surface: the arc meets it first all the same
  EXPECT_NEAR(tool_engagement_travel(c), at_rake_0, 1e-12);
}

}  // namespace
}  // namespace mpmcut
