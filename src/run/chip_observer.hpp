#pragma once
// The chip analysis (analysis/chip_analysis.hpp) of the final state of a cutting run, written
// into summary.json under "chip" and "temperature" when the run ends. `mpmcut analyze` gives the
// same for any snapshot of a finished run.
#include "solver/scene.hpp"
#include "io/run_observer.hpp"

namespace mpmcut {

class ChipObserver final : public RunObserver {
 public:
  // `scene` must be a cutting scene (scene.cutting set); it is copied.
  explicit ChipObserver(const Scene& scene);
  void at_finish(const Simulation& sim, nlohmann::json& summary) override;

 private:
  Scene scene_;
};

}  // namespace mpmcut
