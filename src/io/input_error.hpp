#pragma once
// An error in what the user gave us (case file, --set override, material library entry).
// what() is the complete message for the user, e.g.
//   case.toml:12:5: key 'body[1].particles_per_cell': must be an integer between 1 and 8, got 0
// Errors that are ours (broken invariants) are assertions, not InputError.
#include <stdexcept>
#include <string>

namespace mpmcut {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace mpmcut
