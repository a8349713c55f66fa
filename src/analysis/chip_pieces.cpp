#include "analysis/chip_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>

#include <fmt/core.h>

namespace mpmcut {

namespace {

// Union-find with path halving and union by size.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n), size_(n, 1) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];
      i = parent_[i];
    }
    return i;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

 private:
  std::vector<std::size_t> parent_, size_;
};

}  // namespace

std::size_t Pieces::count_at_least(std::size_t min_points) const {
  return static_cast<std::size_t>(
      std::count_if(size.begin(), size.end(), [min_points](std::size_t s) { return s >= min_points; }));
}

Pieces find_pieces(const std::vector<Vec2>& points, double link_distance, const std::vector<char>& bonds) {
  const std::size_t n = points.size();
  if (!(link_distance > 0.0))
    throw std::invalid_argument(fmt::format("find_pieces: link distance {} must be > 0", link_distance));
  if (!bonds.empty() && bonds.size() != n)
    throw std::invalid_argument(fmt::format("find_pieces: {} bond flags for {} points", bonds.size(), n));
  Pieces out;
  if (n == 0) return out;

  // Bucket the points in square cells of side link_distance: a link can only join neighbouring cells.
  Vec2 lo = points[0];
  for (const Vec2& x : points) lo = lo.cwiseMin(x);
  auto cell_of = [&](const Vec2& x) {
    return std::pair<std::int64_t, std::int64_t>{static_cast<std::int64_t>(std::floor((x.x() - lo.x()) / link_distance)),
                                                 static_cast<std::int64_t>(std::floor((x.y() - lo.y()) / link_distance))};
  };
  std::vector<std::pair<std::int64_t, std::int64_t>> cell(n);
  for (std::size_t i = 0; i < n; ++i) cell[i] = cell_of(points[i]);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cell[a] < cell[b]; });
  std::vector<std::pair<std::int64_t, std::int64_t>> sorted_cells(n);
  for (std::size_t k = 0; k < n; ++k) sorted_cells[k] = cell[order[k]];

  const double d2 = link_distance * link_distance;
  DisjointSets sets(n);
  auto may_bond = [&](std::size_t i) { return bonds.empty() || bonds[i]; };
  for (std::size_t i = 0; i < n; ++i) {
    if (!may_bond(i)) continue;
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const std::pair<std::int64_t, std::int64_t> key{cell[i].first + dx, cell[i].second + dy};
        const auto range = std::equal_range(sorted_cells.begin(), sorted_cells.end(), key);
        for (auto it = range.first; it != range.second; ++it) {
          const std::size_t j = order[static_cast<std::size_t>(it - sorted_cells.begin())];
          if (j <= i || !may_bond(j)) continue;  // each pair once
          if ((points[i] - points[j]).squaredNorm() < d2) sets.unite(i, j);
        }
      }
    }
  }

  // Number the pieces by size, largest first (ties: by first point), so that piece 0 is the main one.
  std::vector<std::size_t> root_count(n, 0);
  for (std::size_t i = 0; i < n; ++i) ++root_count[sets.find(i)];
  std::vector<std::size_t> roots;
  for (std::size_t i = 0; i < n; ++i)
    if (root_count[i] > 0) roots.push_back(i);
  std::stable_sort(roots.begin(), roots.end(),
                   [&](std::size_t a, std::size_t b) { return root_count[a] > root_count[b]; });
  std::vector<int> piece_of_root(n, -1);
  for (std::size_t k = 0; k < roots.size(); ++k) {
    piece_of_root[roots[k]] = static_cast<int>(k);
    out.size.push_back(root_count[roots[k]]);
  }
  out.label.resize(n);
  for (std::size_t i = 0; i < n; ++i) out.label[i] = piece_of_root[sets.find(i)];
  return out;
}

}  // namespace mpmcut
