#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "airshape/error.h"
#include "airshape/problem.h"
#include "airshape/schema/node.h"

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

/// A check for graph::ComponentLocation::leftOutWhen: a lofted component (of generated type
/// `Lofted`, with segments between section elements) whose segments form no chain cannot be
/// built; the warning names its segments.
template <class Lofted>
std::optional<Problem> segmentsFormNoChain(const schema::Node& node) {
  const auto* lofted = dynamic_cast<const Lofted*>(&node);
  if (lofted == nullptr) return std::nullopt;
  std::vector<SegmentEnds> ends;
  if (lofted->segments)
    for (const auto& segment : lofted->segments->segment)
      ends.push_back({segment.fromElementUID, segment.toElementUID});
  try {
    chainOrder(ends);
  } catch (const Error& error) {
    return Problem{Problem::Severity::Warning, lofted->xpath + "/segments",
                   error.message() + "; " + lofted->uID + " cannot be built and is left out"};
  }
  return std::nullopt;
}

}  // namespace airshape::model
