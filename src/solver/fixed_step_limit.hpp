#pragma once
// The refusal of a fixed time step beyond the explicit update's stability limit, one text for the two places that
// check it: the case reader (from the scene, at the key) and the simulation (from its particles, for scenes built in
// code).
#include <string>

#include <fmt/format.h>

namespace mpmcut {

// "<fixed> s exceeds ... at most <limit> s"; `limit` = cell / (wave speed + fastest velocity), s.
inline std::string fixed_step_beyond_stability(double fixed, double limit, double cfl) {
  return fmt::format("{:g} s exceeds the stability limit of the explicit update at the start, cell / (wave speed + "
                     "fastest velocity) = {:g} s: the run would blow up. Use fixed_time_step = 0 (the CFL step, {:g} s "
                     "at solver.cfl = {:g}) or at most {:g} s",
                     fixed, limit, cfl * limit, cfl, limit);
}

}  // namespace mpmcut
