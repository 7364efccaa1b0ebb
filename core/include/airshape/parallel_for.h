#pragma once

#include <cstddef>
#include <functional>

namespace airshape {

/// Calls body(0) ... body(count - 1) on every core: each worker takes the next index not yet
/// taken, so one long call does not hold the others up. The calling thread is one of the
/// workers. When calls throw, the exception of the lowest index is rethrown once all workers
/// have stopped (indices above a failed one are not started).
void parallelFor(std::size_t count, const std::function<void(std::size_t index)>& body);

}  // namespace airshape
