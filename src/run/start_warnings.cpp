#include "run/start_warnings.hpp"

#include "cutting/cutting_resolution.hpp"
#include "cutting/cutting_scene.hpp"
#include "cutting/input_plausibility.hpp"

namespace mpmcut {

std::string cut_start_warning_lines(const CuttingParameters& c, const Scene& scene) {
  std::string out = console_lines(cutting_resolution(c, workpiece_thermal_diffusivity_m2_per_s(c, scene)));
  if (const std::string w = steady_window_warning(c); !w.empty()) out += "warning: " + w + "\n";
  for (const std::string& w : input_plausibility_warnings(c, scene)) out += "warning: " + w + "\n";
  return out;
}

}  // namespace mpmcut
