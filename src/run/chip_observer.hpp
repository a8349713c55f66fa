#pragma once
// The chip analysis (analysis/chip_analysis.hpp) of the final state of a cutting run, written
// into summary.json under "chip" and "temperature" when the run ends. `mpmcut analyze` gives the
// same for any snapshot of a finished run.
#include "solver/scene.hpp"
#include "cutting/cutting_parameters.hpp"
#include "io/run_observer.hpp"

namespace mpmcut {

class ChipObserver final : public RunObserver {
 public:
  // `scene` must be the scene the cutting preset built from `cutting`; both are copied.
  ChipObserver(const Scene& scene, const CuttingParameters& cutting);
  void at_finish(const Simulation& sim, nlohmann::json& summary) override;

 private:
  Scene scene_;
  CuttingParameters cutting_;
};

}  // namespace mpmcut
