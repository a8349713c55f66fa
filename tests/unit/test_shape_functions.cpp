// Shape-function properties (Bardenhagen & Kober 2004): partition of
// unity, zero gradient sum, linear completeness and grad-x = I, at random interior positions.
#include <gtest/gtest.h>

#include <random>

#include "core/shape_functions.hpp"

using namespace mpmcut;

namespace {
void check_properties(ShapeFunctionKind kind, int ppc) {
  const double h = 0.37;
  ShapeFunction sf(kind, h, ppc);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> U(5.0, 15.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double ux = U(rng), uy = U(rng);
    Stencil st;
    sf.evaluate(ux, uy, st);
    double sum_w = 0.0;
    Vec2 sum_grad = Vec2::Zero(), sum_wx = Vec2::Zero();
    Mat2 grad_x = Mat2::Zero();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const Vec2 xi = h * Vec2(st.i0 + a, st.j0 + b);
        const Vec2 g(st.dwdx[a][b], st.dwdy[a][b]);
        sum_w += st.w[a][b];
        sum_grad += g;
        sum_wx += st.w[a][b] * xi;
        grad_x += xi * g.transpose();
      }
    ASSERT_NEAR(sum_w, 1.0, 1e-13);
    ASSERT_NEAR(sum_grad.norm(), 0.0, 1e-12 / h);
    ASSERT_NEAR((sum_wx - h * Vec2(ux, uy)).norm(), 0.0, 1e-12);
    ASSERT_NEAR((grad_x - Mat2::Identity()).norm(), 0.0, 1e-12);
  }
}
}  // namespace

TEST(ShapeFunctions, LinearPartitionGradientCompleteness) { check_properties(ShapeFunctionKind::Linear, 2); }
TEST(ShapeFunctions, UGimpTwoPerCellProperties) { check_properties(ShapeFunctionKind::UGimp, 2); }
TEST(ShapeFunctions, UGimpThreePerCellProperties) { check_properties(ShapeFunctionKind::UGimp, 3); }
TEST(ShapeFunctions, UGimpOnePerCellProperties) { check_properties(ShapeFunctionKind::UGimp, 1); }

// The uGIMP weight is the average of the linear hat over the particle domain [x-lp, x+lp]:
// check against numerical quadrature of that definition (BK04 Eq. 40), and its gradient
// against a central difference.
TEST(ShapeFunctions, UGimpIsTheDomainAverageOfTheHat) {
  const double h = 1.0;
  ShapeFunction gimp(ShapeFunctionKind::UGimp, h, 2);
  ShapeFunction hat(ShapeFunctionKind::Linear, h, 2);
  const double lp = gimp.half_width();
  EXPECT_DOUBLE_EQ(lp, 0.25);
  for (double xi = -1.4; xi <= 1.4; xi += 0.0137) {
    const int n = 20000;
    double avg = 0.0;
    for (int k = 0; k < n; ++k) avg += hat.weight_1d(xi - lp + (k + 0.5) * 2 * lp / n);
    avg /= n;
    EXPECT_NEAR(gimp.weight_1d(xi), avg, 1e-8) << "xi = " << xi;
    const double e = 1e-6;
    EXPECT_NEAR(gimp.gradient_1d(xi), (gimp.weight_1d(xi + e) - gimp.weight_1d(xi - e)) / (2 * e), 1e-6);
  }
}

// The gradient is continuous for uGIMP (no cell-crossing jump) but jumps for linear hats.
TEST(ShapeFunctions, UGimpGradientIsContinuousAcrossNodes) {
  ShapeFunction gimp(ShapeFunctionKind::UGimp, 1.0, 2);
  ShapeFunction hat(ShapeFunctionKind::Linear, 1.0, 2);
  const double e = 1e-9;
  EXPECT_NEAR(gimp.gradient_1d(e), gimp.gradient_1d(-e), 1e-7);
  EXPECT_NEAR(hat.gradient_1d(e) - hat.gradient_1d(-e), -2.0, 1e-12);
}

// The closed-form stencil used in the transfers equals the region-by-region definition.
TEST(ShapeFunctions, StencilMatchesPiecewiseDefinition) {
  for (auto kind : {ShapeFunctionKind::Linear, ShapeFunctionKind::UGimp})
    for (int ppc : {1, 2, 3, 4}) {
      const double h = 0.5;
      ShapeFunction sf(kind, h, ppc);
      for (double ux = 3.0001; ux < 6.0; ux += 0.00731) {  // off the nodes, where linear hats have a kink
        Stencil st;
        sf.evaluate(ux, 4.3, st);
        double wy = 0.0;
        for (int b = 0; b < 3; ++b) wy += st.w[0][b];
        for (int a = 0; a < 3; ++a) {
          const double xi = (ux - (st.i0 + a)) * h;
          double w = 0.0, dx = 0.0;
          for (int b = 0; b < 3; ++b) {
            w += st.w[a][b];
            dx += st.dwdx[a][b];
          }
          ASSERT_NEAR(w, sf.weight_1d(xi), 1e-13) << "ux " << ux << " node " << a;
          ASSERT_NEAR(dx, sf.gradient_1d(xi), 1e-12) << "ux " << ux << " node " << a;
        }
        // Nodes outside the 3-node stencil carry no weight.
        ASSERT_EQ(sf.weight_1d((ux - (st.i0 - 1)) * h), 0.0);
        ASSERT_EQ(sf.weight_1d((ux - (st.i0 + 3)) * h), 0.0);
      }
    }
}
