// A short orthogonal cut of Ti-6Al-4V on a coarse grid, through the cutting preset: the chip
// forms, no particle enters the tool, the forces are positive and finite, the energy balance
// closes, and the force lies in the band that Merchant's analysis gives for this material.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "../support/short_cut.hpp"
#include "physics/flow_stress.hpp"

using namespace mpmcut;
using namespace mpmcut::testing;

TEST(ShortCut, ChipFormsNoPenetrationPositiveForcesEnergyCloses) {
  const CuttingParameters c = coarse_cut(20.0, 0.12e-3);
  const CutResult r = run_cut(c);
  // Material above the cut line flows up the rake face: after 0.12 mm of travel the chip
  // stands well above the original surface (a plough without chip would stay near it).
  EXPECT_GT(r.chip_rise_m, 0.5 * c.uncut_chip_thickness);
  EXPECT_GE(r.deepest_penetration_m, 0.0) << "a workpiece particle entered the tool";
  EXPECT_TRUE(r.finite);
  EXPECT_GT(r.mean_cutting_force_N_per_m, 0.0);
  EXPECT_GT(r.mean_thrust_force_N_per_m, 0.0);
  // Work done by the tool = kinetic + elastic + plastic + damage + friction + the algorithmic terms,
  // within 1 % (docs/cutting.md, "Energy balance").
  std::printf("short cut: energy balance residual %.3f %% of the tool work (%.3f %% without the algorithmic terms)\n",
              100 * r.balance_error, 100 * r.balance_error_without_algorithmic);
  EXPECT_LT(std::abs(r.balance_error), 0.01) << "relative energy balance error " << r.balance_error;
}

// The same cut with closed-crack friction (theory_materials.md §5.8, mu_c = 0.5): damaged and failed particles under
// the rake face's pressure carry friction across their cracks, and that friction's work is booked as plastic work
// (and heat): the ledger still closes within 1 %.
TEST(ShortCut, ClosedCrackFrictionKeepsTheEnergyBalance) {
  MaterialParameters m = ti64();
  m.crack_friction = 0.5;
  const CutResult r = run_cut(coarse_cut(20.0, 0.12e-3), m);
  EXPECT_TRUE(r.finite);
  EXPECT_GE(r.deepest_penetration_m, 0.0) << "a workpiece particle entered the tool";
  std::printf("short cut, crack friction 0.5: Fc %.1f N/mm, Ft %.1f N/mm, energy balance residual %.3f %% of the tool "
              "work\n", r.mean_cutting_force_N_per_m / 1e3, r.mean_thrust_force_N_per_m / 1e3, 100 * r.balance_error);
  EXPECT_LT(std::abs(r.balance_error), 0.01) << "relative energy balance error " << r.balance_error;
}

// Merchant (1945) band for the cutting force per unit width at the reference conditions used by
// published Ti-6Al-4V meshfree studies (500 m/min, t0 = 0.1 mm, rake 0, mu = 0.35):
//   F_c = k t0 cos(beta - alpha) / (sin(phi) cos(phi + beta - alpha)),  tan(beta) = mu,
// with the shear angle between Merchant's phi = 45 - (beta - alpha)/2 and Lee-Shaffer's
// phi = 45 - beta + alpha, and the shear flow stress k = sigma_y/sqrt(3) from the same
// Johnson-Cook law over the primary-zone ranges eps_p 1..3, rate 1e3..1e5 1/s, T 298..900 K
// (Merchant 1945, Lee & Shaffer 1951; JC flow stress computed). The band is widened by 30% each way for what
// Merchant ignores (edge radius, serration, heat): about [60, 400] N/mm. A solver with a
// wrong flow stress, contact force or unit would land far outside.
TEST(ShortCut, ReferenceCutForceInMerchantBand) {
  const MaterialParameters& m = ti64();
  const JohnsonCookFlowStress flow(m);
  const double t0 = 0.1e-3, alpha = 0.0, beta = std::atan(0.35);
  double k_min = 1e300, k_max = 0.0;
  for (double eps : {1.0, 3.0})
    for (double rate : {1e3, 1e5})
      for (double T : {298.0, 900.0}) {
        const double k = flow.yield_stress(eps, rate, T) / std::sqrt(3.0);
        k_min = std::min(k_min, k);
        k_max = std::max(k_max, k);
      }
  auto merchant_force = [&](double k, double phi) {
    return k * t0 * std::cos(beta - alpha) / (std::sin(phi) * std::cos(phi + beta - alpha));
  };
  const double phi_merchant = std::numbers::pi / 4 - (beta - alpha) / 2;
  const double phi_lee_shaffer = std::numbers::pi / 4 - beta + alpha;
  const double f_low = 0.7 * std::min(merchant_force(k_min, phi_merchant), merchant_force(k_min, phi_lee_shaffer));
  const double f_high = 1.3 * std::max(merchant_force(k_max, phi_merchant), merchant_force(k_max, phi_lee_shaffer));
  const CutResult r = run_cut(coarse_cut(500.0 / 60.0, 0.25e-3));
  EXPECT_GT(r.mean_cutting_force_N_per_m, f_low) << "band [" << f_low * 1e-3 << ", " << f_high * 1e-3 << "] N/mm";
  EXPECT_LT(r.mean_cutting_force_N_per_m, f_high) << "band [" << f_low * 1e-3 << ", " << f_high * 1e-3 << "] N/mm";
  // The thrust force is smaller than the cutting force for a sharp 0-degree tool.
  EXPECT_GT(r.mean_thrust_force_N_per_m, 0.0);
  EXPECT_LT(r.mean_thrust_force_N_per_m, r.mean_cutting_force_N_per_m);
}
