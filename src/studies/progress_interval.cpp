#include "studies/progress_interval.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "run/wall_time_units.hpp"

namespace mpmcut {

double parse_progress_interval(std::string_view text) {
  const auto bad = [&](const std::string& why) {
    return InputError(
        fmt::format("'{}': {}; use a wall time (30s, 5min, 1h; a bare number is seconds) or off", text, why));
  };
  std::string s;
  for (const char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (s == "off" || s == "never" || s == "0") return 0.0;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || !(value > 0.0) || !std::isfinite(value)) throw bad("expected a positive number first");
  const std::string unit = s.substr(static_cast<std::size_t>(end - s.data()));
  if (unit.empty()) return value;
  if (const auto seconds = seconds_per_wall_time_unit(unit)) return *seconds * value;
  throw bad(fmt::format("unknown unit '{}'", unit));
}

}  // namespace mpmcut
