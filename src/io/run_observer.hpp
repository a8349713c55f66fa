#pragma once
// An observer reads the simulation between steps and writes outputs; it never changes it.
// The run loop (app/run_case.cpp) owns a list of them: the generic outputs and, for cutting
// scenes, the force and chip outputs of the cutting module.
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
};

}  // namespace mpmcut
