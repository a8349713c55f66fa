#include "physics/johnson_cook.hpp"

#include <stdexcept>

namespace mpmcut {

ConstitutiveIncrement JohnsonCookMaterial::update(Particles&, std::size_t, const Mat2&, const StepContext&) const {
  throw std::logic_error("Johnson-Cook material not implemented yet");
}

}  // namespace mpmcut
