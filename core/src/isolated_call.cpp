#include "airshape/isolated_call.h"

#include <algorithm>
#include <csignal>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

namespace airshape {

namespace {

constexpr int kSucceeded = 0;
constexpr int kFailed = 1;

/// Runs in the child: the call's verdict as the exit status; _exit skips the parent's atexit
/// handlers and stream buffers, which belong to the parent.
[[noreturn]] void runChild(const std::function<bool()>& call) {
  bool succeeded = false;
  try {
    succeeded = call();
  } catch (...) {
    succeeded = false;
  }
  _exit(succeeded ? kSucceeded : kFailed);
}

}  // namespace

IsolatedResult callIsolated(const std::function<bool()>& call, std::chrono::milliseconds timeout) {
  const pid_t child = fork();
  if (child < 0) return {call() ? IsolatedOutcome::Succeeded : IsolatedOutcome::Failed, 0};  // no fork: run here
  if (child == 0) runChild(call);

  const auto deadline = std::chrono::steady_clock::now() + timeout;
  auto pause = std::chrono::microseconds(200);
  int status = 0;
  while (waitpid(child, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(child, SIGKILL);
      waitpid(child, &status, 0);
      return {IsolatedOutcome::TimedOut, 0};
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }
  if (WIFSIGNALED(status)) return {IsolatedOutcome::Crashed, WTERMSIG(status)};
  return {WIFEXITED(status) && WEXITSTATUS(status) == kSucceeded ? IsolatedOutcome::Succeeded : IsolatedOutcome::Failed,
          0};
}

}  // namespace airshape
