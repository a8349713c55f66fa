// Johnson-Cook damage initiation and Hillerborg evolution (docs/theory_materials.md §5).
// Damage constants: Ti-6Al-4V D1..D5 = -0.09, 0.25, -0.5, 0.014, 3.87 (Johnson-Holmquist/Lesuer, the Abaqus
// deck jc_ti64_abq_builtin.inp [V]), with eps_f values worked out by hand from Eq. (5.1).
#include <gtest/gtest.h>

#include <cmath>

#include "physics/damage.hpp"

#include "../support/ti64_parameters.hpp"

using namespace mpmcut;

namespace {
MaterialParameters ti64_damage(DamageEvolution law = DamageEvolution::Linear, double G_f = 2.0e4) {
  MaterialParameters m = mpmcut::testing::with_jc_damage(mpmcut::testing::ti64_johnson_1985(), law, G_f);
  m.name = "ti64-damage";
  return m;
}
double eps_f_closed_form(double eta, double lr, double ts) {
  return (-0.09 + 0.25 * std::exp(-0.5 * eta)) * (1 + 0.014 * lr) * (1 + 3.87 * ts);
}
}  // namespace

// theory §5, Eq. (5.1): values worked out by hand: eta = -1/3, 0, 1/3, 2/3 -> 0.205, 0.160,
// 0.122, 0.089 at epsdot* = 1, T* = 0; and eta = 0, epsdot* = 1e5, T* = 0.4 -> 0.473.
TEST(JohnsonCookDamage, FailureStrainTabulatedValues) {
  const JohnsonCookDamage d(ti64_damage());
  EXPECT_NEAR(d.failure_strain(-1.0 / 3.0, 0.0, 0.0), 0.205, 0.0005);
  EXPECT_NEAR(d.failure_strain(0.0, 0.0, 0.0), 0.160, 0.0005);
  EXPECT_NEAR(d.failure_strain(1.0 / 3.0, 0.0, 0.0), 0.122, 0.0005);
  EXPECT_NEAR(d.failure_strain(2.0 / 3.0, 0.0, 0.0), 0.089, 0.0005);
  EXPECT_NEAR(d.failure_strain(0.0, std::log(1e5), 0.4), 0.473, 0.0005);
  EXPECT_NEAR(d.failure_strain(0.4, 3.0, 0.2), eps_f_closed_form(0.4, 3.0, 0.2), 1e-15);
}

// theory §5, Eq. (5.1) (Johnson & Cook 1985 sign of D3): with tension-positive eta and D3 < 0, eps_f must
// decrease as eta rises; D1 < 0 makes the formula negative above eta = 2.04, so it is clamped.
TEST(JohnsonCookDamage, FailureStrainFallsWithTriaxialityAndIsClamped) {
  const JohnsonCookDamage d(ti64_damage());
  double previous = d.failure_strain(-2.0, 0.0, 0.0);
  for (double eta = -1.9; eta <= 2.0; eta += 0.1) {
    const double ef = d.failure_strain(eta, 0.0, 0.0);
    EXPECT_LT(ef, previous) << eta;
    previous = ef;
  }
  EXPECT_LT(eps_f_closed_form(2.5, 0, 0), 0.0);
  EXPECT_EQ(d.failure_strain(2.5, 0.0, 0.0), 0.01);
  EXPECT_EQ(d.failure_strain(50.0, 0.0, 0.0), 0.01);
  EXPECT_TRUE(std::isfinite(d.failure_strain(-50.0, 0.0, 0.0)));
}

// theory §5, Eq. (5.2): the initiation indicator omega = sum d(eps_p)/eps_f reaches 1 at eps_p = eps_f for a
// proportional path (fixed eta), for eta = -1/3, 0, 1/3, 2/3, with increments that do not divide eps_f.
TEST(JohnsonCookDamage, InitiationAtFailureStrainForFixedTriaxiality) {
  const JohnsonCookDamage d(ti64_damage());
  for (double eta : {-1.0 / 3.0, 0.0, 1.0 / 3.0, 2.0 / 3.0}) {
    const double ef = d.failure_strain(eta, 0.0, 0.0);
    DamageState s;
    double eps = 0.0, eps_at_initiation = -1.0;
    const double de = 7.3e-4;
    while (eps < 2.0 * ef) {
      const DamageStep step = d.advance(s, de, ef, 1.0e9, 5e-6, 0.0);
      if (step.initiated_now) eps_at_initiation = eps + step.strain_before_initiation;
      EXPECT_NEAR(step.strain_before_initiation + step.strain_after_initiation, de, 1e-18);
      eps += de;
    }
    EXPECT_NEAR(eps_at_initiation, ef, 1e-12) << eta;  // exact split; the brief asks for 1 %
    EXPECT_EQ(s.initiation, 1.0);
    EXPECT_EQ(s.initiation_yield_stress, 1.0e9);
    // and u_pl counts only the strain after initiation
    EXPECT_NEAR(s.plastic_displacement, 5e-6 * (eps - ef), 1e-15);
  }
}

// theory §5, Eq. (5.3): linear law D = u_pl/u_f with u_f = 2 G_f/sigma_y0; D = max_damage at u_pl = max*u_f
// (= u_f for max_damage = 1), and the softening work int (1 - D) sigma_y0 du_pl equals G_f.
TEST(JohnsonCookDamage, LinearHillerborgLaw) {
  MaterialParameters m = ti64_damage(DamageEvolution::Linear, 2.0e4);
  m.max_damage = 1.0;
  const JohnsonCookDamage d(m);
  const double sy0 = 1.0e9, L = 5e-6, uf = 2 * 2.0e4 / sy0;
  EXPECT_DOUBLE_EQ(JohnsonCookDamage::failure_displacement(d.fracture_energy(1e6), sy0), uf);
  DamageState s;
  s.initiation = 1.0;
  s.initiation_yield_stress = sy0;
  s.fracture_energy = 2.0e4;
  const int n = 4000;
  const double de = uf / L / n;  // reaches u_f in n increments
  double work = 0.0;             // int (1 - D) sigma_y du, midpoint rule (exact for linear D)
  for (int k = 0; k < n; ++k) {
    const DamageStep step = d.advance(s, de, 0.0, sy0, L, 0.0);
    work += (1.0 - 0.5 * (step.damage_before + s.damage)) * sy0 * L * de;
    EXPECT_NEAR(s.damage, std::min(s.plastic_displacement / uf, 1.0), 1e-12);
    if (k < n - 2) EXPECT_FALSE(step.failed);
  }
  EXPECT_NEAR(s.plastic_displacement, uf, 1e-12 * uf);
  EXPECT_NEAR(s.damage, 1.0, 1e-12);
  EXPECT_TRUE(d.failed(s.damage));
  EXPECT_NEAR(work, 2.0e4, 1e-6 * 2.0e4);
  // with the default cap 0.999 the particle fails at u_pl = 0.999 u_f
  const JohnsonCookDamage capped(ti64_damage(DamageEvolution::Linear, 2.0e4));
  DamageState c;
  c.initiation = 1.0;
  c.initiation_yield_stress = sy0;
  c.fracture_energy = 2.0e4;
  DamageStep last;
  while (!(last = capped.advance(c, de, 0.0, sy0, L, 0.0)).failed) {
  }
  EXPECT_EQ(c.damage, 0.999);
  EXPECT_NEAR(c.plastic_displacement, 0.999 * uf, 1.01 * L * de);
  // a failed particle does not change any more
  const DamageState frozen = c;
  EXPECT_TRUE(capped.advance(c, de, 0.0, sy0, L, 0.0).failed);
  EXPECT_EQ(c.plastic_displacement, frozen.plastic_displacement);
}

// theory §5, Eq. (5.4): exponential law D = 1 - exp(-int sigma_y du_pl / G_f), also with a varying sigma_y;
// the softening work int (1 - D) sigma_y du -> G_f D.
TEST(JohnsonCookDamage, ExponentialHillerborgLaw) {
  const JohnsonCookDamage d(ti64_damage(DamageEvolution::Exponential, 1.0e4));
  DamageState s;
  s.initiation = 1.0;
  s.fracture_energy = 1.0e4;
  const double L = 5e-6, de = 1e-3;
  double W = 0.0, work = 0.0;
  for (int k = 0; k < 100000; ++k) {
    const double sy = 1.0e9 * (1.0 + 0.3 * std::sin(1e-3 * k));  // any positive history
    const DamageStep step = d.advance(s, de, 0.0, sy, L, 0.0);
    W += sy * L * de;
    // softening work int (1 - D) sigma_y du_pl, trapezoidal in D
    work += (1.0 - 0.5 * (s.damage + step.damage_before)) * sy * L * de;
    if (step.failed) break;
    EXPECT_NEAR(s.damage, 1.0 - std::exp(-W / 1.0e4), 1e-12);
  }
  EXPECT_EQ(s.damage, 0.999);
  EXPECT_NEAR(W, -1.0e4 * std::log(1 - 0.999), 1.1e9 * 1.3 * L * de);
  EXPECT_NEAR(work, 0.999 * 1.0e4, 1e-4 * 1.0e4);
}

// theory §5.6: G_f(rate) = G_b + (G_f - G_b)/(1 + (rate/rate_t)^n): G_f at rest, the mean of G_f and G_b at
// rate_t, G_b far above it, monotone in between; rate_t = 0 keeps G_f at every rate.
TEST(JohnsonCookDamage, FractureEnergyDuctileToBrittleTransition) {
  MaterialParameters m = ti64_damage(DamageEvolution::Linear, 15e3);
  EXPECT_EQ(JohnsonCookDamage(m).fracture_energy(1e9), 15e3);  // rate-independent by default
  m.fracture_energy_brittle = 5e3;
  m.fracture_transition_strain_rate = 1e6;
  m.fracture_transition_exponent = 3.0;
  const JohnsonCookDamage d(m);
  EXPECT_EQ(d.fracture_energy(0.0), 15e3);
  EXPECT_NEAR(d.fracture_energy(1e6), 10e3, 1e-9);
  EXPECT_NEAR(d.fracture_energy(2e6), 5e3 + 10e3 / 9.0, 1e-9);
  EXPECT_NEAR(d.fracture_energy(1e9), 5e3, 1e-2);
  double last = d.fracture_energy(1e3);
  for (double r = 2e3; r < 1e9; r *= 2) {
    EXPECT_LT(d.fracture_energy(r), last) << r;
    last = d.fracture_energy(r);
  }
  // the rate at initiation fixes the particle's G_f: u_f = 2 G_f(rate)/sigma_y0, whatever the rate later
  DamageState s;
  s.initiation = 0.99;
  d.advance(s, 0.02, 1.0, 1e9, 5e-6, 2e6);
  EXPECT_EQ(s.initiation, 1.0);
  EXPECT_NEAR(s.fracture_energy, 5e3 + 10e3 / 9.0, 1e-9);
  const double uf = JohnsonCookDamage::failure_displacement(s.fracture_energy, 1e9);
  while (!d.advance(s, 1e-3, 1.0, 1e9, 5e-6, 0.0).failed) EXPECT_NEAR(s.damage, s.plastic_displacement / uf, 1e-12);
  EXPECT_NEAR(s.plastic_displacement, 0.999 * uf, 5e-9);
  // bad constants are refused
  m.fracture_energy_brittle = 0.0;
  EXPECT_THROW(JohnsonCookDamage{m}, std::invalid_argument);
}

// G_f = 0 (Abaqus' "instantaneous failure", which it warns causes dynamic instabilities) is refused by the
// damage model as by the input reader: one rule set, the damage parameter table.
TEST(JohnsonCookDamage, ZeroFractureEnergyIsRefused) {
  EXPECT_THROW(JohnsonCookDamage{ti64_damage(DamageEvolution::Linear, 0.0)}, std::invalid_argument);
  EXPECT_NO_THROW(JohnsonCookDamage{ti64_damage(DamageEvolution::Linear, 1.0)});
}

// theory §5, Eq. (5.5): sigma = (1 - D) s - p_eff I, p_eff = p in compression, (1 - D) p in tension;
// failed: no shear (but a closed crack's friction, §5.8), no tension, compression kept.
TEST(JohnsonCookDamage, DegradedStress) {
  const PlaneStrainTensor s{2e8, -1e8, -1e8, 5e7};
  const PlaneStrainTensor a = degraded_stress(s, 3e8, 0.25, 0.75, false);  // compression
  EXPECT_DOUBLE_EQ(a.xx, 0.75 * 2e8 - 3e8);
  EXPECT_DOUBLE_EQ(a.zz, 0.75 * -1e8 - 3e8);
  EXPECT_DOUBLE_EQ(a.xy, 0.75 * 5e7);
  const PlaneStrainTensor b = degraded_stress(s, -3e8, 0.25, 0.75, false);  // tension
  EXPECT_DOUBLE_EQ(b.yy, 0.75 * -1e8 + 0.75 * 3e8);
  const PlaneStrainTensor c = degraded_stress(s, 3e8, 0.999, 0.0, true);  // failed, compression
  EXPECT_EQ(c.xy, 0.0);
  EXPECT_EQ(c.xx, -3e8);
  EXPECT_EQ(c.yy, -3e8);
  EXPECT_EQ(c.zz, -3e8);
  EXPECT_EQ(c.deviator().contract(c.deviator()), 0.0);
  const PlaneStrainTensor f = degraded_stress(s, 3e8, 0.999, 0.4, true);  // failed, closed crack's friction (§5.8)
  EXPECT_DOUBLE_EQ(f.xy, 0.4 * 5e7);
  EXPECT_DOUBLE_EQ(f.xx, 0.4 * 2e8 - 3e8);
  const PlaneStrainTensor t = degraded_stress(s, -3e8, 0.999, 0.0, true);  // failed, tension
  EXPECT_EQ(t.xx, 0.0);
  EXPECT_EQ(t.xy, 0.0);
  EXPECT_EQ(t.trace(), 0.0);
}

// eta = -p/q with tension positive.
TEST(JohnsonCookDamage, TriaxialitySign) {
  EXPECT_DOUBLE_EQ(stress_triaxiality(-1.0, 3.0), 1.0 / 3.0);  // uniaxial tension: p = -sigma/3, q = sigma
  EXPECT_DOUBLE_EQ(stress_triaxiality(1.0, 3.0), -1.0 / 3.0);
  EXPECT_EQ(stress_triaxiality(1.0, 0.0), 0.0);
}

// theory §5.8: the deviator's share k = 1 - D (1 - phi), phi = min(1, sqrt(3) mu_c p / q) for p > 0: the equivalent
// shear k q/sqrt(3) is (1 - D) tau + D min(tau, mu_c p), tau = q/sqrt(3). Worked by hand for D = 0.8, q = sqrt(3)
// 500 MPa (tau = 500 MPa): mu_c 0.5 at p = 400 MPa gives 0.2 * 500 + 0.8 * 200 = 260 MPa; at p = 2 GPa the crack's
// friction carries all of it (500); in tension, or without crack friction, 0.2 * 500 = 100 MPa.
TEST(JohnsonCookDamage, ClosedCrackShareIsTheIntactPartPlusFriction) {
  MaterialParameters m = ti64_damage();
  m.crack_friction = 0.5;
  const JohnsonCookDamage d(m);
  const double q = std::sqrt(3.0) * 5e8;
  const auto tau = [&](const JohnsonCookDamage& model, double p) {
    return deviator_share(0.8, model.closed_crack_share(p, q)) * 5e8;
  };
  EXPECT_NEAR(tau(d, 4e8), 2.6e8, 1e-6);
  EXPECT_NEAR(tau(d, 2e9), 5e8, 1e-6);
  EXPECT_NEAR(tau(d, -4e8), 1e8, 1e-6);
  EXPECT_NEAR(tau(d, 0.0), 1e8, 1e-6);
  EXPECT_EQ(deviator_share(0.0, d.closed_crack_share(4e8, q)), 1.0);  // undamaged: all of it
  const JohnsonCookDamage without(ti64_damage());
  EXPECT_FALSE(without.has_crack_friction());
  EXPECT_NEAR(tau(without, 2e9), 1e8, 1e-6);
}
