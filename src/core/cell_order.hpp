#pragma once
// Particle order in memory that follows the grid: neighbours in space are neighbours in memory,
// which keeps the transfers cache friendly.
#include "core/grid.hpp"
#include "core/particles.hpp"

namespace mpmcut {

// Reorders the particles by cell, row-major (stable: particles of one cell keep their order).
void sort_particles_by_cell(Particles& particles, const Grid& grid);

}  // namespace mpmcut
