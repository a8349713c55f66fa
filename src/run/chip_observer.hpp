#pragma once
// The chip analysis (analysis/chip_analysis.hpp) of a cutting run: of the final state, written into
// summary.json under "chip" and "temperature" when the run ends, and repeated every half uncut chip thickness of
// tool travel over the force's steady window, whose mean and range go under "chip_over_time"
// (analysis/chip_over_time.hpp). `mpmcut analyze` gives the final-state analysis for any snapshot of a finished run.
#include <string>
#include <string_view>
#include <vector>

#include "analysis/chip_over_time.hpp"
#include "solver/scene.hpp"
#include "cutting/cutting_parameters.hpp"
#include "io/run_observer.hpp"

namespace mpmcut {

class ChipObserver final : public RunObserver {
 public:
  // `scene` must be the scene the cutting preset built from `cutting`; both are copied.
  ChipObserver(const Scene& scene, const CuttingParameters& cutting);
  void at_history(const Simulation& sim) override;
  void at_finish(const Simulation& sim, nlohmann::json& summary) override;
  std::string checkpoint_state() const override { return chip_samples_text(samples_); }
  void restore_checkpoint_state(std::string_view state) override { samples_ = chip_samples_from_text(state); }

 private:
  Scene scene_;
  CuttingParameters cutting_;
  ChipSampling sampling_;
  std::vector<ChipSample> samples_;
};

}  // namespace mpmcut
