#pragma once
// The outputs of one run (docs/outputs.md): history.csv, rigid_forces.csv, the VTU snapshots and
// their .pvd index, and the scene's own observers (run/scene_observers.hpp: the cutting forces and
// the chip analysis). They read the simulation between steps and write; they never change it.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "cutting/cutting_parameters.hpp"
#include "io/checkpoint.hpp"
#include "io/csv_writer.hpp"
#include "io/pvd_writer.hpp"
#include "io/run_observer.hpp"

namespace mpmcut {

class Simulation;

std::vector<std::string> history_columns();
std::string snapshot_name(int index);        // "snapshots/particles_NNNNNN.vtu"
long snapshot_index(const std::string& file_name);  // NNNNNN of "particles_NNNNNN.vtu", or -1
long snapshot_number(const std::string& text);      // a user's snapshot number "12" (>= 0), or -1

class RunOutputs {
 public:
  // With `resume` the CSV files are opened for appending (the caller has cut them back already).
  // `cutting`: the process of a cut (cutting/case.hpp), which adds its observers.
  RunOutputs(const std::filesystem::path& root, Simulation& sim, const std::optional<CuttingParameters>& cutting,
             bool resume);

  void after_step();
  void history_row();
  void rigid_row();
  void snapshot();
  double last_snapshot_time() const { return last_snapshot_time_; }
  int snapshot_count() const { return snapshots_; }
  void flush();
  void finish(nlohmann::json& summary);  // the observers' sections of summary.json

  // Checkpoints: the outputs' part of the run-loop state.
  void save(RunLoopState& s) const;
  void restore(const RunLoopState& s);

 private:
  std::filesystem::path root_;
  Simulation& sim_;
  CsvWriter history_;
  std::optional<CsvWriter> rigid_;
  PvdSeries pvd_;
  std::vector<std::unique_ptr<RunObserver>> observers_;
  int snapshots_ = 0;
  double last_snapshot_time_ = -1.0;
};

}  // namespace mpmcut
