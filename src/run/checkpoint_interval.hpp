#pragma once
// How often a run writes a checkpoint (docs/reliability.md, "Checkpoints").
#include <string>
#include <string_view>

namespace mpmcut {

// Every N steps, or after N seconds of wall time. Parsed from the --checkpoint-every text.
struct CheckpointInterval {
  enum class Kind { Off, Steps, WallSeconds };
  Kind kind = Kind::WallSeconds;
  double value = 1800.0;  // steps or seconds; the default: every 30 min of wall time

  std::string text() const;  // e.g. "every 5000 steps", "every 600 s of wall time", "off"
};

// "5000" or "5000steps" -> every 5000 steps; "600s", "45sec", "10min", "2h" -> wall time;
// "off" or "0" -> never (a checkpoint is still written when a run is stopped). Whitespace between
// number and unit is allowed. Throws InputError with the accepted forms.
CheckpointInterval parse_checkpoint_interval(std::string_view text);

}  // namespace mpmcut
