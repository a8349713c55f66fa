#pragma once
// Explicit heat conduction on the grid (Nairn's transport task structure), sub-cycled: its
// explicit limit h^2/(4 alpha) is thousands of mechanical steps for metals, so it runs once per
// kSubsteps mechanical steps (or sooner, before the limit is reached) over the time they covered.
#include <optional>
#include <span>
#include <vector>

#include "core/grid.hpp"
#include "core/particles.hpp"
#include "core/scene_specs.hpp"
#include "physics/material_parameters.hpp"
#include "core/shape_functions.hpp"
#include "core/strip_colouring.hpp"

namespace mpmcut {

// Where the sub-cycle stands (restart state): mechanical time and steps since the last update.
struct ConductionSubcycle {
  double elapsed = 0.0;  // s
  int steps = 0;
};

class SubcycledConduction {
 public:
  static constexpr int kSubsteps = 16;

  SubcycledConduction() = default;
  // enabled: the scene's thermal.conduction; the limit comes from the conducting materials.
  SubcycledConduction(bool enabled, const std::vector<MaterialParameters>& materials, double cell_size, double cfl);

  bool enabled() const { return enabled_; }
  // Explicit conduction step limit cfl h^2/(4 alpha) over the materials (infinite if none conducts), s.
  double time_step_limit() const { return limit_; }

  // At the start of a step of dt: counts the step and says whether the step ends with a conduction
  // update (P2G must then map the temperatures).
  bool begin_step(ConductionSubcycle& s, double dt) const {
    return enabled_ && (++s.steps >= kSubsteps || s.elapsed + 2 * dt > limit_);
  }
  // At the end of the step: adds dt to the elapsed time; when the update is due, returns the time
  // to conduct over and starts a new sub-cycle.
  std::optional<double> end_step(ConductionSubcycle& s, double dt, bool due) const;

 private:
  bool enabled_ = false;
  double limit_ = 0.0;
};

// Storage that conduct_heat reuses from one update to the next (resized on use): the per-node
// range of old particle temperatures and the per-particle heat cut by the bound.
struct ConductionScratch {
  std::vector<double> node_low;   // K, then J/m (the nodal shares of the cut heat)
  std::vector<double> node_high;  // K, then J/(K m) (the uncut particles' heat capacity)
  std::vector<double> cut_heat;   // J/m per particle
  // At fixed-temperature nodes: the sums of w m c (x_p - x_node), J m/(K m), and of w m c grad T_p,
  // J/(m^2 m) (empty where no node is fixed).
  std::vector<Vec2> face_offset;
  std::vector<Vec2> face_gradient;
  std::vector<double> sink_cut;  // per sink node: the shares of the heat the bound cut there, J/m
};

// One explicit conduction update over dt: nodal temperatures (from P2G) and heat capacities, the
// conductive nodal heat rate -sum V k gradS . gradT_p, fixed-temperature nodes, and temperature
// increments (not values) back to the particles so the field is not smeared. A fixed node's value
// holds at the node; its P2G value, a mean over the particles on one side of it, is brought to the
// mean of the field through that value (see the .cpp). An increment that
// would take a particle outside the range of the temperatures around it (the old ones of the
// particles sharing its nodes, its nodes' new and sink temperatures) is cut back to it, and the heat
// cut is taken from the particles that share the nodes (conservative). `colouring` holds this
// step's strips (particles not moved since P2G). Returns the heat that flowed into the heat sinks (rigid
// bodies with a heat transfer coefficient) over dt, J/m: what the particles lost to them, exactly; grid.sink_heat
// holds it node by node.
double conduct_heat(Particles& particles, Grid& grid, std::span<const ShapeFunction> body_shapes,
                    const std::vector<MaterialParameters>& materials, const StripColouring& colouring, bool parallel,
                    double dt, ConductionScratch& scratch);

}  // namespace mpmcut
