// Seeding (solver/seeding.hpp): a body's particles sit at the centres of its sub-grid squares, on the grid's own
// sub-grid or on one turned by lattice_angle_deg about lattice_origin. Turned with its lattice, a body is the unturned
// body turned: the same particles, the same volume, its sides half a spacing outside its outer rows; turned on the
// grid's sub-grid its sides are staircases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "solver/scene.hpp"
#include "solver/seeding.hpp"
#include "../support/scene_builders.hpp"

using namespace mpmcut;

namespace {

constexpr double kCell = 1e-3;
constexpr int kPpc = 2;
constexpr double kSpacing = kCell / kPpc;
constexpr int kColumns = 20, kRows = 12;  // the body: kColumns x kRows spacings (10 x 6 cells)

Vec2 turned(const Vec2& r, double angle_deg) {
  const double a = angle_deg * std::numbers::pi / 180.0;
  return Vec2(std::cos(a) * r.x() - std::sin(a) * r.y(), std::sin(a) * r.x() + std::cos(a) * r.y());
}

// The body kColumns x kRows spacings turned by angle_deg about its lower-left corner `corner`, on the turned lattice
// through that corner (turned_lattice) or on the grid's sub-grid.
Scene turned_block(double angle_deg, bool turned_lattice, const Vec2& corner = Vec2(15.3e-3, 12.1e-3)) {
  Scene scene;
  scene.grid = {kCell, Vec2(0, 0), Vec2(30 * kCell, 24 * kCell)};
  scene.materials.push_back(mpmcut::testing::elastic_material("m", 1e9, 0.3, 1000.0));
  BodySpec b = mpmcut::testing::rectangle_body("block", "m", Vec2::Zero(), Vec2::Zero(), kPpc);
  b.shape.kind = ShapeKind::Polygon;
  const double w = kColumns * kSpacing, t = kRows * kSpacing;
  for (const Vec2& r : {Vec2(0, 0), Vec2(w, 0), Vec2(w, t), Vec2(0, t)})
    b.shape.polygon.vertices.push_back(corner + turned(r, angle_deg));
  if (turned_lattice) {
    b.lattice_angle_deg = angle_deg;
    b.lattice_origin = corner;
  }
  scene.bodies.push_back(b);
  return scene;
}

Particles seeded(const Scene& scene) {
  Grid grid;
  grid.build(scene.grid);
  Particles particles;
  seed_particles(scene, grid, particles);
  return particles;
}

// The distance of the body's outermost particles from its top side, per stretch of one spacing along that side:
// (least, greatest) over the stretches.
std::pair<double, double> top_row_depth_range(const Particles& P, double angle_deg, const Vec2& corner) {
  std::map<long, double> depth_per_stretch;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const Vec2 r = turned(P.position[p] - corner, -angle_deg);  // in the body's frame
    const long stretch = static_cast<long>(std::floor(r.x() / kSpacing));
    if (stretch < 1 || stretch >= kColumns - 1) continue;  // away from the corners
    const double depth = kRows * kSpacing - r.y();
    auto [it, fresh] = depth_per_stretch.emplace(stretch, depth);
    if (!fresh) it->second = std::min(it->second, depth);
  }
  std::pair<double, double> range{1e300, -1e300};
  for (const auto& [stretch, depth] : depth_per_stretch)
    range = {std::min(range.first, depth), std::max(range.second, depth)};
  return range;
}

}  // namespace

// Unturned, the lattice is the grid's sub-grid: grid.min + spacing (k + 1/2, l + 1/2), exactly as before the keys.
TEST(Seeding, UnturnedParticlesSitAtTheCentresOfTheGridsSubGridSquares) {
  Scene scene;
  scene.grid = {kCell, Vec2(-2e-3, 1e-3), Vec2(20e-3, 20e-3)};
  scene.materials.push_back(mpmcut::testing::elastic_material("m", 1e9, 0.3, 1000.0));
  scene.bodies.push_back(mpmcut::testing::rectangle_body("b", "m", Vec2(0, 3e-3), Vec2(5e-3, 6e-3), kPpc));
  const Particles P = seeded(scene);
  ASSERT_EQ(P.size(), 10u * 6u);
  for (std::size_t p = 0; p < P.size(); ++p) {
    const Vec2 u = (P.position[p] - scene.grid.min) / kSpacing - Vec2(0.5, 0.5);
    EXPECT_EQ(u.x(), std::round(u.x())) << p;
    EXPECT_EQ(u.y(), std::round(u.y())) << p;
    EXPECT_DOUBLE_EQ(P.volume[p], kSpacing * kSpacing);
  }
}

// The body turned with its lattice is the unturned body turned: kColumns x kRows particles, each at its square's
// centre in the body's frame, the body's whole area.
TEST(Seeding, ABodyTurnedWithItsLatticeHasTheUnturnedBodysParticlesTurned) {
  const Vec2 corner(9.3e-3, 4.1e-3);
  for (const double angle : {5.0, 22.5, 30.0, 45.0, -17.0, 90.0}) {
    SCOPED_TRACE(angle);
    const Particles P = seeded(turned_block(angle, true, corner));
    ASSERT_EQ(P.size(), static_cast<std::size_t>(kColumns * kRows));
    std::vector<bool> taken(kColumns * kRows, false);
    double volume = 0.0;
    for (std::size_t p = 0; p < P.size(); ++p) {
      const Vec2 u = turned(P.position[p] - corner, -angle) / kSpacing - Vec2(0.5, 0.5);
      const long k = std::lround(u.x()), l = std::lround(u.y());
      EXPECT_NEAR(u.x(), static_cast<double>(k), 1e-9);
      EXPECT_NEAR(u.y(), static_cast<double>(l), 1e-9);
      ASSERT_TRUE(k >= 0 && k < kColumns && l >= 0 && l < kRows) << k << ", " << l;
      EXPECT_FALSE(taken[l * kColumns + k]) << "two particles in square " << k << ", " << l;
      taken[l * kColumns + k] = true;
      volume += P.volume[p];
    }
    EXPECT_NEAR(volume, kColumns * kRows * kSpacing * kSpacing, 1e-12 * volume);
  }
}

// Why the lattice turns: turned on the grid's sub-grid, the outer row steps in and out along the side (from next to
// nothing to a whole spacing deep); turned with the body, it runs half a spacing inside the side everywhere.
TEST(Seeding, ATurnedSideRunsAlongAParticleRowOnlyOnTheTurnedLattice) {
  const Vec2 corner(9.3e-3, 4.1e-3);
  for (const double angle : {5.0, 30.0}) {
    SCOPED_TRACE(angle);
    const auto [least, greatest] = top_row_depth_range(seeded(turned_block(angle, true, corner)), angle, corner);
    EXPECT_NEAR(least, 0.5 * kSpacing, 1e-9 * kSpacing);
    EXPECT_NEAR(greatest, 0.5 * kSpacing, 1e-9 * kSpacing);
    const auto [step_least, step_greatest] =
        top_row_depth_range(seeded(turned_block(angle, false, corner)), angle, corner);
    EXPECT_GT(step_greatest - step_least, 0.5 * kSpacing) << "the grid's sub-grid gave a smooth side";
  }
}

// The checks before a run count on the same points: a turned lattice keeps the count estimate an upper bound of
// the points seeded (the scan of a large body is bounded by it), and matches the unturned one at 0 deg.
TEST(Seeding, TheCountEstimateBoundsTheTurnedLatticesPoints) {
  for (const double angle : {0.0, 5.0, 30.0, 45.0, -60.0}) {
    SCOPED_TRACE(angle);
    const Scene scene = turned_block(angle, true);
    const double estimate = seed_points_in_box(scene.bodies[0], kCell);
    long visited = 0;
    for_each_seed_point(scene.bodies[0], scene.grid.min, kCell, [&](const Vec2&) { return ++visited, true; });
    EXPECT_EQ(visited, kColumns * kRows);
    EXPECT_GE(estimate, visited);
    EXPECT_LE(estimate, 5.0 * (kColumns + 1) * (kRows + 1)) << "the estimate is no longer a bound worth having";
  }
}
