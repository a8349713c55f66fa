#pragma once
// How options taking a duration read it (--checkpoint-every 10min, --progress-every 30s): the number, its unit, and
// the wall-time units.
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

namespace mpmcut {

// A duration option's text as given, without whitespace and in lower case.
struct DurationText {
  std::string text;
  bool off() const { return text == "off" || text == "never" || text == "0"; }
  // The positive, finite number it starts with, and the rest (the unit, maybe empty); nullopt without one.
  std::optional<std::pair<double, std::string>> number_and_unit() const {
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || !(value > 0.0) || !std::isfinite(value)) return std::nullopt;
    return std::pair{value, text.substr(static_cast<std::size_t>(end - text.data()))};
  }
};

inline DurationText duration_text(std::string_view given) {
  DurationText d;
  for (const char c : given)
    if (!std::isspace(static_cast<unsigned char>(c))) d.text += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return d;
}

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
