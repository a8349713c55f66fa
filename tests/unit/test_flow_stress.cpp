// Johnson-Cook flow stress sigma_y(eps_p, epsdot, T) (docs/theory_materials.md §2; Johnson & Cook 1983),
// the equation of state (theory §3) and the return-mapping solve (theory §4).
// Parameters: Ti-6Al-4V, Johnson 1985 set A = 862 MPa, B = 331 MPa, n = 0.34, C = 0.012, m = 0.8,
// epsdot0 = 1/s, T_r = 298 K, T_m = 1878 K (docs/materials.md); E = 113.8 GPa, nu = 0.342,
// rho = 4430, c = 526.3 (Payette; docs/materials.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>

#include "physics/equation_of_state.hpp"
#include "physics/flow_stress.hpp"
#include "physics/johnson_cook.hpp"

#include "../support/ti64_parameters.hpp"

using namespace mpmcut;
using mpmcut::testing::ti64_johnson_1985;
using mpmcut::testing::ti64_sima_ozel_2010;


namespace {
struct State {
  double eps, rate, T;
};

// The analytic partial derivatives of sigma_y agree with central differences (steps: 1e-6 relative in strain
// and rate, hT in temperature) to `tolerance` relative in the strain slope (1e-3 Pa absolute besides) and the
// rate slope and 10 x tolerance in the temperature slope; evaluate() also returns yield_stress() itself.
void expect_derivatives_match_finite_differences(const JohnsonCookFlowStress& f, std::initializer_list<State> states,
                                                 double hT, double tolerance) {
  for (const State s : states) {
    SCOPED_TRACE(s.eps);
    const FlowStressValue v = f.evaluate(s.eps, s.rate, s.T);
    EXPECT_NEAR(v.stress, f.yield_stress(s.eps, s.rate, s.T), 1e-12 * v.stress);
    const double he = 1e-6 * s.eps, hr = 1e-6 * s.rate;
    const double de = (f.yield_stress(s.eps + he, s.rate, s.T) - f.yield_stress(s.eps - he, s.rate, s.T)) / (2 * he);
    const double dr = (f.yield_stress(s.eps, s.rate + hr, s.T) - f.yield_stress(s.eps, s.rate - hr, s.T)) / (2 * hr);
    const double dT = (f.yield_stress(s.eps, s.rate, s.T + hT) - f.yield_stress(s.eps, s.rate, s.T - hT)) / (2 * hT);
    EXPECT_NEAR(v.d_strain, de, tolerance * std::abs(de) + 1e-3);
    EXPECT_NEAR(v.d_rate, dr, 1e-6 * std::abs(dr));
    EXPECT_NEAR(v.d_temperature, dT, 10 * tolerance * std::abs(dT));
    EXPECT_NEAR(v.log_rate_ratio, std::log(s.rate), 1e-14 * std::log(s.rate));
  }
}
}  // namespace

// theory §2, Eq. (2.1): self-check values (Johnson 85 set, T_m = 1878 K),
// computed by hand: 862, 1248, 815, 540 MPa.
TEST(JohnsonCookFlowStress, ReproducesTabulatedTi64Values) {
  const JohnsonCookFlowStress f(ti64_johnson_1985());
  EXPECT_NEAR(f.yield_stress(0.0, 1.0, 298.0), 862e6, 0.5e6);
  EXPECT_NEAR(f.yield_stress(0.5, 1e4, 298.0), 1248e6, 0.5e6);
  EXPECT_NEAR(f.yield_stress(1.0, 1e5, 800.0), 815e6, 0.5e6);
  EXPECT_NEAR(f.yield_stress(2.0, 1e6, 1200.0), 540e6, 0.5e6);
  // and the product form exactly
  const double eps = 0.3, rate = 3e3, T = 700.0;
  const double Ts = (T - 298.0) / (1878.0 - 298.0);
  const double expected = (862e6 + 331e6 * std::pow(eps, 0.34)) * (1.0 + 0.012 * std::log(rate)) *
                          (1.0 - std::pow(Ts, 0.8));
  EXPECT_NEAR(f.yield_stress(eps, rate, T), expected, 1e-12 * expected);
}

// theory §2, Eq. (2.2): no rate effect below epsdot0 (epsdot* floored at 1), so a zero or tiny rate is
// finite and equals the quasi-static value.
TEST(JohnsonCookFlowStress, RateFloorBelowReferenceRate) {
  const JohnsonCookFlowStress f(ti64_johnson_1985());
  const double qs = f.yield_stress(0.2, 1.0, 298.0);
  for (double rate : {0.0, 1e-12, 1e-8, 0.5, 1.0}) {
    EXPECT_EQ(f.rate_factor(rate), 1.0) << rate;
    EXPECT_EQ(f.yield_stress(0.2, rate, 298.0), qs) << rate;
    EXPECT_EQ(f.log_rate_ratio(rate), 0.0) << rate;
  }
  EXPECT_NEAR(f.rate_factor(1e3), 1.0 + 0.012 * std::log(1e3), 1e-15);
  // Rate ratio at equal strain and temperature: (1 + C ln e1*)/(1 + C ln e2*).
  EXPECT_NEAR(f.yield_stress(0.1, 1e5, 400.0) / f.yield_stress(0.1, 1e2, 400.0),
              (1.0 + 0.012 * std::log(1e5)) / (1.0 + 0.012 * std::log(1e2)), 1e-14);
}

// theory §2, Eq. (2.3): T* clamped to [0, 1]: below room temperature no NaN and full strength; at and
// above T_m zero strength; in between exactly 1 - T*^m.
TEST(JohnsonCookFlowStress, TemperatureClampsAndMelt) {
  const JohnsonCookFlowStress f(ti64_johnson_1985());
  EXPECT_EQ(f.thermal_factor(77.0), 1.0);
  EXPECT_EQ(f.homologous_temperature(77.0), 0.0);
  EXPECT_TRUE(std::isfinite(f.yield_stress(0.1, 1e3, 4.0)));
  EXPECT_EQ(f.yield_stress(0.1, 1e3, 77.0), f.yield_stress(0.1, 1e3, 298.0));
  EXPECT_EQ(f.thermal_factor(1878.0), 0.0);
  EXPECT_EQ(f.yield_stress(0.5, 1e5, 1878.0), 0.0);
  EXPECT_EQ(f.yield_stress(0.5, 1e5, 2500.0), 0.0);
  EXPECT_TRUE(f.melted(1878.0));
  EXPECT_FALSE(f.melted(1877.9));
  for (double T : {350.0, 900.0, 1500.0, 1870.0}) {
    const double Ts = (T - 298.0) / 1580.0;
    EXPECT_NEAR(f.thermal_factor(T), 1.0 - std::pow(Ts, 0.8), 1e-15) << T;
    EXPECT_NEAR(f.yield_stress(0.3, 1e3, T) / f.yield_stress(0.3, 1e3, 298.0), 1.0 - std::pow(Ts, 0.8), 1e-14) << T;
  }
}

// theory §2, Eq. (2.4): the analytic partial derivatives used by the Newton solve agree with central
// differences (a wrong derivative would still converge through bisection, but slowly; this catches it).
TEST(JohnsonCookFlowStress, DerivativesMatchFiniteDifferences) {
  const JohnsonCookFlowStress f(ti64_johnson_1985());
  expect_derivatives_match_finite_differences(
      f, {State{0.05, 1e3, 400.0}, State{0.8, 2e5, 1100.0}, State{2.0, 5e6, 1700.0}}, 1e-4, 1e-6);
  // Floors: no rate or temperature slope there; n < 1 gives an infinite hardening slope at eps = 0.
  const FlowStressValue v0 = f.evaluate(0.0, 0.5, 250.0);
  EXPECT_EQ(v0.d_rate, 0.0);
  EXPECT_EQ(v0.d_temperature, 0.0);
  EXPECT_TRUE(std::isinf(v0.d_strain));
  EXPECT_EQ(v0.stress, 862e6);
}

TEST(JohnsonCookFlowStress, RejectsUnusableParameters) {
  MaterialParameters m = ti64_johnson_1985();
  m.melting_temperature = 0.0;  // not set
  EXPECT_THROW(JohnsonCookFlowStress{m}, std::invalid_argument);
  m = ti64_johnson_1985();
  m.reference_strain_rate = 0.0;
  EXPECT_THROW(JohnsonCookFlowStress{m}, std::invalid_argument);
  m = ti64_johnson_1985();
  m.taylor_quinney = 0.9;
  m.specific_heat = 0.0;  // heating without a heat capacity
  EXPECT_THROW(JohnsonCookMaterial{m}, std::invalid_argument);
}


// theory §2, Eq. (2.5): values worked out from the published formula (by hand, in a calculator script):
// 724.7, 1466.2, 928.5, 533.4, 313.7 MPa, and the formula written out independently here.
TEST(TanhFlowSoftening, ReproducesTheSimaOzelFormula) {
  const JohnsonCookFlowStress f(ti64_sima_ozel_2010());
  EXPECT_TRUE(f.softens());
  EXPECT_NEAR(f.yield_stress(0.0, 1.0, 298.0), 724.7e6, 0.05e6);
  EXPECT_NEAR(f.yield_stress(0.5, 1e4, 298.0), 1466.21e6, 0.05e6);
  EXPECT_NEAR(f.yield_stress(1.0, 1e5, 800.0), 928.541e6, 0.05e6);
  EXPECT_NEAR(f.yield_stress(3.0, 1e5, 1000.0), 533.357e6, 0.05e6);
  EXPECT_NEAR(f.yield_stress(2.0, 1e6, 1400.0), 313.748e6, 0.05e6);
  const double eps = 1.7, rate = 3e4, T = 900.0, Tm = 1878.0;
  const double H = 724.7e6 + 683.1e6 * std::pow(eps, 0.47) * std::exp(-eps * eps);
  const double D = 1.0 - T / Tm, S = std::pow(T / Tm, 5.0);
  const double W = D + (1.0 - D) * std::pow(std::tanh(1.0 / ((eps + S) * (eps + S))), 0.05);
  const double expected = H * (1.0 + 0.035 * std::log(rate)) * (1.0 - (T - 298.0) / (Tm - 298.0)) * W;
  EXPECT_NEAR(f.yield_stress(eps, rate, T), expected, 1e-12 * expected);
  EXPECT_NEAR(f.softening_factor(eps, T), W, 1e-14);
  EXPECT_NEAR(f.hardening(eps), H, 1e-6);
  // Without the switch the same constants are plain Johnson-Cook: no damping, W = 1.
  MaterialParameters plain = ti64_sima_ozel_2010();
  plain.flow_softening = FlowSoftening::None;
  const JohnsonCookFlowStress g(plain);
  EXPECT_FALSE(g.softens());
  EXPECT_EQ(g.softening_factor(eps, T), 1.0);
  EXPECT_NEAR(g.hardening(eps), 724.7e6 + 683.1e6 * std::pow(eps, 0.47), 1e-6);
}

// What the softening is for: at large strain the flow stress falls (Johnson-Cook only hardens), the more
// the hotter the material (W falls towards D = 1 - T/T_m), and it never falls below A D R Theta.
TEST(TanhFlowSoftening, SoftensAtLargeStrainAndMoreWhenHot) {
  const JohnsonCookFlowStress f(ti64_sima_ozel_2010());
  const double rate = 1e5;
  for (double T : {298.0, 700.0, 1200.0}) {
    SCOPED_TRACE(T);
    const double peak = f.yield_stress(0.5, rate, T);
    EXPECT_LT(f.yield_stress(2.0, rate, T), 0.7 * peak);  // B eps^n is damped by exp(-eps^2)
    EXPECT_LT(f.yield_stress(6.0, rate, T), f.yield_stress(2.0, rate, T));
    const double D = 1.0 - T / 1878.0;
    EXPECT_GE(f.softening_factor(50.0, T), D);
    EXPECT_LT(f.softening_factor(50.0, T), 1.0);
  }
  EXPECT_LT(f.softening_factor(3.0, 1200.0), f.softening_factor(3.0, 700.0));
  EXPECT_LT(f.softening_factor(3.0, 700.0), f.softening_factor(3.0, 298.0));
  // The surely-elastic bound of the return mapping: no state at room temperature yields below it.
  const double bound = f.elastic_limit_at_room_temperature();
  EXPECT_NEAR(bound, 724.7e6 * (1.0 - 298.0 / 1878.0), 1.0);
  for (double eps : {0.0, 0.5, 3.0, 10.0, 100.0}) EXPECT_GE(f.yield_stress(eps, 1.0, 298.0), bound) << eps;
  EXPECT_LT(f.yield_stress(10.0, 1.0, 298.0), 724.7e6);  // so A alone would be the wrong bound
}

// theory §2, Eq. (2.5): the analytic partial derivatives with the softening agree with central differences,
// also where W moves fast (small strain, hot: S = (T/T_m)^5 comparable with eps) and where the damping peaks.
TEST(TanhFlowSoftening, DerivativesMatchFiniteDifferences) {
  const JohnsonCookFlowStress f(ti64_sima_ozel_2010());
  expect_derivatives_match_finite_differences(f,
                                              {State{0.05, 1e3, 400.0}, State{0.6, 2e5, 1100.0}, State{2.0, 5e6, 1700.0},
                                               State{0.02, 1e4, 1600.0}, State{4.0, 1e5, 900.0}},
                                              1e-3, 1e-5);
  // eps = 0 at room temperature: W = 1 exactly (tanh saturates), no NaN from the overflowing power.
  const FlowStressValue v0 = f.evaluate(0.0, 1.0, 298.0);
  EXPECT_EQ(v0.stress, 724.7e6);
  EXPECT_FALSE(std::isnan(v0.d_temperature));
  MaterialParameters steep = ti64_sima_ozel_2010();
  steep.tanh_b = 50.0;
  steep.tanh_c = 10.0;  // u = (eps + S)^-c overflows to inf at eps = 0
  const FlowStressValue v1 = JohnsonCookFlowStress(steep).evaluate(0.0, 1.0, 500.0);
  EXPECT_TRUE(std::isfinite(v1.stress) && std::isfinite(v1.d_temperature)) << v1.stress << " " << v1.d_temperature;
}

// theory §4, Eq. (4.5): the plastic corrector solves the consistency equation to 1e-12 relative, with
// the smoothed rate and the implicit end-of-step temperature, for cold/hot, slow/fast and smoothed rates.
TEST(JohnsonCookReturnMapping, SolvesConsistencyToRoundOff) {
  for (double tau : {0.0, 1e-7}) for (const bool tanh : {false, true}) {
    MaterialParameters m = tanh ? ti64_sima_ozel_2010() : ti64_johnson_1985();
    m.strain_rate_smoothing_time = tau;
    const JohnsonCookMaterial jc(m);
    const double G = m.shear_modulus();
    struct Case { double q_tr, eps, old_rate, T, dt; };
    for (const Case c : {Case{1.2e9, 0.0, 0.0, 298.0, 1e-9}, Case{1.1e9, 0.3, 1e5, 600.0, 1e-9},
                         Case{2.0e9, 1.5, 1e6, 1500.0, 1e-8}, Case{9.0e8, 0.0, 0.0, 298.0, 1.0},
                         Case{7.0e8, 2.0, 3e4, 1800.0, 1e-9}}) {
      const double h = 0.9 / (526.3 * 4430.0);
      const double rate0 = jc.smoothed_rate(c.old_rate, 0.0, c.dt);
      // The softening set hardens more at small strain: its trial stresses are raised to 10 % above yield.
      const double q_tr = tanh ? std::max(c.q_tr, 1.1 * jc.flow_stress().yield_stress(c.eps, rate0, c.T)) : c.q_tr;
      ASSERT_GT(q_tr, jc.flow_stress().yield_stress(c.eps, rate0, c.T));
      const auto rm = jc.return_mapping(q_tr, c.eps, c.old_rate, c.T, h, c.dt);
      const double x = rm.plastic_increment;
      ASSERT_GT(x, 0.0);
      ASSERT_LT(x, q_tr / (3 * G));
      // Everything reported is consistent with x ...
      EXPECT_DOUBLE_EQ(rm.rate, jc.smoothed_rate(c.old_rate, x, c.dt));
      EXPECT_DOUBLE_EQ(rm.temperature, c.T + h * (q_tr - 3 * G * x) * x);
      const double sy = jc.flow_stress().yield_stress(c.eps + x, rm.rate, rm.temperature);
      EXPECT_DOUBLE_EQ(rm.flow_stress, sy);
      // ... and x is the root: q_tr - 3G x = sigma_y(eps + x, rate(x), T(x)).
      EXPECT_NEAR(q_tr - 3 * G * x, sy, 1e-11 * q_tr) << "tau " << tau << " tanh " << tanh << " q_tr " << q_tr;
      EXPECT_LT(rm.iterations, 80);
    }
  }
}

// theory §3, Eq. (3.1): linear EOS is the hypoelastic increment p -= K dEps_v.
TEST(EquationOfState, LinearIncrement) {
  const MaterialParameters m = ti64_johnson_1985();
  const EquationOfStateModel eos(m);
  const double K = m.youngs_modulus / (3 * (1 - 2 * m.poisson_ratio));
  EXPECT_DOUBLE_EQ(eos.pressure(1e8, -1e-4, 4430.0, 298.0), 1e8 + K * 1e-4);
  EXPECT_DOUBLE_EQ(eos.bulk_modulus(5000.0), K);
  EXPECT_FALSE(eos.has_bulk_viscosity());
}

// theory §3, Eq. (3.2): Mie-Grueneisen (Steinberg 1996 Ti-6Al-4V c0 = 5130, s = 1.028, Gamma0 = 1.23
// [M]): reduces to rho0 c0^2 mu at small mu, zero at the reference state, closed form in compression,
// thermal pressure Gamma0 rho0 c (T - T_r), and its tangent modulus matches a finite difference.
TEST(EquationOfState, MieGruneisen) {
  MaterialParameters m = ti64_johnson_1985();
  m.eos = EquationOfState::MieGruneisen;
  m.mg_c0 = 5130.0;
  m.mg_s = 1.028;
  m.mg_gamma0 = 1.23;
  const EquationOfStateModel eos(m);
  const double rho0 = 4430.0, K0 = rho0 * 5130.0 * 5130.0;
  EXPECT_EQ(eos.pressure(123.0, 0.0, rho0, 298.0), 0.0);
  EXPECT_NEAR(eos.pressure(0.0, 0.0, rho0 * (1 + 1e-6), 298.0), K0 * 1e-6, 1e-5 * K0 * 1e-6);
  EXPECT_NEAR(eos.pressure(0.0, 0.0, rho0 * (1 - 1e-3), 298.0), -K0 * 1e-3, 1e-12 * K0);
  const double mu = 0.08;
  const double pH = K0 * mu * (1 + (1 - 1.23 / 2) * mu) / std::pow(1 - 0.028 * mu, 2);
  EXPECT_NEAR(eos.pressure(0.0, 0.0, rho0 * (1 + mu), 298.0), pH, 1e-12 * pH);
  EXPECT_NEAR(eos.pressure(0.0, 0.0, rho0, 798.0), 1.23 * rho0 * 526.3 * 500.0, 1e-3);
  for (double rho : {0.98 * rho0, 1.05 * rho0, 1.2 * rho0}) {
    const double h = 1e-6 * rho;
    const double fd = rho * (eos.pressure(0, 0, rho + h, 298.0) - eos.pressure(0, 0, rho - h, 298.0)) / (2 * h);
    EXPECT_NEAR(eos.bulk_modulus(rho), fd, 1e-6 * fd) << rho;
  }
}

// theory §3, Eq. (3.3): bulk viscosity b1 rho c L |e_v'| + rho (b2 L e_v')^2 in compression, zero in expansion.
TEST(EquationOfState, BulkViscosityCompressionOnly) {
  MaterialParameters m = ti64_johnson_1985();
  m.bulk_viscosity_linear = 0.06;
  m.bulk_viscosity_quadratic = 1.2;
  const EquationOfStateModel eos(m);
  EXPECT_TRUE(eos.has_bulk_viscosity());
  const double rho = 4430, rate = -1e6, L = 5e-6, c = 6300;
  EXPECT_DOUBLE_EQ(eos.bulk_viscosity(rho, rate, L, c), 0.06 * rho * c * L * 1e6 + rho * std::pow(1.2 * L * 1e6, 2));
  EXPECT_EQ(eos.bulk_viscosity(rho, 1e6, L, c), 0.0);
  EXPECT_EQ(eos.bulk_viscosity(rho, 0.0, L, c), 0.0);
}
