#include "app/run_case.hpp"

#include <omp.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <fstream>
#include <iostream>
#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/simulation.hpp"
#include "io/csv_writer.hpp"
#include "io/json_summary.hpp"
#include "io/progress.hpp"
#include "io/pvd_writer.hpp"
#include "io/result_directory.hpp"
#include "io/run_observer.hpp"
#include "io/scene_observers.hpp"
#include "io/scene_writer.hpp"
#include "io/vtu_writer.hpp"

namespace mpmcut {

namespace {

// SIGINT/SIGTERM: the first asks the loop to stop after the current step; a second one exits
// at once (the run stays marked "running", i.e. not complete).
std::atomic<int> g_stop_requests{0};
extern "C" void on_stop_signal(int) {
  if (g_stop_requests.fetch_add(1) >= 1) _exit(kExitInterrupted);
}

struct SignalGuard {
  struct sigaction old_int {}, old_term {};
  SignalGuard() {
    g_stop_requests = 0;
    struct sigaction sa {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
  }
  ~SignalGuard() {
    sigaction(SIGINT, &old_int, nullptr);
    sigaction(SIGTERM, &old_term, nullptr);
  }
};

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
          "external_work_J_per_m",
          "momentum_x_kg_m_per_s_per_m",
          "momentum_y_kg_m_per_s_per_m",
          "max_temperature_K"};
}

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

// The observers of one run: they read the simulation between steps and write files.
class RunOutputs {
 public:
  RunOutputs(const ResultDirectory& dir, Simulation& sim)
      : dir_(dir), sim_(sim), history_(dir.path("history.csv"), history_columns()) {
    observers_ = make_scene_observers(sim.scene(), dir.root());
    if (!sim.rigid_bodies().empty()) rigid_.emplace(dir.path("rigid_forces.csv"), rigid_force_columns(sim));
    std::filesystem::create_directories(dir.path("snapshots"));
  }

  void after_step() {
    for (auto& o : observers_) o->after_step(sim_);
  }

  void history_row() {
    for (auto& o : observers_) o->at_history(sim_);
    sim_.refresh_energy();
    const EnergyTotals& e = sim_.energy();
    const Vec2 m = sim_.total_momentum();
    history_.row({sim_.time(), static_cast<double>(sim_.step_count()), sim_.last_dt(), e.kinetic, e.elastic,
                  e.plastic_work, e.heat, e.damage_dissipation, e.friction, e.external_work, m.x(), m.y(),
                  sim_.max_temperature()});
  }

  void rigid_row() {
    if (!rigid_) return;
    std::vector<double> row{sim_.time()};
    for (const auto& r : sim_.rigid_bodies()) {
      row.insert(row.end(), {r.force.x(), r.force.y(), r.displacement.x(), r.displacement.y()});
    }
    rigid_->row(row);
  }

  void snapshot() {
    if (!sim_.scene().output.vtu) return;
    const std::string name = fmt::format("snapshots/particles_{:06d}.vtu", snapshots_++);
    write_particles_vtu(sim_.particles(), dir_.path(name), sim_.time());
    pvd_.add(sim_.time(), name);
    pvd_.write(dir_.path("particles.pvd"));
    last_snapshot_time_ = sim_.time();
  }
  double last_snapshot_time() const { return last_snapshot_time_; }
  int snapshot_count() const { return snapshots_; }

  void flush() {
    history_.flush();
    if (rigid_) rigid_->flush();
    for (auto& o : observers_) o->flush();
  }

  void finish(nlohmann::json& summary) {
    for (auto& o : observers_) o->at_finish(sim_, summary);
  }

 private:
  const ResultDirectory& dir_;
  Simulation& sim_;
  CsvWriter history_;
  std::optional<CsvWriter> rigid_;
  PvdSeries pvd_;
  std::vector<std::unique_ptr<RunObserver>> observers_;
  int snapshots_ = 0;
  double last_snapshot_time_ = -1.0;
};

nlohmann::json summary_json(const Simulation& sim, const char* status, double wall_s, const std::string& message,
                            int threads) {
  nlohmann::json j;
  j["status"] = status;
  j["mpmcut_version"] = MPMCUT_VERSION;
  j["title"] = sim.scene().title;
  j["case_file"] = sim.scene().source_file;
  j["particles"] = sim.particles().size();
  j["grid_nodes"] = sim.grid().node_count();
  j["cell_size_m"] = sim.grid().h;
  j["steps"] = sim.step_count();
  j["simulated_time_s"] = sim.time();
  j["end_time_s"] = sim.scene().solver.end_time;
  j["wall_time_s"] = wall_s;
  j["threads"] = threads;
  j["particle_steps_per_s"] =
      wall_s > 0 ? static_cast<double>(sim.particles().size()) * sim.step_count() / wall_s : 0.0;
  const EnergyTotals& e = sim.energy();
  j["energy_J_per_m"] = {{"kinetic", e.kinetic},
                         {"elastic", e.elastic},
                         {"plastic_work", e.plastic_work},
                         {"heat", e.heat},
                         {"damage_dissipation", e.damage_dissipation},
                         {"friction_work", e.friction},
                         {"external_work", e.external_work}};
  j["max_temperature_K"] = sim.max_temperature();
  nlohmann::json rigid = nlohmann::json::array();
  for (const auto& r : sim.rigid_bodies())
    rigid.push_back({{"name", r.name},
                     {"force_N_per_m", {r.force.x(), r.force.y()}},
                     {"impulse_N_s_per_m", {r.impulse.x(), r.impulse.y()}},
                     {"displacement_m", {r.displacement.x(), r.displacement.y()}},
                     {"work_J_per_m", r.work}});
  j["rigid_bodies"] = rigid;
  if (!message.empty()) j["message"] = message;
  return j;
}

}  // namespace

int run_case(const Scene& scene, const RunOptions& options) {
  const int threads = options.threads > 0 ? options.threads : omp_get_num_procs();
  omp_set_num_threads(threads);
  std::optional<ResultDirectory> dir;
  try {
    dir = ResultDirectory::open(options.out_dir, options.force);
    std::ofstream expanded(dir->path("scene.toml"));
    write_scene(scene, expanded);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitOutputError;
  }

  Simulation sim(scene);
  const auto start = std::chrono::steady_clock::now();
  const auto wall = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  write_json_atomically(dir->path("summary.json"), summary_json(sim, run_status::running, 0.0, "", threads));

  SignalGuard signals;
  Progress progress(scene.solver.end_time, std::cerr, options.progress ? std::nullopt : std::optional<bool>(false));
  const char* status = run_status::complete;
  std::string message;
  int exit_code = kExitComplete;
  std::optional<RunOutputs> outputs;
  try {
    RunOutputs& out = outputs.emplace(*dir, sim);
    out.history_row();
    out.rigid_row();
    out.snapshot();
    const double end = scene.solver.end_time;
    const double snap_dt = scene.output.snapshot_interval;
    const double hist_dt = scene.output.history_interval;
    double next_snapshot = snap_dt > 0 ? snap_dt : end;
    double next_history = hist_dt > 0 ? hist_dt : 0.0;
    const double eps = 1e-12 * end;
    try {
      while (sim.time() < end - eps && (scene.solver.max_steps <= 0 || sim.step_count() < scene.solver.max_steps)) {
        // Land exactly on the next output time (and on the end time).
        double target = std::min(next_snapshot, end);
        if (hist_dt > 0) target = std::min(target, next_history);
        sim.step(target - sim.time());
        out.after_step();
        if (hist_dt <= 0 || sim.time() >= next_history - eps) {
          out.history_row();
          out.rigid_row();
          while (hist_dt > 0 && next_history <= sim.time() + eps) next_history += hist_dt;
        }
        if (sim.time() >= next_snapshot - eps) {
          out.snapshot();
          while (next_snapshot <= sim.time() + eps) next_snapshot += snap_dt > 0 ? snap_dt : end;
        }
        if (options.progress) progress.update(sim.time(), sim.step_count(), sim.last_dt());
        if (g_stop_requests.load() > 0) {
          status = run_status::interrupted;
          message = fmt::format("interrupted by a signal at step {}, time {:.6g} s", sim.step_count(), sim.time());
          exit_code = kExitInterrupted;
          break;
        }
      }
      if (out.last_snapshot_time() < sim.time()) out.snapshot();
    } catch (const SimulationError& e) {
      status = run_status::failed;
      message = e.what();
      exit_code = kExitSimulationFailed;
      // The state at failure is the most useful picture for finding the cause.
      try {
        out.snapshot();
      } catch (...) {
      }
    }
    out.flush();
  } catch (const std::exception& e) {  // output errors: disk full, unwritable directory, ...
    status = run_status::failed;
    message = std::string("output error: ") + e.what();
    exit_code = kExitOutputError;
  }
  if (options.progress) progress.finish(status);
  const double wall_s = wall();
  try {
    nlohmann::json summary = summary_json(sim, status, wall_s, message, threads);
    if (outputs) outputs->finish(summary);
    write_json_atomically(dir->path("summary.json"), summary);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitOutputError;
  }
  if (!message.empty()) std::cerr << (exit_code == kExitInterrupted ? "" : "error: ") << message << "\n";
  std::cerr << fmt::format("{}: {} particles, {} steps, {:.3g} s simulated in {:.1f} s wall ({:.3g} particle-steps/s); "
                           "results in {}\n",
                           status, sim.particles().size(), sim.step_count(), sim.time(), wall_s,
                           wall_s > 0 ? sim.particles().size() * static_cast<double>(sim.step_count()) / wall_s : 0.0,
                           dir->root().string());
  return exit_code;
}

}  // namespace mpmcut
