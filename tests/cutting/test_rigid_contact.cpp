// Rigid-body contact with Coulomb friction (multi-velocity-field form, Bardenhagen et al. 2001; docs/cutting.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../support/scene_builders.hpp"
#include "solver/simulation.hpp"

using namespace mpmcut;
using namespace mpmcut::testing;

namespace {

Polygon box(Vec2 lo, Vec2 hi) { return Polygon{{lo, Vec2(hi.x(), lo.y()), hi, Vec2(lo.x(), hi.y())}}; }

// A block resting on a horizontal rigid plane under gravity tilted by theta: equivalent to a
// block on a plane inclined by theta. Returns the least-squares slope of the block's mean
// velocity along the plane over t in [0.25, 1] s (the normal force rings at first).
double sliding_acceleration(double theta_deg, double mu, ShapeFunctionKind kind) {
  const double h = 0.02, g = 10.0, theta = theta_deg * std::numbers::pi / 180.0;
  Scene s;
  s.grid = {h, Vec2(0, 0), Vec2(3.5, 0.4)};
  s.solver.shape_function = kind;
  s.solver.cfl = 0.4;
  s.body_force = g * Vec2(std::sin(theta), -std::cos(theta));
  s.materials.push_back(elastic_material("rubber", 1e6, 0.3, 1000.0));
  s.bodies.push_back(rectangle_body("block", "rubber", Vec2(0.1, 0.1), Vec2(0.3, 0.2), 2));
  RigidBodySpec plane;
  plane.name = "plane";
  plane.polygon = box(Vec2(-0.1, -0.1), Vec2(3.6, 0.1));
  plane.friction = mu;
  s.rigid_bodies.push_back(plane);
  Simulation sim(s);
  double M = 0.0;
  for (double m : sim.particles().mass) M += m;
  double st = 0, sv = 0, stt = 0, stv = 0;
  int n = 0;
  while (sim.time() < 1.0) {
    sim.step();
    if (sim.time() < 0.25) continue;
    const double v = sim.total_momentum().x() / M;
    st += sim.time();
    sv += v;
    stt += sim.time() * sim.time();
    stv += sim.time() * v;
    ++n;
  }
  return (n * stv - st * sv) / (n * stt - st * st);
}

}  // namespace

TEST(RigidContact, BlockSlidesWithCoulombFriction) {
  const double g = 10.0, theta = 30.0 * std::numbers::pi / 180.0, mu = 0.3;
  const double expected = g * (std::sin(theta) - mu * std::cos(theta));  // 2.402 m/s^2
  for (auto kind : {ShapeFunctionKind::UGimp, ShapeFunctionKind::Linear}) {
    const double a = sliding_acceleration(30.0, mu, kind);
    EXPECT_NEAR(a, expected, 0.02 * expected);
  }
}

TEST(RigidContact, FrictionlessBlockSlidesFreely) {
  const double expected = 10.0 * std::sin(30.0 * std::numbers::pi / 180.0);
  EXPECT_NEAR(sliding_acceleration(30.0, 0.0, ShapeFunctionKind::UGimp), expected, 0.02 * expected);
}

TEST(RigidContact, BlockSticksWhenTanThetaBelowMu) {
  // tan(10 deg) = 0.176 < mu = 0.3: no sliding; compare with the free-slip acceleration 1.74 m/s^2.
  const double a = sliding_acceleration(10.0, 0.3, ShapeFunctionKind::UGimp);
  EXPECT_LT(std::abs(a), 0.01 * 10.0 * std::sin(10.0 * std::numbers::pi / 180.0));
}

// An elastic block hits a fixed frictionless rigid wall at v0 and rebounds: the impulse on the
// wall is 2 m v0; no particle ever enters the wall.
// nu = 0 makes the block a bundle of 1D rods, for which the rebound is perfect; with nu > 0
// part of the energy stays in transverse vibration and the impulse is genuinely smaller.
struct Rebound {
  double impulse_x = 0.0, impulse_y = 0.0;  // on the wall, N s per m
  double energy_after = 0.0;                // kinetic + elastic, J per m
  double min_distance = 1.0;                // of a particle centre from the wall, m
  double velocity_after = 0.0;              // mean x velocity, m/s
  double mass = 0.0;                        // kg per m
  double first_contact_time = -1.0;         // s: end of the first step with an impulse on the wall
  double time_step = 0.0;                   // s: the last step's
};

Rebound rebound_from_wall(double h, double v0, double wall_offset, ContactDetection detection) {
  Scene s;
  s.solver.contact_detection = detection;
  s.grid = {h, Vec2(0, 0), Vec2(0.6, 0.2)};
  s.solver.cfl = 0.4;
  s.materials.push_back(elastic_material("rubber", 1e6, 0.0, 1000.0));
  s.bodies.push_back(rectangle_body("block", "rubber", Vec2(0.3, 0.05), Vec2(0.4, 0.15), 2, Vec2(v0, 0)));
  RigidBodySpec wall;
  wall.name = "wall";
  wall.polygon = box(Vec2(0.4 + wall_offset, -0.1), Vec2(0.7, 0.3));
  s.rigid_bodies.push_back(wall);
  Simulation sim(s);
  Rebound out;
  for (double m : sim.particles().mass) out.mass += m;
  const RigidPolygon geom(wall.polygon);
  while (sim.time() < 0.03) {  // contact lasts about 2 L / c = 5.5 ms
    const double t_before = sim.time();
    sim.step();
    out.time_step = sim.time() - t_before;
    if (out.first_contact_time < 0.0 && sim.rigid_bodies()[0].impulse.x() != 0.0) out.first_contact_time = sim.time();
    for (const Vec2& x : sim.particles().position) {
      Vec2 n;
      out.min_distance = std::min(out.min_distance, geom.signed_distance(x, n));
    }
  }
  out.impulse_x = sim.rigid_bodies()[0].impulse.x();
  out.impulse_y = sim.rigid_bodies()[0].impulse.y();
  sim.refresh_energy();
  out.energy_after = sim.energy().kinetic + sim.energy().elastic;
  out.velocity_after = sim.total_momentum().x() / out.mass;
  return out;
}

TEST(RigidContact, ElasticBlockRebouncesFromWallWithImpulseTwoMV) {
  const double h = 0.005, v0 = 1.0;
  const Rebound r = rebound_from_wall(h, v0, 0.5 * h, ContactDetection::Node);
  const double M = r.mass;
  EXPECT_NEAR(r.impulse_x, 2 * M * v0, 0.03 * 2 * M * v0);
  EXPECT_NEAR(r.impulse_y, 0.0, 1e-3 * M * v0);
  EXPECT_NEAR(r.energy_after, 0.5 * M * v0 * v0, 0.06 * 0.5 * M * v0 * v0);
  EXPECT_GT(r.min_distance, 0.0) << "a particle entered the wall";
  EXPECT_LT(r.velocity_after, -0.9 * v0);  // it bounced back
}

// A rigid body pushing a block: the momentum the block gains equals the impulse the rigid
// body delivers (action = reaction) and its work equals the block's kinetic + elastic energy.
TEST(RigidContact, PushingConservesMomentumAndEnergy) {
  const double h = 0.005;
  Scene s;
  s.grid = {h, Vec2(0, 0), Vec2(0.6, 0.2)};
  s.solver.cfl = 0.4;
  s.materials.push_back(elastic_material("rubber", 1e6, 0.3, 1000.0));
  s.bodies.push_back(rectangle_body("block", "rubber", Vec2(0.2, 0.05), Vec2(0.3, 0.15), 2));
  RigidBodySpec pusher;
  pusher.name = "pusher";
  pusher.polygon = box(Vec2(0.05, 0.02), Vec2(0.2 - 0.5 * h, 0.18));
  pusher.velocity = Vec2(2.0, 0.0);
  s.rigid_bodies.push_back(pusher);
  Simulation sim(s);
  while (sim.time() < 0.02) sim.step();
  sim.refresh_energy();
  const Vec2 p = sim.total_momentum();
  // Exact up to nodes below the mass cut-off, which keep their velocity and drop their force.
  EXPECT_NEAR(p.x(), -sim.rigid_bodies()[0].impulse.x(), 1e-4 * std::abs(p.x()));
  const double stored = sim.energy().kinetic + sim.energy().elastic;
  EXPECT_GT(p.x(), 0.0);
  EXPECT_NEAR(sim.energy().external_work, stored, 0.05 * stored);
}

// A block (0.2 m x 0.1 m, material m) sliding at v0 = 2 m/s along a plane with friction mu, under
// gravity g = 10 m/s^2 pressing it on the plane; the plane sends friction_heat_share of the frictional
// heat into the block.
constexpr double kSlideG = 10.0, kSlideV0 = 2.0;
Scene sliding_block(const MaterialParameters& m, double mu, double friction_heat_share = 1.0) {
  Scene s;
  s.grid = {0.02, Vec2(0, 0), Vec2(2.0, 0.4)};
  s.solver.cfl = 0.4;
  s.body_force = Vec2(0.0, -kSlideG);
  s.materials.push_back(m);
  BodySpec b = rectangle_body("block", m.name, Vec2(0.1, 0.1), Vec2(0.3, 0.2), 2, Vec2(kSlideV0, 0));
  b.temperature = m.room_temperature;
  s.bodies.push_back(b);
  RigidBodySpec plane;
  plane.name = "plane";
  plane.polygon = box(Vec2(-0.1, -0.1), Vec2(2.1, 0.1));
  plane.friction = mu;
  plane.friction_heat_share = friction_heat_share;
  s.rigid_bodies.push_back(plane);
  return s;
}

// The block stops by friction: the frictional work (Coulomb force x slip) accounts for the kinetic
// energy it loses, and its deceleration is mu g.
TEST(RigidContact, FrictionalWorkEqualsKineticEnergyLost) {
  const double mu = 0.3;
  Simulation sim(sliding_block(elastic_material("rubber", 1e6, 0.3, 1000.0), mu));
  sim.refresh_energy();
  const double E0 = sim.energy().kinetic;
  double M = 0.0;
  for (double m : sim.particles().mass) M += m;
  while (sim.time() < 0.4) sim.step();  // stops at v0/(mu g) = 0.67 s
  sim.refresh_energy();
  const EnergyTotals& e = sim.energy();
  const double lost = E0 - e.kinetic;
  EXPECT_NEAR(e.friction + e.elastic - e.external_work, lost, 0.01 * lost);
  EXPECT_NEAR(sim.total_momentum().x() / M, kSlideV0 - mu * kSlideG * sim.time(), 0.02 * kSlideV0);
  EXPECT_NEAR(e.heat, e.friction, 1e-12 * e.friction);  // frictional work becomes heat
}

// friction_heat_share: only that share of the frictional work heats the block (the rest flows into
// the plane), and the mechanics do not change. The same slide at shares 1, 0.25 and 0: the heat is
// share x friction work to rounding, the friction work and the final momentum are those of share 1
// to the last bit (the share enters nothing but the heat). A share applied twice, or to the friction
// work instead of the heat, fails the first check; one that leaks into the contact law, the second.
TEST(RigidContact, FrictionHeatShareSplitsTheHeatNotTheWork) {
  const MaterialParameters m = elastic_material("rubber", 1e6, 0.3, 1000.0);  // no melting point: no cap
  double friction_all = 0.0, momentum_all = 0.0;
  for (double share : {1.0, 0.25, 0.0}) {
    SCOPED_TRACE(::testing::Message() << "share " << share);
    Simulation sim(sliding_block(m, 0.3, share));
    while (sim.time() < 0.2) sim.step();
    const EnergyTotals& e = sim.energy();
    ASSERT_GT(e.friction, 0.0);
    EXPECT_NEAR(e.heat, share * e.friction, 1e-9 * e.friction);
    if (share == 1.0) {
      friction_all = e.friction;
      momentum_all = sim.total_momentum().x();
    } else {
      EXPECT_EQ(e.friction, friction_all);
      EXPECT_EQ(sim.total_momentum().x(), momentum_all);
    }
  }
}

// Frictional heating cannot take the surface beyond the melting temperature (a molten film
// carries no shear); the excess counts as heat flowing into the rigid body.
TEST(RigidContact, FrictionalHeatingStopsAtMelting) {
  MaterialParameters m = elastic_material("rubber", 1e6, 0.3, 1000.0);
  m.specific_heat = 0.01;          // tiny heat capacity: friction alone would heat it by kelvins
  m.room_temperature = 298.0;
  m.melting_temperature = 300.0;
  Simulation sim(sliding_block(m, 0.3));
  while (sim.time() < 0.3) sim.step();
  EXPECT_LE(sim.max_temperature(), 300.0);
  EXPECT_GT(sim.max_temperature(), 299.9);  // it did heat up to the cap
  EXPECT_LT(sim.energy().heat, 0.5 * sim.energy().friction);
}

// Gap detection: contact starts when the particle domains reach the wall, on every grid (the block's
// domain edge starts 0.1 h and 0.7 h from the wall, so at v0 it touches after 0.1 h / v0 and 0.7 h / v0);
// node detection starts it when the nodes' material is within half a cell, earlier (measured: in the first
// step at 0.1 h, after 0.47 h / v0 at 0.7 h, on both grids). The price of stopping
// every node that a touching particle reaches (up to 1.25 cells deep) at once: the impact is not quite
// elastic. Measured: impulse 1.88-1.90 m v0 at 5 mm cells, 1.93-1.94 m v0 at 2.5 mm (2 m v0 exact), the
// loss about halving with the cell (first order); the test holds that trend and the size, so that a change
// that makes the gap law more dissipative fails it.
TEST(RigidContact, GapDetectionStartsContactWhenTheDomainsTouch) {
  const double v0 = 1.0;
  for (double offset : {0.1, 0.7}) {
    double loss_coarse = 0.0;
    for (double h : {0.005, 0.0025}) {
      SCOPED_TRACE(::testing::Message() << "h = " << h << " m, wall " << offset << " h beyond the block");
      const Rebound r = rebound_from_wall(h, v0, offset * h, ContactDetection::Gap);
      const double M = r.mass, touch = offset * h / v0;
      const double loss = 1.0 - r.energy_after / (0.5 * M * v0 * v0);
      std::printf("gap, h = %.4f, offset %.1f h: first impulse at %.3f ms (touch %.3f ms, dt %.3f ms), J = %.4f m v0, "
                  "energy lost %.4f, v after %.3f v0\n",
                  h, offset, 1e3 * r.first_contact_time, 1e3 * touch, 1e3 * r.time_step,
                  r.impulse_x / (M * v0), loss, r.velocity_after / v0);
      // The first step with an impulse is the one in which the domains reach the wall.
      EXPECT_GE(r.first_contact_time, touch - 1e-9);
      EXPECT_LE(r.first_contact_time, touch + 1.01 * r.time_step);
      EXPECT_NEAR(r.impulse_x, 2 * M * v0, 0.07 * 2 * M * v0);
      EXPECT_NEAR(r.impulse_y, 0.0, 1e-3 * M * v0);
      EXPECT_LT(loss, 0.14);
      EXPECT_GT(r.min_distance, 0.0) << "a particle entered the wall";
      if (loss_coarse > 0.0) EXPECT_LT(loss, 0.7 * loss_coarse);  // first order in the cell
      loss_coarse = loss;
    }
  }
}

// Penalty contact: the normal force is a spring on the overlap of the particle domains with the wall, with no
// dashpot. Measured: the first impulse comes one step after the step in which the domains reach the wall
// (the overlap is taken at the start of a step), J = 1.92-1.96 m v0 (2 m v0 exact), 4.2-5.9 % of the energy
// lost, less on the finer grid (node detection here: within 3 % and 6 %); no particle centre enters the
// wall. The bounds hold those figures, so that a dashpot or a lost step fails the test.
TEST(RigidContact, PenaltyContactReboundStartsWhenTheDomainsTouch) {
  const double v0 = 1.0;
  for (double offset : {0.1, 0.7}) {
    double loss_coarse = 0.0;
    for (double h : {0.005, 0.0025}) {
      SCOPED_TRACE(::testing::Message() << "h = " << h << " m, wall " << offset << " h beyond the block");
      const Rebound r = rebound_from_wall(h, v0, offset * h, ContactDetection::Penalty);
      const double M = r.mass, touch = offset * h / v0;
      const double loss = 1.0 - r.energy_after / (0.5 * M * v0 * v0);
      std::printf("penalty, h = %.4f, offset %.1f h: first impulse at %.3f ms (touch %.3f ms, dt %.3f ms), J = %.4f m v0, "
                  "energy lost %.4f, v after %.3f v0\n",
                  h, offset, 1e3 * r.first_contact_time, 1e3 * touch, 1e3 * r.time_step, r.impulse_x / (M * v0), loss,
                  r.velocity_after / v0);
      EXPECT_GE(r.first_contact_time, touch - 1e-9);
      EXPECT_LE(r.first_contact_time, touch + 2.01 * r.time_step);
      EXPECT_NEAR(r.impulse_x, 2 * M * v0, 0.05 * 2 * M * v0);
      EXPECT_NEAR(r.impulse_y, 0.0, 1e-3 * M * v0);
      EXPECT_LT(loss, 0.065);
      EXPECT_GT(r.min_distance, 0.0) << "a particle centre entered the wall";
      EXPECT_LT(r.velocity_after, -0.9 * v0);
      if (loss_coarse > 0.0) EXPECT_LT(loss, loss_coarse);
      loss_coarse = loss;
    }
  }
}
