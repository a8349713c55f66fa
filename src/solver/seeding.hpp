#pragma once
// The particles a scene starts with.
#include "core/grid.hpp"
#include "core/particles.hpp"
#include "solver/scene.hpp"

namespace mpmcut {

// Fills each body with particles on a regular sub-grid aligned with the background grid:
// particles_per_cell per direction per cell, each owning a square of side h/ppc (its uGIMP
// domain), at the body's velocity and temperature. Throws std::invalid_argument for a body whose
// material the scene does not have.
void seed_particles(const Scene& scene, const Grid& grid, Particles& particles);

}  // namespace mpmcut
