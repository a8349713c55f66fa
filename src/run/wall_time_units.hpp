#pragma once
// The wall-time units that options taking a duration accept (--checkpoint-every 10min, --progress-every 30s).
#include <optional>
#include <string_view>

namespace mpmcut {

// Seconds per unit for a lower-case unit name ("s", "sec", "min", "m", "h", ...); nullopt for anything else.
inline std::optional<double> seconds_per_wall_time_unit(std::string_view unit) {
  for (std::string_view s : {"s", "sec", "secs", "second", "seconds"})
    if (unit == s) return 1.0;
  for (std::string_view m : {"min", "mins", "minute", "minutes", "m"})
    if (unit == m) return 60.0;
  for (std::string_view h : {"h", "hour", "hours"})
    if (unit == h) return 3600.0;
  return std::nullopt;
}

}  // namespace mpmcut
