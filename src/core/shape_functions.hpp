#pragma once
// Shape functions on a regular grid: classic linear hats and uGIMP (Bardenhagen & Kober
// 2004) with a fixed particle half-width lp. Both are evaluated as a tensor product on a
// 3x3 node stencil (linear uses 2x2 of it; the third weight is zero).
#include <cmath>

#include "core/scene_specs.hpp"
#include "core/tensor.hpp"

namespace mpmcut {

// Weights and gradients of one particle on its 3x3 node stencil.
struct Stencil {
  int i0 = 0, j0 = 0;      // lower-left node of the stencil (grid node indices)
  double w[3][3];          // S_ip for nodes (i0+a, j0+b)
  double dwdx[3][3];       // dS_ip/dx, 1/m
  double dwdy[3][3];       // dS_ip/dy, 1/m
};

class ShapeFunction {
 public:
  ShapeFunction() = default;
  // kind, cell size h (m), particles per cell per direction (sets lp = h/(2 ppc) for uGIMP).
  ShapeFunction(ShapeFunctionKind kind, double cell_size, int particles_per_cell);

  ShapeFunctionKind kind() const { return kind_; }
  double half_width() const { return lp_; }  // lp, m (0 for linear)

  // 1D weight and derivative (d/dx_p) for a node at distance xi = x_p - x_i (m).
  double weight_1d(double xi) const;
  double gradient_1d(double xi) const;

  // Stencil for a particle at u = (x_p - grid origin)/h in cell units. Inline: it is the
  // innermost work of every transfer.
  inline void evaluate(double ux, double uy, Stencil& st) const {
    double wx[3], wy[3], dx[3], dy[3];
    evaluate_1d(ux, st.i0, wx, dx);
    evaluate_1d(uy, st.j0, wy, dy);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        st.w[a][b] = wx[a] * wy[b];
        st.dwdx[a][b] = dx[a] * wy[b];
        st.dwdy[a][b] = wx[a] * dy[b];
      }
  }

 private:
  // The three weights of one direction in closed form. With first = floor(u - l) and
  // f = u - first - l in [0, 1): node 0 is at distance f + l, node 1 at f + l - 1, node 2 at
  // f + l - 2 (in cells); for f < 1 - 2l the particle domain lies in one cell and the weights
  // are the linear ones, otherwise it straddles node 1 and the quadratic GIMP pieces apply.
  // (Same values as weight_1d/gradient_1d, which the tests compare against.)
  inline void evaluate_1d(double u, int& first, double w[3], double dw[3]) const {
    const double l = l_, inv_h = 1.0 / h_;
    const double fl = std::floor(u - l);
    first = static_cast<int>(fl);
    const double f = u - fl - l;
    if (f < 1.0 - 2.0 * l) {  // includes linear hats (l = 0)
      w[0] = 1.0 - f - l;
      w[1] = f + l;
      w[2] = 0.0;
      dw[0] = -inv_h;
      dw[1] = inv_h;
      dw[2] = 0.0;
    } else {
      const double g = f - (1.0 - 2.0 * l);  // in [0, 2l)
      const double inv4l = 0.25 / l;
      const double xi1 = g - l;               // node 1 offset, |xi1| < l
      w[0] = (2.0 * l - g) * (2.0 * l - g) * inv4l;
      w[1] = 1.0 - (xi1 * xi1 + l * l) * (2.0 * inv4l);
      w[2] = g * g * inv4l;
      dw[0] = -(2.0 * l - g) * (2.0 * inv4l) * inv_h;
      dw[1] = -xi1 / l * inv_h;
      dw[2] = g * (2.0 * inv4l) * inv_h;
    }
  }
  ShapeFunctionKind kind_ = ShapeFunctionKind::UGimp;
  double h_ = 1.0;
  double lp_ = 0.25;   // m
  double l_ = 0.25;    // lp/h
};

}  // namespace mpmcut
