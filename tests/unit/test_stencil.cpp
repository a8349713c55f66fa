// The stencil helper (core/stencil.hpp) that every transfer loops with: it visits each node of a
// particle's 3x3 stencil whose weight or gradient is non-zero, once, with the right grid index and
// values; over the visited nodes the weights sum to 1, the gradients to 0, and sum S x_i = x_p
// ([BardenhagenKober2004]), the properties P2G and G2P rely on to conserve mass and momentum.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "core/stencil.hpp"

using namespace mpmcut;

namespace {

Grid unit_grid(double h) {
  Grid g;
  GridSpec spec;
  spec.cell_size = h;
  spec.min = Vec2(0.0, 0.0);
  spec.max = Vec2(20 * h, 20 * h);
  g.build(spec);
  return g;
}

void check_stencil(ShapeFunctionKind kind, int ppc) {
  const double h = 0.37;
  const Grid grid = unit_grid(h);
  const ShapeFunction shape(kind, h, ppc);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(2.0 * h, 18.0 * h);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec2 x(U(rng), U(rng));
    const Stencil st = stencil_at(grid, shape, x);
    std::set<int> seen;
    double sum_w = 0.0;
    Vec2 sum_grad = Vec2::Zero(), sum_wx = Vec2::Zero();
    for_each_stencil_node(grid, st, [&](int node, double w, const Vec2& grad) {
      ASSERT_TRUE(seen.insert(node).second) << "node " << node << " visited twice";
      ASSERT_TRUE(w != 0.0 || grad.x() != 0.0 || grad.y() != 0.0) << "a node that contributes nothing";
      const int i = node % grid.nx, j = node / grid.nx;
      ASSERT_TRUE(i >= st.i0 && i < st.i0 + 3 && j >= st.j0 && j < st.j0 + 3) << "node outside the stencil";
      ASSERT_EQ(w, st.w[i - st.i0][j - st.j0]);
      ASSERT_EQ(grad.x(), st.dwdx[i - st.i0][j - st.j0]);
      ASSERT_EQ(grad.y(), st.dwdy[i - st.i0][j - st.j0]);
      sum_w += w;
      sum_grad += grad;
      sum_wx += w * grid.node_position(i, j);
    });
    // Every node the helper skipped contributes nothing.
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        if (!seen.count(grid.index(st.i0 + a, st.j0 + c))) {
          ASSERT_EQ(st.w[a][c], 0.0);
          ASSERT_EQ(st.dwdx[a][c], 0.0);
          ASSERT_EQ(st.dwdy[a][c], 0.0);
        }
    ASSERT_NEAR(sum_w, 1.0, 1e-13);
    ASSERT_NEAR(sum_grad.norm(), 0.0, 1e-12 / h);
    ASSERT_NEAR((sum_wx - x).norm(), 0.0, 1e-12);
  }
}

}  // namespace

TEST(Stencil, UGimpVisitsTheSupportWithItsWeightsAndGradients) {
  check_stencil(ShapeFunctionKind::UGimp, 2);
  check_stencil(ShapeFunctionKind::UGimp, 3);
}

TEST(Stencil, LinearVisitsTheSupportWithItsWeightsAndGradients) { check_stencil(ShapeFunctionKind::Linear, 1); }

// A particle exactly on a grid line with linear hats: the node beyond the line has weight 0 but a
// non-zero gradient, and must be visited (the velocity gradient and the internal force need it).
TEST(Stencil, LinearOnAGridLineVisitsTheZeroWeightNodeWithAGradient) {
  const double h = 0.5;
  const Grid grid = unit_grid(h);
  const ShapeFunction shape(ShapeFunctionKind::Linear, h, 1);
  const Vec2 x = grid.node_position(8, 8) + Vec2(0.0, 0.25 * h);  // on the vertical line i = 8
  int zero_weight_with_gradient = 0;
  Vec2 sum_grad = Vec2::Zero();
  for_each_stencil_node(grid, stencil_at(grid, shape, x), [&](int, double w, const Vec2& grad) {
    if (w == 0.0 && grad.x() != 0.0) ++zero_weight_with_gradient;
    sum_grad += grad;
  });
  EXPECT_EQ(zero_weight_with_gradient, 2);
  EXPECT_NEAR(sum_grad.norm(), 0.0, 1e-12);
}

TEST(Stencil, ParticleStencilUsesItsBodysShapeFunction) {
  const double h = 0.37;
  const Grid grid = unit_grid(h);
  const std::vector<ShapeFunction> shapes{ShapeFunction(ShapeFunctionKind::UGimp, h, 1),
                                          ShapeFunction(ShapeFunctionKind::UGimp, h, 4)};
  Particles P;
  const Vec2 x = grid.node_position(10, 10) + Vec2(0.49 * h, 0.2 * h);
  P.add(x, Vec2::Zero(), 1.0, 1.0, 300.0, 1, 0);
  const Stencil st = particle_stencil(grid, shapes, P, 0);
  const Stencil expected = stencil_at(grid, shapes[1], x), other = stencil_at(grid, shapes[0], x);
  bool differs_from_body_0 = false;
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(st.w[a][c], expected.w[a][c]);
      differs_from_body_0 = differs_from_body_0 || st.w[a][c] != other.w[a][c];
    }
  EXPECT_TRUE(differs_from_body_0);
}
