#pragma once
// The InputError message that parsing a case text gives ("" if it parses), for input-error tests.
#include <string>
#include <vector>

#include "io/input_error.hpp"
#include "run/case_loading.hpp"

namespace mpmcut::testing {

inline std::string parse_error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse_case(text, "case.toml", overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace mpmcut::testing
