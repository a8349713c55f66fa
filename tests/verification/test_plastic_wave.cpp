// Elastic-plastic wave in uniaxial strain (elastic precursor; docs/theory_materials.md §1-§4, the
// "Grid-level verification" section): a column of elastic-perfectly plastic Johnson-Cook material
// (B = 0, C = 0, no heating, no damage, linear EOS) moving at -v0 hits a fixed wall at x = 0.
//
// Uniaxial strain, eps_yy = eps_zz = 0: sigma_xx = (K + 4G/3) eps until q = |sigma_xx - sigma_yy| =
// 2G |eps| reaches sigma_y, i.e. the Hugoniot elastic limit
//     sigma_HEL = (K + 4G/3) sigma_y / (2G) = sigma_y (1 - nu)/(1 - 2 nu),
// carried by a precursor at c_el = sqrt((K + 4G/3)/rho). Beyond it the deviator stays on the yield
// surface and d(sigma_xx) = K d(eps): a second (plastic) wave at c_pl = sqrt(K/rho). Momentum jumps
// across each front, [sigma] = rho c [v]: the precursor brings the material to v_HEL =
// sigma_HEL/(rho c_el); the plastic wave brings it to rest against the wall, so behind it
//     |sigma_xx| = sigma_HEL + rho c_pl (v0 - v_HEL).
// Small-strain theory: with v0 = 130 m/s the volumetric strain is about 2 %, so the hypoelastic
// (logarithmic) volumetric law and the Lagrangian speeds differ from it by about 1 %; the checks
// allow 3 %.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <cmath>
#include <utility>
#include <vector>

#include "../support/scene_builders.hpp"
#include "solver/simulation.hpp"

using namespace mpmcut;
using namespace mpmcut::testing;

namespace {

// Ti-6Al-4V elastic constants and the Johnson 1985 A (docs/materials.md), made perfectly plastic.
MaterialParameters perfectly_plastic_ti64() {
  MaterialParameters m;
  m.name = "ti64-perfectly-plastic";
  m.model = MaterialModel::JohnsonCook;
  m.density = 4430.0;
  m.youngs_modulus = 113.8e9;
  m.poisson_ratio = 0.342;
  m.specific_heat = 526.3;
  m.taylor_quinney = 0.0;  // no heating: T stays at T_r, no thermal softening
  m.melting_temperature = 1878.0;
  m.jc_A = 862e6;
  m.jc_B = 0.0;
  m.jc_C = 0.0;
  return m;
}

// sigma_xx along the column against the Lagrangian coordinate X (distance from the wall in the
// unstrained column). In a 1D column the particles keep their order, so the X of a particle is its
// rank in x within its row times the initial spacing.
std::vector<std::pair<double, double>> stress_profile(const Particles& P, double spacing) {
  std::vector<std::pair<double, double>> rows[2];  // (x, sigma_xx) for the two particle rows
  const double y_mid = 0.5 * (*std::max_element(P.position.begin(), P.position.end(),
                                                 [](const Vec2& a, const Vec2& b) { return a.y() < b.y(); }))
                                 .y();
  for (std::size_t p = 0; p < P.size(); ++p)
    rows[P.position[p].y() > y_mid ? 1 : 0].emplace_back(P.position[p].x(), P.stress[p].xx);
  std::vector<std::pair<double, double>> out;  // (X, sigma_xx averaged over the two rows)
  for (auto& r : rows) std::sort(r.begin(), r.end());
  const std::size_t n = std::min(rows[0].size(), rows[1].size());
  for (std::size_t k = 0; k < n; ++k)
    out.emplace_back((k + 0.5) * spacing, 0.5 * (rows[0][k].second + rows[1][k].second));
  return out;
}

// Lagrangian position of the last particle (from the wall) whose compression exceeds `level`.
double front(const std::vector<std::pair<double, double>>& profile, double level) {
  double X = 0.0;
  for (const auto& [x, s] : profile)
    if (-s > level) X = x;
  return X;
}

double mean_stress(const std::vector<std::pair<double, double>>& profile, double X0, double X1) {
  double sum = 0.0;
  int n = 0;
  for (const auto& [x, s] : profile)
    if (x > X0 && x < X1) {
      sum += s;
      ++n;
    }
  EXPECT_GT(n, 20) << "too few particles in [" << X0 << ", " << X1 << "] m";
  return n > 0 ? sum / n : 0.0;
}

}  // namespace

TEST(PlasticWave, PrecursorAtHugoniotElasticLimitAndPlasticWaveAtBulkSpeed) {
  const MaterialParameters m = perfectly_plastic_ti64();
  const double rho = m.density, K = m.bulk_modulus(), G = m.shear_modulus(), nu = m.poisson_ratio;
  const double sigma_y = m.jc_A, v0 = 130.0;
  const double c_el = std::sqrt((K + 4.0 * G / 3.0) / rho), c_pl = std::sqrt(K / rho);
  const double sigma_hel = sigma_y * (1.0 - nu) / (1.0 - 2.0 * nu);
  const double v_hel = sigma_hel / (rho * c_el);
  const double sigma_final = sigma_hel + rho * c_pl * (v0 - v_hel);
  ASSERT_GT(v0, 2.0 * v_hel) << "the impact must exceed the elastic limit clearly";

  const double L = 4e-3;  // column length, m
  const int cells = 600;
  const double h = L / cells;
  const Scene s = uniaxial_strain_impact(m, L, cells, v0);
  Simulation sim(s);
  const double spacing = h / 2;

  // Two snapshots: fronts at about 0.45 L and 0.9 L (elastic); the speeds come from the difference,
  // so the start-up of the fronts and their smearing over a few cells cancel.
  struct Snapshot {
    double t, elastic_front, plastic_front, hel, final_stress;
  };
  auto snapshot = [&](double t_target) {
    while (sim.time() < t_target) sim.step(t_target - sim.time());
    const auto profile = stress_profile(sim.particles(), spacing);
    Snapshot sn;
    sn.t = sim.time();
    sn.elastic_front = front(profile, 0.5 * sigma_hel);
    sn.plastic_front = front(profile, 0.5 * (sigma_hel + sigma_final));
    const double gap = sn.elastic_front - sn.plastic_front;
    // The plastic front is smeared over ~10 cells behind it: take the plateau from the leading half.
    sn.hel = -mean_stress(profile, sn.plastic_front + 0.5 * gap, sn.elastic_front - 0.15 * gap);
    sn.final_stress = -mean_stress(profile, 0.15 * sn.plastic_front, 0.75 * sn.plastic_front);
    return sn;
  };
  const Snapshot a = snapshot(0.45 * L / c_el);
  const Snapshot b = snapshot(0.9 * L / c_el);

  const double elastic_speed = (b.elastic_front - a.elastic_front) / (b.t - a.t);
  const double plastic_speed = (b.plastic_front - a.plastic_front) / (b.t - a.t);
  RecordProperty("sigma_HEL_ratio", std::to_string(b.hel / sigma_hel));
  RecordProperty("c_el_ratio", std::to_string(elastic_speed / c_el));
  RecordProperty("c_pl_ratio", std::to_string(plastic_speed / c_pl));
  RecordProperty("sigma_final_ratio", std::to_string(b.final_stress / sigma_final));
  std::printf("sigma_HEL %.4g (theory %.4g), c_el %.5g (%.5g), c_pl %.5g (%.5g), sigma_final %.4g (%.4g) Pa\n",
              b.hel, sigma_hel, elastic_speed, c_el, plastic_speed, c_pl, b.final_stress, sigma_final);

  EXPECT_GT(b.elastic_front - b.plastic_front, 40 * spacing) << "the two fronts must be well separated";
  EXPECT_NEAR(b.hel, sigma_hel, 0.03 * sigma_hel);
  EXPECT_NEAR(elastic_speed, c_el, 0.03 * c_el);
  EXPECT_NEAR(plastic_speed, c_pl, 0.03 * c_pl);
  EXPECT_NEAR(b.final_stress, sigma_final, 0.03 * sigma_final);
  EXPECT_NEAR(a.final_stress, sigma_final, 0.03 * sigma_final);
}

// The artificial bulk viscosity's work is booked (theory_materials.md §6, EnergyTotals::viscous): the same
// impact with von Neumann-Richtmyer viscosity on conserves energy only when the viscous work is counted.
// The fixed wall does no work, so initial kinetic = kinetic + elastic + plastic + viscous.
TEST(PlasticWave, BulkViscosityWorkClosesTheEnergyBalance) {
  MaterialParameters m = perfectly_plastic_ti64();
  m.bulk_viscosity_linear = 0.06;  // Abaqus/Explicit defaults
  m.bulk_viscosity_quadratic = 1.2;
  const double v0 = 130.0;
  Simulation sim(uniaxial_strain_impact(m, 4e-3, 200, v0));
  double mass = 0.0;
  for (double mp : sim.particles().mass) mass += mp;
  const double initial = 0.5 * mass * v0 * v0;
  while (sim.time() < 0.3e-6) sim.step();  // the waves run about half the column
  sim.refresh_energy();
  const EnergyTotals& e = sim.energy();
  EXPECT_GT(e.viscous, 1e-3 * initial);
  const double balance = e.kinetic + e.elastic + e.plastic_work + e.viscous;
  EXPECT_NEAR(balance, initial, 0.01 * initial)
      << "kinetic " << e.kinetic << ", elastic " << e.elastic << ", plastic " << e.plastic_work << ", viscous "
      << e.viscous << " J/m";
  // Without the viscous term the balance misses it by more than the tolerance.
  EXPECT_GT(initial - (balance - e.viscous), 0.01 * initial);
}
