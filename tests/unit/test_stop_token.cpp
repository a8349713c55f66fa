// The stop token (src/run/stop_token.hpp): a request during a run loop is honoured once, cleanly; one
// outside a loop, or a second one, tells a signal handler to exit at once; a loop forgets earlier requests.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace mpmcut
