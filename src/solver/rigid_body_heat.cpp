#include "solver/rigid_body_heat.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace mpmcut {

BodyConduction make_body_conduction(const RigidBodySpec& spec, double h) {
  const RigidPolygon outline(spec.polygon, spec.rounding_radius);
  const Vec2 origin = outline.lower();
  const int nx = std::max(1, static_cast<int>(std::ceil((outline.upper().x() - origin.x()) / h)));
  const int ny = std::max(1, static_cast<int>(std::ceil((outline.upper().y() - origin.y()) / h)));
  const std::vector<Vec2>& v = spec.polygon.vertices;
  double twice_area = 0.0;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2& a = v[k];
    const Vec2& b = v[(k + 1) % v.size()];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  const double outward = twice_area >= 0.0 ? 1.0 : -1.0;  // counter-clockwise: the right-hand normal points out
  const double r = spec.rounding_radius;
  std::vector<BodyCell> kinds(static_cast<std::size_t>(nx) * ny, BodyCell::Outside);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const Vec2 c = origin + h * Vec2(i + 0.5, j + 0.5);
      if (!outline.inside(c)) continue;
      BodyCell kind = BodyCell::Conducting;
      for (const int f : spec.held_faces) {
        const Vec2& a = v[f];
        const Vec2& b = v[(f + 1) % v.size()];
        const double length = (b - a).norm();
        const Vec2 along = (b - a) / length, normal = outward * Vec2(along.y(), -along.x());
        const double s = (c - a).dot(normal), t = (c - a).dot(along);
        if (t >= -h && t <= length + h && s >= r - h && s <= r) kind = BodyCell::Held;
      }
      kinds[static_cast<std::size_t>(j) * nx + i] = kind;
    }
  }
  return BodyConduction(origin, nx, ny, h, std::move(kinds), spec.conductivity, spec.volumetric_heat_capacity,
                        spec.temperature);
}

RigidBodyHeat::RigidBodyHeat(const std::vector<RigidBodySpec>& specs, double h)
    : bodies_(specs.size()), steady_(specs.size(), 0), averaging_time_(specs.size(), 0.0), links_(specs.size()) {
  for (std::size_t r = 0; r < specs.size(); ++r) {
    if (specs[r].conductivity <= 0.0) continue;
    bodies_[r] = make_body_conduction(specs[r], h);
    steady_[r] = specs[r].volumetric_heat_capacity <= 0.0;
    averaging_time_[r] = specs[r].heat_averaging_time;
    // Factorised here, so that a body its held faces do not reach is refused before the run.
    if (steady_[r]) {
      std::vector<double> field = bodies_[r].initial_field();
      try {
        bodies_[r].steady_field(std::vector<double>(bodies_[r].cell_count(), 0.0), field);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(fmt::format("rigid body \"{}\" (held_faces = [{}]): {}", specs[r].name,
                                                fmt::join(specs[r].held_faces, ", "), e.what()));
      }
    }
    any_ = true;
  }
}

void RigidBodyHeat::start(std::vector<RigidBodyState>& bodies) const {
  for (std::size_t r = 0; r < bodies_.size(); ++r) {
    bodies[r].temperature_field = bodies_[r].active() ? bodies_[r].initial_field() : std::vector<double>{};
    bodies[r].heat_input_average.assign(steady_[r] ? bodies_[r].cell_count() : 0, 0.0);
  }
}

void RigidBodyHeat::check(const std::vector<RigidBodyState>& bodies) const {
  for (std::size_t r = 0; r < bodies_.size(); ++r) {
    const std::size_t cells = bodies_[r].active() ? static_cast<std::size_t>(bodies_[r].cell_count()) : 0;
    if (bodies[r].temperature_field.size() != cells || bodies[r].heat_input_average.size() != (steady_[r] ? cells : 0))
      throw std::invalid_argument(fmt::format("rigid body \"{}\": the restart state holds a temperature field of {} "
                                              "cells, the scene's body has {}",
                                              bodies[r].name, bodies[r].temperature_field.size(), cells));
  }
}

SurfaceTemperature RigidBodyHeat::surface_temperature(const std::vector<RigidBodyState>& bodies) {
  for (auto& l : links_) l.clear();
  return [this, &bodies](std::size_t r, int node, const Vec2& x_body, double distance, const Vec2& normal,
                         double conductance) {
    const BodyConduction& body = bodies_[r];
    // Half a cell inside the outline under the node: the body's surface cell there.
    const int cell = body.body_cell_near(x_body - (distance + 0.5 * body.cell_size()) * normal);
    if (cell < 0) return body.held_temperature();  // no cell within two (a sliver of the outline)
    links_[r].push_back({node, cell, conductance});
    return bodies[r].temperature_field[cell];
  };
}

void RigidBodyHeat::couple_implicitly(Grid& grid, double dt) {
  for (std::size_t r = 0; r < bodies_.size(); ++r) {
    if (!bodies_[r].active() || steady_[r] || links_[r].empty()) continue;
    const BodyConduction& body = bodies_[r];
    const double capacity = body.volumetric_heat_capacity() * body.cell_size() * body.cell_size();  // J/(K m)
    heat_.assign(body.cell_count(), 0.0);  // here: the conductance into each cell, W/(K m)
    for (const Link& l : links_[r]) heat_[l.cell] += l.conductance;
    for (Link& l : links_[r]) {
      const double g = l.conductance / (1.0 + heat_[l.cell] * dt / capacity);
      grid.sink_conductance[l.node] -= l.conductance - g;
      l.conductance = g;
    }
  }
}

// The cells' temperatures follow the averaged input through the steady response R (K per W/m), and the heat they
// take follows them back through their conductances G (W/(K m)), so one update of the average, weight a, multiplies
// its deviation from the coupled steady state by 1 - a (1 + GR). Without overshoot for a <= 1 / (1 + rho(GR)); the
// spectral radius is at most GR's largest row sum, G_c sum_d R_cd over the linked cells (R >= 0). The weight
// dt / averaging_time alone passed it in short cuts on coarse cells (a 4-cell cut at 40 m/s: 0.2 against a bound
// of ~0.1), and the tool's field grew by orders of magnitude within a few updates.
double RigidBodyHeat::stable_average_weight(std::size_t r) {
  if (links_[r].empty()) return 1.0;
  const BodyConduction& body = bodies_[r];
  conductance_.assign(body.cell_count(), 0.0);
  for (const Link& l : links_[r]) conductance_[l.cell] += l.conductance;
  unit_.assign(body.cell_count(), 0.0);
  for (int c = 0; c < body.cell_count(); ++c)
    if (conductance_[c] > 0.0) unit_[c] = 1.0;
  body.steady_rise(unit_, rise_);
  double row_sum = 0.0;
  for (int c = 0; c < body.cell_count(); ++c) row_sum = std::max(row_sum, conductance_[c] * rise_[c]);
  return 1.0 / (1.0 + row_sum);
}

void RigidBodyHeat::deposit_and_advance(const Grid& grid, std::vector<RigidBodyState>& bodies, double dt) {
  for (std::size_t r = 0; r < bodies_.size(); ++r) {
    if (!bodies_[r].active()) continue;
    heat_.assign(bodies_[r].cell_count(), 0.0);
    if (!grid.sink_heat.empty())
      for (const Link& l : links_[r]) {
        const double g = grid.sink_conductance[l.node];
        if (g > 0.0) heat_[l.cell] += grid.sink_heat[l.node] * l.conductance / g;
      }
    if (!steady_[r]) {
      links_[r].clear();
      bodies_[r].advance(bodies[r].temperature_field, heat_, dt);
      continue;
    }
    // A steady body: the field its heat input would settle to, the input averaged over the averaging time
    // (an exponential average: the field follows the cut, not each update), or over more updates where an update
    // that long would overshoot (stable_average_weight).
    std::vector<double>& average = bodies[r].heat_input_average;
    const double a = dt > 0.0 ? std::min({1.0, dt / averaging_time_[r], stable_average_weight(r)}) : 0.0;
    links_[r].clear();
    if (dt > 0.0)
      for (std::size_t c = 0; c < average.size(); ++c) average[c] += a * (heat_[c] / dt - average[c]);
    bodies_[r].steady_field(average, bodies[r].temperature_field);
  }
}

}  // namespace mpmcut
