#pragma once
// Multi-velocity-field contact between the deformable material on the grid and rigid bodies
// ([Bardenhagen2000]; the rigid form of [Nairn2013]): the nodal Coulomb law of contact_law.hpp applied
// at the nodes near each rigid body, the impulse and work it exchanges with each body, the
// frictional work it leaves on the nodes (frictional_heating.hpp turns it into heat), a record of
// what it did, and the particle push-out safeguard behind it. docs/cutting.md, "Contact".
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "contact/contact_law.hpp"
#include "contact/rigid_body.hpp"
#include "contact/rigid_polygon.hpp"
#include "core/energy_totals.hpp"
#include "core/grid.hpp"
#include "core/particles.hpp"
#include "core/scene_specs.hpp"
#include "physics/material_parameters.hpp"
#include "core/shape_functions.hpp"

namespace mpmcut {

// When in the step the nodal law acts: on the P2G velocity (grid.velocity), on the velocity after
// the momentum update (grid.velocity_new), and on the MUSL re-mapped velocity (grid.velocity_new).
enum class ContactPass { AfterP2G, AfterUpdate, MuslRemap };

// A box of grid nodes in node indices (empty while lo > hi).
struct NodeBox {
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::max());
  Vec2 hi = Vec2::Constant(-std::numeric_limits<double>::max());
  bool empty() const { return lo.x() > hi.x(); }
  void add(int i, int j) {
    lo = lo.cwiseMin(Vec2(i, j));
    hi = hi.cwiseMax(Vec2(i, j));
  }
};

// The grid nodes (i0..i1, j0..j1) that can touch a rigid body: its bounding box, displaced by shift,
// plus two cells, clipped to the grid.
struct NodeRange {
  int i0, i1, j0, j1;
};
NodeRange nodes_near_body(const RigidPolygon& geom, const Vec2& shift, const Grid& grid);

struct RigidContactSettings {
  double contact_distance = 0.0;    // m: a node's material within this of the surface can be in contact
  ContactDetection detection = ContactDetection::Node;
  double node_mass_cutoff = 0.0;    // kg/m: lighter nodes count as empty
  double penalty_stiffness = 1.0;   // penalty detection: k = this x m / dt_stable^2 (penalty_law.hpp)
};

class RigidContact {
 public:
  RigidContact() = default;
  RigidContact(const std::vector<RigidBodySpec>& bodies, const RigidContactSettings& settings);

  bool empty() const { return geometry_.empty(); }
  bool has_friction() const { return has_friction_; }
  // Body r's outline at t = 0; at time t it is displaced by its state's displacement.
  const RigidPolygon& geometry(std::size_t r) const { return geometry_[r]; }

  // Start of a step: zero each body's step impulse, forget the last step's records and heated nodes.
  void begin_step(std::vector<RigidBodyState>& bodies);

  // Particle detection (before the first pass): each node's contact weight, the share of its mass
  // carried by particles in contact, and their mean surface normal.
  void compute_particle_weights(const Particles& particles, const Grid& grid, std::span<const ShapeFunction> body_shapes,
                                double inertia_factor, const std::vector<RigidBodyState>& bodies);

  // Gap detection (before the first pass): per node, the gap between the rigid surface and the nearest
  // particle domain that the node's stencil reaches (signed distance of the particle's centre minus its
  // half-width lp; <= 0: touching or overlapping), and that surface's outward normal.
  void compute_node_gaps(const Particles& particles, const Grid& grid, std::span<const ShapeFunction> body_shapes,
                         const std::vector<RigidBodyState>& bodies);

  // Penalty contact (instead of the nodal passes, after P2G): the force of penalty_law.hpp on every
  // particle whose domain reaches into a rigid body, spread onto the grid's force by the particle's
  // weights; the reaction on the body, its work, the frictional work (on grid.friction_heat) and one
  // record per particle in contact; each particle's contact_friction_force carries its stick history.
  // The slip is the grid's P2G velocity at the particle relative to the body (grid.velocity must hold it).
  // stable_dt: the step's stable (CFL) step, which sets the springs' stiffness (penalty_law.hpp), dt <= stable_dt.
  void apply_penalty(Particles& particles, Grid& grid, std::span<const ShapeFunction> body_shapes,
                     double inertia_factor, double dt, double stable_dt, std::vector<RigidBodyState>& bodies,
                     EnergyTotals& energy);

  // One pass of the nodal law on the pass's grid velocity. The passes after P2G and after the
  // momentum update (whose corrections reach the particles) record the impulse on each body, its
  // work and the frictional work (on grid.friction_heat); the step's force is both passes' impulses
  // (and the safeguard's) over dt.
  void apply(ContactPass pass, double dt, Grid& grid, std::vector<RigidBodyState>& bodies, EnergyTotals& energy);

  // The safeguard behind the grid contact, after G2P: a particle whose new position lies inside a
  // rigid body is put back on its surface and its approach velocity removed.
  void push_particles_out(Particles& particles, std::vector<Vec2>& position_new, double dt, double inertia_factor,
                          double cell_size, bool parallel, std::vector<RigidBodyState>& bodies, EnergyTotals& energy);

  // What the contact did this step: one record per contact node and pass, and per particle the
  // safeguard moved. Diagnostics, not restart state.
  const std::vector<ContactRecord>& records() const { return records_; }
  // Nodes with frictional work this step (grid.friction_heat > 0 only inside).
  const NodeBox& heated_nodes() const { return heated_; }
  // Particle corrections by the safeguard since the start (diagnostics, not restart state).
  long pushed_out_particles() const { return pushed_out_; }

 private:
  std::vector<RigidPolygon> geometry_;  // outlines at t = 0; current = outline + displacement
  std::vector<double> friction_;        // Coulomb coefficient per body
  std::vector<double> heat_share_;      // share of the frictional work that heats the material, per body
  bool has_friction_ = false;
  RigidContactSettings settings_;
  std::vector<std::vector<double>> weight_;  // particle detection: per body, per node: sum S m phi, kg/m
  std::vector<std::vector<Vec2>> normal_;    // per body, per node: sum S m phi n (particle); the normal (gap)
  std::vector<std::vector<double>> gap_;     // gap detection: per body, per node: nearest domain's gap, m
  std::vector<std::uint8_t> touched_;         // penalty detection: per particle, in contact this step
  std::vector<ContactRecord> records_;
  NodeBox heated_;
  long pushed_out_ = 0;
};

}  // namespace mpmcut
