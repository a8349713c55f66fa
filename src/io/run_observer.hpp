#pragma once
// An observer reads the simulation between steps and writes outputs; it never changes it.
// The run loop (run/case_run.cpp) owns a list of them: the generic outputs and, for cutting
// scenes, the force and chip outputs of the cutting module.
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

namespace mpmcut {

class Simulation;

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void after_step(const Simulation&) {}   // every step
  virtual void at_history(const Simulation&) {}   // at the history cadence
  virtual void flush() {}                         // push buffered rows to disk (checkpoints, end)
  virtual void at_finish(const Simulation&, nlohmann::json& summary) {}  // add results to summary.json

  // Restarts (io/checkpoint.hpp). An observer that keeps state between steps (running sums,
  // the last chip length, ...) returns it as bytes here; a resumed run hands the same bytes to
  // restore_checkpoint_state() before the first step. Files an observer writes are reopened in
  // append mode on resume (make_scene_observers' `resume` flag); the run loop has already cut
  // every *.csv in the result directory back to its length at the checkpoint.
  virtual std::string checkpoint_state() const { return {}; }
  virtual void restore_checkpoint_state(std::string_view) {}
};

}  // namespace mpmcut
