#include "cutting/cutting_forces.hpp"

#include <cstring>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "core/simulation.hpp"
#include "cutting/cutting_scene.hpp"

namespace mpmcut {

namespace {
constexpr double kPerMm = 1e-3;  // N/m -> N/mm

std::vector<std::string> force_columns() {
  return {"time_s",
          "cutting_force_N_per_mm",
          "thrust_force_N_per_mm",
          "cutting_force_raw_N_per_mm",
          "thrust_force_raw_N_per_mm",
          "cutting_force_N",
          "thrust_force_N",
          "tool_displacement_m"};
}
}  // namespace

CuttingForcesObserver::CuttingForcesObserver(const CuttingParameters& c, const std::filesystem::path& result_dir,
                                             bool append)
    : c_(c),
      csv_(result_dir / "forces.csv", force_columns(), append ? CsvWriter::Mode::Append : CsvWriter::Mode::Create) {
  steady_start_time_ = steady_window_start_travel(c) / c.cutting_speed;
}

void CuttingForcesObserver::after_step(const Simulation& sim) {
  // The impulse at the start of the steady window, for an exact time average over it.
  if (!steady_start_impulse_ && sim.time() >= steady_start_time_) {
    steady_start_impulse_ = sim.rigid_bodies()[0].impulse;
    steady_start_time_ = sim.time();
  }
}

void CuttingForcesObserver::at_history(const Simulation& sim) {
  const RigidBodyState& tool = sim.rigid_bodies()[0];
  const double t = sim.time();
  // Filtered: the mean force since the previous row (impulse difference over time), which
  // averages the step-to-step contact noise without lag beyond one row interval.
  Vec2 filtered = tool.force;
  if (t > last_row_time_) filtered = (tool.impulse - last_row_impulse_) / (t - last_row_time_);
  last_row_time_ = t;
  last_row_impulse_ = tool.impulse;
  csv_.row({t, filtered.x() * kPerMm, filtered.y() * kPerMm, tool.force.x() * kPerMm, tool.force.y() * kPerMm,
            filtered.x() * c_.width_of_cut, filtered.y() * c_.width_of_cut, -tool.displacement.x()});
}

std::string CuttingForcesObserver::checkpoint_state() const {
  const Vec2 start = steady_start_impulse_.value_or(Vec2::Zero());
  const double v[7] = {last_row_time_,     last_row_impulse_.x(), last_row_impulse_.y(), steady_start_time_,
                       steady_start_impulse_ ? 1.0 : 0.0, start.x(), start.y()};
  return std::string(reinterpret_cast<const char*>(v), sizeof v);
}

void CuttingForcesObserver::restore_checkpoint_state(std::string_view state) {
  double v[7];
  if (state.size() != sizeof v)
    throw std::runtime_error("forces observer: checkpoint state has " + std::to_string(state.size()) +
                             " bytes, expected " + std::to_string(sizeof v));
  std::memcpy(v, state.data(), sizeof v);
  last_row_time_ = v[0];
  last_row_impulse_ = Vec2(v[1], v[2]);
  steady_start_time_ = v[3];
  steady_start_impulse_.reset();
  if (v[4] != 0.0) steady_start_impulse_ = Vec2(v[5], v[6]);
}

void CuttingForcesObserver::at_finish(const Simulation& sim, nlohmann::json& summary) {
  const RigidBodyState& tool = sim.rigid_bodies()[0];
  nlohmann::json inputs = {{"material", c_.material},
                           {"cutting_speed_m_per_s", c_.cutting_speed},
                           {"cutting_speed_m_per_min", c_.cutting_speed * 60.0},
                           {"uncut_chip_thickness_m", c_.uncut_chip_thickness},
                           {"width_of_cut_m", c_.width_of_cut},
                           {"cut_length_m", c_.cut_length},
                           {"rake_angle_deg", c_.rake_angle_deg},
                           {"clearance_angle_deg", c_.clearance_angle_deg},
                           {"edge_radius_m", c_.edge_radius},
                           {"friction", c_.friction},
                           {"initial_temperature_K", c_.initial_temperature},
                           {"cell_size_m", sim.grid().h},
                           {"particles_per_cell", c_.particles_per_cell}};
  summary["cutting"] = inputs;
  if (steady_start_impulse_ && sim.time() > steady_start_time_) {
    const Vec2 mean = (tool.impulse - *steady_start_impulse_) / (sim.time() - steady_start_time_);
    summary["mean_cutting_force_N_per_mm"] = mean.x() * kPerMm;
    summary["mean_thrust_force_N_per_mm"] = mean.y() * kPerMm;
    summary["mean_cutting_force_N"] = mean.x() * c_.width_of_cut;
    summary["mean_thrust_force_N"] = mean.y() * c_.width_of_cut;
    summary["steady_window"] = {{"start_time_s", steady_start_time_},
                                {"end_time_s", sim.time()},
                                {"start_tool_travel_m", steady_start_time_ * c_.cutting_speed},
                                {"end_tool_travel_m", -tool.displacement.x()},
                                {"definition", "mean of the contact force over the tool travel after the chip has "
                                               "formed: from max(steady_start_fraction * cut_length, 3 t0) to the end"}};
  } else {
    summary["mean_cutting_force_N_per_mm"] = nullptr;
    summary["mean_thrust_force_N_per_mm"] = nullptr;
    summary["steady_window"] = {{"definition", "not reached: the run ended before the steady window began"}};
  }
}

}  // namespace mpmcut
