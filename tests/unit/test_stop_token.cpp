// The stop token (src/run/stop_token.hpp): a request during a run loop is honoured once, cleanly; one
// outside a loop, or a second one, tells a signal handler to exit at once; a loop forgets earlier requests.
// The repeated-signal filter (src/run/repeated_signal.hpp): one stop delivered twice counts once.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "run/repeated_signal.hpp"
#include "run/stop_token.hpp"

namespace mpmcut {
namespace {

TEST(StopToken, FirstRequestInALoopStopsItCleanly) {
  StopToken token;
  EXPECT_FALSE(token.request_stop());  // no loop: the command line exits at once
  {
    const StopToken::LoopScope loop(token);
    EXPECT_FALSE(token.stop_requested());  // the request before the loop is forgotten
    EXPECT_TRUE(token.request_stop());     // the loop stops after this step
    EXPECT_TRUE(token.stop_requested());
    EXPECT_FALSE(token.request_stop());    // a second request: exit at once
  }
  EXPECT_FALSE(token.request_stop());  // after the loop: exit at once
}

// A run that completed says so to a signal after its loop (the handler exits at once, but the results are whole);
// the next loop starts without it.
TEST(StopToken, CompletedResultsAreKnownAfterTheLoopUntilTheNextOne) {
  StopToken token;
  EXPECT_FALSE(token.results_complete());
  {
    const StopToken::LoopScope loop(token);
    token.mark_results_complete();
  }
  EXPECT_TRUE(token.results_complete());
  const StopToken::LoopScope next(token);
  EXPECT_FALSE(token.results_complete());
}

TEST(RepeatedSignalFilter, ASignalWithinTheWindowIsTheSameStop) {
  RepeatedSignalFilter filter;
  EXPECT_TRUE(filter.is_new_stop());
  EXPECT_FALSE(filter.is_new_stop());  // at once: timeout's second delivery
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_FALSE(filter.is_new_stop());  // still within the window (and it does not extend it)
  std::this_thread::sleep_for(std::chrono::duration<double>(RepeatedSignalFilter::kSameStopWindowS));
  EXPECT_TRUE(filter.is_new_stop());   // a user's deliberate second Ctrl-C
  filter.reset();
  EXPECT_TRUE(filter.is_new_stop());   // a new study starts afresh
}

}  // namespace
}  // namespace mpmcut
