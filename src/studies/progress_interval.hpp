#pragma once
// How often a study (sweep, validate, calibrate) prints a line on how far its running cases have got
// (docs/reliability.md, "Progress of a study").
#include <string_view>

namespace mpmcut {

// Long enough not to flood the console of a sweep of one-minute cases (which report as they end), short enough
// that an hour-long case is not silent.
inline constexpr double kDefaultProgressIntervalS = 600.0;

// "30s", "5min", "1h", a bare number of seconds, or "off"/"0" (no periodic line; cases still report as they
// end) -> seconds (0 = off). Throws InputError with the text and the accepted forms (the caller names the option).
double parse_progress_interval(std::string_view text);

}  // namespace mpmcut
