#include "studies/validation_metrics.hpp"

#include <algorithm>
#include <cmath>

#include "solver/simulation.hpp"

namespace mpmcut {

std::optional<double> least_squares_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = std::min(x.size(), y.size());
  if (n < 2) return std::nullopt;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) mx += x[i], my += y[i];
  mx /= n;
  my /= n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my);
  // Distinct x: a spread above round-off of the mean.
  if (!(sxx > 1e-24 * std::max(1.0, mx * mx) * n)) return std::nullopt;
  return sxy / sxx;
}

std::optional<double> speed_trend_slope(const std::vector<double>& speeds, const std::vector<double>& forces) {
  std::vector<double> ln_v;
  for (double v : speeds) {
    if (!(v > 0)) return std::nullopt;
    ln_v.push_back(std::log(v));
  }
  return least_squares_slope(ln_v, forces);
}

std::optional<double> relative_error(std::optional<double> simulated, double measured) {
  if (!simulated || !std::isfinite(*simulated) || !std::isfinite(measured) || measured == 0.0) return std::nullopt;
  return (*simulated - measured) / measured;
}

ErrorSummary summarize_errors(const std::vector<std::optional<double>>& errors) {
  ErrorSummary s;
  double sum = 0.0;
  for (std::size_t i = 0; i < errors.size(); ++i) {
    if (!errors[i]) continue;
    const double a = std::abs(*errors[i]);
    sum += a;
    ++s.count;
    if (s.worst_index < 0 || a > s.worst_abs) s.worst_abs = a, s.worst_index = static_cast<int>(i);
  }
  if (s.count > 0) s.mean_abs = sum / s.count;
  return s;
}

RunCost estimate_run_cost(const Scene& scene) {
  const Simulation sim(scene);
  RunCost c;
  c.particles = static_cast<long>(sim.particles().size());
  c.grid_nodes = static_cast<long>(sim.grid().nx) * sim.grid().ny;
  c.time_step_s = sim.stable_time_step();
  c.steps = c.time_step_s > 0 ? std::ceil(scene.solver.end_time / c.time_step_s) : 0.0;
  c.mass_scaling_factor = scene.solver.mass_scaling_factor;
  return c;
}

namespace {
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
}  // namespace

std::optional<RunCostCorrection> observed_cost_correction(const std::vector<RunCostObservation>& runs) {
  std::vector<double> ratios, costs;
  const auto usable = [](double x) { return std::isfinite(x) && x > 0.0; };
  for (const RunCostObservation& r : runs) {
    if (!usable(r.estimated_steps) || !usable(r.steps) || !usable(r.core_seconds_per_particle_step)) continue;
    ratios.push_back(r.steps / r.estimated_steps);
    costs.push_back(r.core_seconds_per_particle_step);
  }
  if (ratios.empty()) return std::nullopt;
  RunCostCorrection c;
  c.runs = static_cast<int>(ratios.size());
  c.step_ratio = median(ratios);
  c.step_ratio_min = *std::min_element(ratios.begin(), ratios.end());
  c.step_ratio_max = *std::max_element(ratios.begin(), ratios.end());
  c.core_seconds_per_particle_step = median(costs);
  return c;
}

}  // namespace mpmcut
