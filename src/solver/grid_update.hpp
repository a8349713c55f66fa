#pragma once
// The grid stage of the step: the domain's boundary flags on the nodes, velocity boundary
// conditions, and the explicit momentum update.
#include "core/grid.hpp"
#include "solver/scene.hpp"

namespace mpmcut {

// Marks the nodes on each domain side and on the padding beyond it: velocity constraints
// (grid.fixed bits 0, 1) and fixed temperatures (bit 2, grid.fixed_temperature).
void mark_boundary_nodes(const BoundarySpec& velocity, const ThermalSpec& temperature, Grid& grid);

// Which velocities the constraints act on: the P2G velocity (the raw P2G momentum stays, so that
// FLIP sees the constraint as a change), or the updated velocity and the force.
enum class BoundaryPhase { AfterP2G, AfterUpdate };

// Zeroes the constrained velocity components at fixed and roller nodes.
void apply_velocity_boundary_conditions(BoundaryPhase phase, bool parallel, Grid& grid);

// velocity_new = velocity + dt f / m, then the boundary conditions. From the velocity (which
// carries the first contact pass), not the raw P2G momentum. Nodes lighter than node_mass_cutoff
// keep their velocity: a / m there would be noise.
void update_grid_momentum(double dt, double node_mass_cutoff, bool parallel, Grid& grid);

}  // namespace mpmcut
