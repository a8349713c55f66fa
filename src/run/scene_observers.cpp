#include "run/scene_observers.hpp"

#include "run/chip_observer.hpp"
#include "cutting/cutting_forces.hpp"

namespace mpmcut {

std::vector<std::unique_ptr<RunObserver>> make_scene_observers(const Scene& scene,
                                                               const std::optional<CuttingParameters>& cutting,
                                                               const std::filesystem::path& result_dir,
                                                               bool resume) {
  std::vector<std::unique_ptr<RunObserver>> observers;
  if (cutting) observers.push_back(std::make_unique<CuttingForcesObserver>(*cutting, result_dir, resume));
  if (cutting) observers.push_back(std::make_unique<ChipObserver>(scene, *cutting));
  return observers;
}

}  // namespace mpmcut
