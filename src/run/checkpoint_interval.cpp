#include "run/checkpoint_interval.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "run/wall_time_units.hpp"

namespace mpmcut {

std::string CheckpointInterval::text() const {
  switch (kind) {
    case Kind::Off: return "off";
    case Kind::Steps: return fmt::format("every {} steps", value);
    case Kind::WallSeconds: return fmt::format("every {} s of wall time", value);
  }
  return "?";
}

CheckpointInterval parse_checkpoint_interval(std::string_view text) {
  const auto bad = [&](const std::string& why) {
    return InputError(fmt::format("--checkpoint-every '{}': {}; use a step count (5000, 5000steps), a wall time "
                                  "(600s, 10min, 2h) or off",
                                  text, why));
  };
  std::string s;
  for (const char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (s == "off" || s == "never" || s == "0") return {CheckpointInterval::Kind::Off, 0.0};
  double value = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || !(value > 0.0) || !std::isfinite(value)) throw bad("expected a positive number first");
  const std::string unit = s.substr(static_cast<std::size_t>(end - s.data()));
  if (unit.empty() || unit == "step" || unit == "steps") {
    if (value != std::floor(value)) throw bad("a step count must be a whole number");
    return {CheckpointInterval::Kind::Steps, value};
  }
  if (const auto seconds = seconds_per_wall_time_unit(unit))
    return {CheckpointInterval::Kind::WallSeconds, *seconds * value};
  throw bad(fmt::format("unknown unit '{}'", unit));
}

}  // namespace mpmcut
