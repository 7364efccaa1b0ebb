#include "airshape/model/segment_chain.h"

#include <gtest/gtest.h>

#include "airshape/error.h"

namespace airshape::model {
namespace {

TEST(SegmentChain, SortsSegmentsIntoTheirChain) {
  EXPECT_EQ(chainOrder({{"b", "c"}, {"a", "b"}, {"c", "d"}}), (std::vector<std::size_t>{1, 0, 2}));
  EXPECT_EQ(chainOrder({{"a", "b"}}), (std::vector<std::size_t>{0}));
  EXPECT_TRUE(chainOrder({}).empty());
}

std::string chainError(const std::vector<SegmentEnds>& segments) {
  try {
    chainOrder(segments);
  } catch (const Error& error) {
    return error.message();
  }
  return "no error";
}

TEST(SegmentChain, RefusesWhatIsNoChain) {
  EXPECT_NE(chainError({{"c", "b"}, {"a", "b"}}).find("two segments end at element 'b'"), std::string::npos);
  EXPECT_NE(chainError({{"a", "b"}, {"a", "c"}}).find("two segments start at element 'a'"), std::string::npos);
  EXPECT_NE(chainError({{"a", "b"}, {"b", "a"}}).find("loop"), std::string::npos);
  EXPECT_NE(chainError({{"a", "b"}, {"c", "d"}}).find("more than one first segment"), std::string::npos);
}

}  // namespace
}  // namespace airshape::model
