#pragma once
// A particle's 3x3 node stencil on the grid, and the loops over it that every transfer uses
// (P2G, G2P, the MUSL remap, the velocity gradient, contact weights, heat conduction).
#include <cstddef>
#include <span>

#include "core/grid.hpp"
#include "core/particles.hpp"
#include "core/shape_functions.hpp"
#include "core/tensor.hpp"

namespace mpmcut {

// Weights and gradients of shape function `shape` for a particle at x (m).
inline Stencil stencil_at(const Grid& grid, const ShapeFunction& shape, const Vec2& x) {
  Stencil st;
  const Vec2 u = (x - grid.origin) / grid.h;  // cell units
  shape.evaluate(u.x(), u.y(), st);
  return st;
}

// The stencil of particle p, with the shape function of its body (uGIMP's lp depends on the
// body's particles per cell, so there is one shape function per body).
inline Stencil particle_stencil(const Grid& grid, std::span<const ShapeFunction> body_shapes, const Particles& particles,
                                std::size_t p) {
  return stencil_at(grid, body_shapes[particles.body[p]], particles.position[p]);
}

// Calls visit(node index, S_ip, grad S_ip) for each stencil node where the weight or its gradient
// is non-zero; the others contribute nothing. (The weight alone can be zero where the gradient is
// not: linear hats for a particle exactly on a grid line. Transfers that divide by nodal mass skip
// w = 0 themselves.)
template <class Visit>
inline void for_each_stencil_node(const Grid& grid, const Stencil& st, Visit&& visit) {
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) {
      const double w = st.w[a][c];
      const Vec2 grad(st.dwdx[a][c], st.dwdy[a][c]);
      if (w == 0.0 && grad.x() == 0.0 && grad.y() == 0.0) continue;
      visit(grid.index(st.i0 + a, st.j0 + c), w, grad);
    }
}

// Calls visit(node index, S_ip) for each stencil node with a non-zero weight: the transfers that need
// no gradient (G2P, the MUSL remap, contact weights, heat back to the particles). The same nodes
// and order as the loop above, without building and testing gradients (which made G2P and the
// remap take 60-80 % more instructions).
template <class Visit>
inline void for_each_stencil_weight(const Grid& grid, const Stencil& st, Visit&& visit) {
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) {
      const double w = st.w[a][c];
      if (w != 0.0) visit(grid.index(st.i0 + a, st.j0 + c), w);
    }
}

// Calls visit(node index, grad S_ip) for each stencil node with a non-zero weight gradient (the
// velocity gradient).
template <class Visit>
inline void for_each_stencil_gradient(const Grid& grid, const Stencil& st, Visit&& visit) {
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) {
      const double gx = st.dwdx[a][c], gy = st.dwdy[a][c];
      if (gx != 0.0 || gy != 0.0) visit(grid.index(st.i0 + a, st.j0 + c), Vec2(gx, gy));
    }
}

}  // namespace mpmcut
