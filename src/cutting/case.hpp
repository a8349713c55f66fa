#pragma once
// A validated case: the scene the solver runs and, for a cut, the process it stands for. The
// solver knows only the scene; the cutting outputs (forces.csv, the chip analysis), the run
// estimate's messages and the expanded scene.toml's [cutting_process] record read the process.
// run/case_loading.hpp makes one from a case file; Python calls it mpmcut.Case.
#include <optional>

#include "solver/scene.hpp"
#include "cutting/cutting_parameters.hpp"

namespace mpmcut {

struct Case {
  Scene scene;
  // Set when the scene was built by the cutting preset ([cutting], or the [cutting_process]
  // record of an expanded cutting scene). The tool is scene.rigid_bodies[0].
  std::optional<CuttingParameters> cutting;

  bool operator==(const Case&) const = default;  // field-wise, for round-trip tests
};

}  // namespace mpmcut
