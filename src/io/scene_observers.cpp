#include "io/scene_observers.hpp"

#include "cutting/cutting_forces.hpp"

namespace mpmcut {

std::vector<std::unique_ptr<RunObserver>> make_scene_observers(const Scene& scene,
                                                               const std::filesystem::path& result_dir) {
  std::vector<std::unique_ptr<RunObserver>> observers;
  if (scene.cutting) observers.push_back(std::make_unique<CuttingForcesObserver>(*scene.cutting, result_dir));
  return observers;
}

}  // namespace mpmcut
