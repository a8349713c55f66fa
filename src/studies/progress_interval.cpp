#include "studies/progress_interval.hpp"

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
  const DurationText d = duration_text(text);
  if (d.off()) return 0.0;
  const auto number = d.number_and_unit();
  if (!number) throw bad("expected a positive number first");
  const auto& [value, unit] = *number;
  if (unit.empty()) return value;
  if (const auto seconds = seconds_per_wall_time_unit(unit)) return *seconds * value;
  throw bad(fmt::format("unknown unit '{}'", unit));
}

}  // namespace mpmcut
