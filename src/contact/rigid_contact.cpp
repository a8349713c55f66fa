#include "contact/rigid_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/penalty_law.hpp"
#include "core/stencil.hpp"

namespace mpmcut {

namespace {

// The momentum `impulse` the material received from a rigid body this step (and the body's
// `work` on it): the reaction is the force on the body; its work is external work on the material.
void book_contact_impulse(RigidBodyState& body, const Vec2& impulse, double work, double dt, EnergyTotals& energy) {
  body.step_impulse -= impulse;
  body.force = body.step_impulse / dt;
  body.impulse -= impulse;
  body.work += work;
  energy.external_work += work;
}

// Calls visit(p, x, shape, d, normal) for each particle p within two cells of the rigid body's bounding box,
// with its signed distance d from the body's outline (shifted by `shift`) and the outward normal there.
template <class Visit>
void for_each_particle_near(const Particles& P, const Grid& G, std::span<const ShapeFunction> body_shapes,
                            const RigidPolygon& geom, const Vec2& shift, Visit&& visit) {
  const Vec2 lo = geom.lower() + shift - Vec2::Constant(2.0 * G.h), hi = geom.upper() + shift + Vec2::Constant(2.0 * G.h);
  for (std::size_t p = 0; p < P.size(); ++p) {
    const Vec2 x = P.position[p];
    if (x.x() < lo.x() || x.x() > hi.x() || x.y() < lo.y() || x.y() > hi.y()) continue;
    Vec2 normal;
    const double d = geom.signed_distance(x - shift, normal);
    visit(p, x, body_shapes[P.body[p]], d, normal);
  }
}

}  // namespace

NodeRange nodes_near_body(const RigidPolygon& geom, const Vec2& shift, const Grid& G) {
  const Vec2 lo = (geom.lower() + shift - G.origin) / G.h - Vec2::Constant(2.0);
  const Vec2 hi = (geom.upper() + shift - G.origin) / G.h + Vec2::Constant(2.0);
  return {std::max(0, static_cast<int>(std::floor(lo.x()))), std::min(G.nx - 1, static_cast<int>(std::ceil(hi.x()))),
          std::max(0, static_cast<int>(std::floor(lo.y()))), std::min(G.ny - 1, static_cast<int>(std::ceil(hi.y())))};
}

RigidContact::RigidContact(const std::vector<RigidBodySpec>& bodies, const RigidContactSettings& settings)
    : settings_(settings) {
  for (const RigidBodySpec& r : bodies) {
    geometry_.emplace_back(r.polygon, r.rounding_radius);
    friction_.push_back(r.friction);
    heat_share_.push_back(r.friction_heat_share);
    has_friction_ = has_friction_ || r.friction > 0.0;
  }
}

void RigidContact::begin_step(std::vector<RigidBodyState>& bodies) {
  for (auto& r : bodies) r.step_impulse = Vec2::Zero();
  records_.clear();
  heated_ = NodeBox{};
}

// Contact detected from the particles rather than the nodes: a particle is in contact with a rigid
// body when its uGIMP domain reaches the surface (signed distance of its centre d <= lp), fading
// linearly to out of contact at d = lp + contact_distance. A node's contact weight is the share of
// its mass carried by particles in contact, sum S m phi / sum S m, and its normal is the
// mass-weighted mean of their exact surface normals. Both move smoothly with the rigid body across
// the grid, instead of switching when the tool crosses a node line.
void RigidContact::compute_particle_weights(const Particles& P, const Grid& G, std::span<const ShapeFunction> body_shapes,
                                            double inertia_factor, const std::vector<RigidBodyState>& bodies) {
  const std::size_t nn = G.node_count();
  weight_.resize(geometry_.size());
  normal_.resize(geometry_.size());
  const double band = settings_.contact_distance;
  for (std::size_t r = 0; r < geometry_.size(); ++r) {
    std::vector<double>& W = weight_[r];
    std::vector<Vec2>& N = normal_[r];
    W.assign(nn, 0.0);
    N.assign(nn, Vec2::Zero());
    const Vec2 shift = bodies[r].displacement;
    for_each_particle_near(P, G, body_shapes, geometry_[r], shift,
                           [&](std::size_t p, const Vec2& x, const ShapeFunction& shape, double d, const Vec2& normal) {
      const double lp = shape.half_width();
      const double phi = band > 0.0 ? std::clamp(1.0 - (d - lp) / band, 0.0, 1.0) : (d <= lp ? 1.0 : 0.0);
      if (phi <= 0.0) return;
      const double m = inertia_factor * P.mass[p];  // as the grid mass it is compared with
      for_each_stencil_weight(G, stencil_at(G, shape, x), [&](int n, double w) {
        W[n] += w * m * phi;
        N[n] += (w * m * phi) * normal;
      });
    });
  }
}

// Gap detection: where the material really is, at the resolution of its particles. A GIMP particle's
// domain reaches lp beyond its centre, so the material's boundary facing the surface is at d - lp. A node
// takes the smallest gap among the particles its stencil reaches, with the exact outward normal at that
// particle. Unlike the node test there is no band of a fixed fraction of a cell: contact starts when the
// domains touch the surface, on every grid.
void RigidContact::compute_node_gaps(const Particles& P, const Grid& G, std::span<const ShapeFunction> body_shapes,
                                     const std::vector<RigidBodyState>& bodies) {
  const std::size_t nn = G.node_count();
  gap_.resize(geometry_.size());
  normal_.resize(geometry_.size());
  for (std::size_t r = 0; r < geometry_.size(); ++r) {
    std::vector<double>& gap = gap_[r];
    std::vector<Vec2>& N = normal_[r];
    gap.assign(nn, std::numeric_limits<double>::infinity());
    N.assign(nn, Vec2::Zero());
    const Vec2 shift = bodies[r].displacement;
    for_each_particle_near(P, G, body_shapes, geometry_[r], shift,
                           [&](std::size_t, const Vec2& x, const ShapeFunction& shape, double d, const Vec2& normal) {
      const double g = d - shape.half_width();
      if (g > 2.0 * G.h) return;  // no node within reach can need it
      for_each_stencil_weight(G, stencil_at(G, shape, x), [&](int n, double w) {
        if (w > 0.0 && g < gap[n]) {
          gap[n] = g;
          N[n] = normal;
        }
      });
    });
  }
}

// Penalty contact: each particle feels its own contact force, from its own overlap and slip, so the
// tool force follows the material continuously as the tool crosses the grid. The force enters the
// momentum update as an external nodal force (sum over particles of S_ip f_p). Energy: the body's
// work is f . v_body dt; the sliding part of the slip dissipates mu f_n per unit length (frictional
// work, heat); the rest goes into the springs' energy, f^2 / (2 k), a fraction of a per mille of the
// tool's work in a cut. A particle keeps one friction history (contact_friction_force): that of the
// first body in the scene's order it touches; touching another body in the same step, it starts
// afresh there.
void RigidContact::apply_penalty(Particles& P, Grid& G, std::span<const ShapeFunction> body_shapes,
                                 double inertia_factor, double dt, double stable_dt,
                                 std::vector<RigidBodyState>& bodies, EnergyTotals& energy) {
  touched_.assign(P.size(), 0);
  for (std::size_t r = 0; r < geometry_.size(); ++r) {
    const Vec2 shift = bodies[r].displacement;
    const Vec2 vr = bodies[r].velocity;
    const double mu = friction_[r];
    Vec2 impulse = Vec2::Zero();
    double friction_work = 0.0;
    // Particles in index order: deterministic sums.
    for_each_particle_near(P, G, body_shapes, geometry_[r], shift,
                           [&](std::size_t p, const Vec2& x, const ShapeFunction& shape, double d, const Vec2& normal) {
      const double overlap = shape.half_width() - d;
      if (overlap <= 0.0) return;
      const bool first = !touched_[p];
      touched_[p] = 1;
      const double m = inertia_factor * P.mass[p];
      const Stencil stencil = stencil_at(G, shape, x);
      // The slip is the material's as the grid carries it (the P2G velocity at the particle), not the particle's own
      // velocity: that carries sub-grid noise the grid never moves the material with, and a stick spring and its
      // slip work integrated from it booked friction the forces did not do (cut: +0.7 % of the tool's work, pure
      // FLIP +20 %; with the nodal average -0.3 %). docs/cutting.md, "Penalty contact".
      Vec2 material_velocity = Vec2::Zero();
      for_each_stencil_weight(G, stencil, [&](int n, double w) { material_velocity += w * G.velocity[n]; });
      const PenaltyContactForce c =
          penalty_contact_force(overlap, material_velocity - vr, normal, m, dt, settings_.penalty_stiffness, mu,
                                first ? P.contact_friction_force[p] : Vec2::Zero(), stable_dt);
      if (first) P.contact_friction_force[p] = c.friction_force;
      const Vec2 dp = dt * c.force;  // momentum given to the particle's nodes this step
      const double q = c.slip_work;
      for_each_stencil_weight(G, stencil, [&](int n, double w) {
        G.force[n] += w * c.force;
        if (q > 0.0) {
          G.friction_heat[n] += heat_share_[r] * w * q;
          heated_.add(n % G.nx, n / G.nx);
        }
      });
      impulse += dp;
      friction_work += q;
      records_.push_back({static_cast<int>(r), 1, x, normal, dp, c.sliding, q});
    });
    book_contact_impulse(bodies[r], impulse, impulse.dot(vr), dt, energy);
    energy.friction += friction_work;
  }
  for (std::size_t p = 0; p < P.size(); ++p)  // out of contact: the history ends
    if (!touched_[p]) P.contact_friction_force[p] = Vec2::Zero();
}

// The rigid body has infinite mass, so at a contact node only the material's velocity changes.
// Contact holds where the material approaches the rigid surface and its mean position at the node
// lies within contact_distance of it (no one-cell gap), or, with particle detection, on the node's
// contact weight, or, with gap detection, where it approaches faster than its gap closes in the
// step. The normal is the exact outward normal of the rigid outline. Normal approach is removed (gap
// detection: cut to the gap-closing speed); the tangential slip is reduced by at most mu times the
// normal change (Coulomb stick/slip). Nodes with velocity boundary conditions are never changed.
void RigidContact::apply(ContactPass pass, double dt, Grid& G, std::vector<RigidBodyState>& bodies,
                         EnergyTotals& energy) {
  if (geometry_.empty() || settings_.detection == ContactDetection::Penalty) return;
  std::vector<Vec2>& v = pass == ContactPass::AfterP2G ? G.velocity : G.velocity_new;
  const bool accumulate_force = pass != ContactPass::MuslRemap;
  if (pass == ContactPass::AfterUpdate) std::fill(G.in_contact.begin(), G.in_contact.end(), 0);
  const double cutoff = settings_.contact_distance;
  for (std::size_t r = 0; r < geometry_.size(); ++r) {
    const RigidPolygon& geom = geometry_[r];
    const Vec2 shift = bodies[r].displacement;
    const Vec2 vr = bodies[r].velocity;
    const double mu = friction_[r];
    // Only nodes near the rigid body's bounding box can be in contact.
    const auto [i0, i1, j0, j1] = nodes_near_body(geom, shift, G);
    Vec2 impulse = Vec2::Zero();
    double work = 0.0, friction_work = 0.0;
    // Nodes in a fixed order: deterministic sums.
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const int n = G.index(i, j);
        const double m = G.mass[n];
        if (m <= settings_.node_mass_cutoff || (G.fixed[n] & 3)) continue;  // never change BC nodes
        const Vec2 xbar = G.mass_position[n] / m;
        Vec2 normal;
        double weight = 1.0;
        double max_approach = 0.0;  // gap detection: the approach speed that just closes the gap in this step
        if (settings_.detection == ContactDetection::Particle) {
          weight = std::min(1.0, weight_[r][n] / m);
          if (weight <= 0.0) continue;
          const double nn = normal_[r][n].norm();
          if (nn <= 0.0) continue;
          normal = normal_[r][n] / nn;
        } else if (settings_.detection == ContactDetection::Gap) {
          if (!std::isfinite(gap_[r][n])) continue;
          normal = normal_[r][n];
          max_approach = std::max(0.0, gap_[r][n]) / dt;
        } else {
          const double dist = geom.signed_distance(xbar - shift, normal);
          if (dist > cutoff) continue;
        }
        const Vec2 rel = v[n] - vr;
        const double vn = rel.dot(normal);
        if (pass == ContactPass::MuslRemap) {
          // Only where the momentum update found contact, and there whatever the sign: the
          // strain update must see the same constraint that moved the particles (an approach
          // test here lets the strain velocity disagree with the motion and creates energy).
          if (!G.in_contact[n]) continue;
        } else if (vn >= -max_approach) {
          continue;  // separating, or closing no more than the gap
        }
        if (pass == ContactPass::AfterUpdate) G.in_contact[n] = 1;
        const ContactCorrection cc =
            settings_.detection == ContactDetection::Gap
                ? coulomb_rigid_gap_correction(rel, normal, mu, max_approach, pass == ContactPass::MuslRemap)
                : coulomb_rigid_correction(rel, normal, mu, weight);
        const Vec2& new_rel = cc.new_relative;
        const Vec2 dv = new_rel - rel;
        v[n] = vr + new_rel;
        if (accumulate_force) {
          const Vec2 dp = m * dv;  // momentum given to the material by the rigid body
          impulse += dp;
          work += dp.dot(vr);
          // Frictional work = friction impulse x the slip that goes on (Coulomb force times slip
          // distance); sticking does no frictional work. It becomes heat in the deformable body at
          // this node, all of it or the body's friction_heat_share (the rest flows into the rigid body,
          // which is not thermally modelled). The other kinetic energy the correction
          // removes at the node is the velocity jump of imposing contact on the grid; with FLIP
          // it is not lost by the particles, so it is not counted as a dissipation (counting it
          // overstated friction heat and broke the energy balance of a cut by ~15%).
          const double q = m * cc.friction_dv * cc.slip_after;
          records_.push_back(
              {static_cast<int>(r), pass == ContactPass::AfterP2G ? 0 : 1, xbar, normal, dp, cc.sliding, q});
          friction_work += q;
          G.friction_heat[n] += heat_share_[r] * q;
          if (q > 0.0) heated_.add(i, j);
        }
      }
    }
    if (accumulate_force) {
      book_contact_impulse(bodies[r], impulse, work, dt, energy);
      energy.friction += friction_work;
    }
  }
}

// Possible at a sharp edge, where neighbouring nodes have different normals. The momentum the
// safeguard takes counts as contact impulse on the rigid body, like the grid corrections.
void RigidContact::push_particles_out(Particles& P, std::vector<Vec2>& position_new, double dt, double inertia_factor,
                                      double cell_size, bool parallel, std::vector<RigidBodyState>& bodies,
                                      EnergyTotals& energy) {
  const std::size_t n = P.size();
  for (std::size_t r = 0; r < geometry_.size(); ++r) {
    const RigidPolygon& geom = geometry_[r];
    const Vec2 shift = bodies[r].displacement + dt * bodies[r].velocity;  // where it is at the end of the step
    const Vec2 lo = geom.lower() + shift, hi = geom.upper() + shift;
    const Vec2 vr = bodies[r].velocity;
    std::vector<std::size_t> inside;
#pragma omp parallel if (parallel)
    {
      std::vector<std::size_t> mine;
#pragma omp for schedule(static) nowait
      for (std::size_t p = 0; p < n; ++p) {
        const Vec2 x = position_new[p];
        if (x.x() < lo.x() || x.x() > hi.x() || x.y() < lo.y() || x.y() > hi.y()) continue;
        Vec2 normal;
        if (geom.signed_distance(x - shift, normal) < 0.0) mine.push_back(p);
      }
#pragma omp critical
      inside.insert(inside.end(), mine.begin(), mine.end());
    }
    std::sort(inside.begin(), inside.end());  // fixed order: deterministic sums
    Vec2 impulse = Vec2::Zero();
    double work = 0.0, lost = 0.0;
    for (std::size_t p : inside) {
      Vec2 normal;
      const double d = geom.signed_distance(position_new[p] - shift, normal);
      position_new[p] -= (d - 1e-9 * cell_size) * normal;  // onto the surface, a hair outside
      const double vn = (P.velocity[p] - vr).dot(normal);
      if (vn < 0.0) {
        const Vec2 dp = -inertia_factor * P.mass[p] * vn * normal;
        P.velocity[p] -= vn * normal;
        impulse += dp;
        records_.push_back({static_cast<int>(r), 2, position_new[p], normal, dp, false});
        work += dp.dot(vr);
        // Removing the approach velocity relative to the body is a perfectly inelastic impact:
        // the particle's kinetic energy changes by dp.vr - m vn^2 / 2, so m vn^2 / 2 is lost.
        lost += 0.5 * inertia_factor * P.mass[p] * vn * vn;
      }
      ++pushed_out_;
    }
    book_contact_impulse(bodies[r], impulse, work, dt, energy);
    energy.contact_safeguard += lost;
  }
}

}  // namespace mpmcut
