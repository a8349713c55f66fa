#pragma once
// Edit distance between two names, for "did you mean" suggestions (unknown case keys, misspelt data columns).
#include <cstddef>
#include <string_view>

namespace mpmcut {

// Levenshtein distance: the fewest single-character insertions, deletions and substitutions from a to b.
std::size_t levenshtein(std::string_view a, std::string_view b);

}  // namespace mpmcut
