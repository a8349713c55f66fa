#include "solver/scene.hpp"

namespace mpmcut {

int Scene::material_index(const std::string& name) const {
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace mpmcut
