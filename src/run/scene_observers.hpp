#pragma once
// The observers a case asks for beyond the generic outputs: for a cut (cutting/case.hpp), the cutting
// forces (cutting/cutting_forces.hpp) and the chip analysis of the final state (run/chip_observer.hpp).
#include <filesystem>
#include <memory>
#include <vector>

#include <optional>

#include "solver/scene.hpp"
#include "cutting/cutting_parameters.hpp"
#include "io/run_observer.hpp"

namespace mpmcut {

// `resume`: the run continues from a checkpoint, so observers open their files in append mode
// (CsvWriter::Mode::Append) instead of creating them.
std::vector<std::unique_ptr<RunObserver>> make_scene_observers(const Scene& scene,
                                                               const std::optional<CuttingParameters>& cutting,
                                                               const std::filesystem::path& result_dir,
                                                               bool resume = false);

}  // namespace mpmcut
