#include "io/run_estimate.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include <fmt/format.h>

#include "io/input_error.hpp"

namespace mpmcut {

namespace {

double shape_area(const Shape& s) {
  switch (s.kind) {
    case ShapeKind::Rectangle: return (s.rectangle.max - s.rectangle.min).prod();
    case ShapeKind::Disk: return std::numbers::pi * s.disk.radius * s.disk.radius;
    case ShapeKind::Polygon: {
      double a = 0.0;
      const auto& v = s.polygon.vertices;
      for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) a += v[j].x() * v[i].y() - v[i].x() * v[j].y();
      return 0.5 * std::abs(a);
    }
  }
  return 0.0;
}

}  // namespace

RunEstimate estimate_run(const Scene& scene) {
  RunEstimate e;
  const double h = scene.grid.cell_size;
  const Vec2 extent = scene.grid.max - scene.grid.min;
  // In doubles: a grid of 1e12 cells must be refused, not overflow an int first.
  e.grid_nodes = (std::ceil(extent.x() / h) + 7.0) * (std::ceil(extent.y() / h) + 7.0);
  double v_max = 0.0;
  for (const BodySpec& b : scene.bodies) {
    const double d = h / b.particles_per_cell;
    // Plus one row of particles along the outline: the sub-grid rounds outwards.
    Vec2 lo, hi;
    b.shape.bounds(lo, hi);
    e.particles += shape_area(b.shape) / (d * d) + 2.0 * ((hi - lo).sum() / d + 2.0);
    v_max = std::max(v_max, b.velocity.norm());
  }
  for (const RigidBodySpec& r : scene.rigid_bodies) v_max = std::max(v_max, r.velocity.norm());
  e.bytes = e.particles * kBytesPerParticle + e.grid_nodes * kBytesPerGridNode;

  double dt = std::numeric_limits<double>::infinity();
  if (scene.solver.fixed_time_step > 0.0) {
    dt = scene.solver.fixed_time_step;
  } else {
    double c_max = 0.0;
    for (const MaterialParameters& m : scene.materials) c_max = std::max(c_max, m.p_wave_speed());
    if (c_max + v_max > 0.0) dt = scene.solver.cfl * h / (c_max + v_max);
    // Mass scaling multiplies the inertia by f, so the wave speed, and the step with it, by sqrt(f);
    // a target step, where given, is what the factor is chosen to reach.
    if (scene.solver.mass_scaling_target_time_step > 0.0) dt = std::max(dt, scene.solver.mass_scaling_target_time_step);
    else if (scene.solver.mass_scaling_factor > 1.0) dt *= std::sqrt(scene.solver.mass_scaling_factor);
    if (scene.thermal.conduction)
      for (const MaterialParameters& m : scene.materials)
        if (m.thermal_conductivity > 0.0 && m.specific_heat > 0.0)
          dt = std::min(dt, scene.solver.cfl * h * h * m.density * m.specific_heat / (4.0 * m.thermal_conductivity));
  }
  // Steps land exactly on every output time, so an output interval shorter than the step is the step.
  if (scene.output.snapshot_interval > 0.0) dt = std::min(dt, scene.output.snapshot_interval);
  if (scene.output.history_interval > 0.0) dt = std::min(dt, scene.output.history_interval);
  e.steps = std::ceil(scene.solver.end_time / dt);
  if (scene.solver.max_steps > 0) e.steps = std::min(e.steps, static_cast<double>(scene.solver.max_steps));
  e.snapshots = scene.output.snapshot_interval > 0.0 ? scene.solver.end_time / scene.output.snapshot_interval + 2.0 : 2.0;
  return e;
}

double available_memory_bytes() {
  double available = 0.0;
  {
    std::ifstream in("/proc/meminfo");
    for (std::string line; std::getline(in, line);) {
      if (!line.starts_with("MemAvailable:")) continue;
      std::istringstream s(line.substr(13));
      double kib = 0.0;
      if (s >> kib) available = kib * 1024.0;
    }
  }
  if (available <= 0.0) {
    const long pages = sysconf(_SC_AVPHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0) available = static_cast<double>(pages) * static_cast<double>(page);
  }
  // A container's limit (cgroup v2) is what the kernel enforces, whatever the host has free.
  std::ifstream max_file("/sys/fs/cgroup/memory.max"), current_file("/sys/fs/cgroup/memory.current");
  double limit = 0.0, current = 0.0;
  if (std::string text; max_file >> text && text != "max") {
    limit = std::strtod(text.c_str(), nullptr);
    if (current_file >> current && limit > current) limit -= current;
    if (limit > 0.0) available = available > 0.0 ? std::min(available, limit) : limit;
  }
  return available;
}

std::string format_bytes(double bytes) {
  if (bytes >= 1024.0 * 1024.0 * 1024.0) return fmt::format("{:.3g} GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  return fmt::format("{:.3g} MiB", bytes / (1024.0 * 1024.0));
}

void check_run_fits(const Scene& scene, const RunEstimate& e, double available, const RunSizeKeys& keys) {
  const std::string where = scene.source_file.empty() ? "the case" : scene.source_file;
  if (available > 0.0 && e.bytes > available)
    throw InputError(fmt::format(
        "{}: the run needs about {} of memory ({:.3g} particles, {:.3g} grid nodes) but this machine has {} "
        "available; keys that set the size: {}",
        where, format_bytes(e.bytes), e.particles, e.grid_nodes, format_bytes(available), keys.size));
  if (!(e.steps <= kMaxSteps))
    throw InputError(fmt::format(
        "{}: the run needs about {:.3g} time steps, more than the {:.0e} any run can finish; keys that set the step "
        "count: {} (simulated time), {}, solver.cfl, output.snapshot_interval/history_interval (steps land on every "
        "output time)",
        where, e.steps, kMaxSteps, keys.simulated_time, keys.cell_size));
  if (!(e.snapshots <= kMaxSnapshots))
    throw InputError(fmt::format("{}: key 'output.snapshot_interval': asks for {:.3g} snapshots, at most {:.0e} "
                                 "(end_time / snapshot_interval)",
                                 where, e.snapshots, kMaxSnapshots));
}

}  // namespace mpmcut
