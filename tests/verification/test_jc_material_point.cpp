// Homogeneous Johnson-Cook material-point tests through the full constitutive update (no grid):
// docs/theory_materials.md §2-§6. One particle, constant velocity
// gradient, F <- (I + L dt) F, V = det(F) V0, then JohnsonCookMaterial::update.
// Ti-6Al-4V, Johnson 1985 set: A = 862 MPa, B = 331 MPa, n = 0.34, C = 0.012, m = 0.8, epsdot0 = 1/s,
// T_r = 298 K, T_m = 1878 K (docs/materials.md); E = 113.8 GPa, nu = 0.342, rho = 4430,
// c = 526.3 J/(kg K), chi = 0.9 (Payette; ETH IWF); damage D1..D5 = -0.09, 0.25, -0.5, 0.014, 3.87
// (Johnson-Holmquist/Lesuer; docs/references.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "physics/johnson_cook.hpp"
#include "physics/material_point_driver.hpp"

#include "../support/ti64_parameters.hpp"

using namespace mpmcut;

namespace {
MaterialParameters ti64() { return mpmcut::testing::ti64_johnson_1985(); }
MaterialParameters with_damage(MaterialParameters m, DamageEvolution law = DamageEvolution::Linear,
                               double G_f = 2.0e4) {
  return mpmcut::testing::with_jc_damage(m, law, G_f);
}
// Perfectly plastic at A = 862 MPa, rate- and temperature-independent (no heating), linear Hillerborg damage with
// G_f, and the given EOS (Mie-Grueneisen constants of Steinberg 1996 [M]): sigma_y0 at initiation is exactly A.
MaterialParameters perfectly_plastic_with_damage(EquationOfState eos, double G_f) {
  MaterialParameters m = with_damage(ti64(), DamageEvolution::Linear, G_f);
  m.jc_B = 0.0;
  m.jc_C = 0.0;
  m.taylor_quinney = 0.0;
  m.eos = eos;
  m.mg_c0 = 5130.0;
  m.mg_s = 1.028;
  m.mg_gamma0 = 1.23;
  return m;
}
Mat2 simple_shear(double gamma_dot) {
  Mat2 L;
  L << 0.0, gamma_dot, 0.0, 0.0;
  return L;
}
Mat2 diagonal(double a, double b) {
  Mat2 L;
  L << a, 0.0, 0.0, b;
  return L;
}

double triaxiality(const PlaneStrainTensor& s) { return s.mean() / s.von_mises(); }

// Largest |q - sigma_y(eps_p, epsdot, T)| / sigma_y over the steps that flowed plastically, with the
// state recorded at the end of the step (the update is implicit in eps_p, rate and T).
struct Consistency {
  double max_error = 0.0;
  int plastic_steps = 0;
};
Consistency yield_consistency(const JohnsonCookMaterial& jc, const std::vector<MaterialPointRecord>& h) {
  Consistency c;
  for (std::size_t k = 1; k < h.size(); ++k) {
    if (!(h[k].plastic_strain > h[k - 1].plastic_strain)) continue;
    const double q = h[k].effective_stress.von_mises();
    const double sy = jc.flow_stress().yield_stress(h[k].plastic_strain, h[k].plastic_strain_rate, h[k].temperature);
    c.max_error = std::max(c.max_error, std::abs(q - sy) / sy);
    ++c.plastic_steps;
  }
  return c;
}

// Linear interpolation of a recorded quantity at a given plastic strain (eps_p is non-decreasing).
double at_plastic_strain(const std::vector<MaterialPointRecord>& h, double eps,
                         const std::function<double(const MaterialPointRecord&)>& f) {
  for (std::size_t k = 1; k < h.size(); ++k) {
    if (h[k].plastic_strain >= eps && h[k - 1].plastic_strain < eps) {
      const double w = (eps - h[k - 1].plastic_strain) / (h[k].plastic_strain - h[k - 1].plastic_strain);
      return (1 - w) * f(h[k - 1]) + w * f(h[k]);
    }
  }
  ADD_FAILURE() << "plastic strain " << eps << " not reached";
  return 0.0;
}
}  // namespace

// theory §4, Eq. (4.5) (radial return): whenever the step is plastic, the end-of-step
// state lies on the yield surface, q = sigma_y(eps_p, epsdot, T), to 1e-8, along plane-strain tension
// (sigma_yy = 0), simple shear and uniaxial-strain compression, rate-dependent, with adiabatic heating,
// with and without rate smoothing.
TEST(JohnsonCookMaterialPoint, StaysOnYieldSurfaceAlongThreePaths) {
  for (double tau : {0.0, 2e-7}) {
    MaterialParameters m = ti64();
    m.strain_rate_smoothing_time = tau;
    const JohnsonCookMaterial jc(m);
    const double dt = 1e-8;
    {
      MaterialPointDriver d(jc, 298.0, 5e-6);
      d.run(simple_shear(1e4), dt, 6000);
      const Consistency c = yield_consistency(jc, d.history());
      EXPECT_GT(c.plastic_steps, 5000);
      EXPECT_LT(c.max_error, 1e-8) << "simple shear, tau " << tau;
    }
    {
      MaterialPointDriver d(jc, 298.0, 5e-6);
      d.run(diagonal(-1e4, 0.0), dt, 3000);
      const Consistency c = yield_consistency(jc, d.history());
      EXPECT_GT(c.plastic_steps, 2500);
      EXPECT_LT(c.max_error, 1e-8) << "uniaxial-strain compression, tau " << tau;
      // uniaxial strain: strongly compressive triaxiality once plastic
      EXPECT_LT(triaxiality(d.last().stress), -3.0);
    }
    {
      MaterialPointDriver d(jc, 298.0, 5e-6);
      for (int k = 0; k < 3000; ++k) d.step_free_yy(diagonal(1e4, -1e4), dt);
      const Consistency c = yield_consistency(jc, d.history());
      EXPECT_GT(c.plastic_steps, 2500);
      EXPECT_LT(c.max_error, 1e-8) << "plane-strain tension, tau " << tau;
      const PlaneStrainTensor& s = d.last().stress;
      EXPECT_LT(std::abs(s.yy), 1e-6 * s.xx);
      // Plane-strain plastic flow: s_zz -> 0, i.e. sigma_zz -> sigma_xx/2 and eta -> 1/sqrt(3).
      // Dropping sigma_zz would give 1/3 and a wrong q.
      EXPECT_NEAR(s.zz / s.xx, 0.5, 0.01);
      EXPECT_NEAR(triaxiality(s), 1.0 / std::sqrt(3.0), 0.01);
    }
  }
}

// theory §2, Eq. (2.2) through the full update (heating off): at equal eps_p the flow-stress ratio of two
// rates is (1 + C ln e1*)/(1 + C ln e2*), with e* the recorded plastic rates, and close to the ratio at the
// nominal equivalent rates gamma_dot/sqrt(3).
TEST(JohnsonCookMaterialPoint, RateDependence) {
  MaterialParameters m = ti64();
  m.taylor_quinney = 0.0;
  const JohnsonCookMaterial jc(m);
  MaterialPointDriver fast(jc, 298.0, 5e-6), slow(jc, 298.0, 5e-6);
  const double g1 = 1e5, g2 = 1e2, steps = 4000;
  fast.run(simple_shear(g1), 0.4 / g1 / steps, 4000);
  slow.run(simple_shear(g2), 0.4 / g2 / steps, 4000);
  auto q = [](const MaterialPointRecord& r) { return r.effective_stress.von_mises(); };
  auto rate = [](const MaterialPointRecord& r) { return r.plastic_strain_rate; };
  for (double eps : {0.05, 0.1, 0.2}) {
    const double ratio = at_plastic_strain(fast.history(), eps, q) / at_plastic_strain(slow.history(), eps, q);
    const double e1 = at_plastic_strain(fast.history(), eps, rate), e2 = at_plastic_strain(slow.history(), eps, rate);
    EXPECT_NEAR(ratio, (1 + 0.012 * std::log(e1)) / (1 + 0.012 * std::log(e2)), 1e-6) << eps;
    EXPECT_NEAR(ratio, (1 + 0.012 * std::log(g1 / std::sqrt(3.0))) / (1 + 0.012 * std::log(g2 / std::sqrt(3.0))),
                1e-3)
        << eps;
    EXPECT_NEAR(e1, g1 / std::sqrt(3.0), 0.01 * g1);
  }
}

// theory §2, Eq. (2.3) through the full update (heating off, C = 0 so that only T differs): at equal eps_p
// q(T)/q(T_r) = 1 - T*^m.
TEST(JohnsonCookMaterialPoint, TemperatureDependence) {
  MaterialParameters m = ti64();
  m.taylor_quinney = 0.0;
  m.jc_C = 0.0;
  const JohnsonCookMaterial jc(m);
  MaterialPointDriver cold(jc, 298.0, 5e-6);
  cold.run(simple_shear(1e4), 1e-8, 4000);
  auto q = [](const MaterialPointRecord& r) { return r.effective_stress.von_mises(); };
  for (double T : {500.0, 900.0, 1400.0, 1800.0}) {
    MaterialPointDriver hot(jc, T, 5e-6);
    hot.run(simple_shear(1e4), 1e-8, 4000);
    EXPECT_EQ(hot.last().temperature, T);
    const double Ts = (T - 298.0) / (1878.0 - 298.0);
    for (double eps : {0.05, 0.15}) {
      const double ratio = at_plastic_strain(hot.history(), eps, q) / at_plastic_strain(cold.history(), eps, q);
      EXPECT_NEAR(ratio, 1.0 - std::pow(Ts, 0.8), 1e-6) << T << " " << eps;
    }
  }
}

// theory §2, Eq. (2.3) and §4 step 3: at or above T_m the deviator is zero and nothing flows; the pressure
// still follows the EOS (uniaxial strain: p = K eps_v).
TEST(JohnsonCookMaterialPoint, MeltCarriesNoDeviator) {
  const MaterialParameters m = ti64();
  const JohnsonCookMaterial jc(m);
  for (double T : {1878.0, 2200.0}) {
    MaterialPointDriver d(jc, T, 5e-6);
    d.run(simple_shear(1e4), 1e-8, 100);
    EXPECT_EQ(d.last().stress.von_mises(), 0.0);
    EXPECT_EQ(d.last().plastic_strain, 0.0);
    EXPECT_EQ(d.last().cumulative.plastic_work, 0.0);
    d.run(diagonal(-1e4, 0.0), 1e-8, 100);
    const PlaneStrainTensor& s = d.last().stress;
    EXPECT_EQ(s.xy, 0.0);
    EXPECT_NEAR(s.von_mises(), 0.0, 1e-6 * std::abs(s.mean()));
    EXPECT_NEAR(-s.mean(), m.bulk_modulus() * 100 * 1e-4, 1e-3 * m.bulk_modulus() * 1e-2);
  }
}

// Rate floor and T* clamp (theory §2): tiny rates (1e-8/s) and temperatures below room give finite
// results and the quasi-static, room-temperature yield surface A + B eps^n.
TEST(JohnsonCookMaterialPoint, TinyRatesAndColdTemperaturesStayFinite) {
  MaterialParameters m = ti64();
  m.taylor_quinney = 0.0;  // keep T fixed so that the closed form below applies
  const JohnsonCookMaterial jc(m);
  for (double T : {4.0, 77.0, 298.0}) {
    MaterialPointDriver d(jc, T, 5e-6);
    d.run(simple_shear(1e-8), 2e4, 2000);  // gamma = 0.4
    for (const MaterialPointRecord& r : d.history()) {
      ASSERT_TRUE(std::isfinite(r.stress.xy) && std::isfinite(r.temperature) && std::isfinite(r.plastic_strain));
    }
    const MaterialPointRecord& r = d.last();
    EXPECT_GT(r.plastic_strain, 0.2);
    EXPECT_NEAR(r.effective_stress.von_mises(), 862e6 + 331e6 * std::pow(r.plastic_strain, 0.34),
                1e-8 * 1e9);
    EXPECT_LT(r.plastic_strain_rate, 1e-7);
  }
}

// In simple shear eps_eq = gamma/sqrt(3); at large gamma eps_p is that minus the
// elastic part q/(3G) (loose: Jaumann rotation and heating make it approximate).
TEST(JohnsonCookMaterialPoint, SimpleShearPlasticStrainAtLargeShear) {
  const MaterialParameters m = ti64();
  const JohnsonCookMaterial jc(m);
  MaterialPointDriver d(jc, 298.0, 5e-6);
  const double gamma = 2.0;
  d.run(simple_shear(1e4), gamma / 1e4 / 20000, 20000);
  const MaterialPointRecord& r = d.last();
  const double expected = gamma / std::sqrt(3.0) - r.effective_stress.von_mises() / (3 * m.shear_modulus());
  EXPECT_NEAR(r.plastic_strain, expected, 0.02 * expected);
  EXPECT_EQ(r.volume, 1.0);
}

// theory §4, Eq. (4.7) (Taylor & Quinney 1934): the driver temperature equals the adiabatic ODE
// dT/deps_p = chi sigma_y(eps_p, epsdot, T)/(rho c) integrated independently with RK4 along the recorded
// rate history, to 1e-3 of the temperature rise; and the energy bookkeeping matches m c dT.
// Returns the driver's final temperature rise, after checking it against the RK4 integral.
static double expect_adiabatic_heating_matches_rk4(const MaterialParameters& m, double gamma) {
  const JohnsonCookMaterial jc(m);
  MaterialPointDriver d(jc, 298.0, 5e-6);
  d.run(simple_shear(1e5), gamma / 1e5 / 20000, 20000);
  const auto& h = d.history();
  const double eps_end = d.last().plastic_strain;
  const double rho = m.density, c = m.specific_heat, chi = m.taylor_quinney;
  auto rate_at = [&](double eps) {
    if (eps <= h[1].plastic_strain) return h[1].plastic_strain_rate;
    return at_plastic_strain(h, eps, [](const MaterialPointRecord& r) { return r.plastic_strain_rate; });
  };
  auto dTde = [&](double eps, double T) {
    return chi * jc.flow_stress().yield_stress(eps, rate_at(eps), T) / (rho * c);
  };
  const int n = 4000;
  const double he = eps_end / n;
  double T = 298.0, eps = 0.0;
  for (int k = 0; k < n; ++k) {
    const double k1 = dTde(eps, T), k2 = dTde(eps + he / 2, T + he / 2 * k1), k3 = dTde(eps + he / 2, T + he / 2 * k2),
                 k4 = dTde(eps + he, T + he * k3);
    T += he / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    eps += he;
  }
  const double rise = d.last().temperature - 298.0;
  EXPECT_NEAR(rise, T - 298.0, 1e-3 * (T - 298.0));
  // Energy: heat = chi * plastic work and m c dT = heat (no damage here).
  EXPECT_NEAR(d.last().cumulative.heat, chi * d.last().cumulative.plastic_work, 1e-12 * d.last().cumulative.heat);
  EXPECT_NEAR(m.density * 1.0 * c * rise, d.last().cumulative.heat, 1e-9 * d.last().cumulative.heat);
  return rise;
}

TEST(JohnsonCookMaterialPoint, AdiabaticHeatingMatchesRK4) {
  EXPECT_GT(expect_adiabatic_heating_matches_rk4(ti64(), 2.5), 500.0);
}

// The same with the TANH softening (Sima & Oezel 2010 model 3, theory §2, Eq. 2.5): the update follows
// sigma_y(eps_p, epsdot, T) with W through the implicit heating, and the adiabatic shear stress has a
// maximum and then falls (Johnson-Cook alone keeps hardening at these strains: the softening the
// shear bands of titanium chips need).
TEST(JohnsonCookMaterialPoint, TanhSofteningAdiabaticShearPeaksAndFalls) {
  const MaterialParameters m = mpmcut::testing::ti64_sima_ozel_2010();
  EXPECT_GT(expect_adiabatic_heating_matches_rk4(m, 4.0), 300.0);
  const JohnsonCookMaterial jc(m);
  MaterialPointDriver d(jc, 298.0, 5e-6);
  d.run(simple_shear(1e5), 4.0 / 1e5 / 20000, 20000);
  double peak = 0.0, peak_strain = 0.0;
  for (const MaterialPointRecord& r : d.history())
    if (r.effective_stress.von_mises() > peak) peak = r.effective_stress.von_mises(), peak_strain = r.plastic_strain;
  EXPECT_GT(peak_strain, 0.2);
  EXPECT_LT(peak_strain, 1.2);
  EXPECT_LT(d.last().effective_stress.von_mises(), 0.75 * peak) << "peak " << peak << " at eps_p " << peak_strain;
  // ... on the yield surface all the way
  const Consistency c = yield_consistency(jc, d.history());
  EXPECT_GT(c.plastic_steps, 15000);
  EXPECT_LT(c.max_error, 1e-8);
}

// theory §5, Eq. (5.2) through the full update: omega reaches 1 at eps_p = eps_f(eta) (within 1 %; the
// split step makes it much closer). eta = 0 from unconstrained simple shear; eta = -1/3, 1/3, 2/3 by
// solving L_yy each step for the triaxiality. Quasi-static (epsdot* < 1) and isothermal, so eps_f depends
// on eta only; the values are worked out by hand from Eq. (5.1).
TEST(JohnsonCookMaterialPoint, InitiationAtFailureStrain) {
  MaterialParameters m = with_damage(ti64());
  m.taylor_quinney = 0.0;
  m.damage_triaxiality_cutoff = -1.0;  // the JC law itself down to eta = -1/3 (the cut-off: next test)
  const JohnsonCookMaterial jc(m);
  struct Case { double eta, eps_f; };
  for (const Case c : {Case{0.0, 0.160}, Case{-1.0 / 3.0, 0.205}, Case{1.0 / 3.0, 0.122}, Case{2.0 / 3.0, 0.089}}) {
    const double ef = jc.damage_model().failure_strain(c.eta, 0.0, 0.0);
    EXPECT_NEAR(ef, c.eps_f, 0.0005);
    MaterialPointDriver d(jc, 298.0, 5e-6);
    const double dt = 1e-3;
    double eps_at_initiation = -1.0;
    for (int k = 0; k < 20000 && d.last().damage_initiation < 1.0; ++k) {
      const MaterialPointRecord before = d.last();
      const MaterialPointRecord r =
          c.eta == 0.0 ? d.step(simple_shear(0.5), dt)
                       : d.step_with_triaxiality(diagonal(c.eta < 0 ? -0.25 : 0.25, 0.0), dt, c.eta);
      if (r.plastic_strain > before.plastic_strain) {
        EXPECT_NEAR(triaxiality(r.stress), c.eta, 1e-9);
        EXPECT_LT(r.plastic_strain_rate, 1.0);  // below epsdot0: no rate term
      }
      if (r.damage_initiation < 1.0) {
        // omega = sum d(eps_p)/eps_f = eps_p/eps_f on this proportional path
        EXPECT_NEAR(r.damage_initiation, r.plastic_strain / ef, 1e-9) << "eta " << c.eta;
      } else {
        // initiation inside this step: omega = 1 where eps_p = eps_f, inside [eps_p^(k-1), eps_p^k]
        eps_at_initiation = before.plastic_strain + (1.0 - before.damage_initiation) * ef;
        EXPECT_GE(eps_at_initiation, before.plastic_strain);
        EXPECT_LE(eps_at_initiation, r.plastic_strain);
        EXPECT_LT(r.plastic_strain - before.plastic_strain, 0.01 * ef);
        EXPECT_LT(r.damage, 1e-3);  // only the rest of this step softened
      }
    }
    ASSERT_GT(eps_at_initiation, 0.0) << "no initiation for eta " << c.eta;
    EXPECT_NEAR(eps_at_initiation, ef, 1e-6 * ef) << "eta " << c.eta;
  }
}

// theory §5.7: no ductile fracture at or below the triaxiality cut-off (Bao & Wierzbicki 2005, -1/3 by
// default). Plastic flow at eta = -0.4 (compression with shear) to eps_p = 1, five times the JC eps_f of
// eta = -1/3, neither initiates nor damages, and all its work is plastic work; just above the cut-off
// (eta = -0.3) the same path initiates.
TEST(JohnsonCookMaterialPoint, NoFractureBelowTheTriaxialityCutOff) {
  MaterialParameters m = with_damage(ti64());
  m.taylor_quinney = 0.0;
  const JohnsonCookMaterial jc(m);
  for (const double eta : {-0.4, -0.3}) {
    MaterialPointDriver d(jc, 298.0, 5e-6);
    for (int k = 0; k < 40000 && d.last().plastic_strain < 1.0; ++k)
      d.step_with_triaxiality(diagonal(-0.25, 0.0), 1e-3, eta);
    ASSERT_GE(d.last().plastic_strain, 1.0) << "eta " << eta;
    if (eta < m.damage_triaxiality_cutoff) {
      EXPECT_EQ(d.last().damage_initiation, 0.0);
      EXPECT_EQ(d.last().damage, 0.0);
      EXPECT_EQ(d.last().cumulative.damage_dissipation, 0.0);
      EXPECT_GT(d.last().cumulative.plastic_work, 0.0);
    } else {
      EXPECT_GE(d.last().damage_initiation, 1.0) << "eta " << eta;
      EXPECT_GT(d.last().damage, 0.0) << "eta " << eta;
    }
  }
}

// theory §5, Eq. (5.2): flow and damage use the same smoothed rate and the end-of-step temperature: the
// recorded omega equals sum d(eps_p)/eps_f(eta, epsdot, T) evaluated from the recorded states, at high
// rate with heating and rate smoothing on (so that all three factors of eps_f vary).
TEST(JohnsonCookMaterialPoint, InitiationUsesRecordedRateAndTemperature) {
  MaterialParameters m = with_damage(ti64());
  m.strain_rate_smoothing_time = 1e-7;
  const JohnsonCookMaterial jc(m);
  MaterialPointDriver d(jc, 298.0, 5e-6);
  const auto& h = d.run(simple_shear(2e5), 2e-9, 1500);
  double omega = 0.0;
  for (std::size_t k = 1; k < h.size() && h[k].damage_initiation < 1.0; ++k) {
    const double de = h[k].plastic_strain - h[k - 1].plastic_strain;
    if (de <= 0.0) continue;
    const double ef = jc.damage_model().failure_strain(triaxiality(h[k].effective_stress),
                                                       std::max(0.0, std::log(h[k].plastic_strain_rate / 1.0)),
                                                       (h[k].temperature - 298.0) / (1878.0 - 298.0));
    omega += de / ef;
    EXPECT_NEAR(h[k].damage_initiation, omega, 1e-10 * omega);
  }
  EXPECT_GT(omega, 0.5);
}

// theory §5, Eq. (5.3) and §6: linear Hillerborg law through the full update. After initiation
// D = u_pl/u_f, D reaches max_damage at u_pl = max_damage * u_f, and the energy dissipated after
// initiation per unit crack area, sum(damage_dissipation)/(V/L), equals G_f within 1 %. No hardening,
// rate or heating after initiation (B = C = chi = 0), so the linear law's G_f is exact (theory §6).
TEST(JohnsonCookMaterialPoint, LinearSofteningDissipatesFractureEnergy) {
  MaterialParameters m = with_damage(ti64(), DamageEvolution::Linear, 2.0e4);
  m.jc_B = 0.0;
  m.jc_C = 0.0;
  m.taylor_quinney = 0.0;
  const JohnsonCookMaterial jc(m);
  const double L = 5e-6, G_f = 2.0e4, uf = 2 * G_f / 862e6;
  MaterialPointDriver d(jc, 298.0, L);
  const double gamma_dot = 1.0, dt = 1e-3;
  int k = 0;
  while (d.last().damage < m.max_damage && k++ < 40000) {
    const MaterialPointRecord r = d.step(simple_shear(gamma_dot), dt);
    if (r.damage_initiation >= 1.0) {
      EXPECT_EQ(r.initiation_yield_stress, 862e6);
      EXPECT_NEAR(r.damage, std::min(r.plastic_displacement / uf, m.max_damage), 1e-12);
    }
  }
  const MaterialPointRecord r = d.last();
  ASSERT_EQ(r.damage, m.max_damage);
  EXPECT_NEAR(r.plastic_displacement, m.max_damage * uf, 0.01 * uf);
  const double per_area = r.cumulative.damage_dissipation / (r.volume / L);
  EXPECT_NEAR(per_area, G_f, 0.01 * G_f);
  // Failed: no shear stress any more; shear on does nothing, no more dissipation.
  EXPECT_EQ(r.stress.xy, 0.0);
  EXPECT_EQ(r.stress.von_mises(), 0.0);
  d.run(simple_shear(gamma_dot), dt, 100);
  EXPECT_EQ(d.last().stress.von_mises(), 0.0);
  EXPECT_EQ(d.last().cumulative.damage_dissipation, r.cumulative.damage_dissipation);
  EXPECT_LT(d.last().elastic_energy, 1e-6);  // only round-off pressure left
}

// theory §5, Eq. (5.4): exponential law through the full update: the dissipation after initiation per unit
// area approaches G_f (G_f * max_damage + the small stored energy released at failure).
TEST(JohnsonCookMaterialPoint, ExponentialSofteningDissipatesFractureEnergy) {
  MaterialParameters m = with_damage(ti64(), DamageEvolution::Exponential, 1.0e4);
  m.jc_C = 0.0;
  m.taylor_quinney = 0.0;
  const JohnsonCookMaterial jc(m);
  const double L = 5e-6, G_f = 1.0e4;
  MaterialPointDriver d(jc, 298.0, L);
  int k = 0;
  while (d.last().damage < m.max_damage && k++ < 60000) d.step(simple_shear(1.0), 1e-3);
  const MaterialPointRecord& r = d.last();
  ASSERT_EQ(r.damage, m.max_damage);
  EXPECT_NEAR(r.cumulative.damage_dissipation / (r.volume / L), G_f, 0.01 * G_f);
}

// theory §5.5: the tensile cut-off after initiation. Uniaxial-strain tension (eta > 1): isochoric flow
// alone cannot fail the particle, since its hydrostatic tension would grow as K eps_v. After initiation
// the undamaged tension stays at sigma_y0, the rest of the stretch is opening that drives u_pl, the
// particle fails, and the energy balance (work in = stored + plastic + damage) closes, with the tension
// stored above sigma_y0 at initiation counted as released. Both EOS forms.
TEST(JohnsonCookMaterialPoint, TensileCutOffAfterInitiationOpensAndFails) {
  for (EquationOfState eos : {EquationOfState::Linear, EquationOfState::MieGruneisen}) {
    const MaterialParameters m = perfectly_plastic_with_damage(eos, 2.0e4);
    const JohnsonCookMaterial jc(m);
    const double L = 5e-6, uf = 2 * 2.0e4 / 862e6;
    MaterialPointDriver d(jc, 298.0, L);
    const double rate = 1e3, dt = 1e-7;  // 1e-4 strain per step
    double work = 0.0;                  // int sigma : D dt V, trapezoidal
    int k = 0;
    while (d.last().damage < m.max_damage && k++ < 20000) {
      const MaterialPointRecord before = d.last();
      const MaterialPointRecord r = d.step(diagonal(rate, 0.0), dt);
      work += 0.5 * (before.stress.xx * before.volume + r.stress.xx * r.volume) * rate * dt;
      if (before.damage_initiation >= 1.0 && r.damage < m.max_damage) {
        EXPECT_LE(r.effective_stress.mean(), 862e6 * (1 + 1e-12)) << "step " << k;
        EXPECT_NEAR(r.damage, r.plastic_displacement / uf, 1e-12);
      }
    }
    const MaterialPointRecord& r = d.last();
    const char* what = eos == EquationOfState::Linear ? "linear EOS" : "Mie-Grueneisen";
    ASSERT_EQ(r.damage, m.max_damage) << what << ": did not fail after " << k << " steps";
    // The opening is u_f: a strain u_f/L beyond initiation at eps_p = 0.01 (1.5 % stretch), at most.
    EXPECT_LT(std::log(r.volume), 0.015 + 1.5 * uf / L) << what;
    const ConstitutiveIncrement& c = r.cumulative;
    const double balance = r.elastic_energy + c.plastic_work + c.damage_dissipation;
    // Mie-Grueneisen: elastic_energy() stores p^2/(2K) with the tangent K(rho), exact only for the linear law.
    EXPECT_NEAR(balance, work, (eos == EquationOfState::Linear ? 0.005 : 0.02) * work) << what;
    // After initiation about G_f per area V0/L, plus the stored tension released at initiation.
    EXPECT_GT(c.damage_dissipation / (1.0 / L), 2.0e4) << what;
  }
}

// theory §5.3b: the crack gap. A particle opened by the tensile cut-off (uniaxial-strain tension after
// initiation) is solid plus gap. Compressed again, its undamaged pressure rises from -sigma_y0 to zero as the
// solid unloads (sigma_y0/K of strain), stays at zero while the gap closes (crack_opening of strain), and only
// then grows with K; pulled back, the gap reopens at zero stress up to the largest opening before the solid
// takes tension. The energy balance closes over the whole cycle (closing and reopening do no work), and
// the time step does not see the gap: the wave speed stays that of the solid. Both EOS forms (Mie-Grueneisen
// closes with its tangent modulus, so its zero is approximate).
TEST(JohnsonCookMaterialPoint, OpenedCrackClosesAtZeroPressureThenBearsCompression) {
  for (EquationOfState eos : {EquationOfState::Linear, EquationOfState::MieGruneisen}) {
    const char* what = eos == EquationOfState::Linear ? "linear EOS" : "Mie-Grueneisen";
    const MaterialParameters m = perfectly_plastic_with_damage(eos, 2.0e6);  // far from failing
    const JohnsonCookMaterial jc(m);
    const double K = eos == EquationOfState::Linear ? m.bulk_modulus() : m.density * m.mg_c0 * m.mg_c0;
    const double cap = 862e6, L = 5e-6, rate = 1e3, dt = 1e-7, de = rate * dt;  // 1e-4 strain per step
    const double tol = (eos == EquationOfState::Linear ? 1e-6 : 2e-2) * cap;
    MaterialPointDriver d(jc, 298.0, L);
    double work = 0.0;  // int sigma : D dt V, trapezoidal (only sigma_xx works: L = diag(a, 0))
    auto drive = [&](double a) {
      const MaterialPointRecord before = d.last();
      const MaterialPointRecord r = d.step(diagonal(a, 0.0), dt);
      work += 0.5 * (before.stress.xx * before.volume + r.stress.xx * r.volume) * a * dt;
      return r;
    };
    auto pressure = [](const MaterialPointRecord& r) { return -r.effective_stress.mean(); };
    // Open: pull until the gap is 0.3 (V about 1.35 V0).
    int k = 0;
    while (d.last().crack_opening < 0.3 && k++ < 10000) drive(rate);
    const double gap = d.last().crack_opening;
    ASSERT_GE(gap, 0.3) << what;
    ASSERT_LT(d.last().damage, m.max_damage) << what;
    EXPECT_NEAR(pressure(d.last()), -cap, tol) << what;
    EXPECT_EQ(d.last().crack_opening_max, gap) << what;
    const double c_solid = std::sqrt((K + 4.0 / 3.0 * jc.shear_modulus()) / m.density);
    EXPECT_LT(jc.wave_speed(d.particles(), 0), 1.01 * c_solid) << what << ": the gap shortens the time step";

    // Close: compress by cap/K + gap + 0.002.
    const double unload = cap / K, solid = 0.002;
    const int n_close = static_cast<int>(std::ceil((unload + gap + solid) / de));
    double x = 0.0;
    for (int s = 0; s < n_close; ++s) {
      const MaterialPointRecord r = drive(-rate);
      x += de;
      const double expected = x < unload ? -cap + K * x : x < unload + gap ? 0.0 : K * (x - unload - gap);
      if (eos == EquationOfState::Linear || x > unload + 2 * de)  // MG: its tangent K differs near -cap
        ASSERT_NEAR(pressure(r), expected, tol + (eos == EquationOfState::Linear ? 0.0 : 0.02 * expected))
            << what << ", closing, strain " << x;
    }
    EXPECT_EQ(d.last().crack_opening, 0.0) << what;
    EXPECT_GT(pressure(d.last()), 0.5 * K * solid) << what << ": a closed crack bears compression";

    // Reopen: pull by 0.002 + gap + cap/K + 0.001: the solid unloads, the gap reopens at zero stress, then the
    // solid takes tension up to the cap and opens further.
    const double n_reopen = static_cast<int>(std::ceil((solid + gap + unload + 0.001) / de));
    const double p_start = pressure(d.last()), x_start = x - unload - gap;  // solid compression at the start
    double y = 0.0;
    for (int s = 0; s < n_reopen; ++s) {
      const MaterialPointRecord r = drive(rate);
      y += de;
      const double expected = y < x_start ? p_start - K * y : y < x_start + gap ? 0.0
                                                                 : std::max(-K * (y - x_start - gap), -cap);
      if (eos == EquationOfState::Linear)
        ASSERT_NEAR(pressure(r), expected, tol + 1e-9 * std::abs(p_start)) << what << ", reopening, strain " << y;
      else if (y > x_start + 2 * de && y < x_start + gap - 2 * de)
        ASSERT_NEAR(pressure(r), 0.0, tol) << what << ", reopening, strain " << y;
    }
    EXPECT_NEAR(d.last().crack_opening, d.last().crack_opening_max, 1e-12) << what;
    EXPECT_GT(d.last().crack_opening_max, gap) << what << ": the pull beyond the old gap opens it further";
    const ConstitutiveIncrement& c = d.last().cumulative;
    const double balance = d.last().elastic_energy + c.plastic_work + c.damage_dissipation;
    EXPECT_NEAR(balance, work, (eos == EquationOfState::Linear ? 0.005 : 0.02) * std::abs(work)) << what;
  }
}

// theory §5, Eq. (5.5) (as MPM3D, Zhang, Chen & Liu 2016): a fully failed particle carries no tension and no shear but
// keeps compression (and its mass).
TEST(JohnsonCookMaterialPoint, FailedParticleKeepsCompressionOnly) {
  const MaterialParameters m = with_damage(ti64());
  const JohnsonCookMaterial jc(m);
  MaterialPointDriver d(jc, 298.0, 5e-6);
  Particles& p = d.particles();
  p.damage_initiation[0] = 1.0;
  p.damage[0] = m.max_damage;
  p.effective_stress[0] = {5e8, -2e8, 1e8, 3e8};  // whatever it was before failing
  const double mass = p.mass[0];
  d.run(diagonal(-1e3, 0.0), 1e-6, 10);  // compress: eps_v = -1e-2
  PlaneStrainTensor s = d.last().stress;
  EXPECT_EQ(s.xy, 0.0);
  EXPECT_EQ(s.xx, s.yy);
  EXPECT_EQ(s.xx, s.zz);
  EXPECT_GT(-s.mean(), 0.0);
  EXPECT_GT(d.last().elastic_energy, 0.0);
  d.run(diagonal(2e3, 0.0), 1e-6, 10);  // pull back past the original volume: tension
  s = d.last().stress;
  EXPECT_EQ(s.xx, 0.0);
  EXPECT_EQ(s.yy, 0.0);
  EXPECT_EQ(s.zz, 0.0);
  EXPECT_EQ(s.xy, 0.0);
  EXPECT_EQ(d.last().elastic_energy, 0.0);
  d.run(simple_shear(1e4), 1e-8, 10);
  EXPECT_EQ(d.last().stress.xy, 0.0);
  EXPECT_EQ(d.particles().mass[0], mass);
  EXPECT_EQ(d.last().plastic_strain, 0.0);
}

// theory §5.8: a damaged particle (D = 0.8, initiated) under a pressure p, sheared, carries the equivalent shear
// (1 - D) tau + D min(tau, mu_c p) of its undamaged shear tau: its closed crack's faces carry Coulomb friction, an open
// one (tension) none. Perfectly plastic at A = 862 MPa (tau_y = 497.7 MPa), linear EOS, simple shear (no volume
// change, so p stays). Worked by hand for p = 600 MPa, at yield: mu_c = 0 gives 99.5 MPa, mu_c = 0.5 gives
// 0.2 * 497.7 + 0.8 * 300 = 339.5 MPa, mu_c = 1 all 497.7 MPa; elastically (gamma = 0.2 %, tau = G gamma) the same law,
// and in tension (1 - D) G gamma for any mu_c; a failed particle (D = D_max) carries the friction alone,
// min(tau, mu_c p), and nothing in tension. The flow stays below the triaxiality cut-off (eta = -0.70), so D
// stays 0.8 and the crack's friction work is plastic work, all of it heat (the intact part's: chi of it), m c dT is
// the heat, and the work put in equals elastic energy + plastic work to 0.5 % (the sliding crack dissipates what it
// does not store). The wave speed sees the shear stiffness of the share carried.
TEST(JohnsonCookMaterialPoint, ClosedCrackCarriesFrictionUpToMuTimesPressure) {
  struct Case {
    double mu_c, pressure, gamma, expected_tau;
    double D = 0.8;
  };
  const double A = 862e6, tau_y = A / std::sqrt(3.0), D = 0.8, failed = 0.999;
  const double G = perfectly_plastic_with_damage(EquationOfState::Linear, 2e4).shear_modulus();
  const double tau_el = G * 0.002;  // 88 MPa, elastic
  const std::vector<Case> cases{
      {0.0, 6e8, 0.1, (1 - D) * tau_y},
      {0.5, 6e8, 0.1, (1 - D) * tau_y + D * 0.5 * 6e8},
      {1.0, 6e8, 0.1, tau_y},
      {0.1, 6e8, 0.002, (1 - D) * tau_el + D * 0.1 * 6e8},
      {0.5, 6e8, 0.002, tau_el},
      {0.5, -2e8, 0.002, (1 - D) * tau_el},
      // failed: the crack's friction alone, min(tau, mu_c p); nothing in tension
      {0.5, 6e8, 0.1, 0.5 * 6e8, failed},
      {0.1, 6e8, 0.002, 0.1 * 6e8, failed},
      {0.5, 6e8, 0.002, tau_el, failed},
      {0.5, -2e8, 0.002, 0.0, failed},
  };
  for (const Case& c : cases) {
    const std::string what = "D " + std::to_string(c.D) + ", mu_c " + std::to_string(c.mu_c) + ", p " +
                             std::to_string(c.pressure) + " Pa, gamma " + std::to_string(c.gamma);
    MaterialParameters m = perfectly_plastic_with_damage(EquationOfState::Linear, 2e4);
    m.crack_friction = c.mu_c;
    m.taylor_quinney = 0.9;  // heats (by ~15 K); with m = 50 the flow stress does not feel it (T*^m ~ 1e-100)
    m.jc_m = 50.0;
    const JohnsonCookMaterial jc(m);
    MaterialPointDriver d(jc, 298.0, 5e-6);
    Particles& p = d.particles();
    p.damage_initiation[0] = 1.0;
    p.damage[0] = c.D;
    p.initiation_yield_stress[0] = A;
    p.fracture_energy[0] = 2e4;
    p.plastic_displacement[0] = c.D * 2 * 2e4 / A;
    p.effective_stress[0] = {-c.pressure, -c.pressure, -c.pressure, 0.0};
    const double T0 = p.temperature[0], mass = p.mass[0], stored0 = jc.elastic_energy(p, 0);
    const int steps = 4000;
    const double rate = 1e3, dt = c.gamma / rate / steps;
    double work = 0.0;  // the stress's work per unit volume x V, trapezoid over the steps
    for (int k = 0; k < steps; ++k) {
      const double before = d.last().stress.xy * d.last().volume;
      const MaterialPointRecord r = d.step(simple_shear(rate), dt);
      work += 0.5 * (before + r.stress.xy * r.volume) * rate * dt;
    }
    const MaterialPointRecord& r = d.last();
    EXPECT_EQ(r.damage, c.D) << what;
    const double tau = r.stress.deviator().von_mises() / std::sqrt(3.0);
    EXPECT_NEAR(tau, c.expected_tau, 0.005 * c.expected_tau + 1e-3) << what;
    // tension degraded (5.5), none left once failed
    const double pressure = c.pressure > 0.0 ? c.pressure : (c.D < failed ? 1 - c.D : 0.0) * c.pressure;
    EXPECT_NEAR(-r.stress.mean(), pressure, 1e-6 * std::abs(pressure) + 1e-3) << what;
    const ConstitutiveIncrement& e = r.cumulative;
    EXPECT_EQ(e.damage_dissipation, 0.0) << what;
    // chi of the intact part's plastic work, all of the crack's friction
    EXPECT_GE(e.heat, 0.9 * e.plastic_work - 1e-6) << what;
    EXPECT_LE(e.heat, e.plastic_work + 1e-6) << what;
    EXPECT_NEAR(mass * m.specific_heat * (r.temperature - T0), e.heat, 1e-9 * e.heat + 1e-6) << what;
    const double stored = r.elastic_energy - stored0;
    EXPECT_NEAR(stored + e.plastic_work, work, 0.005 * work + 1e-3) << what;
    if (c.gamma > 0.01) EXPECT_GT(e.plastic_work, 0.0) << what;
    // theory §7.1: the wave speed sees the shear stiffness of the share k the particle carries.
    const double k = r.stress.deviator().von_mises() / r.effective_stress.deviator().von_mises();
    EXPECT_NEAR(jc.wave_speed(d.particles(), 0),
                std::sqrt((m.bulk_modulus() + k * 4.0 / 3.0 * G) / std::max(r.density, m.density)), 1e-9 * 6000.0)
        << what;
  }
}

// theory §3, Eq. (3.2) through the update: with Mie-Grueneisen the pressure is p(rho, T) of the current
// density mass/volume and the end-of-step temperature; the wave speed uses the current tangent modulus.
TEST(JohnsonCookMaterialPoint, MieGruneisenPressureFollowsDensity) {
  MaterialParameters m = ti64();
  m.eos = EquationOfState::MieGruneisen;
  m.mg_c0 = 5130.0;
  m.mg_s = 1.028;
  m.mg_gamma0 = 1.23;
  const JohnsonCookMaterial jc(m);
  const EquationOfStateModel eos(m);
  MaterialPointDriver d(jc, 298.0, 5e-6);
  EXPECT_NEAR(jc.wave_speed(d.particles(), 0),
              std::sqrt((4430.0 * 5130.0 * 5130.0 + 4.0 / 3.0 * m.shear_modulus()) / 4430.0), 1e-9);
  d.run(diagonal(-1e4, 0.0), 1e-8, 500);  // 5 % uniaxial strain
  const MaterialPointRecord& r = d.last();
  EXPECT_GT(r.temperature, 298.0);
  EXPECT_NEAR(-r.stress.mean(), eos.pressure(0.0, 0.0, r.density, r.temperature), 1e-12 * 1e10);
  EXPECT_NEAR(r.density, 4430.0 / r.deformation_gradient.determinant(), 1e-9);
  EXPECT_GT(jc.wave_speed(d.particles(), 0), std::sqrt((4430.0 * 5130.0 * 5130.0) / 4430.0));
}

// theory §7.1: linear EOS P-wave speed sqrt((K + 4G/3)/rho) = 6313 m/s for Ti-6Al-4V (computed
// from E, nu, rho) at the reference density, at the current density otherwise; failed or molten particles have
// no shear stiffness, and an opened failed particle does not raise the speed through its low density.
TEST(JohnsonCookMaterialPoint, WaveSpeed) {
  const MaterialParameters m = with_damage(ti64());
  const JohnsonCookMaterial jc(m);
  MaterialPointDriver d(jc, 298.0, 5e-6);
  Particles& p = d.particles();
  EXPECT_NEAR(jc.wave_speed(p, 0), 6313.0, 1.0);
  const double K = m.bulk_modulus(), M = K + 4.0 / 3.0 * m.shear_modulus();
  p.volume[0] = 0.98;
  EXPECT_NEAR(jc.wave_speed(p, 0), std::sqrt(M / (4430.0 / 0.98)), 1e-9);
  p.damage[0] = m.max_damage;
  EXPECT_NEAR(jc.wave_speed(p, 0), std::sqrt(K / (4430.0 / 0.98)), 1e-9);
  p.volume[0] = 3.0;  // an open crack
  EXPECT_NEAR(jc.wave_speed(p, 0), std::sqrt(K / 4430.0), 1e-9);
  p.damage[0] = 0.0;
  p.volume[0] = 1.0;
  p.temperature[0] = 1900.0;  // molten
  EXPECT_NEAR(jc.wave_speed(p, 0), std::sqrt(K / 4430.0), 1e-9);
}

// Bulk viscosity (theory §3, Eq. (3.3)): only in compression, only in the force stress (not in the stored
// undamaged stress), and its work is reported as viscous dissipation.
TEST(JohnsonCookMaterialPoint, BulkViscosityInCompressionOnly) {
  MaterialParameters m = ti64();
  m.bulk_viscosity_linear = 0.06;
  m.bulk_viscosity_quadratic = 1.2;
  const JohnsonCookMaterial jc(m);
  MaterialPointDriver d(jc, 298.0, 5e-6);
  const MaterialPointRecord c = d.step(diagonal(-1e6, 0.0), 1e-9);
  EXPECT_LT(c.stress.mean(), c.effective_stress.mean());  // more compressive than the EOS alone
  EXPECT_EQ(c.stress.xy, c.effective_stress.xy);
  EXPECT_GT(c.increment.viscous_dissipation, 0.0);
  const MaterialPointRecord t = d.step(diagonal(1e6, 0.0), 1e-9);
  EXPECT_EQ(t.stress.mean(), t.effective_stress.mean());
  EXPECT_EQ(t.increment.viscous_dissipation, 0.0);
}
