#pragma once
// The OpenMP thread count that steps fastest on this machine right now (docs/reliability.md, "Busy
// machines"). A step is some twenty parallel regions, each closed by a barrier; when another
// process holds one of the cores, the thread that shares it is descheduled for whole time slices
// and every barrier waits for it: two threads then step 4-25x slower than one. The tuner times
// short trials of the candidate counts (1, ..., max/2, max) every few seconds of wall time and
// runs with the fastest in between. Results do not depend on the thread count (fixed reduction
// orders), so switching is free.
#include <chrono>
#include <vector>

namespace mpmcut {

class ThreadTuner {
 public:
  // max_threads: the most the run may use (--threads); retune_s: wall time between trials;
  // trial_steps / trial_s: each candidate is timed over at least this many steps and this long
  // (20 steps = one particle re-sort, so every candidate pays the same extra work).
  explicit ThreadTuner(int max_threads, double retune_s = 10.0, int trial_steps = 20, double trial_s = 0.05);

  // Around every step: sets the thread count of the coming step, then records its wall time.
  void before_step();
  void after_step();

  int threads() const { return current_; }        // the count of the coming (or last) step
  int chosen() const { return chosen_; }          // the winner of the last trial
  long trials() const { return trials_; }         // trials completed

 private:
  using Clock = std::chrono::steady_clock;
  void start_trial();
  std::vector<int> candidates_;
  double retune_s_;
  int trial_steps_;
  double trial_s_;
  bool in_trial_ = false;
  std::size_t candidate_ = 0;         // index into candidates_ during a trial
  std::vector<double> seconds_per_step_;
  int steps_ = 0;                     // steps of the current candidate
  double seconds_ = 0.0;              // their wall time
  int current_ = 1, chosen_ = 1;
  long trials_ = 0;
  Clock::time_point step_start_, run_start_;
};

}  // namespace mpmcut
