#pragma once
// Frictional work found at rigid contact nodes (grid.friction_heat, left by RigidContact::apply)
// heats the particles there. docs/cutting.md, "Contact", item 6.
#include <span>
#include <vector>

#include "contact/rigid_contact.hpp"
#include "core/grid.hpp"
#include "core/particles.hpp"
#include "core/scene_specs.hpp"
#include "physics/material_parameters.hpp"
#include "core/shape_functions.hpp"

namespace mpmcut {

// Node i's heat q_i goes to particle p in proportion to S_ip m_p c_p, so that
// sum_p m_p c_p dT_p = sum_i q_i exactly. The workpiece surface cannot be heated by friction beyond
// its melting temperature: a molten film would carry no shear, so that part of the frictional heat
// is taken to flow into the tool (it stays in the friction work, not in the workpiece's heat).
// `heated` bounds the nodes with heat; `deposited` is scratch (per particle, J/m). Returns the heat
// the particles took, J/m. Needs grid.heat_capacity from this step's P2G.
double deposit_frictional_heat(Particles& particles, const Grid& grid, std::span<const ShapeFunction> body_shapes,
                               const std::vector<MaterialParameters>& materials, const NodeBox& heated,
                               std::vector<double>& deposited, bool parallel);

}  // namespace mpmcut
