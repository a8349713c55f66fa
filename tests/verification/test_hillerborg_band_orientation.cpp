// Hillerborg objectivity where the grid, not the geometry, chooses the band's width, and the band's orientation
// to the grid (docs/theory_materials.md §10, "A band the grid chooses").
//
// Set-up: a layer four cells thick of elastic-perfectly plastic Johnson-Cook material between two heavy, stiff
// elastic blocks (density and modulus x 1e4, free: no grid side to hold them, so the sandwich can be rotated), the
// upper one sliding at v0 along the layer; the layer starts with the matching linear velocity profile (simple
// shear). A seed strip one particle spacing thick just below the layer's middle (one particle row) has the lower
// failure strain (0.02 against 0.1): it initiates first, and the strain localises from it into a band whose width
// the grid decides.
// The measure is the damage dissipation of the particles over the middle 60 % of the layer's length per unit
// length (the ends are free surfaces), over G_f.
//
// Aligned with the grid the band is one cell wide and dissipates G_f per crack area (1.007 at 20 um, 1.017 at
// 10 um). Inclined, it is not: 3.03 G_f at 22.5 deg and 2.44 G_f at 45 deg (20 um cells, 9.4 us: the damaged zone
// about two cells wide and still spreading), 2.09 at 45 deg on 10 um cells. The Hillerborg length is the cell
// size whatever the band's direction, so a band at an angle to the grid dissipates G_f several times per unit
// area. That case is the DISABLED_ test below, which fails today (issue 11, item 3: the damage dissipation of a
// cut stands for 0.8-2 times its real new surface, and primary and segment bands run at 30-50 deg to the grid).
// Part of the excess is tension stored before initiation, which a failure strain that falls with triaxiality removes
// (second DISABLED_ test: 2.43 and 2.56); the rest is the zone's width. A direction-dependent length, a second
// velocity field across failed particles and a softening strain averaged over a band three cells wide (nonlocal)
// were tried and do not remove it: the width is kinematic (docs/theory_materials.md §10). Most of it is volumetric
// locking: the consistent nodal average of the volumetric rate ([solver] volumetric_average = "nodal", off by
// default) gives 1.88 / 1.24 (triaxial 2.16 / 1.28) with the band along the grid unchanged (the last two tests).
// It is not the sandwich's stepped sides: seeded on the lattice turned with it (every side along a particle row,
// docs/input.md lattice_angle_deg), the inclined band dissipates 3.88 / 3.36 G_f (nodal 1.89 / 1.66, triaxial
// 2.56 / 2.21, 45 deg on 10 um cells 2.56): the excess is the grid's, not the seeding's. (Numbers of 2026-12-06 s50,
// after the seed strip was moved off the particle rows; before, its rows went to the layer by round-off and the
// inclined numbers were 3.06 / 2.58, nodal 1.78 / 1.56.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "../support/hillerborg_material.hpp"
#include "../support/scene_builders.hpp"
#include "solver/simulation.hpp"

using namespace mpmcut;
using namespace mpmcut::testing;

namespace {

using namespace mpmcut::testing::hillerborg;

// How the failure strain depends on the triaxiality eta.
enum class Initiation {
  Constant,  // eps_f the same at every eta (hydrostatic tension builds up before initiation)
  Triaxial,  // eps_f exp(-3 eta): initiation soon in tension, as Ti-6Al-4V's sets (D3 < 0)
};

MaterialParameters band_material(const std::string& name, double failure_strain, Initiation initiation) {
  MaterialParameters m = layer_material(name, DamageEvolution::Linear, failure_strain);
  if (initiation == Initiation::Triaxial) {
    m.jc_D1 = 0.0;
    m.jc_D2 = failure_strain;
    m.jc_D3 = -3.0;
    m.min_failure_strain = 1e-3;
  }
  return m;
}

// Dissipation per unit length of the layer's middle over G_f, after `slip_time` of sliding.
double band_dissipation_over_gf(double theta_deg, double h, double slip_time,
                                Initiation initiation = Initiation::Constant,
                                VolumetricAverage average = VolumetricAverage::Off, bool turned_lattice = false) {
  const double theta = theta_deg * std::numbers::pi / 180.0, L = 30 * h, H = 4 * h, v0 = 5.0, d = h / 2;
  const Vec2 s(std::cos(theta), std::sin(theta)), n(-std::sin(theta), std::cos(theta));
  const Vec2 o(3 * h + 8 * h * std::sin(theta), 3 * h);
  Scene scene;
  scene.grid = {h, Vec2(0, 0), Vec2(L * std::cos(theta) + 20 * h, L * std::sin(theta) + H + 20 * h)};
  scene.solver.cfl = 0.4;
  scene.solver.volumetric_average = average;
  scene.materials.push_back(band_material("layer", 0.1, initiation));
  scene.materials.push_back(band_material("seed", 0.02, initiation));
  scene.materials.push_back(elastic_material("heavy", kE * 1e4, kNu, kRho * 1e4));
  const double mid = 0.5 * H;
  scene.bodies.push_back(inclined_strip("anchor", "heavy", -2 * h, 0.0, L, theta, o, Vec2::Zero()));
  // The seed's sides lie between particle rows (a whole number of spacings from o): it holds the row just below the
  // middle, also on the turned lattice (sides on a row would leave the row to whichever strip round-off gives it).
  scene.bodies.push_back(inclined_strip("lower layer", "layer", 0.0, mid - d, L, theta, o, Vec2::Zero()));
  scene.bodies.push_back(inclined_strip("seed", "seed", mid - d, mid, L, theta, o, Vec2::Zero()));
  scene.bodies.push_back(inclined_strip("upper layer", "layer", mid, H, L, theta, o, Vec2::Zero()));
  scene.bodies.push_back(inclined_strip("driver", "heavy", H, H + 2 * h, L, theta, o, v0 * s));
  if (turned_lattice) seed_on_turned_lattice(scene, theta_deg, o);
  Simulation sim(scene);
  auto& P = sim.particles();
  for (std::size_t p = 0; p < P.size(); ++p)
    if (P.material[p] != 2) P.velocity[p] = v0 * std::clamp((P.position[p] - o).dot(n) / H, 0.0, 1.0) * s;
  while (sim.time() < slip_time) sim.step();
  double dissipation = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const double along = (P.position[p] - o).dot(s);
    if (along >= 0.2 * L && along <= 0.8 * L) dissipation += P.damage_dissipation[p];
  }
  const double ratio = dissipation / (kFractureEnergy * 0.6 * L);
  std::printf("band at %.1f deg to the grid, h = %.0f um, %s failure strain, volumetric average %s, %s lattice: "
              "dissipation / (G_f length) = %.3f\n",
              theta_deg, h * 1e6, initiation == Initiation::Constant ? "constant" : "triaxial",
              average == VolumetricAverage::Nodal ? "nodal" : "off", turned_lattice ? "turned" : "grid", ratio);
  return ratio;
}

// Initiation of the seed (0.02 of the layer's shear), the band's softening slip u_f and a margin, at 5 m/s.
double slip_time(double h) { return 3.0 * (0.02 * 4 * h + 2 * 2 * kFractureEnergy / kYield + 0.2 * h) / 5.0; }

}  // namespace

// Aligned: the band is the seed's cell row (one cell wide), for two cell sizes.
TEST(HillerborgBandOrientation, ABandAlongTheGridChosenByTheGridDissipatesFractureEnergy) {
  for (double h : {20e-6, 10e-6}) EXPECT_NEAR(band_dissipation_over_gf(0.0, h, slip_time(h)), 1.0, 0.05) << h;
}

// Inclined: fails today (2.4-3.9 G_f, see the file's header), on the grid's particle lattice and on the one turned
// with the sandwich; run with --gtest_also_run_disabled_tests.
TEST(HillerborgBandOrientation, DISABLED_ABandInclinedToTheGridDissipatesFractureEnergy) {
  for (bool turned_lattice : {false, true})
    for (double theta : {22.5, 45.0})
      EXPECT_NEAR(band_dissipation_over_gf(theta, 20e-6, slip_time(20e-6), Initiation::Constant,
                                           VolumetricAverage::Off, turned_lattice),
                  1.0, 0.1)
          << theta << (turned_lattice ? " deg, turned lattice" : " deg");
}

// The same with a failure strain that falls with triaxiality: no stored tension, every failed particle dissipates its
// share G_f V0/L (1.01-1.02), and what is left is the zone's width: 2.43 at 22.5 deg, 2.56 at 45 deg (fails today).
TEST(HillerborgBandOrientation, DISABLED_ABandInclinedToTheGridDissipatesFractureEnergyWithTriaxialInitiation) {
  for (double theta : {22.5, 45.0})
    EXPECT_NEAR(band_dissipation_over_gf(theta, 20e-6, slip_time(20e-6), Initiation::Triaxial), 1.0, 0.1) << theta;
}

// With the nodal average of the volumetric rate (solver/volumetric_average.hpp) the band along the grid is unchanged
// (1.007 / 1.017 measured) ...
TEST(HillerborgBandOrientation, WithTheNodalVolumetricAverageABandAlongTheGridStillDissipatesFractureEnergy) {
  for (double h : {20e-6, 10e-6})
    EXPECT_NEAR(band_dissipation_over_gf(0.0, h, slip_time(h), Initiation::Constant, VolumetricAverage::Nodal), 1.0,
                0.05)
        << h;
}

// ... and most of the inclined band's excess is gone: 1.88 G_f at 22.5 deg and 1.24 at 45 deg on 20 um cells
// (without it 3.03 and 2.44, the DISABLED_ test above). The bounds fail if the average does nothing or breaks the
// band (below 1: a band that never softens fully); what is left grows after the band has failed (§10).
TEST(HillerborgBandOrientation, TheNodalVolumetricAverageTakesMostOfTheInclinedBandsExcessAway) {
  for (double theta : {22.5, 45.0}) {
    const double ratio =
        band_dissipation_over_gf(theta, 20e-6, slip_time(20e-6), Initiation::Constant, VolumetricAverage::Nodal);
    EXPECT_GT(ratio, 0.95) << theta;
    EXPECT_LT(ratio, theta < 30.0 ? 2.0 : 1.8) << theta;
  }
}

