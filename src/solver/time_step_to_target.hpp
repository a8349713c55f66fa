#pragma once
// How a step approaches a target time (an output, the end) without a sliver step (docs/solver.md).

namespace mpmcut {

// The step to take towards a target `remaining` seconds ahead when the stable step is `stable`.
// Cutting the last step short to land on the target can leave a sliver of a tiny fraction of the
// stable step, and a contact correction is a velocity change, not proportional to dt: over a sliver
// it reads as a force spike tens of times the mean in the step force (forces.csv's *_raw columns).
// So when the target is between one and two stable steps ahead, the last two steps share the
// remainder equally: every step is at least half the stable one (unless two targets lie closer).
inline double time_step_to_target(double remaining, double stable) {
  if (remaining <= stable) return remaining;
  if (remaining < 2.0 * stable) return 0.5 * remaining;
  return stable;
}

}  // namespace mpmcut
