#pragma once
// Text files compiled into the program (see the "embedded input files" block in CMakeLists.txt):
// the material library (materials/*.toml) and the built-in demo case (cases/elastic_demo.toml),
// so that an installed binary works without the source tree.
#include <span>
#include <string_view>

namespace mpmcut {

struct EmbeddedText {
  std::string_view path;  // relative to the source tree, e.g. "materials/ti6al4v.toml"
  std::string_view text;
};

// All embedded files, in the order CMake listed them (materials sorted by name, then cases).
std::span<const EmbeddedText> embedded_texts();

}  // namespace mpmcut
