#include "run/checkpoint_interval.hpp"

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
  const DurationText d = duration_text(text);
  if (d.off()) return {CheckpointInterval::Kind::Off, 0.0};
  const auto number = d.number_and_unit();
  if (!number) throw bad("expected a positive number first");
  const auto& [value, unit] = *number;
  if (unit.empty() || unit == "step" || unit == "steps") {
    if (value != std::floor(value)) throw bad("a step count must be a whole number");
    return {CheckpointInterval::Kind::Steps, value};
  }
  if (const auto seconds = seconds_per_wall_time_unit(unit))
    return {CheckpointInterval::Kind::WallSeconds, *seconds * value};
  throw bad(fmt::format("unknown unit '{}'", unit));
}

}  // namespace mpmcut
