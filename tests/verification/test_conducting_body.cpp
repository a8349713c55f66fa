// A conducting rigid body ([[rigid_body]] conductivity, the cutting tool's tool_conductivity): its own temperature
// field on cells fixed to it (thermal/body_conduction), held at its temperature on its held faces, heated through
// the heat transfer coefficient by the material it touches (solver/rigid_body_heat). Checked against:
//  - a bar heated at one end and held at the other: the steady field is linear, T_held + q x / k (finite volumes
//    are exact on it), and the transient field reaches it, keeping heat in = stored + out;
//  - a bar cooling from a uniform start through its held end: the mean temperature follows the series
//    8/pi^2 sum exp(-(2n+1)^2 pi^2 Fo / 4) / (2n+1)^2 (Carslaw & Jaeger 1959, §3.3, [CarslawJaeger1959]);
//  - a slab held hot on top, resting on a conducting plate held cold below: the steady heat flow is the
//    series of the three resistances, (T_top - T_bottom) / (L_s / k_s + 1 / h_c + L_p / k_p), for a steady and
//    a transient plate alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../support/scene_builders.hpp"
#include "solver/rigid_body_heat.hpp"
#include "solver/simulation.hpp"

using namespace mpmcut;
using namespace mpmcut::testing;

namespace {

// A rectangle [0, L] x [0, W] (counter-clockwise: edge 1 is its right side x = L), held on that side.
RigidBodySpec bar(double L, double W, double k, double rho_c, double T_held) {
  RigidBodySpec b;
  b.name = "bar";
  b.polygon = Polygon{{Vec2(0.0, 0.0), Vec2(L, 0.0), Vec2(L, W), Vec2(0.0, W)}};
  b.heat_transfer_coefficient = 1.0;
  b.conductivity = k;
  b.volumetric_heat_capacity = rho_c;
  b.heat_averaging_time = rho_c > 0.0 ? 0.0 : 1.0;
  b.temperature = T_held;
  b.held_faces = {1};
  return b;
}

}  // namespace

// 40 cells along, 4 across; q = 10 W/m into the first column, k = 2 W/(m K): T = T_held + (q / W) (x_held - x) / k
// at every cell centre (x_held = L - h/2, the held column's centre), to round-off. A flow through the wrong number
// of faces, or a held column one cell off, misses by a cell's share (2.5 %) or more.
TEST(BodyConduction, SteadyBarIsLinear) {
  const double L = 0.4, W = 0.04, h = 0.01, k = 2.0, T_held = 300.0, q = 10.0;
  const BodyConduction body = make_body_conduction(bar(L, W, k, 0.0, T_held), h);
  ASSERT_EQ(body.cell_count(), 40 * 4);
  std::vector<double> input(body.cell_count(), 0.0), field = body.initial_field();
  for (int j = 0; j < 4; ++j) input[j * 40] = q / 4.0;
  body.steady_field(input, field);
  double worst = 0.0;
  for (int c = 0; c < body.cell_count(); ++c) {
    const double x = body.cell_centre(c).x();
    const double exact = T_held + (q / W) * ((L - 0.5 * h) - x) / k;
    worst = std::max(worst, std::abs(field[c] - exact));
    EXPECT_EQ(body.kind(c), c % 40 == 39 ? BodyCell::Held : BodyCell::Conducting) << "cell " << c;
  }
  std::printf("steady bar: hottest %.4f K (exact %.4f K), worst error %.2e K\n", field[0],
              T_held + (q / W) * (L - h) / k, worst);
  EXPECT_LT(worst, 1e-9 * T_held);
}

// The same bar with rho c = 1e3 J/(m^3 K) (alpha = 2e-3 m^2/s; L^2 / alpha = 80 s), heated for 1000 s: the
// transient field reaches the steady one (to 1e-6 of its rise), and over every stretch the heat put in is what it
// stored plus what left through the held column (to 1e-9).
TEST(BodyConduction, TransientBarReachesTheSteadyFieldAndKeepsItsHeat) {
  const double L = 0.4, W = 0.04, h = 0.01, k = 2.0, T_held = 300.0, q = 10.0;
  const BodyConduction body = make_body_conduction(bar(L, W, k, 1e3, T_held), h);
  const BodyConduction steady = make_body_conduction(bar(L, W, k, 0.0, T_held), h);
  std::vector<double> rate(body.cell_count(), 0.0), expected = steady.initial_field();
  for (int j = 0; j < 4; ++j) rate[j * 40] = q / 4.0;
  steady.steady_field(rate, expected);
  std::vector<double> field = body.initial_field();
  const double dt = 5.0;
  std::vector<double> heat(rate.size());
  for (std::size_t c = 0; c < rate.size(); ++c) heat[c] = rate[c] * dt;
  for (int s = 0; s < 200; ++s) {
    const double before = body.stored_heat(field);
    const double out = body.advance(field, heat, dt);
    const double stored = body.stored_heat(field) - before;
    ASSERT_NEAR(stored + out, q * dt, 1e-9 * q * dt) << "stretch " << s;
  }
  const double rise = expected[0] - T_held;
  std::printf("transient bar after 1000 s: %.6f K at the heated end, steady %.6f K\n", field[0], expected[0]);
  for (int c = 0; c < body.cell_count(); ++c) EXPECT_NEAR(field[c], expected[c], 1e-6 * rise) << "cell " << c;
}

// 40 cells, the bar at 400 K cooling through its held end (at 300 K): the mean over the conducting cells against
// the series for a slab of length L' = L - h/2 (the held column's centre to the insulated end's face) at Fo =
// alpha t / L'^2 = 0.05, 0.2, 0.5; within 1.5 % of the excess (finite volumes on 39 cells). A heat capacity
// applied twice, or not at all, misses by tens of per cent.
TEST(BodyConduction, BarCoolsThroughItsHeldEndAsTheSeries) {
  const double L = 0.4, W = 0.04, h = 0.01, k = 2.0, rho_c = 1e3, T_held = 300.0, T0 = 400.0;
  const BodyConduction body = make_body_conduction(bar(L, W, k, rho_c, T_held), h);
  const double alpha = k / rho_c, Lp = L - 0.5 * h;
  std::vector<double> field = body.initial_field(), none(body.cell_count(), 0.0);
  for (int c = 0; c < body.cell_count(); ++c)
    if (body.kind(c) == BodyCell::Conducting) field[c] = T0;
  double t = 0.0;
  for (const double Fo : {0.05, 0.2, 0.5}) {
    const double t_end = Fo * Lp * Lp / alpha;
    body.advance(field, none, t_end - t);
    t = t_end;
    double series = 0.0;
    for (int n = 0; n < 200; ++n) {
      const double m = 2 * n + 1;
      series += 8.0 / (M_PI * M_PI * m * m) * std::exp(-m * m * M_PI * M_PI * Fo / 4.0);
    }
    const double mean = body.stored_heat(field) / (rho_c * h * h * 39 * 4) / (T0 - T_held);
    std::printf("bar cooling, Fo %.2f: mean excess %.4f, series %.4f\n", Fo, mean, series);
    EXPECT_NEAR(mean, series, 0.015) << "Fo " << Fo;
  }
}

// Part of the body its held faces do not reach would heat without bound when steady: refused when the scene's
// simulation is built.
TEST(BodyConduction, SteadyBodyNeedsAHeldFaceThatReachesIt) {
  RigidBodySpec b = bar(0.4, 0.04, 2.0, 0.0, 300.0);
  b.held_faces = {};
  try {
    RigidBodyHeat heat({b}, 0.01);
    ADD_FAILURE() << "a steady body without a held face was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("rigid body \"bar\""), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no path to a held face"), std::string::npos) << e.what();
  }
}

namespace {

constexpr double kTop = 500.0, kBottom = 300.0;  // K
constexpr double kSlab = 0.2, kPlate = 0.1;        // thicknesses, m
constexpr double kSlabK = 1.0, kPlateK = 2.0, kHc = 25.0;

// The slab (k = rho = c = 1) from y = 0.1 to 0.3 held at kTop on top (the grid's top row), on a plate from y = 0
// to 0.1 of the same width, conducting (kPlateK) and held at kBottom on its lower face (edge 0), h_c = kHc between.
Scene slab_on_conducting_plate(double h, double plate_rho_c, double h_c = kHc, double averaging_time = 0.005) {
  Scene s;
  s.grid = {h, Vec2(0, 0), Vec2(0.4, kPlate + kSlab)};
  s.solver.cfl = 0.4;
  s.thermal.conduction = true;
  s.thermal.top = kTop;
  MaterialParameters m = elastic_material("slab", 1.0, 0.0, 1.0);
  m.specific_heat = 1.0;
  m.thermal_conductivity = kSlabK;
  s.materials.push_back(m);
  BodySpec b = rectangle_body("slab", "slab", Vec2(0.1, kPlate), Vec2(0.3, kPlate + kSlab), 2);
  b.temperature = kBottom;
  s.bodies.push_back(b);
  RigidBodySpec plate;
  plate.name = "plate";
  plate.polygon = Polygon{{Vec2(0.1, 0.0), Vec2(0.3, 0.0), Vec2(0.3, kPlate), Vec2(0.1, kPlate)}};
  plate.heat_transfer_coefficient = h_c;
  plate.temperature = kBottom;
  plate.conductivity = kPlateK;
  plate.volumetric_heat_capacity = plate_rho_c;
  plate.heat_averaging_time = plate_rho_c > 0.0 ? 0.0 : averaging_time;
  plate.held_faces = {0};
  s.rigid_bodies.push_back(plate);
  return s;
}

}  // namespace

// Steady state after t = 0.4 s (10 slab diffusion times): the heat flow into the plate against the series
// resistance (width 0.2 m), over the last 0.1 s, and the plate's temperature at its top cells against T_bottom +
// q (L_p - h) / k_p (their centres lie h/2 below the face, the held row's h/2 above the bottom). 20 mm cells
// (10 across the slab, 5 across the plate); within 3 %.
// Without the plate's conduction (a sink at 300 K) the flow would be 16 % higher; a plate that took its heat in the
// wrong cells, or not at all, would not settle.
TEST(ConductingBody, SlabOnAConductingPlateCarriesTheSeriesFlow) {
  const double h = 0.02;
  const double q = (kTop - kBottom) / (kSlab / kSlabK + 1.0 / kHc + kPlate / kPlateK);  // W/m^2
  for (const double rho_c : {0.0, 2.0}) {
    Simulation sim(slab_on_conducting_plate(h, rho_c));
    const double t_end = 0.4, t_mean = 0.3;
    double heat = 0.0;
    while (sim.time() < t_end) {
      sim.step(t_end - sim.time());
      if (sim.time() > t_mean) heat += sim.last_step_heat_to_rigid_bodies();
    }
    const double flow = heat / (t_end - t_mean), exact = q * 0.2;
    const RigidBodyState& plate = sim.rigid_bodies()[0];
    const BodyConduction& cells = sim.rigid_body_heat().body(0);
    double top = 0.0;
    int count = 0;
    for (int c = 0; c < cells.cell_count(); ++c)
      if (cells.kind(c) == BodyCell::Conducting && cells.cell_centre(c).y() > kPlate - h) top += plate.temperature_field[c], ++count;
    top /= count;
    const double top_exact = kBottom + q * (kPlate - h) / kPlateK;
    std::printf("%s plate: flow %.3f W/m (series %.3f), plate top %.2f K (exact %.2f K)\n",
                rho_c > 0.0 ? "transient" : "steady", flow, exact, top, top_exact);
    EXPECT_NEAR(flow, exact, 0.03 * exact) << "rho c " << rho_c;
    EXPECT_NEAR(top - kBottom, top_exact - kBottom, 0.03 * (top_exact - kBottom)) << "rho c " << rho_c;
  }
}

// A steady plate whose input average is given a time shorter than one update (weight 1) and a contact 40 times
// more conductive (h_c = 1000 W/(m^2 K)): the plate's cells would answer each update's heat with a rise that sends
// more than that heat back (the loop gain of the surface cells is several), and the plate's field and the slab's
// temperatures would oscillate with a growing amplitude (negative kelvins within a few hundred updates). The average
// takes no more weight than the loop allows (RigidBodyHeat::stable_average_weight), so the flow settles to the
// series value within 3 % and no temperature leaves [T_bottom, T_top].
TEST(ConductingBody, SteadyPlateWithAStiffContactSettlesWithoutOvershoot) {
  const double h = 0.02, h_c = 1000.0;
  const double q = (kTop - kBottom) / (kSlab / kSlabK + 1.0 / h_c + kPlate / kPlateK);  // W/m^2
  Simulation sim(slab_on_conducting_plate(h, 0.0, h_c, 1e-9));
  const double t_end = 0.4, t_mean = 0.3;
  double heat = 0.0;
  double coldest = kTop, hottest = kBottom;
  while (sim.time() < t_end) {
    sim.step(t_end - sim.time());
    if (sim.time() > t_mean) heat += sim.last_step_heat_to_rigid_bodies();
    const RigidBodyState& plate = sim.rigid_bodies()[0];
    const BodyConduction& cells = sim.rigid_body_heat().body(0);
    for (int c = 0; c < cells.cell_count(); ++c)
      if (cells.kind(c) != BodyCell::Outside) {
        coldest = std::min(coldest, plate.temperature_field[c]);
        hottest = std::max(hottest, plate.temperature_field[c]);
      }
    for (const double T : sim.particles().temperature) {
      coldest = std::min(coldest, T);
      hottest = std::max(hottest, T);
    }
  }
  const double flow = heat / (t_end - t_mean), exact = q * 0.2;
  std::printf("stiff contact: flow %.3f W/m (series %.3f), temperatures %.2f..%.2f K\n", flow, exact, coldest, hottest);
  EXPECT_NEAR(flow, exact, 0.03 * exact);
  EXPECT_GE(coldest, kBottom - 1e-6);
  EXPECT_LE(hottest, kTop + 1e-6);
}
