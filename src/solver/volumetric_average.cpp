#include "solver/volumetric_average.hpp"

#include "core/stencil.hpp"

namespace mpmcut {

namespace {

double in_plane_mean(const PlaneStrainTensor& s) { return 0.5 * (s.xx + s.yy); }

// value_n <- value_n / M_n where the node has mass (others stay 0: no particle weights them).
void divide_by_mass(std::vector<double>& value, const std::vector<double>& mass, bool parallel) {
  const std::size_t nn = value.size();
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t n = 0; n < nn; ++n) value[n] = mass[n] > 0.0 ? value[n] / mass[n] : 0.0;
}

}  // namespace

void NodalVolumetricAverage::project_mean_stress(const Particles& P, const Grid& G,
                                                 std::span<const ShapeFunction> body_shapes,
                                                 const StripColouring& colouring, bool parallel) {
  node_mass_.assign(G.node_count(), 0.0);
  node_mean_stress_.assign(G.node_count(), 0.0);
  colouring.for_each(parallel, [&](std::size_t p) {
    const double m = P.mass[p], vs = P.volume[p] * in_plane_mean(P.stress[p]);
    for_each_stencil_weight(G, particle_stencil(G, body_shapes, P, p), [&](int n, double w) {
      node_mass_[n] += w * m;
      node_mean_stress_[n] += w * vs;
    });
  });
  divide_by_mass(node_mean_stress_, node_mass_, parallel);
}

void NodalVolumetricAverage::average_volumetric_rates(Particles& P, const Grid& G,
                                                      std::span<const ShapeFunction> body_shapes,
                                                      const StripColouring& colouring, bool parallel) {
  node_rate_.assign(G.node_count(), 0.0);
  colouring.for_each(parallel, [&](std::size_t p) {
    const double md = P.mass[p] * P.velocity_gradient[p].trace();
    for_each_stencil_weight(G, particle_stencil(G, body_shapes, P, p), [&](int n, double w) { node_rate_[n] += w * md; });
  });
  divide_by_mass(node_rate_, node_mass_, parallel);
  const std::size_t np = P.size();
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t p = 0; p < np; ++p) {
    double averaged = 0.0;
    for_each_stencil_weight(G, particle_stencil(G, body_shapes, P, p), [&](int n, double w) { averaged += w * node_rate_[n]; });
    P.velocity_gradient[p] += 0.5 * (averaged - P.velocity_gradient[p].trace()) * Mat2::Identity();
  }
}

}  // namespace mpmcut
