// A particle's volume follows its motion exactly enough however far it is stretched (core/particles.hpp,
// advance_deformation). In a cut at 5 um cells a failed particle drawn along the tool's edge reached F entries of
// ~1e7: V = det F V0 then lost every digit (J in steps of 0.25, then 0, density and pressure infinite, the run
// stopped with a non-finite stress). The volume now follows det(I + dt L) step by step.
#include <gtest/gtest.h>

#include <cmath>

#include "core/particles.hpp"

namespace mpmcut {
namespace {

Particles one_particle() {
  Particles p;
  p.add(Vec2::Zero(), Vec2::Zero(), 4430.0 * 1e-10, 1e-10, 298.0, 0, 0);
  return p;
}

// An extension along axes at 30 degrees, rate r, for ln(lambda) = 20: F's entries reach ~5e8 and det F computed from
// them is noise, while J = V/V0 is the product of the steps' det(I + dt L) = 1 - (r dt)^2.
TEST(DeformationUpdate, VolumeStaysExactUnderLongStretching) {
  Particles p = one_particle();
  const double r_dt = 1e-3, c = std::cos(M_PI / 3.0), s = std::sin(M_PI / 3.0);
  Mat2 L;
  L << c, s, s, -c;  // R diag(1, -1) R^T, R at 30 degrees: traceless
  const double dt = 1e-9, rate = r_dt / dt;
  const int steps = 20000;
  for (int n = 0; n < steps; ++n) advance_deformation(p, 0, rate * L, dt);
  const double J_exact = std::pow(1.0 - r_dt * r_dt, steps);
  EXPECT_GT(p.deformation_gradient[0].cwiseAbs().maxCoeff(), 1e8);  // the stretch the test is about
  EXPECT_NEAR(p.volume[0] / p.initial_volume[0], J_exact, 1e-12 * J_exact);
  // det F of those entries: a cancellation of products ~1e17 (kept here to show why V is not taken from it).
  const double det_F = p.deformation_gradient[0].determinant();
  EXPECT_FALSE(std::abs(det_F - J_exact) < 1e-3) << "det F " << det_F << " was expected to have lost its digits";
}

// In ordinary flow (a shear, a compression and a rotation) the step-by-step volume and det F V0 agree to rounding.
TEST(DeformationUpdate, VolumeIsDetFTimesV0InOrdinaryFlow) {
  Particles p = one_particle();
  Mat2 L;
  L << -0.2, 1.5, -0.7, 0.1;
  for (int n = 0; n < 1000; ++n) advance_deformation(p, 0, L, 1e-3);
  const double J = p.deformation_gradient[0].determinant();
  EXPECT_NEAR(p.volume[0] / p.initial_volume[0], J, 1e-12 * J);
  EXPECT_LT(J, 0.95);  // it did compress
}

}  // namespace
}  // namespace mpmcut
