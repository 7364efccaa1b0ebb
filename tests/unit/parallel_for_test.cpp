// parallelFor (airshape/parallel_for.h): every index once, and the lowest failure reported.
#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "airshape/parallel_for.h"

namespace airshape {
namespace {

TEST(ParallelFor, CallsEveryIndexOnce) {
  std::vector<std::atomic<int>> calls(1000);
  parallelFor(calls.size(), [&](std::size_t i) { ++calls[i]; });
  for (const auto& count : calls) EXPECT_EQ(count.load(), 1);
  parallelFor(0, [](std::size_t) { FAIL() << "no index to call"; });
}

TEST(ParallelFor, RethrowsTheFailureOfTheLowestIndex) {
  try {
    parallelFor(200, [](std::size_t i) {
      if (i == 37 || i == 150) throw std::runtime_error("index " + std::to_string(i));
    });
    FAIL() << "the failures must be rethrown";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()), "index 37");
  }
}

}  // namespace
}  // namespace airshape
