#include "run/run_outputs.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "solver/simulation.hpp"
#include "io/vtu_writer.hpp"
#include "run/scene_observers.hpp"

namespace mpmcut {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> rigid_force_columns(const Simulation& sim) {
  std::vector<std::string> cols{"time_s"};
  for (const auto& r : sim.rigid_bodies()) {
    cols.push_back(r.name + "_force_x_N_per_m");
    cols.push_back(r.name + "_force_y_N_per_m");
    cols.push_back(r.name + "_displacement_x_m");
    cols.push_back(r.name + "_displacement_y_m");
  }
  return cols;
}

}  // namespace

std::vector<std::string> history_columns() {
  return {"time_s",
          "step",
          "dt_s",
          "kinetic_energy_J_per_m",
          "elastic_energy_J_per_m",
          "plastic_work_J_per_m",
          "heat_J_per_m",
          "damage_dissipation_J_per_m",
          "friction_work_J_per_m",
          "viscous_dissipation_J_per_m",
          "external_work_J_per_m",
          "transfer_dissipation_J_per_m",
          "contact_safeguard_J_per_m",
          "removed_energy_J_per_m",
          "momentum_x_kg_m_per_s_per_m",
          "momentum_y_kg_m_per_s_per_m",
          "max_temperature_K"};
}

std::string snapshot_name(int index) { return fmt::format("snapshots/particles_{:06d}.vtu", index); }

long snapshot_number(const std::string& text) {
  if (text.empty() || text.size() > 9 || !std::all_of(text.begin(), text.end(), ::isdigit)) return -1;
  return std::stol(text);
}

// Number of a snapshot file name "particles_NNNNNN.vtu", or -1.
long snapshot_index(const std::string& file_name) {
  constexpr std::string_view prefix = "particles_", suffix = ".vtu";
  if (!file_name.starts_with(prefix) || !file_name.ends_with(suffix)) return -1;
  return snapshot_number(file_name.substr(prefix.size(), file_name.size() - prefix.size() - suffix.size()));
}

RunOutputs::RunOutputs(const fs::path& root, Simulation& sim, const std::optional<CuttingParameters>& cutting,
                       bool resume)
    : root_(root),
      sim_(sim),
      history_(root / "history.csv", history_columns(), resume ? CsvWriter::Mode::Append : CsvWriter::Mode::Create) {
  observers_ = make_scene_observers(sim.scene(), cutting, root, resume);
  if (!sim.rigid_bodies().empty())
    rigid_.emplace(root / "rigid_forces.csv", rigid_force_columns(sim),
                   resume ? CsvWriter::Mode::Append : CsvWriter::Mode::Create);
  fs::create_directories(root / "snapshots");
}

void RunOutputs::after_step() {
  for (auto& o : observers_) o->after_step(sim_);
}

void RunOutputs::history_row() {
  for (auto& o : observers_) o->at_history(sim_);
  sim_.refresh_energy();
  const EnergyTotals& e = sim_.energy();
  const Vec2 m = sim_.total_momentum();
  history_.row({sim_.time(), static_cast<double>(sim_.step_count()), sim_.last_dt(), e.kinetic, e.elastic,
                e.plastic_work, e.heat, e.damage_dissipation, e.friction, e.viscous, e.external_work, e.transfer_dissipation, e.contact_safeguard,
                e.removed_energy, m.x(), m.y(),
                sim_.max_temperature()});
}

void RunOutputs::rigid_row() {
  if (!rigid_) return;
  std::vector<double> row{sim_.time()};
  for (const auto& r : sim_.rigid_bodies()) {
    row.insert(row.end(), {r.force.x(), r.force.y(), r.displacement.x(), r.displacement.y()});
  }
  rigid_->row(row);
}

void RunOutputs::snapshot() {
  if (!sim_.scene().output.vtu) return;
  const std::string name = snapshot_name(snapshots_++);
  write_particles_vtu(sim_.particles(), root_ / name, sim_.time());
  pvd_.add(sim_.time(), name);
  pvd_.write(root_ / "particles.pvd");
  last_snapshot_time_ = sim_.time();
}

void RunOutputs::flush() {
  history_.flush();
  if (rigid_) rigid_->flush();
  for (auto& o : observers_) o->flush();
}

void RunOutputs::finish(nlohmann::json& summary) {
  for (auto& o : observers_) o->at_finish(sim_, summary);
}

void RunOutputs::save(RunLoopState& s) const {
  s.snapshot_count = snapshots_;
  s.last_snapshot_time_s = last_snapshot_time_;
  s.pvd = pvd_.entries();
  s.observer_states.clear();
  for (const auto& o : observers_) s.observer_states.push_back(o->checkpoint_state());
}

void RunOutputs::restore(const RunLoopState& s) {
  if (s.observer_states.size() != observers_.size()) {
    throw CheckpointError(fmt::format("the checkpoint has the state of {} observers, this scene has {}",
                                      s.observer_states.size(), observers_.size()));
  }
  for (std::size_t k = 0; k < observers_.size(); ++k) observers_[k]->restore_checkpoint_state(s.observer_states[k]);
  snapshots_ = s.snapshot_count;
  last_snapshot_time_ = s.last_snapshot_time_s;
  pvd_ = PvdSeries();
  for (const auto& e : s.pvd) pvd_.add(e.time_s, e.file);
  if (sim_.scene().output.vtu) pvd_.write(root_ / "particles.pvd");
}

}  // namespace mpmcut
