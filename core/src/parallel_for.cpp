#include "airshape/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <future>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

namespace airshape {

void parallelFor(std::size_t count, const std::function<void(std::size_t index)>& body) {
  static const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
  std::atomic<std::size_t> next{0};
  std::mutex failing;
  std::size_t failedIndex = std::numeric_limits<std::size_t>::max();
  std::exception_ptr failure;
  auto work = [&] {
    for (std::size_t index = next++; index < count; index = next++) {
      {
        const std::lock_guard<std::mutex> lock(failing);
        if (index > failedIndex) return;
      }
      try {
        body(index);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failing);
        if (index < failedIndex) {
          failedIndex = index;
          failure = std::current_exception();
        }
      }
    }
  };
  std::vector<std::future<void>> helpers;
  for (std::size_t worker = 1; worker < std::min(cores, count); ++worker)
    helpers.push_back(std::async(std::launch::async, work));
  work();
  for (auto& helper : helpers) helper.get();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace airshape
