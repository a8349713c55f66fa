// Chip pieces: connected groups of particles, neighbours within 1.5 particle spacings, fully
// damaged particles bond to nothing (docs/analysis.md).
#include <gtest/gtest.h>

#include "analysis/chip_pieces.hpp"

namespace mpmcut {
namespace {

void block(std::vector<Vec2>& x, std::vector<char>& bonds, double x0, double y0, int nx, int ny, double d,
           bool bond = true) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      x.emplace_back(x0 + i * d, y0 + j * d);
      bonds.push_back(bond);
    }
}

TEST(ChipPieces, BlocksSeparatedByFailedRowsAndAnIsolatedBlock) {
  const double d = 5e-6;
  std::vector<Vec2> x;
  std::vector<char> bonds;
  // Three 10 x 10 blocks stacked in y, each separated from the next by one row of fully damaged
  // particles on the same lattice (so they touch their neighbours), plus one block far away.
  block(x, bonds, 0.0, 0.0, 10, 10, d);
  block(x, bonds, 0.0, 10 * d, 10, 1, d, false);
  block(x, bonds, 0.0, 11 * d, 10, 10, d);
  block(x, bonds, 0.0, 21 * d, 10, 1, d, false);
  block(x, bonds, 0.0, 22 * d, 10, 10, d);
  block(x, bonds, 1e-3, 0.0, 6, 6, d);
  const Pieces p = find_pieces(x, 1.5 * d, bonds);
  // 3 + 1 blocks and 20 failed particles on their own.
  ASSERT_EQ(p.size.size(), 4u + 20u);
  EXPECT_EQ(p.count_at_least(10), 4u);
  EXPECT_EQ(p.size[0], 100u);
  EXPECT_EQ(p.size[3], 36u);
  // The failed particles are singletons; labels follow the sizes.
  EXPECT_EQ(p.size.back(), 1u);
  EXPECT_EQ(p.label[0], p.label[99]);
  EXPECT_NE(p.label[0], p.label[110]);
}

TEST(ChipPieces, WithoutTheFailedRowTheBlocksAreOne) {
  const double d = 5e-6;
  std::vector<Vec2> x;
  std::vector<char> bonds;
  block(x, bonds, 0.0, 0.0, 10, 31, d);
  EXPECT_EQ(find_pieces(x, 1.5 * d, bonds).size, (std::vector<std::size_t>{310}));
  EXPECT_EQ(find_pieces(x, 1.5 * d).size.size(), 1u);  // no bond flags: all bond
}

TEST(ChipPieces, DiagonalNeighboursLinkButTheNextRingDoesNot) {
  const double d = 1.0;
  EXPECT_EQ(find_pieces({Vec2(0, 0), Vec2(d, d)}, 1.5 * d).size.size(), 1u);        // sqrt(2) d
  EXPECT_EQ(find_pieces({Vec2(0, 0), Vec2(2 * d, 0)}, 1.5 * d).size.size(), 2u);    // 2 d
  EXPECT_TRUE(find_pieces({}, 1.5 * d).size.empty());
}

}  // namespace
}  // namespace mpmcut
