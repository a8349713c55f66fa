#include "io/scene_observers.hpp"

namespace mpmcut {

std::vector<std::unique_ptr<RunObserver>> make_scene_observers(const Scene&, const std::filesystem::path&) {
  std::vector<std::unique_ptr<RunObserver>> observers;
  return observers;
}

}  // namespace mpmcut
