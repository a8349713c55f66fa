#pragma once
// The model version of a scene: how many of the changes to the physics that alter a run's numbers apply to
// it. Every run records it in summary.json (`model_version`); a complete or resumable run, or a study's run
// record, made by an older model of its scene is outdated: the studies (`run --keep-complete`, sweep,
// validate, calibrate, `validate --records`) run it again instead of reporting it, and `resume` refuses to
// continue it (docs/reliability.md, "Model version").
//
// A change that alters results is added to model_changes() with the next version and the scenes it
// applies to, so that only the runs it touches are rerun (a change of the penalty contact leaves the node
// detection's runs current). A summary without the key was made before the versions were counted: 0.
#include <string>
#include <vector>

#include "solver/scene.hpp"

namespace mpmcut {

struct ModelChange {
  int version;             // 1, 2, ... in the order they were made
  const char* revision;    // the commit that made it
  const char* what;        // one line for messages
  bool (*applies)(const Scene&);  // the scenes whose numbers it changes
};

// Every change, oldest first.
const std::vector<ModelChange>& model_changes();

// The version of the newest change that applies to `scene`; 0 when none does.
int model_version(const Scene& scene);

// The changes that apply to `scene` made after version `recorded`, each "version N (revision): what",
// joined by "; ". Empty when there are none.
std::string model_changes_since(int recorded, const Scene& scene);

}  // namespace mpmcut
