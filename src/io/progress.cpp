#include "io/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include <fmt/core.h>

namespace mpmcut {

namespace {
constexpr double terminal_interval_s = 0.2;  // ~5 redraws per second
constexpr double plain_interval_s = 30.0;
constexpr long clock_every_calls = 8;  // steps are >= microseconds; 8 keeps redraws timely
constexpr int bar_width = 24;

double seconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration<double>(d).count();
}
}  // namespace

Progress::Progress(double end_time_s, std::ostream& out, std::optional<bool> terminal)
    : end_time_s_(end_time_s),
      out_(out),
      terminal_(terminal.value_or(&out == &std::cerr && ::isatty(STDERR_FILENO) == 1)),
      start_(Clock::now()),
      last_print_(start_) {}

double Progress::fraction(double time_s) const {
  if (!(end_time_s_ > 0.0)) return 1.0;
  return std::clamp(time_s / end_time_s_, 0.0, 1.0);
}

void Progress::update(double time_s, long step, double dt_s) {
  last_time_s_ = time_s;
  last_step_ = step;
  last_dt_s_ = dt_s;
  if (!first_time_s_) first_time_s_ = time_s;
  const bool crossed_mark = !terminal_ && fraction(time_s) >= next_fraction_;
  if (!crossed_mark && ++calls_ % clock_every_calls != 0) return;

  const Clock::time_point now = Clock::now();
  const double since_print_s = seconds(now - last_print_);
  if (crossed_mark || since_print_s >= (terminal_ ? terminal_interval_s : plain_interval_s)) {
    draw(time_s, step, dt_s, seconds(now - start_));
    last_print_ = now;
    while (next_fraction_ <= fraction(time_s)) next_fraction_ += 0.1;
  }
}

void Progress::finish(std::string_view status) {
  const double elapsed_s = seconds(Clock::now() - start_);
  if (terminal_) {
    draw(last_time_s_, last_step_, last_dt_s_, elapsed_s);
    out_ << '\n';
  }
  out_ << fmt::format("{}: t = {}, {} steps, wall time {}\n", status, format_sim_time(last_time_s_),
                      last_step_, format_wall_time(elapsed_s));
  out_.flush();
}

std::string Progress::status_text(double time_s, long step, double dt_s, double elapsed_s) const {
  const double f = fraction(time_s);
  // ETA from the progress made since this object started (a restart begins part-way).
  const double done = f - fraction(first_time_s_.value_or(0.0));
  std::string eta = "?";
  if (done > 0.0 && f < 1.0) eta = format_wall_time(elapsed_s * (1.0 - f) / done);
  if (f >= 1.0) eta = format_wall_time(0.0);
  return fmt::format("{:5.1f} %  t = {} / {}  step {}  dt = {:.3g} s  elapsed {}  ETA {}",
                     100.0 * f, format_sim_time(time_s), format_sim_time(end_time_s_), step, dt_s,
                     format_wall_time(elapsed_s), eta);
}

void Progress::draw(double time_s, long step, double dt_s, double elapsed_s) {
  const std::string text = status_text(time_s, step, dt_s, elapsed_s);
  if (terminal_) {
    const int filled = static_cast<int>(std::lround(fraction(time_s) * bar_width));
    // \r returns to the line start; ESC[K clears what a longer previous line left behind.
    out_ << fmt::format("\r[{}{}] {}\x1b[K", std::string(filled, '#'),
                        std::string(bar_width - filled, '.'), text);
  } else {
    out_ << "progress: " << text << '\n';
  }
  out_.flush();
}

std::string Progress::format_wall_time(double s) {
  if (!std::isfinite(s) || s < 0.0) return "?";
  if (s < 9.95) return fmt::format("{:.1f} s", s);  // short runs: tenths are informative
  const long total = std::lround(s);
  if (total < 60) return fmt::format("{} s", total);
  if (total < 3600) return fmt::format("{} min {:02} s", total / 60, total % 60);
  return fmt::format("{} h {:02} min", total / 3600, (total % 3600) / 60);
}

std::string Progress::format_sim_time(double s) {
  const double a = std::fabs(s);
  if (a == 0.0 || a >= 1.0) return fmt::format("{:.4g} s", s);
  if (a >= 1e-3) return fmt::format("{:.4g} ms", s * 1e3);
  if (a >= 1e-6) return fmt::format("{:.4g} us", s * 1e6);
  return fmt::format("{:.4g} ns", s * 1e9);
}

}  // namespace mpmcut
