#include "core/range.hpp"

#include <fmt/format.h>

namespace mpmcut {

std::string Range::interval() const {
  return fmt::format("{}{:g}, {:g}{}", min_open ? '(' : '[', min, max, max_open ? ')' : ']');
}

std::string Range::text() const {
  std::string t = "in " + interval();
  if (!unit.empty()) t += fmt::format(" {}", unit);
  if (!note.empty()) t += fmt::format(" ({})", note);
  return t;
}

}  // namespace mpmcut
