// The rigid contact (contact/rigid_contact.hpp) on a hand-made grid, without the solver: at a node
// whose material approaches a rigid plate the approach is removed and the slip reduced by mu times
// the normal change (Coulomb), the impulse goes to the plate, the frictional work to the node; a
// separating node is left alone; the MUSL pass acts exactly where the pass after the momentum
// update found contact. docs/cutting.md, "Contact".
#include <gtest/gtest.h>

#include "contact/penalty_law.hpp"
#include "contact/rigid_contact.hpp"
#include "core/particles.hpp"
#include "core/shape_functions.hpp"

using namespace mpmcut;

namespace {

constexpr double h = 1e-3;

struct PlateFixture {
  Grid grid;
  RigidContact contact;
  std::vector<RigidBodyState> bodies;
  EnergyTotals energy;

  explicit PlateFixture(double mu) {
    GridSpec spec;
    spec.cell_size = h;
    spec.min = Vec2(0.0, 0.0);
    spec.max = Vec2(20 * h, 20 * h);
    grid.build(spec);
    RigidBodySpec plate;  // top face at y = 5h, outward normal +y there
    plate.name = "plate";
    plate.polygon.vertices = {{2 * h, 2 * h}, {18 * h, 2 * h}, {18 * h, 5 * h}, {2 * h, 5 * h}};
    plate.friction = mu;
    RigidContactSettings settings;
    settings.contact_distance = 0.5 * h;
    contact = RigidContact({plate}, settings);
    RigidBodyState s;
    s.name = plate.name;
    bodies.push_back(s);
  }
  // Material of mass m at node (i, j) whose mean position is `height` above the plate.
  int put(int i, int j, double m, const Vec2& v, double height) {
    const int n = grid.index(i, j);
    grid.mass[n] = m;
    grid.velocity[n] = v;
    grid.velocity_new[n] = v;
    grid.mass_position[n] = m * Vec2(grid.node_position(i, j).x(), 5 * h + height);
    return n;
  }
};

}  // namespace

TEST(RigidContactPasses, ApproachingNodeGetsCoulombCorrectionAndThePlateItsImpulse) {
  PlateFixture f(0.3);
  const double m = 2e-3, dt = 1e-8;
  const int n = f.put(13, 9, m, Vec2(1.0, -2.0), 0.2 * h);
  f.contact.begin_step(f.bodies);
  f.contact.apply(ContactPass::AfterP2G, dt, f.grid, f.bodies, f.energy);
  // Normal approach -2 removed; slip 1 reduced by mu * 2 = 0.6 (the Coulomb limit: sliding).
  EXPECT_NEAR((f.grid.velocity[n] - Vec2(0.4, 0.0)).norm(), 0.0, 1e-15);
  const Vec2 dp = m * (Vec2(0.4, 0.0) - Vec2(1.0, -2.0));
  EXPECT_NEAR((f.bodies[0].step_impulse + dp).norm(), 0.0, 1e-18);
  EXPECT_NEAR((f.bodies[0].force + dp / dt).norm(), 0.0, 1e-9);
  ASSERT_EQ(f.contact.records().size(), 1u);
  EXPECT_EQ(f.contact.records()[0].pass, 0);
  EXPECT_TRUE(f.contact.records()[0].sliding);
  // Frictional work = friction velocity change x continuing slip x m, on the node and in the ledger.
  EXPECT_NEAR(f.grid.friction_heat[n], m * 0.6 * 0.4, 1e-18);
  EXPECT_NEAR(f.energy.friction, m * 0.6 * 0.4, 1e-18);
  EXPECT_FALSE(f.contact.heated_nodes().empty());
  EXPECT_EQ(f.contact.heated_nodes().lo, Vec2(13, 9));
}

TEST(RigidContactPasses, SeparatingOrDistantMaterialIsLeftAlone) {
  PlateFixture f(0.3);
  const int leaving = f.put(10, 9, 1e-3, Vec2(1.0, 0.5), 0.2 * h);
  const int far = f.put(12, 11, 1e-3, Vec2(0.0, -1.0), 2.0 * h);  // beyond the contact distance
  f.contact.begin_step(f.bodies);
  f.contact.apply(ContactPass::AfterP2G, 1e-8, f.grid, f.bodies, f.energy);
  EXPECT_EQ(f.grid.velocity[leaving], Vec2(1.0, 0.5));
  EXPECT_EQ(f.grid.velocity[far], Vec2(0.0, -1.0));
  EXPECT_TRUE(f.contact.records().empty());
  EXPECT_EQ(f.bodies[0].step_impulse, Vec2::Zero());
}

TEST(RigidContactPasses, MuslPassActsWhereTheUpdatePassFoundContactWhateverTheSign) {
  PlateFixture f(0.0);
  const int touched = f.put(13, 9, 1e-3, Vec2(0.0, -1.0), 0.2 * h);
  const int other = f.put(11, 9, 1e-3, Vec2(0.0, 1.0), 0.2 * h);
  f.contact.begin_step(f.bodies);
  f.contact.apply(ContactPass::AfterUpdate, 1e-8, f.grid, f.bodies, f.energy);
  EXPECT_EQ(f.grid.in_contact[touched], 1);
  EXPECT_EQ(f.grid.in_contact[other], 0);
  // The remapped velocity at the contact node now separates: still constrained (normal removed).
  f.grid.velocity_new[touched] = Vec2(0.5, 0.7);
  f.grid.velocity_new[other] = Vec2(0.0, -0.7);
  const Vec2 impulse_before = f.bodies[0].impulse;
  f.contact.apply(ContactPass::MuslRemap, 0.0, f.grid, f.bodies, f.energy);
  EXPECT_NEAR((f.grid.velocity_new[touched] - Vec2(0.5, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_EQ(f.grid.velocity_new[other], Vec2(0.0, -0.7));  // approaching, but not found in contact
  EXPECT_EQ(f.bodies[0].impulse, impulse_before);          // the MUSL pass exchanges no force
}

// The gap law (contact_detection = "gap"): material may approach the surface at up to the speed that
// closes its gap within the step; faster approach is cut to that speed, and the slip is reduced by mu times
// the normal change (Coulomb), to sticking at most.
TEST(ContactLaw, GapCorrectionLimitsTheApproachToTheGapClosingSpeed) {
  const Vec2 normal(0.0, 1.0);
  {  // approach 3 m/s, gap closes at 1 m/s: normal change 2 m/s; slip 1 m/s reduced by 0.3 * 2 = 0.6
    const ContactCorrection c = coulomb_rigid_gap_correction(Vec2(1.0, -3.0), normal, 0.3, 1.0);
    EXPECT_NEAR((c.new_relative - Vec2(0.4, -1.0)).norm(), 0.0, 1e-15);
    EXPECT_TRUE(c.sliding);
    EXPECT_NEAR(c.friction_dv, 0.6, 1e-15);
    EXPECT_NEAR(c.slip_after, 0.4, 1e-15);
  }
  {  // a large normal change sticks: the whole slip 1 m/s is removed, no more
    const ContactCorrection c = coulomb_rigid_gap_correction(Vec2(1.0, -3.0), normal, 0.8, 0.5);
    EXPECT_NEAR((c.new_relative - Vec2(0.0, -0.5)).norm(), 0.0, 1e-15);
    EXPECT_FALSE(c.sliding);
    EXPECT_NEAR(c.slip_after, 0.0, 1e-15);
  }
  {  // touching (gap 0): the approach is removed entirely, as the node law does
    const ContactCorrection gap = coulomb_rigid_gap_correction(Vec2(1.0, -2.0), normal, 0.3, 0.0);
    const ContactCorrection node = coulomb_rigid_correction(Vec2(1.0, -2.0), normal, 0.3, 1.0);
    EXPECT_NEAR((gap.new_relative - node.new_relative).norm(), 0.0, 1e-15);
  }
  {  // approach slower than the gap closes: unchanged
    const ContactCorrection c = coulomb_rigid_gap_correction(Vec2(1.0, -0.5), normal, 0.3, 1.0);
    EXPECT_NEAR((c.new_relative - Vec2(1.0, -0.5)).norm(), 0.0, 1e-15);
    EXPECT_EQ(c.friction_dv, 0.0);
  }
  {  // forced (the MUSL re-map of a node the update constrained): set to the closing speed even when separating
    const ContactCorrection c = coulomb_rigid_gap_correction(Vec2(0.0, 0.7), normal, 0.0, 1.0, true);
    EXPECT_NEAR((c.new_relative - Vec2(0.0, -1.0)).norm(), 0.0, 1e-15);
  }
}

// The penalty law (contact_detection = "penalty", contact/penalty_law.hpp): normal and tangential springs
// of stiffness k = s m / dt^2; the friction force builds up from the last step's by k v_t dt (stick) and is
// returned onto mu f_n where it would exceed it (slide), dissipating mu f_n times the slip beyond the spring's.
TEST(PenaltyLaw, NormalSpringAndElasticStickWithCoulombLimit) {
  const Vec2 normal(0.0, 1.0);
  const double m = 2e-6, dt = 1e-8, s = 0.5, overlap = 1e-9;
  const double k = s * m / (dt * dt);  // 1e10 N/m^2
  const double fn = k * overlap;       // 10 N/m
  {  // fast slip 3 m/s: the trial force k v_t dt = 300 N/m exceeds mu fn = 3 N/m; slides against the slip
    const PenaltyContactForce c = penalty_contact_force(overlap, Vec2(3.0, -1.0), normal, m, dt, s, 0.3);
    EXPECT_NEAR(c.normal_force, fn, 1e-12 * fn);
    EXPECT_TRUE(c.sliding);
    EXPECT_NEAR((c.force - Vec2(-0.3 * fn, fn)).norm(), 0.0, 1e-12 * fn);
    EXPECT_NEAR(c.slip_work, 0.3 * fn * (3.0 * dt - 0.3 * fn / k), 1e-12 * 0.3 * fn * 3.0 * dt);
  }
  {  // slow slip 1e-3 m/s: trial 0.1 N/m below mu fn; sticks, no dissipation
    const PenaltyContactForce c = penalty_contact_force(overlap, Vec2(-1e-3, 0.0), normal, m, dt, s, 0.3);
    EXPECT_FALSE(c.sliding);
    EXPECT_NEAR((c.friction_force - Vec2(k * dt * 1e-3, 0.0)).norm(), 0.0, 1e-12 * fn);
    EXPECT_EQ(c.slip_work, 0.0);
    // The next step at zero slip keeps the force (elastic stick): a sticking particle can carry shear.
    const PenaltyContactForce next = penalty_contact_force(overlap, Vec2::Zero(), normal, m, dt, s, 0.3, c.friction_force);
    EXPECT_EQ(next.friction_force, c.friction_force);
    // It builds up over steps until it reaches mu fn, and no further.
    Vec2 f = Vec2::Zero();
    int steps = 0;
    for (; steps < 100; ++steps) {
      const PenaltyContactForce d = penalty_contact_force(overlap, Vec2(-1.3e-3, 0.0), normal, m, dt, s, 0.3, f);
      f = d.friction_force;
      if (d.sliding) break;
    }
    EXPECT_EQ(steps, 23);  // 23 x 0.13 N/m = 2.99 N/m < mu fn = 3 N/m < 24 x 0.13
    EXPECT_NEAR(f.x(), 0.3 * fn, 1e-12 * fn);
  }
  {  // the history is taken in the current tangent plane: its normal part is dropped
    const PenaltyContactForce c =
        penalty_contact_force(overlap, Vec2::Zero(), normal, m, dt, s, 0.3, Vec2(1.0, 5.0));
    EXPECT_NEAR((c.friction_force - Vec2(1.0, 0.0)).norm(), 0.0, 1e-14);
  }
  {  // no overlap: no force, whatever the velocity or history
    const PenaltyContactForce c = penalty_contact_force(-1e-9, Vec2(1.0, -5.0), normal, m, dt, s, 0.3, Vec2(1, 0));
    EXPECT_EQ(c.force, Vec2::Zero());
    EXPECT_EQ(c.slip_work, 0.0);
  }
  {  // the normal force depends on the overlap only, not on the approach speed (no dashpot)
    const PenaltyContactForce a = penalty_contact_force(overlap, Vec2(0.0, -5.0), normal, m, dt, s, 0.0);
    const PenaltyContactForce b = penalty_contact_force(overlap, Vec2(0.0, 5.0), normal, m, dt, s, 0.0);
    EXPECT_EQ(a.force, b.force);
  }
}

// A step shortened to land on an output time (0.5-1 of the stable one) must not stiffen the springs: with k from
// the step itself, the normal force of the same overlap jumped by 1 / r^2 (4x at r = 0.5) on every history row.
TEST(PenaltyLaw, TheSpringsDoNotStiffenOnAShortenedStep) {
  const Vec2 normal(0.0, 1.0);
  const double m = 2e-6, stable = 1e-8, s = 0.5, overlap = 1e-9;
  const PenaltyContactForce full = penalty_contact_force(overlap, Vec2(-1e-3, 0.0), normal, m, stable, s, 0.3);
  const PenaltyContactForce shortened =
      penalty_contact_force(overlap, Vec2(-1e-3, 0.0), normal, m, 0.5 * stable, s, 0.3, Vec2::Zero(), stable);
  EXPECT_EQ(shortened.normal_force, full.normal_force);
  // The stick spring builds the friction force by k v_t dt: half of the full step's in half the time.
  EXPECT_NEAR(shortened.friction_force.x(), 0.5 * full.friction_force.x(), 1e-12 * std::abs(full.friction_force.x()));
  // Without spring_dt the step sets k, as before (the unit tests above).
  EXPECT_NEAR(penalty_contact_force(overlap, Vec2::Zero(), normal, m, 0.5 * stable, s, 0.3).normal_force,
              4.0 * full.normal_force, 1e-12 * full.normal_force);
}

// apply_penalty on a hand-made particle above the plate of PlateFixture: its force reaches the grid as
// S_ip f (summing to f), the plate gets the reaction, the body's work and the frictional work are booked.
// The slip is the grid's velocity at the particle, not the particle's own (sub-grid noise: rigid_contact.cpp).
TEST(PenaltyContact, ParticleForceGoesToItsNodesAndTheReactionToThePlate) {
  PlateFixture f(0.3);
  RigidContactSettings settings;
  settings.detection = ContactDetection::Penalty;
  settings.penalty_stiffness = 0.5;
  RigidBodySpec plate;
  plate.name = "plate";
  plate.polygon.vertices = {{2 * h, 2 * h}, {18 * h, 2 * h}, {18 * h, 5 * h}, {2 * h, 5 * h}};
  plate.friction = 0.3;
  f.contact = RigidContact({plate}, settings);
  f.bodies[0].velocity = Vec2(-1.0, 0.0);
  const ShapeFunction shape(ShapeFunctionKind::UGimp, h, 2);  // lp = h / 4
  Particles P;
  const double m = 1e-3, dt = 1e-7;
  P.add(Vec2(10.3 * h, 5 * h + 0.2499 * h), Vec2(7.0, 3.0), m, 0.25 * h * h, 300.0, 0, 0);  // overlap 1e-4 h
  P.add(Vec2(8.3 * h, 5 * h + 0.3 * h), Vec2(2.0, -0.5), m, 0.25 * h * h, 300.0, 0, 0);   // clear of it
  f.grid.reset();
  std::fill(f.grid.velocity.begin(), f.grid.velocity.end(), Vec2(2.0, -0.5));  // the material as the grid carries it
  f.contact.begin_step(f.bodies);
  const std::vector<ShapeFunction> shapes{shape};
  f.contact.apply_penalty(P, f.grid, shapes, 1.0, dt, dt, f.bodies, f.energy);
  const PenaltyContactForce c =
      penalty_contact_force(0.25 * h - (5.2499 * h - 5 * h), Vec2(3.0, -0.5), Vec2(0, 1), m, dt, 0.5, 0.3);
  ASSERT_TRUE(c.sliding);
  Vec2 sum = Vec2::Zero();
  double heat = 0.0;
  for (std::size_t n = 0; n < f.grid.node_count(); ++n) {
    sum += f.grid.force[n];
    heat += f.grid.friction_heat[n];
  }
  ASSERT_GT(c.slip_work, 0.0);
  EXPECT_NEAR((sum - c.force).norm(), 0.0, 1e-8 * c.force.norm());
  EXPECT_NEAR((f.bodies[0].step_impulse + dt * c.force).norm(), 0.0, 1e-8 * dt * c.force.norm());
  EXPECT_NEAR(f.energy.external_work, dt * c.force.dot(Vec2(-1.0, 0.0)), 1e-8 * std::abs(dt * c.force.x()));
  EXPECT_NEAR(f.energy.friction, c.slip_work, 1e-8 * c.slip_work);
  EXPECT_NEAR(heat, c.slip_work, 1e-8 * c.slip_work);
  ASSERT_EQ(f.contact.records().size(), 1u);  // only the overlapping particle
  EXPECT_TRUE(f.contact.records()[0].sliding);
  EXPECT_NEAR((P.contact_friction_force[0] - c.friction_force).norm(), 0.0, 1e-8 * c.force.norm());  // its history
  EXPECT_EQ(P.contact_friction_force[1], Vec2::Zero());
  // The nodal passes do nothing with penalty detection.
  const std::vector<Vec2> before = f.grid.velocity;
  f.grid.velocity[f.grid.index(10, 5)] = Vec2(0.0, -1.0);
  f.contact.apply(ContactPass::AfterP2G, dt, f.grid, f.bodies, f.energy);
  EXPECT_EQ(f.grid.velocity[f.grid.index(10, 5)], Vec2(0.0, -1.0));
}
