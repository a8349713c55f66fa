#include "solver/transfers.hpp"

#include "core/stencil.hpp"

namespace mpmcut {

void particles_to_grid(const Particles& P, std::span<const ShapeFunction> body_shapes,
                       const std::vector<MaterialParameters>& materials, double inertia_factor, const Vec2& b,
                       P2GFields fields, std::span<const double> node_mean_stress, bool parallel,
                       const StripColouring& colouring, Grid& G) {
  G.reset();
  const bool averaged = !node_mean_stress.empty();
  colouring.for_each(parallel, [&](std::size_t p) {
    const double m = inertia_factor * P.mass[p];  // inertial (scaled) mass
    const Vec2 mv = m * P.velocity[p];
    Mat2 sigma = P.stress[p].in_plane();
    const double V = P.volume[p];
    // Heat capacity from the true mass: mass scaling changes inertia only.
    const double mc = fields.heat_capacity ? P.mass[p] * materials[P.material[p]].specific_heat : 0.0;
    const Stencil st = particle_stencil(G, body_shapes, P, p);
    if (averaged) {
      double projected = 0.0;  // sum_n S_pn pi_n / M_n
      for_each_stencil_weight(G, st, [&](int n, double w) { projected += w * node_mean_stress[n]; });
      sigma += (P.mass[p] / V * projected - 0.5 * sigma.trace()) * Mat2::Identity();
    }
    for_each_stencil_node(G, st, [&](int n, double w, const Vec2& grad) {
      G.mass[n] += w * m;
      G.momentum[n] += w * mv;
      G.force[n] += -V * (sigma * grad) + (w * m) * b;
      if (fields.mass_position) G.mass_position[n] += (w * m) * P.position[p];
      if (fields.heat_capacity) G.heat_capacity[n] += w * mc;
      if (fields.temperature) G.temperature[n] += w * mc * P.temperature[p];  // sum S m c T; divided below
    });
  });
  const std::size_t nn = G.node_count();
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t n = 0; n < nn; ++n) {
    G.velocity[n] = G.mass[n] > 0.0 ? Vec2(G.momentum[n] / G.mass[n]) : Vec2::Zero();
    if (fields.temperature) G.temperature[n] = G.heat_capacity[n] > 0.0 ? G.temperature[n] / G.heat_capacity[n] : 0.0;
  }
}

void grid_to_particles(Particles& P, const Grid& G, std::span<const ShapeFunction> body_shapes, double inertia_factor,
                       double flip, double dt, bool parallel, std::vector<Vec2>& position_new,
                       std::vector<double>& transfer_loss) {
  const std::size_t n = P.size();
  position_new.resize(n);
  transfer_loss.resize(n);
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t p = 0; p < n; ++p) {
    Vec2 v_pic = Vec2::Zero(), dv = Vec2::Zero();
    // Nodes with w > 0 only: below, the node's mass is divided by, and w > 0 means it has some.
    for_each_stencil_weight(G, particle_stencil(G, body_shapes, P, p), [&](int node, double w) {
      v_pic += w * G.velocity_new[node];
      // FLIP increment from the raw P2G velocity, so the particles receive the contact and
      // boundary corrections of both passes: momentum given = contact impulse + f dt.
      const Vec2 v_p2g = G.momentum[node] / G.mass[node];
      dv += w * (G.velocity_new[node] - v_p2g);
    });
    const Vec2 v_flip = P.velocity[p] + dv;
    const Vec2 v_new = flip * v_flip + (1.0 - flip) * v_pic;
    // The grid's work reaches the particles through the FLIP increment; the PIC share replaces the
    // part of the particle velocity the grid does not carry, and that kinetic energy is lost.
    transfer_loss[p] = 0.5 * inertia_factor * P.mass[p] * (v_flip.squaredNorm() - v_new.squaredNorm());
    P.velocity[p] = v_new;
    position_new[p] = P.position[p] + dt * v_pic;
  }
}

void remap_momentum_musl(const Particles& P, std::span<const ShapeFunction> body_shapes, double inertia_factor,
                         const StripColouring& colouring, bool parallel, Grid& G) {
  std::fill(G.momentum.begin(), G.momentum.end(), Vec2::Zero());
  colouring.for_each(parallel, [&](std::size_t p) {
    const Vec2 mv = inertia_factor * P.mass[p] * P.velocity[p];
    for_each_stencil_weight(G, particle_stencil(G, body_shapes, P, p), [&](int n, double w) { G.momentum[n] += w * mv; });
  });
  const std::size_t nn = G.node_count();
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t n = 0; n < nn; ++n)
    G.velocity_new[n] = G.mass[n] > 0.0 ? Vec2(G.momentum[n] / G.mass[n]) : Vec2::Zero();
}

namespace {

Mat2 velocity_gradient(const Particles& P, const Grid& G, std::span<const ShapeFunction> body_shapes, std::size_t p) {
  Mat2 L = Mat2::Zero();
  // Nodes with a non-zero gradient only (a zero term could flip the sign of a zero).
  for_each_stencil_gradient(G, particle_stencil(G, body_shapes, P, p), [&](int node, const Vec2& grad) {
    L += G.velocity_new[node] * grad.transpose();
  });
  return L;
}

void advance_deformation_gradient(Particles& P, double dt, std::size_t p) {
  advance_deformation(P, p, P.velocity_gradient[p], dt);
}

}  // namespace

void update_velocity_gradients(Particles& P, const Grid& G, std::span<const ShapeFunction> body_shapes, double dt,
                               bool parallel) {
  const std::size_t n = P.size();
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t p = 0; p < n; ++p) {
    P.velocity_gradient[p] = velocity_gradient(P, G, body_shapes, p);
    advance_deformation_gradient(P, dt, p);
  }
}

void compute_velocity_gradients(Particles& P, const Grid& G, std::span<const ShapeFunction> body_shapes,
                                bool parallel) {
  const std::size_t n = P.size();
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t p = 0; p < n; ++p) P.velocity_gradient[p] = velocity_gradient(P, G, body_shapes, p);
}

void advance_deformation_gradients(Particles& P, double dt, bool parallel) {
  const std::size_t n = P.size();
#pragma omp parallel for schedule(static) if (parallel)
  for (std::size_t p = 0; p < n; ++p) advance_deformation_gradient(P, dt, p);
}

}  // namespace mpmcut
