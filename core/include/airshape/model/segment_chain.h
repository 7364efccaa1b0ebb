#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace airshape::model {

/// The two element uIDs a segment of a lofted component runs between.
struct SegmentEnds {
  std::string fromElementUid;
  std::string toElementUid;
};

/// The order in which segments form one continuous chain, each ending where the next
/// begins (to(i) == from(i+1)), whatever their order in the file. Segment indices of the
/// query protocol count in this order. Throws Error(InvalidModel) when the segments do not
/// form one chain (a branch, a gap, a loop, two segments leaving or reaching one element).
std::vector<std::size_t> chainOrder(const std::vector<SegmentEnds>& segments);

}  // namespace airshape::model
