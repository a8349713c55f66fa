#pragma once
// Shape functions on a regular grid: classic linear hats and uGIMP (Bardenhagen & Kober
// 2004) with a fixed particle half-width lp. Both are evaluated as a tensor product on a
// 3x3 node stencil (linear uses 2x2 of it; the third weight is zero).
#include <cmath>

#include "core/scene.hpp"
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

  // Stencil for a particle at u = (x_p - grid origin)/h in cell units.
  void evaluate(double ux, double uy, Stencil& st) const;

 private:
  void evaluate_1d(double u, int& first, double w[3], double dw[3]) const;
  ShapeFunctionKind kind_ = ShapeFunctionKind::UGimp;
  double h_ = 1.0;
  double lp_ = 0.25;   // m
  double l_ = 0.25;    // lp/h
};

}  // namespace mpmcut
