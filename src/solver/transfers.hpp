#pragma once
// The particle-grid transfers of the explicit step, as free functions over particles and grid:
// P2G, G2P (FLIP/PIC blend), the MUSL momentum remap and the velocity gradient. Each particle uses
// its body's shape function (core/stencil.hpp); masses are inertial (mass scaling factor f, see
// docs/mass_scaling.md), heat capacities use the true mass. Scatters run in the strips of a
// StripColouring, so results do not depend on the number of threads.
#include <span>
#include <vector>

#include "core/grid.hpp"
#include "core/particles.hpp"
#include "solver/scene.hpp"
#include "core/shape_functions.hpp"
#include "core/strip_colouring.hpp"

namespace mpmcut {

// What P2G maps besides mass, momentum and force.
struct P2GFields {
  bool mass_position = false;  // sum S m x: the rigid contact's position check
  bool heat_capacity = false;  // sum S m c: conduction or frictional heating this step
  bool temperature = false;    // sum S m c T / sum S m c: conduction this step (needs heat_capacity)
};

// Resets the grid and maps mass, momentum, internal force -V sigma grad S plus body force, and `fields`, in the
// strips of `colouring` (bucketed for these positions); then the nodal velocity (and temperature).
// `node_mean_stress` non-empty (volumetric_average.hpp): the in-plane mean stress in sigma is replaced by
// (m_p / V_p) sum_n S_pn node_mean_stress[n].
void particles_to_grid(const Particles& particles, std::span<const ShapeFunction> body_shapes,
                       const std::vector<MaterialParameters>& materials, double inertia_factor, const Vec2& body_force,
                       P2GFields fields, std::span<const double> node_mean_stress, bool parallel,
                       const StripColouring& colouring, Grid& grid);

// Particle velocity from the updated grid velocity as the FLIP/PIC blend (flip fraction), and the
// new position x + dt v_PIC into position_new. transfer_loss[p] receives the kinetic energy the
// blend took from particle p (J/m; docs/cutting.md, "Energy balance").
void grid_to_particles(Particles& particles, const Grid& grid, std::span<const ShapeFunction> body_shapes,
                       double inertia_factor, double flip, double dt, bool parallel, std::vector<Vec2>& position_new,
                       std::vector<double>& transfer_loss);

// MUSL: the updated particle momenta mapped back to the grid with this step's weights (the
// colouring from P2G), and the grid velocity they give (grid.velocity_new).
void remap_momentum_musl(const Particles& particles, std::span<const ShapeFunction> body_shapes, double inertia_factor,
                         const StripColouring& colouring, bool parallel, Grid& grid);

// Velocity gradient L = sum v_I grad S_I^T from grid.velocity_new, and with it the deformation
// gradient F <- (I + dt L) F and the volume V <- det(I + dt L) V of every particle (core/particles.hpp).
void update_velocity_gradients(Particles& particles, const Grid& grid, std::span<const ShapeFunction> body_shapes,
                               double dt, bool parallel);

// The same in two halves, for a change of L in between (volumetric_average.hpp): L only, then F and V from it.
void compute_velocity_gradients(Particles& particles, const Grid& grid, std::span<const ShapeFunction> body_shapes,
                                bool parallel);
void advance_deformation_gradients(Particles& particles, double dt, bool parallel);

}  // namespace mpmcut
