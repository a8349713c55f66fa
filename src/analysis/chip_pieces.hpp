#pragma once
// Connected pieces of a particle cloud: the chip's fragments, or the clusters of high plastic
// strain that are its shear bands. Two points are linked when they are closer than a link
// distance (1.5 particle spacings for a lattice of spacing d reaches the 8 lattice neighbours,
// sqrt(2) d, but not the next ring, 2 d) and both may bond; a piece is a connected component of
// that graph. A point that may not bond (a fully damaged particle: a crack) is a piece of its own.
#include <cstddef>
#include <vector>

#include "core/tensor.hpp"

namespace mpmcut {

struct Pieces {
  std::vector<int> label;         // per point: index of its piece; pieces are numbered by size, largest first
  std::vector<std::size_t> size;  // points per piece, non-increasing
  std::size_t count_at_least(std::size_t min_points) const;
};

// `bonds[i]` false: point i links to nothing. Empty `bonds`: every point bonds.
// O(n log n): points are bucketed in cells of the link distance and only neighbouring cells are compared.
Pieces find_pieces(const std::vector<Vec2>& points, double link_distance, const std::vector<char>& bonds = {});

}  // namespace mpmcut
