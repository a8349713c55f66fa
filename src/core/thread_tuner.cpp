#include "core/thread_tuner.hpp"

#include <omp.h>

#include <algorithm>

namespace mpmcut {

ThreadTuner::ThreadTuner(int max_threads, double retune_s, int trial_steps, double trial_s)
    : retune_s_(retune_s), trial_steps_(trial_steps), trial_s_(trial_s) {
  // 1 first: it is the reference that a descheduled extra thread cannot spoil, and a slower
  // candidate's trial is cut short as soon as it cannot win (on a busy machine a two-thread step
  // can take 100 ms: twenty of them would cost seconds).
  for (int n = std::max(1, max_threads); n > 1; n /= 2) candidates_.insert(candidates_.begin(), n);
  candidates_.insert(candidates_.begin(), 1);
  current_ = chosen_ = candidates_.back();
  if (candidates_.size() > 1) start_trial();
  omp_set_num_threads(current_);
}

void ThreadTuner::start_trial() {
  in_trial_ = true;
  candidate_ = 0;
  seconds_per_step_.assign(candidates_.size(), 0.0);
  steps_ = 0;
  seconds_ = 0.0;
  current_ = candidates_[0];
}

void ThreadTuner::before_step() {
  if (!in_trial_ && candidates_.size() > 1 &&
      std::chrono::duration<double>(Clock::now() - run_start_).count() >= retune_s_)
    start_trial();
  omp_set_num_threads(current_);
  step_start_ = Clock::now();
}

void ThreadTuner::after_step() {
  if (!in_trial_) return;
  seconds_ += std::chrono::duration<double>(Clock::now() - step_start_).count();
  ++steps_;
  const double best = candidate_ > 0 ? *std::min_element(seconds_per_step_.begin(), seconds_per_step_.begin() + candidate_)
                                     : 0.0;
  const bool lost = candidate_ > 0 && seconds_ > best * std::max(steps_, trial_steps_);
  if (!lost && (steps_ < trial_steps_ || seconds_ < trial_s_)) return;
  seconds_per_step_[candidate_] = lost ? 1e300 : seconds_ / steps_;
  steps_ = 0;
  seconds_ = 0.0;
  if (++candidate_ < candidates_.size()) {
    current_ = candidates_[candidate_];
    return;
  }
  const auto fastest = std::min_element(seconds_per_step_.begin(), seconds_per_step_.end());
  chosen_ = current_ = candidates_[static_cast<std::size_t>(fastest - seconds_per_step_.begin())];
  in_trial_ = false;
  ++trials_;
  run_start_ = Clock::now();
}

}  // namespace mpmcut
