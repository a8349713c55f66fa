#include "run/chip_observer.hpp"

#include <exception>

#include <nlohmann/json.hpp>

#include "analysis/chip_analysis.hpp"
#include "analysis/fracture_accounting.hpp"
#include "cutting/cutting_scene.hpp"
#include "solver/simulation.hpp"

namespace mpmcut {

ChipObserver::ChipObserver(const Scene& scene, const CuttingParameters& cutting) : scene_(scene), cutting_(cutting) {
  // From where the force is averaged, every half t0 of travel: about seven samples over validate's 6 t0 cut.
  sampling_.first_travel_m = steady_window_start_travel(cutting_);
  sampling_.interval_m = 0.5 * cutting_.uncut_chip_thickness;
}

void ChipObserver::at_history(const Simulation& sim) {
  const double travel = sim.rigid_bodies().at(0).displacement.norm();
  if (!sampling_.due(travel, samples_)) return;
  // A sample that cannot be analysed is left out; the final-state analysis reports the error.
  try {
    const ChipAnalysisSetup setup = chip_analysis_setup(scene_, cutting_, sim.rigid_bodies().at(0).displacement, sim.time());
    samples_.push_back(chip_sample(analyze_chip(sim.particles(), setup)));
  } catch (const std::exception&) {
  }
}

void ChipObserver::at_finish(const Simulation& sim, nlohmann::json& summary) {
  // Also at the end of a failed or interrupted run: the state up to there is what the user has.
  // The analysis must never cost the run its summary, so a failure here becomes a note.
  try {
    const ChipAnalysisSetup setup = chip_analysis_setup(scene_, cutting_, sim.rigid_bodies().at(0).displacement, sim.time());
    const ChipAnalysis a = analyze_chip(sim.particles(), setup);
    nlohmann::json chip = chip_json(a), temperature = temperature_json(a);
    chip["source"] = "final state of the run";
    temperature["source"] = "final state of the run";
    summary["chip"] = chip;
    summary["temperature"] = temperature;
    nlohmann::json over_time = chip_over_time_json(samples_, sampling_);
    over_time["source"] = "the run's states every tool_travel_interval_m of travel from first_tool_travel_m (the force's "
                          "steady window) on";
    summary["chip_over_time"] = over_time;
    // Does the fracture work correspond to real new surface? (docs/analysis.md, "Fracture accounting")
    const EnergyTotals& e = sim.energy();
    const FractureAccounting f = account_fracture(sim.particles(), setup, a, e.damage_dissipation);
    const EnergyPartition part = energy_partition(sim.rigid_bodies().at(0).work, e.plastic_work, e.damage_dissipation,
                                                  e.friction, e.kinetic, e.elastic, e.viscous);
    nlohmann::json fracture = fracture_json(f, part);
    fracture["source"] = "final state of the run";
    summary["fracture"] = fracture;
  } catch (const std::exception& e) {
    summary["chip"] = {{"error", e.what()}};
  }
}

}  // namespace mpmcut
