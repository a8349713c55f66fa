// Three-grid Richardson extrapolation and GCI (analysis/grid_convergence.hpp) against the worked example
// of Celik et al. (2008), Table 1, and against results with a known error model phi = phi0 + a h^p.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>

#include "analysis/grid_convergence.hpp"

namespace mpmcut {
namespace {

// Celik et al. 2008, Table 1, column phi = dimensionless reattachment length: N = 18000, 8000, 4500 cells
// in 2D (h ~ N^(-1/2)), phi = 6.063, 5.972, 5.863 -> p = 1.53, phi_ext21 = 6.1685, e_a21 = 1.5 %,
// e_ext21 = 1.7 %, GCI_fine21 = 2.2 %.
TEST(GridConvergence, ReproducesTheWorkedExampleOfCelik2008) {
  const double h1 = 1.0 / std::sqrt(18000.0), h2 = 1.0 / std::sqrt(8000.0), h3 = 1.0 / std::sqrt(4500.0);
  const GridConvergenceEstimate e = three_grid_convergence(h1, 6.063, h2, 5.972, h3, 5.863);
  EXPECT_EQ(e.behaviour, "monotonic");
  ASSERT_TRUE(e.observed_order && e.extrapolated && e.extrapolated_relative_error && e.gci_fine);
  EXPECT_NEAR(*e.observed_order, 1.53, 0.005);
  EXPECT_NEAR(*e.extrapolated, 6.1685, 0.0005);
  EXPECT_NEAR(e.approximate_relative_error, 0.015, 0.0005);
  EXPECT_NEAR(*e.extrapolated_relative_error, 0.017, 0.0005);
  EXPECT_NEAR(*e.gci_fine, 0.022, 0.0005);
  EXPECT_TRUE(e.order_plausible);
}

// A small observed order extrapolates far: flagged as outside the asymptotic range.
TEST(GridConvergence, FlagsAnImplausibleOrder) {
  const auto phi = [](double h) { return 100.0 + 40.0 * std::pow(h, 0.3); };
  const GridConvergenceEstimate e = three_grid_convergence(1.0, phi(1.0), 1.5, phi(1.5), 2.25, phi(2.25));
  ASSERT_TRUE(e.observed_order);
  EXPECT_NEAR(*e.observed_order, 0.3, 1e-6);
  EXPECT_FALSE(e.order_plausible);
}

// phi = 100 + a h^p exactly: the estimate returns p and 100 for equal and unequal refinement ratios, and
// the GCI covers the true error of the finest grid.
TEST(GridConvergence, RecoversAKnownOrderAndLimit) {
  for (double p : {1.0, 2.0, 0.7})
    for (double a : {5.0, -3.0})
      for (const auto& h : {std::array<double, 3>{1.0, 1.5, 2.25}, std::array<double, 3>{4.17, 6.25, 8.33}}) {
        const auto phi = [&](double x) { return 100.0 + a * std::pow(x, p); };
        const GridConvergenceEstimate e = three_grid_convergence(h[0], phi(h[0]), h[1], phi(h[1]), h[2], phi(h[2]));
        SCOPED_TRACE(testing::Message() << "p " << p << " a " << a << " h1 " << h[0]);
        EXPECT_EQ(e.behaviour, "monotonic");
        ASSERT_TRUE(e.observed_order && e.extrapolated && e.gci_fine);
        EXPECT_NEAR(*e.observed_order, p, 1e-6);
        EXPECT_NEAR(*e.extrapolated, 100.0, 1e-6);
        EXPECT_GE(*e.gci_fine * std::abs(phi(h[0])), std::abs(phi(h[0]) - 100.0));
      }
}

// First-order convergence of a thrust that falls with the cell, as the sharp-edge cut's does: an estimate
// that ignored the unequal ratios (16 -> 24 is 1.5, 12 -> 16 is 1.33) would report p = 1.4, not 1.
TEST(GridConvergence, UsesUnequalRefinementRatios) {
  const double h1 = 100.0 / 24, h2 = 100.0 / 16, h3 = 100.0 / 12;
  const GridConvergenceEstimate e = three_grid_convergence(h1, 20.0 + 3.0 * h1, h2, 20.0 + 3.0 * h2, h3, 20.0 + 3.0 * h3);
  ASSERT_TRUE(e.observed_order);
  EXPECT_NEAR(*e.observed_order, 1.0, 1e-6);
  EXPECT_NEAR(*e.extrapolated, 20.0, 1e-6);
}

TEST(GridConvergence, OscillatingResultsGetTheirSpreadAsBandAndNoExtrapolation) {
  const GridConvergenceEstimate e = three_grid_convergence(1.0, 100.0, 1.5, 104.0, 2.25, 98.0);
  EXPECT_EQ(e.behaviour, "oscillatory");
  EXPECT_FALSE(e.observed_order);
  EXPECT_FALSE(e.extrapolated);
  ASSERT_TRUE(e.gci_fine);
  EXPECT_NEAR(*e.gci_fine, 0.5 * 6.0 / 100.0, 1e-12);
}

TEST(GridConvergence, ChangesThatDoNotShrinkGetNoOrder) {
  // Changes 2 then 4 as the grid is refined by 1.5 each time: no positive order fits.
  const GridConvergenceEstimate e = three_grid_convergence(1.0, 106.0, 1.5, 102.0, 2.25, 100.0);
  EXPECT_EQ(e.behaviour, "not shrinking");
  EXPECT_FALSE(e.observed_order);
  EXPECT_FALSE(e.gci_fine);
}

TEST(GridConvergence, EqualResultsAreConverged) {
  const GridConvergenceEstimate e = three_grid_convergence(1.0, 5.0, 2.0, 5.0, 4.0, 5.0);
  EXPECT_EQ(e.behaviour, "converged");
  EXPECT_EQ(*e.gci_fine, 0.0);
}

TEST(GridConvergence, RejectsUnorderedOrNonFiniteInput) {
  EXPECT_THROW(three_grid_convergence(2.0, 1.0, 1.0, 1.0, 4.0, 1.0), std::invalid_argument);
  EXPECT_THROW(three_grid_convergence(0.0, 1.0, 1.0, 1.0, 4.0, 1.0), std::invalid_argument);
  EXPECT_THROW(three_grid_convergence(1.0, NAN, 2.0, 1.0, 4.0, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace mpmcut
