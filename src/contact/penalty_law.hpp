#pragma once
// The particle-level penalty law between a deformable particle and a rigid surface
// (solver.contact_detection = "penalty"; docs/cutting.md, "Penalty contact"): a normal spring on the
// overlap of the particle's domain with the body, and Coulomb friction capped at mu times that spring
// force. It acts on each particle from its own position and velocity, so the force moves smoothly with
// the body across the grid instead of switching when the body crosses a node line (the nodal law's
// cell-crossing noise), and the contact starts where the material's domains touch the surface.
#include <algorithm>
#include <cmath>

#include "core/tensor.hpp"

namespace mpmcut {

struct PenaltyContactForce {
  Vec2 force = Vec2::Zero();           // on the particle, N per m of thickness
  Vec2 friction_force = Vec2::Zero();  // its tangential part, the next step's `previous_friction`, N/m
  double normal_force = 0.0;           // >= 0, N/m
  bool sliding = false;                // Coulomb limit reached: the slip goes on
  double slip_work = 0.0;              // frictional dissipation in the step, mu f_n times the slip, J/m
};

// overlap: how far the particle's domain reaches into the body, m (its half-width minus the signed
// distance of its centre; <= 0: no contact). rel: the material's velocity at the particle relative to the
// body's, m/s (the solver passes the grid's velocity there, not the particle's own: rigid_contact.cpp).
// normal: the body's unit outward normal at the particle. mass: the particle's inertial mass, kg/m.
// previous_friction: the friction force of its last step (zero when it was out of contact).
// spring_dt: the step that sets the springs (0: dt). The solver passes its stable step, so that k does not jump on
// the steps shortened to land on an output time (up to 4x on every history row with k from dt; the overlap built
// at the old k then pushed back harder, force noise and energy the ledger did not book); dt <= spring_dt keeps
// k dt^2 <= stiffness mass, the stable range.
// Both directions are springs of stiffness k = stiffness mass / spring_dt^2: the normal force is k times the
// overlap; the friction force is the previous one (in the current tangent) plus k times this step's
// slip v_t dt against it (elastic stick), returned onto mu f_n where it would exceed it (slide: the
// slip beyond the spring's is real sliding and dissipates mu f_n per unit length). The stick spring
// is what lets a sticking particle carry the interface's whole shear with a slip of f_t / k (a few
// nanometres in a cut); a force that only stopped the step's slip (m v_t / dt) would let the chip
// creep along the face at 2 C tau / (rho c), about 15 m/s for Ti-6Al-4V at tau = 500 MPa.
inline PenaltyContactForce penalty_contact_force(double overlap, const Vec2& rel, const Vec2& normal, double mass,
                                                 double dt, double stiffness, double mu,
                                                 const Vec2& previous_friction = Vec2::Zero(), double spring_dt = 0.0) {
  PenaltyContactForce c;
  if (overlap <= 0.0) return c;
  const double t_k = spring_dt > 0.0 ? spring_dt : dt;
  const double k = stiffness * mass / (t_k * t_k);
  c.normal_force = k * overlap;
  const Vec2 vt = rel - rel.dot(normal) * normal;
  const Vec2 trial = previous_friction - previous_friction.dot(normal) * normal - (k * dt) * vt;
  const double trial_norm = trial.norm(), limit = mu * c.normal_force;
  c.sliding = trial_norm > limit;
  c.friction_force = c.sliding ? Vec2((limit / trial_norm) * trial) : trial;
  c.slip_work = c.sliding ? limit * (trial_norm - limit) / k : 0.0;
  c.force = c.normal_force * normal + c.friction_force;
  return c;
}

}  // namespace mpmcut
