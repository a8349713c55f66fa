#pragma once
// A request to stop a run after its current step, owned by whoever drives the run: the command
// line binds one to SIGINT/SIGTERM (app/stop_signal.hpp), Python asks through Run.stop(), a
// test simply calls request_stop(). The run loop checks it after every step and then writes a
// checkpoint and the outputs so far (summary status "interrupted").
// Lock-free atomics only, so request_stop() may be called from a signal handler or another thread.
#include <atomic>

namespace mpmcut {

class StopToken {
 public:
  // Records a request. Returns true when a run loop is running and this is the first request
  // since it began, i.e. the loop will stop cleanly after this step; false otherwise (no loop, or
  // the loop has already been asked), where a signal handler exits at once instead.
  // `signal_number`: the signal that asks (SIGINT, SIGTERM), 0 for a request of the driving program.
  bool request_stop(int signal_number = 0) noexcept {
    if (signal_number != 0) signal_.store(signal_number);
    const int n = requests_.fetch_add(1) + 1;
    return running_.load() && n == 1;
  }
  bool stop_requested() const noexcept { return requests_.load() > 0; }
  // The signal of the request, 0 when none came by a signal.
  int signal_number() const noexcept { return signal_.load(); }
  // Set by the run loop's owner once its results are final and complete (summary written), before the loop's scope
  // ends: a signal after that, which exits at once, interrupts nothing but what follows, and says so.
  void mark_results_complete() noexcept { results_complete_ = true; }
  bool results_complete() const noexcept { return results_complete_.load(); }

  // The span of one run loop: requests made before it began are forgotten (the command line has
  // already exited on them), and requests during it stop it cleanly.
  class LoopScope {
   public:
    explicit LoopScope(StopToken& token) : token_(token) {
      token_.requests_ = 0;
      token_.signal_ = 0;
      token_.results_complete_ = false;
      token_.running_ = true;
    }
    ~LoopScope() { token_.running_ = false; }
    LoopScope(const LoopScope&) = delete;
    LoopScope& operator=(const LoopScope&) = delete;

   private:
    StopToken& token_;
  };

 private:
  std::atomic<int> requests_{0};
  std::atomic<int> signal_{0};
  std::atomic<bool> running_{false};
  std::atomic<bool> results_complete_{false};
};

}  // namespace mpmcut
