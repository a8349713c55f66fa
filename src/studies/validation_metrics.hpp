#pragma once
// The arithmetic of the validation report (mpmcut validate): errors over the conditions, speed trends,
// and the cost of a run before it is started. Pure functions, so that tests can check them alone.
#include <optional>
#include <string>
#include <vector>

#include "solver/scene.hpp"

namespace mpmcut {

// Least-squares slope of y over x; none with fewer than two distinct x.
std::optional<double> least_squares_slope(const std::vector<double>& x, const std::vector<double>& y);

// Speed trend of a force: the least-squares slope of F over ln(v), in the unit of F per e-fold of speed
// (N/mm for forces per mm). Its sign says whether F rises or falls with speed; ln v because the measured
// speeds span 10-500 m/min and the forces follow the logarithmic rate terms of the flow stress.
std::optional<double> speed_trend_slope(const std::vector<double>& speeds, const std::vector<double>& forces);

// (simulated - measured) / measured, -; none if either is missing or measured is 0.
std::optional<double> relative_error(std::optional<double> simulated, double measured);

// Mean and worst of |relative error| over conditions (the ones with a value).
struct ErrorSummary {
  int count = 0;
  double mean_abs = 0.0;   // -
  double worst_abs = 0.0;  // -
  int worst_index = -1;    // index into the input of the worst one; -1 if count = 0
};
ErrorSummary summarize_errors(const std::vector<std::optional<double>>& relative_errors);

// What a run of a scene will cost, from its set-up: particles, grid nodes and the explicit steps at the
// first step's stable time step (CFL with mass scaling; the tool speed). Builds the Simulation (particles
// and grid) but steps nothing. The step grows only where the wave speed falls (heating), so the count is
// an upper estimate of a run that completes.
struct RunCost {
  long particles = 0;
  long grid_nodes = 0;
  double time_step_s = 0.0;
  double steps = 0.0;
  double mass_scaling_factor = 1.0;
  double particle_steps() const { return static_cast<double>(particles) * steps; }
};
RunCost estimate_run_cost(const Scene& scene);

// Core-seconds per particle-step of a cutting run (Johnson-Cook, damage, heating, uGIMP, MUSL, one thread),
// for turning particle-steps into core-hours. Measured on 17 complete matrix runs (docs/results/validation_matrix
// and validation_speed_ends records, t0/10, 1.8e4-1e5 particles, two runs at a time on 2 cores): 0.22-0.26 us
// on a core of its own, up to 0.45 us on a shared one; their steps were 6-23 % more than the first step's
// stable time step predicts (the time step shrinks as the chip heats). 0.35 us covers both. An order of
// magnitude, not a benchmark.
inline constexpr double kCoreSecondsPerParticleStep = 0.35e-6;

// What one complete run of a study took against its estimate (estimate_run_cost): its steps, and its cost
// per particle-step, threads / (summary.json particle_steps_per_s, over its whole wall time).
struct RunCostObservation {
  double estimated_steps = 0.0;
  double steps = 0.0;
  double core_seconds_per_particle_step = 0.0;
};
// The estimate corrected by the complete runs of the same study on this machine: the median ratio of actual
// to estimated steps (cracked particles compressed again shorten the step at fine cells: 1.35 at 1 um) and
// the median core-seconds per particle-step (two runs on two cores share the memory bandwidth). Medians, so
// that one odd run does not move it. None without a usable observation (non-positive or non-finite ones are
// left out).
struct RunCostCorrection {
  int runs = 0;
  double step_ratio = 1.0, step_ratio_min = 1.0, step_ratio_max = 1.0;  // actual / estimated steps, -
  double core_seconds_per_particle_step = kCoreSecondsPerParticleStep;    // s
  // Core-hours of `particle_steps` estimated particle-steps, corrected.
  double core_hours(double particle_steps) const {
    return particle_steps * step_ratio * core_seconds_per_particle_step / 3600.0;
  }
};
std::optional<RunCostCorrection> observed_cost_correction(const std::vector<RunCostObservation>& runs);

}  // namespace mpmcut
