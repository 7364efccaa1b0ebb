#include "airshape/model/segment_chain.h"

#include <unordered_map>

#include "airshape/error.h"

namespace airshape::model {

namespace {

[[noreturn]] void notAChain(const std::string& why) {
  throw Error(ErrorCode::InvalidModel, "segments do not form one continuous chain: " + why);
}

}  // namespace

std::vector<std::size_t> chainOrder(const std::vector<SegmentEnds>& segments) {
  std::unordered_map<std::string, std::size_t> startingAt;  // element uID -> segment leaving it
  std::unordered_map<std::string, std::size_t> endingAt;    // element uID -> segment reaching it
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (!startingAt.emplace(segments[i].fromElementUid, i).second)
      notAChain("two segments start at element '" + segments[i].fromElementUid + "'");
    if (!endingAt.emplace(segments[i].toElementUid, i).second)
      notAChain("two segments end at element '" + segments[i].toElementUid + "'");
  }
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (endingAt.count(segments[i].fromElementUid) == 0) {
      if (!order.empty()) notAChain("it has more than one first segment");
      order.push_back(i);
    }
  }
  if (order.empty() && !segments.empty()) notAChain("the segments form a loop");
  while (!order.empty() && order.size() < segments.size()) {
    const auto next = startingAt.find(segments[order.back()].toElementUid);
    if (next == startingAt.end()) notAChain("it breaks after element '" + segments[order.back()].toElementUid + "'");
    order.push_back(next->second);
  }
  return order;
}

}  // namespace airshape::model
