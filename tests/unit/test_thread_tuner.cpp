// The thread tuner (core/thread_tuner.hpp) picks the thread count whose steps are fastest, cuts a
// losing trial short, and re-times after its interval. The "steps" here sleep for a time that
// depends on the thread count in use, so the outcome is known.
#include <gtest/gtest.h>

#include <omp.h>

#include <chrono>
#include <thread>

#include "core/thread_tuner.hpp"

using namespace mpmcut;

namespace {

// Runs `steps` steps of the tuner whose duration is ms_for(threads in use); returns the steps
// taken with each count.
template <class F>
std::vector<int> run(ThreadTuner& tuner, int steps, F ms_for) {
  std::vector<int> taken(3, 0);
  for (int k = 0; k < steps; ++k) {
    tuner.before_step();
    const int n = omp_get_max_threads();
    EXPECT_EQ(n, tuner.threads());
    ++taken[std::min(n, 2)];
    std::this_thread::sleep_for(std::chrono::microseconds(static_cast<int>(1000 * ms_for(n))));
    tuner.after_step();
  }
  return taken;
}

}  // namespace

TEST(ThreadTuner, ChoosesTwoThreadsWhenTheyAreFaster) {
  ThreadTuner tuner(2, 100.0, 5, 0.0);
  run(tuner, 30, [](int n) { return n == 2 ? 2.0 : 8.0; });
  EXPECT_EQ(tuner.trials(), 1);
  EXPECT_EQ(tuner.chosen(), 2);
}

// A busy core: two threads step much slower. The tuner runs one thread, and the two-thread trial
// stops as soon as it has lost (one 30 ms step is already more than five 2 ms steps).
TEST(ThreadTuner, ChoosesOneThreadOnABusyCoreAndCutsTheLosingTrialShort) {
  ThreadTuner tuner(2, 100.0, 5, 0.0);
  const std::vector<int> taken = run(tuner, 30, [](int n) { return n == 2 ? 30.0 : 2.0; });
  EXPECT_EQ(tuner.chosen(), 1);
  EXPECT_EQ(taken[2], 1);
  EXPECT_EQ(taken[1], 29);
}

// After the interval the counts are timed again: a machine that became idle gets its second thread back.
TEST(ThreadTuner, RetimesAfterItsInterval) {
  ThreadTuner tuner(2, 0.05, 5, 0.0);
  run(tuner, 12, [](int n) { return n == 2 ? 20.0 : 2.0; });
  EXPECT_EQ(tuner.chosen(), 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  run(tuner, 12, [](int n) { return n == 2 ? 2.0 : 8.0; });
  EXPECT_GE(tuner.trials(), 2);
  EXPECT_EQ(tuner.chosen(), 2);
}

TEST(ThreadTuner, OneThreadNeedsNoTrials) {
  ThreadTuner tuner(1);
  run(tuner, 5, [](int) { return 0.1; });
  EXPECT_EQ(tuner.trials(), 0);
  EXPECT_EQ(tuner.chosen(), 1);
}
