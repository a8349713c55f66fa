#pragma once
// The nodal contact law between a deformable body and a rigid body (multi-velocity-field
// contact, Bardenhagen et al. 2000; rigid form as in Nairn 2013), and the per-node record of
// what it did, which outputs read (tool-chip contact length, rake-face normal and friction force).
#include <algorithm>
#include <cmath>

#include "core/tensor.hpp"

namespace mpmcut {

// Result of imposing contact on the material's velocity relative to the rigid body.
struct ContactCorrection {
  Vec2 new_relative = Vec2::Zero();  // relative velocity after contact, m/s
  bool sliding = false;              // Coulomb limit reached: the slip goes on
  double friction_dv = 0.0;          // size of the tangential velocity change at the node, m/s
  double slip_after = 0.0;           // slip speed of the material in contact after the change, m/s
};

// Removes the normal component vn of the relative velocity `rel` (callers apply it where vn < 0,
// the approach, or where an earlier pass found contact) and reduces the tangential
// slip by at most mu |vn| (Coulomb: the friction impulse is at most mu times the normal impulse
// at the node; below that the node sticks). `normal` is the rigid body's unit outward normal.
// With weight w in (0, 1], the share of the node's mass that is in contact, the law acts on that
// share: the fraction w of the normal approach is removed, and friction can at most stop the
// fraction w of the slip (sticking brings the contacting mass, not the whole node, to the rigid
// body's tangential velocity). With w = 1 this is the plain nodal law.
inline ContactCorrection coulomb_rigid_correction(const Vec2& rel, const Vec2& normal, double mu, double w = 1.0) {
  const double vn = rel.dot(normal);
  const Vec2 vt = rel - vn * normal;
  const double vt_norm = vt.norm();
  const double dvn = w * std::abs(vn);                   // size of the normal velocity change
  const double reduction = std::min(w * vt_norm, mu * dvn);  // |dv_t| <= mu |dv_n|
  ContactCorrection c;
  c.sliding = w * vt_norm > mu * dvn;
  c.friction_dv = reduction;
  c.slip_after = w > 0.0 ? std::max(0.0, vt_norm - reduction / w) : vt_norm;
  c.new_relative = rel - (w * vn) * normal - (vt_norm > 0.0 ? Vec2((reduction / vt_norm) * vt) : Vec2::Zero());
  return c;
}

// Contact with a gap (ContactDetection::Gap): the material may approach the rigid surface at up to
// `max_approach` (m/s, >= 0: the gap over the step), not faster. Where it approaches faster, the normal
// velocity is raised to -max_approach; where `force`, it is set to -max_approach whatever its sign (the
// MUSL re-map of a node the momentum update constrained). Friction is Coulomb on that normal change: the
// slip is reduced by at most mu |dv_n|, to sticking at most.
inline ContactCorrection coulomb_rigid_gap_correction(const Vec2& rel, const Vec2& normal, double mu,
                                                      double max_approach, bool force = false) {
  const double vn = rel.dot(normal);
  const double vn_new = force ? -max_approach : std::max(vn, -max_approach);
  const Vec2 vt = rel - vn * normal;
  const double vt_norm = vt.norm();
  const double dvn = std::abs(vn_new - vn);
  const double reduction = std::min(vt_norm, mu * dvn);
  ContactCorrection c;
  c.sliding = vt_norm > mu * dvn;
  c.friction_dv = reduction;
  c.slip_after = vt_norm - reduction;
  c.new_relative = vn_new * normal + (vt_norm > 0.0 ? Vec2(vt * (1.0 - reduction / vt_norm)) : Vec2::Zero());
  return c;
}

// What the contact did at one grid node (or, for the safeguard, one particle) in one step.
struct ContactRecord {
  int rigid_body = 0;           // index into the scene's rigid bodies
  int pass = 0;                 // 0: after P2G, 1: after the momentum update, 2: particle safeguard
  Vec2 position = Vec2::Zero(); // mass-weighted material position at the node (particle position), m
  Vec2 normal = Vec2::Zero();   // rigid body's unit outward normal there
  Vec2 impulse = Vec2::Zero();  // momentum given to the material, N s per m of thickness
  bool sliding = false;         // Coulomb limit reached (slip goes on)
  double friction_work = 0.0;   // frictional dissipation here in the step (the ledger's friction term), J/m
};

}  // namespace mpmcut
