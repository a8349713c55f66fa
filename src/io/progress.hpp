#pragma once
// Run progress for humans. On a terminal: one line redrawn in place (at most ~5 times a
// second) with percent, bar, simulated time, steps, dt, elapsed and ETA. Elsewhere (log files,
// CI): a plain line every 10 % of simulated time or every 30 s of wall time, whichever first.
// update() is cheap enough to call every step: it reads the clock only every few calls.
#include <chrono>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>

namespace mpmcut {

class Progress {
 public:
  // `terminal`: draw the in-place bar; by default, when `out` is std::cerr and stderr is a tty.
  Progress(double end_time_s, std::ostream& out, std::optional<bool> terminal = std::nullopt);

  void update(double time_s, long step, double dt_s);
  // Prints the last state and `status` (e.g. "complete") and ends the line.
  void finish(std::string_view status);

  // Human-readable durations, exposed for tests: "0.4 s", "45 s", "3 min 05 s", "2 h 04 min";
  // simulated times pick s, ms, us or ns: "1.234 ms".
  static std::string format_wall_time(double seconds);
  static std::string format_sim_time(double seconds);

 private:
  using Clock = std::chrono::steady_clock;
  double fraction(double time_s) const;
  std::string status_text(double time_s, long step, double dt_s, double elapsed_s) const;
  void draw(double time_s, long step, double dt_s, double elapsed_s);

  double end_time_s_;
  std::ostream& out_;
  bool terminal_;
  Clock::time_point start_;
  Clock::time_point last_print_;
  std::optional<double> first_time_s_;  // simulated time at the first update (restarts)
  double next_fraction_ = 0.1;          // plain mode: next 10 % mark
  long calls_ = 0;
  double last_time_s_ = 0.0;
  long last_step_ = 0;
  double last_dt_s_ = 0.0;
};

}  // namespace mpmcut
