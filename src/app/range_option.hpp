#pragma once
// A number option checked against a key's Range (core/range.hpp), so that the command line allows what the input
// file allows and says so in the same words. NaN is refused (CLI11's own Range lets it through).
#include <cmath>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "core/range.hpp"

namespace mpmcut {

inline CLI::Validator within(const Range& range) {
  return CLI::Validator(
      [range](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || !range.contains(value))
          return fmt::format("Value {} is not a number {}", text, range.text());
        return {};
      },
      range.interval());
}

}  // namespace mpmcut
