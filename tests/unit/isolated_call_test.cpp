// Calls made in a child process: what a crash, a hang and an answer come to.
#include <csignal>

#include <gtest/gtest.h>

#include "airshape/isolated_call.h"

namespace airshape {
namespace {

using std::chrono::milliseconds;

TEST(IsolatedCall, ReportsTheAnswer) {
  EXPECT_EQ(callIsolated([] { return true; }, milliseconds(5000)).outcome, IsolatedOutcome::Succeeded);
  EXPECT_EQ(callIsolated([] { return false; }, milliseconds(5000)).outcome, IsolatedOutcome::Failed);
  EXPECT_EQ(callIsolated([]() -> bool { throw 1; }, milliseconds(5000)).outcome, IsolatedOutcome::Failed);
}

TEST(IsolatedCall, ACrashInTheChildLeavesTheCallerRunning) {
  const IsolatedResult result = callIsolated(
      [] {
        std::raise(SIGSEGV);
        return true;
      },
      milliseconds(5000));
  EXPECT_EQ(result.outcome, IsolatedOutcome::Crashed);
  EXPECT_EQ(result.signal, SIGSEGV);
}

TEST(IsolatedCall, AChildThatDoesNotFinishIsKilled) {
  const auto start = std::chrono::steady_clock::now();
  const IsolatedResult result = callIsolated(
      [] {
        for (volatile bool forever = true; forever;) {
        }
        return true;
      },
      milliseconds(200));
  EXPECT_EQ(result.outcome, IsolatedOutcome::TimedOut);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

}  // namespace
}  // namespace airshape
