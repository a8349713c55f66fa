#pragma once
// One stop that arrives as two signals counts once. coreutils `timeout -s INT`, and a `kill` of a
// process group that holds the program, deliver the same stop twice within microseconds (to the
// process and again to its group); taken as a user's second Ctrl-C it would skip the checkpoint
// (docs/reliability.md, "Signals"). A signal within kSameStopWindowS of the last counted one is
// the same stop; a deliberate second Ctrl-C comes later than that.
// Async-signal-safe: clock_gettime and a lock-free atomic only.
#include <time.h>

#include <atomic>

namespace mpmcut {

class RepeatedSignalFilter {
 public:
  static constexpr double kSameStopWindowS = 0.5;

  // True when this signal is a new stop request; false when it repeats the last one.
  bool is_new_stop() noexcept {
    timespec now{};
    ::clock_gettime(CLOCK_MONOTONIC, &now);
    const long long now_ns = static_cast<long long>(now.tv_sec) * 1000000000LL + now.tv_nsec;
    const long long last_ns = last_ns_.load();
    if (last_ns != kNever && now_ns - last_ns < static_cast<long long>(kSameStopWindowS * 1e9)) return false;
    last_ns_.store(now_ns);
    return true;
  }
  void reset() noexcept { last_ns_.store(kNever); }

 private:
  static constexpr long long kNever = -1;
  std::atomic<long long> last_ns_{kNever};
};

}  // namespace mpmcut
