#pragma once
// The regular background grid: node arrays (structure of arrays), padded with empty
// cells beyond the domain so that every GIMP stencil of a particle inside the domain is
// complete (pitfall: a truncated stencil loses mass).
#include <cstdint>
#include <vector>

#include "core/scene_specs.hpp"
#include "core/tensor.hpp"

namespace mpmcut {

struct Grid {
  static constexpr int kPadding = 3;  // cells beyond the domain on every side

  double h = 0.0;              // cell size, m
  Vec2 origin = Vec2::Zero();  // position of node (0, 0), m
  int nx = 0, ny = 0;          // nodes per direction
  Vec2 domain_min = Vec2::Zero(), domain_max = Vec2::Zero();  // the user's domain, whole cells, m

  // Nodal fields of the (single) deformable velocity field.
  std::vector<double> mass;            // kg/m
  std::vector<Vec2> momentum;          // kg/s (per m), after P2G
  std::vector<Vec2> force;             // N/m, internal + external
  std::vector<Vec2> velocity;          // m/s, before the momentum update
  std::vector<Vec2> velocity_new;      // m/s, after the momentum update (and contact)
  std::vector<Vec2> mass_position;     // sum S m x, for the contact position check, kg m/m
  // Thermal fields
  std::vector<double> heat_capacity;   // sum S m c, J/(K m)
  std::vector<double> temperature;     // K
  std::vector<double> heat_rate;       // W/m
  std::vector<double> friction_heat;   // J/m, frictional work at rigid contacts this step
  // Heat sinks of the conduction update (rigid bodies with a heat transfer coefficient): conductance
  // to the body, W/(K m), and its temperature, K. Filled by mark_heat_sinks (contact/rigid_heat_transfer)
  // on the steps that conduct; empty when no rigid body exchanges heat.
  std::vector<double> sink_conductance;
  std::vector<double> sink_temperature;
  // Heat each sink node gave to the rigid bodies in the last conduction update, J/m (filled by conduct_heat).
  std::vector<double> sink_heat;
  // Boundary flags: bit 0 = x velocity fixed, bit 1 = y velocity fixed; bits 2.. = fixed temperature
  std::vector<std::uint8_t> in_contact;  // 1 where rigid contact acted after the momentum update
  std::vector<std::uint8_t> fixed;
  std::vector<double> fixed_temperature;  // K, where bit 2 is set

  void build(const GridSpec& spec);
  int index(int i, int j) const { return j * nx + i; }
  Vec2 node_position(int i, int j) const { return origin + h * Vec2(i, j); }
  std::size_t node_count() const { return mass.size(); }
  void reset();  // zeroes all accumulated fields (not the boundary flags)
};

}  // namespace mpmcut
