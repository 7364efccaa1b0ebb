#pragma once

#include <chrono>
#include <functional>

namespace airshape {

/// How a call made in a child process ended.
enum class IsolatedOutcome {
  Succeeded,  ///< it returned true
  Failed,     ///< it returned false or threw
  Crashed,    ///< the child died of a signal (a segmentation fault in a library, say)
  TimedOut,   ///< it did not finish in time and the child was killed
};

struct IsolatedResult {
  IsolatedOutcome outcome = IsolatedOutcome::Failed;
  int signal = 0;  ///< the signal that ended a Crashed child
};

/// Makes `call` in a forked child process and reports how it ended, so that a library that
/// crashes or loops forever on a damaged input file (OCCT's BREP reader does both) cannot take
/// the calling process with it. Nothing the child computes comes back: callers probe an input
/// this way, then read it for real. Only for single-threaded callers (fork copies one thread).
IsolatedResult callIsolated(const std::function<bool()>& call, std::chrono::milliseconds timeout);

}  // namespace airshape
