#include "cutting/chip_observer.hpp"

#include <exception>

#include <nlohmann/json.hpp>

#include "analysis/chip_analysis.hpp"
#include "core/simulation.hpp"

namespace mpmcut {

ChipObserver::ChipObserver(const Scene& scene) : scene_(scene) {}

void ChipObserver::at_finish(const Simulation& sim, nlohmann::json& summary) {
  // Also at the end of a failed or interrupted run: the state up to there is what the user has.
  // The analysis must never cost the run its summary, so a failure here becomes a note.
  try {
    const ChipAnalysis a =
        analyze_chip(sim.particles(), chip_analysis_setup(scene_, sim.rigid_bodies().at(0).displacement, sim.time()));
    nlohmann::json chip = chip_json(a), temperature = temperature_json(a);
    chip["source"] = "final state of the run";
    temperature["source"] = "final state of the run";
    summary["chip"] = chip;
    summary["temperature"] = temperature;
  } catch (const std::exception& e) {
    summary["chip"] = {{"error", e.what()}};
  }
}

}  // namespace mpmcut
