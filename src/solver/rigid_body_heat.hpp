#pragma once
// The heat a conducting rigid body (the cutting tool) exchanges with the material. Its cells
// (thermal/body_conduction) are built from its outline; at each conduction update the heat-sink nodes
// (contact/rigid_heat_transfer) take the body's temperature in the surface cell under them, and the
// heat they gave (grid.sink_heat) goes into that cell, after which the body's field advances over the
// update's time. docs/cutting.md, "Contact", item 7.
#include <vector>

#include "contact/rigid_body.hpp"
#include "contact/rigid_heat_transfer.hpp"
#include "contact/rigid_polygon.hpp"
#include "core/grid.hpp"
#include "core/scene_specs.hpp"
#include "thermal/body_conduction.hpp"

namespace mpmcut {

// The body's cells: its outline's box in cells of size h. A cell whose centre lies inside the outline
// conducts; it is held where that centre lies within one cell of a face in spec.held_faces.
BodyConduction make_body_conduction(const RigidBodySpec& spec, double h);

class RigidBodyHeat {
 public:
  RigidBodyHeat() = default;
  RigidBodyHeat(const std::vector<RigidBodySpec>& specs, double h);

  bool any() const { return any_; }
  const BodyConduction& body(std::size_t r) const { return bodies_[r]; }
  // The fields at t = 0 (empty for bodies that do not conduct).
  void start(std::vector<RigidBodyState>& bodies) const;
  // Throws std::invalid_argument where a restored body's field does not fit its cells.
  void check(const std::vector<RigidBodyState>& bodies) const;
  // For mark_heat_sinks: each conducting body's surface temperature at a node, from the cell half a cell
  // inside its outline under the node (remembered for deposit_and_advance).
  SurfaceTemperature surface_temperature(const std::vector<RigidBodyState>& bodies);
  // After mark_heat_sinks, for a transient body: the exchange between a node and the cell under it made implicit
  // in the cell's temperature too (the node's conductance g becomes g / (1 + G dt / C), G the cell's conductance
  // to all its nodes, C its heat capacity), so that a cell of small heat capacity cannot overshoot its nodes.
  void couple_implicitly(Grid& grid, double dt);
  // After conduct_heat: the heat each sink node gave goes into its cell (shared between bodies by their
  // conductances there), and every conducting body's field advances over dt.
  void deposit_and_advance(const Grid& grid, std::vector<RigidBodyState>& bodies, double dt);

 private:
  struct Link {
    int node = 0, cell = 0;
    double conductance = 0.0;  // W/(K m), this body's part of the node's
  };
  bool any_ = false;
  std::vector<BodyConduction> bodies_;  // inactive where a body does not conduct
  std::vector<char> steady_;             // a conducting body without heat capacity
  std::vector<double> averaging_time_;   // s, of a steady body's heat input
  std::vector<std::vector<Link>> links_;
  std::vector<double> heat_;  // scratch: J/m per cell
  std::vector<double> conductance_, unit_, rise_;  // scratch of stable_average_weight, per cell
  // The largest weight of one update in steady body r's input average that cannot overshoot (from its links).
  double stable_average_weight(std::size_t r);
};

}  // namespace mpmcut
